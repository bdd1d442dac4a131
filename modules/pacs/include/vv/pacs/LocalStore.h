// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// The local study store: DICOM files on disk, one folder per study
// (<root>/<study UID>/<series UID>/<SOP instance UID>.dcm, folders 0700), and
// an index in SQLite (<root>/index.sqlite, through Qt SQL) that holds only
// what the Local studies browser shows. Writes go through a Transaction:
// instances are staged under <root>/.incoming and only commit() moves them
// into their study folders and marks them complete in the index, so a failed
// or cancelled transfer leaves nothing marked complete.

#include <cstddef>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "vv/pacs/StudyFields.h"

namespace vv::pacs {

/// What the index knows of one instance (what the browser shows).
struct InstanceFields {
    std::string sopInstanceUid;
    std::string studyInstanceUid;
    std::string seriesInstanceUid;
    std::string patientName;
    std::string patientId;
    std::string studyDate;
    std::string studyDescription;
    std::string accessionNumber;
    std::string modality;
    std::string seriesDescription;
    int seriesNumber = -1;
};

struct StoredSeries {
    std::string seriesInstanceUid;
    std::string modality;
    std::string seriesDescription;
    int seriesNumber = -1;
    int instances = 0;
    std::filesystem::path folder;
};

struct StoredStudy : StudyFields {
    std::vector<StoredSeries> series;
    std::filesystem::path folder;
};

class LocalStore {
  public:
    /// Opens (creating when missing) the store at `root` with permissions 0700
    /// and its index. Throws IoError when the folder or the index cannot be
    /// made, FormatError when the index is not a store index.
    explicit LocalStore(std::filesystem::path root);

    [[nodiscard]] const std::filesystem::path& root() const noexcept { return root_; }

    /// The complete studies, sorted by study date (newest first), then UID.
    /// Throws IoError when the index cannot be read.
    [[nodiscard]] std::vector<StoredStudy> studies() const;

    /// One transfer's instances; discarded on destruction unless committed.
    class Transaction {
      public:
        Transaction(Transaction&&) noexcept;
        Transaction& operator=(Transaction&&) = delete;
        Transaction(const Transaction&) = delete;
        Transaction& operator=(const Transaction&) = delete;
        ~Transaction();

        /// A fresh file path in this transaction's staging folder.
        [[nodiscard]] std::filesystem::path stagingPath();
        /// Records the instance written to `staged` (from stagingPath()). Throws
        /// InvalidArgumentError for a malformed UID in `fields` (the file is
        /// removed) and after commit() or discard().
        void add(const std::filesystem::path& staged, const InstanceFields& fields);
        /// Instances added so far.
        [[nodiscard]] std::size_t size() const noexcept;
        /// Moves the staged files into their study folders and marks them
        /// complete in the index (one SQL transaction). Throws IoError; then
        /// nothing of this transaction is marked complete.
        void commit();
        /// Removes the staged files; nothing is marked complete.
        void discard() noexcept;

      private:
        friend class LocalStore;
        struct State;
        explicit Transaction(std::unique_ptr<State> state);
        std::unique_ptr<State> state_;
    };

    /// Starts a transaction. Throws IoError when its staging folder cannot be made.
    [[nodiscard]] Transaction begin() const;

  private:
    std::filesystem::path root_;
};

}  // namespace vv::pacs
