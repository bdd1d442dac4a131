// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// The local study store: DICOM files on disk, one folder per study
// (<root>/<study UID>/<series UID>/<SOP instance UID>.dcm, folders 0700), and
// an index in SQLite (<root>/index.sqlite, through Qt SQL) that holds only
// what the Local studies browser shows. Writes go through a Transaction:
// instances are staged under <root>/.incoming and only commit() moves them
// into their study folders and marks them complete in the index, so a failed
// or cancelled transfer leaves nothing marked complete.
//
// Size limit: when the complete studies' files exceed sizeLimit(), whole
// studies are removed, the least recently used first (the time a study was
// last committed or opened with open()), after every commit and on cleanUp().
// A study that is open (an OpenLease on it, in this or any other process
// sharing the folder: a shared flock on <study>/.open) is never removed, nor
// is the study a commit has just made complete: when that study alone is over
// the limit, every other study that is not open goes and the store stays over
// its limit until the study is removed or the limit raised.

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "vv/core/Error.h"
#include "vv/pacs/StudyFields.h"

namespace vv::pacs {

/// LocalStore::remove() of a study that is open (an OpenLease on it, in this
/// or another process): nothing was removed.
class StudyOpenError : public Error {
    using Error::Error;
};

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
    /// Copies (and moves) share nothing but the folder; the limit is copied.
    LocalStore(const LocalStore& other);
    LocalStore& operator=(const LocalStore& other);
    LocalStore(LocalStore&& other) noexcept;
    LocalStore& operator=(LocalStore&& other) noexcept;
    ~LocalStore() = default;

    [[nodiscard]] const std::filesystem::path& root() const noexcept { return root_; }

    /// The complete studies, sorted by study date (newest first), then UID.
    /// Throws IoError when the index cannot be read.
    [[nodiscard]] std::vector<StoredStudy> studies() const;

    /// The size limit in bytes of the complete studies' files; 0 (the
    /// default) means none. Any thread may set it; it applies from the next
    /// begin() and cleanUp() on.
    void setSizeLimit(std::uint64_t bytes) noexcept;
    [[nodiscard]] std::uint64_t sizeLimit() const noexcept;

    /// Bytes of the complete studies' files on disk (what the limit counts).
    /// Throws IoError when the index cannot be read.
    [[nodiscard]] std::uint64_t sizeOnDisk() const;

    /// Keeps one study from clean-up while it lives (RAII; movable). Held
    /// across processes: a shared flock on <study>/.open, released when the
    /// lease is destroyed or its process ends.
    class OpenLease {
      public:
        OpenLease(OpenLease&& other) noexcept;
        OpenLease& operator=(OpenLease&& other) noexcept;
        OpenLease(const OpenLease&) = delete;
        OpenLease& operator=(const OpenLease&) = delete;
        ~OpenLease();
        [[nodiscard]] const std::string& studyInstanceUid() const noexcept { return uid_; }

      private:
        friend class LocalStore;
        OpenLease(int fd, std::string uid) noexcept;
        int fd_ = -1;
        std::string uid_;
    };

    /// Marks the complete study `studyInstanceUid` open (clean-up leaves it
    /// alone until the lease ends) and records now as its last use. Throws
    /// InvalidArgumentError when the study is not complete in the store (or
    /// was just removed), IoError when its lock cannot be taken in 10 s.
    [[nodiscard]] OpenLease open(const std::string& studyInstanceUid) const;

    /// Removes whole studies, least recently used first, until the store is
    /// within its limit (nothing without a limit). Skips open studies and
    /// those in `keep`. Each removal takes the study out of the index first
    /// (one SQL transaction) and then deletes its folder, so a crash midway
    /// leaves at most an unindexed folder, never an indexed study without
    /// files; such leftovers (of a crash, or of a commit that failed midway)
    /// are deleted by the next clean-up. Returns the removed Study Instance
    /// UIDs, oldest first. Throws IoError when the index cannot be read or
    /// written.
    // NOLINTNEXTLINE(modernize-use-nodiscard): called for its effect
    std::vector<std::string> cleanUp(const std::vector<std::string>& keep = {}) const;

    /// Removes the whole complete study `studyInstanceUid` as cleanUp() removes
    /// one: out of the index first (one SQL transaction), then its folder.
    /// Throws StudyOpenError when it is open (an OpenLease on it, in this or
    /// any other process; nothing is removed then), InvalidArgumentError when
    /// it is not in the store, IoError when the index cannot be read or
    /// written or another process holds the store lock for more than 30 s.
    void remove(const std::string& studyInstanceUid) const;

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
        /// nothing of this transaction is marked complete. Afterwards, when
        /// the store is over its limit, cleans up (the studies just committed
        /// kept); a failing clean-up is logged ("vv.pacs"), not thrown.
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
    std::atomic<std::uint64_t> sizeLimit_{0};
};

}  // namespace vv::pacs
