// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// The SQLite index of the local store, through Qt SQL. Each call opens its own
// connection, so any thread may call (the listener's worker, a retrieve).

#include <filesystem>
#include <string>
#include <vector>

#include "vv/pacs/LocalStore.h"

namespace vv::pacs::detail {

/// Creates the index's tables when missing. Throws IoError / FormatError.
void createIndex(const std::filesystem::path& database);

/// One series made complete by a commit: its fields and its instance count.
struct CommittedSeries {
    InstanceFields fields;  ///< study and series fields (from one of its instances)
    int instances = 0;      ///< files now in the series folder
};

/// Inserts or updates the studies and series in one SQL transaction. Throws IoError.
void recordSeries(const std::filesystem::path& database,
                  const std::vector<CommittedSeries>& series);

/// Records now as the last use of the study; false when it is not indexed.
/// Throws IoError.
bool touchStudy(const std::filesystem::path& database, const std::string& studyUid);

/// The indexed studies' UIDs, least recently used first. Throws IoError.
std::vector<std::string> studiesByUse(const std::filesystem::path& database);

/// Takes the study and its series out of the index (one SQL transaction).
/// Throws IoError.
void removeStudy(const std::filesystem::path& database, const std::string& studyUid);

/// The indexed studies with their series (folders not filled in). Throws IoError.
std::vector<StoredStudy> readIndex(const std::filesystem::path& database);

}  // namespace vv::pacs::detail
