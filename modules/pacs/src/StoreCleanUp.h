// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// The store's size limit: clean-up of whole studies, least recently used
// first, skipping open (leased) studies; and the locks that keep commits and
// clean-ups of every process sharing a store one at a time.

#include <cstdint>
#include <filesystem>
#include <mutex>
#include <string>
#include <vector>

#include "FileLock.h"

namespace vv::pacs::detail {

/// Commits and clean-ups of this process go one at a time.
std::mutex& storeMutex();

/// The store-wide lock (<root>/.lock) of commits and clean-ups across
/// processes; waits at most 30 s. Throws IoError.
FileLock lockStore(const std::filesystem::path& root);

/// Bytes of the files in `folder` and below (0 when it is missing).
std::uint64_t folderBytes(const std::filesystem::path& folder);

/// Removes the indexed study `studyUid` (out of the index in one SQL
/// transaction, then its folder) unless it is open; false (nothing removed)
/// when it is. For a caller that holds storeMutex() and lockStore(root).
/// Throws IoError.
bool removeUnlessOpen(const std::filesystem::path& root, const std::string& studyUid);

/// Clean-up as LocalStore::cleanUp() promises, for a caller that holds
/// storeMutex() and lockStore(root). Throws IoError.
std::vector<std::string> cleanUpLocked(const std::filesystem::path& root, std::uint64_t limit,
                                       const std::vector<std::string>& keep);

}  // namespace vv::pacs::detail
