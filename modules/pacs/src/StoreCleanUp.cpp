// SPDX-License-Identifier: GPL-3.0-or-later
#include "StoreCleanUp.h"

#include <unistd.h>

#include <algorithm>
#include <map>
#include <optional>
#include <system_error>
#include <utility>

#include "StoreIndex.h"
#include "vv/core/Error.h"
#include "vv/core/Log.h"
#include "vv/pacs/LocalStore.h"
#include "vv/pacs/Uid.h"

namespace fs = std::filesystem;

namespace vv::pacs {

namespace {

constexpr log::Category kLog("vv.pacs");

fs::path indexFile(const fs::path& root) {
    return root / "index.sqlite";
}

fs::path leaseFile(const fs::path& root, const std::string& studyUid) {
    return root / studyUid / ".open";
}

/// Deletes the folder of a study already taken out of the index: first moved
/// aside (one rename), so that the study's path is free at once.
void removeFolder(const fs::path& root, const std::string& studyUid) {
    std::error_code ec;
    const fs::path aside =
        root / ".incoming" / ("removed-" + studyUid + "-" + std::to_string(::getpid()));
    fs::remove_all(aside, ec);
    fs::rename(root / studyUid, aside, ec);
    fs::remove_all(ec ? root / studyUid : aside, ec);
    if (ec) {
        log::warning(kLog, "cannot delete the files of a removed study: " + ec.message());
    }
}

/// Deletes what a crashed or failed clean-up or commit left: folders being
/// removed (.incoming/removed-*) and study folders the index does not know.
/// Safe under the store lock: no commit or clean-up is running then.
void sweepLeftovers(const fs::path& root, const std::vector<std::string>& indexed) {
    std::error_code ec;
    for (const auto& e : fs::directory_iterator(root / ".incoming", ec)) {
        if (e.path().filename().string().starts_with("removed-")) {
            fs::remove_all(e.path(), ec);
        }
    }
    for (const auto& e : fs::directory_iterator(root, ec)) {
        const std::string name = e.path().filename().string();
        bool isUid = e.is_directory(ec);
        try {
            validateUid(name);
        } catch (const InvalidArgumentError&) {
            isUid = false;
        }
        if (isUid && std::find(indexed.begin(), indexed.end(), name) == indexed.end()) {
            fs::remove_all(e.path(), ec);
        }
    }
}

}  // namespace

namespace detail {

std::mutex& storeMutex() {
    static std::mutex m;
    return m;
}

FileLock lockStore(const fs::path& root) {
    return FileLock::wait(root / ".lock", true, 30);
}

std::uint64_t folderBytes(const fs::path& folder) {
    std::uint64_t bytes = 0;
    std::error_code ec;
    for (fs::recursive_directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec)) {
        std::error_code sizeError;
        if (it->is_regular_file(sizeError)) {
            const auto size = it->file_size(sizeError);
            bytes += sizeError ? 0 : size;
        }
    }
    return bytes;
}

bool removeUnlessOpen(const fs::path& root, const std::string& studyUid) {
    std::optional<FileLock> lock;
    if (fs::is_directory(root / studyUid)) {
        lock = FileLock::tryExclusive(leaseFile(root, studyUid));
        if (!lock) {
            return false;
        }
    }
    removeStudy(indexFile(root), studyUid);
    removeFolder(root, studyUid);
    return true;
}

std::vector<std::string> cleanUpLocked(const fs::path& root, std::uint64_t limit,
                                       const std::vector<std::string>& keep) {
    std::vector<std::string> removed;
    const std::vector<std::string> byUse = studiesByUse(indexFile(root));
    sweepLeftovers(root, byUse);
    if (limit == 0) {
        return removed;
    }
    std::map<std::string, std::uint64_t> bytes;
    std::uint64_t total = 0;
    for (const std::string& uid : byUse) {
        total += bytes[uid] = folderBytes(root / uid);
    }
    for (const std::string& uid : byUse) {
        if (total <= limit) {
            break;
        }
        if (std::find(keep.begin(), keep.end(), uid) != keep.end()) {
            continue;
        }
        if (!removeUnlessOpen(root, uid)) {
            continue;  // open in this or another process
        }
        total -= bytes[uid];
        removed.push_back(uid);
    }
    if (total > limit) {
        log::warning(kLog, "the study store is over its size limit: the rest is open or new");
    }
    if (!removed.empty()) {
        log::info(kLog, "removed " + std::to_string(removed.size()) +
                            " least recently used stud(ies) to keep the store within its limit");
    }
    return removed;
}

}  // namespace detail

void LocalStore::setSizeLimit(std::uint64_t bytes) noexcept {
    sizeLimit_ = bytes;
}

std::uint64_t LocalStore::sizeLimit() const noexcept {
    return sizeLimit_;
}

std::uint64_t LocalStore::sizeOnDisk() const {
    std::uint64_t total = 0;
    for (const std::string& uid : detail::studiesByUse(indexFile(root_))) {
        total += detail::folderBytes(root_ / uid);
    }
    return total;
}

std::vector<std::string> LocalStore::cleanUp(const std::vector<std::string>& keep) const {
    const std::lock_guard lock(detail::storeMutex());
    const detail::FileLock storeLock = detail::lockStore(root_);
    return detail::cleanUpLocked(root_, sizeLimit_, keep);
}

void LocalStore::remove(const std::string& studyInstanceUid) const {
    validateUid(studyInstanceUid);
    const std::lock_guard lock(detail::storeMutex());
    const detail::FileLock storeLock = detail::lockStore(root_);
    const std::vector<std::string> indexed = detail::studiesByUse(indexFile(root_));
    if (std::find(indexed.begin(), indexed.end(), studyInstanceUid) == indexed.end()) {
        throw InvalidArgumentError(root_, "the study is not in the store");
    }
    if (!detail::removeUnlessOpen(root_, studyInstanceUid)) {
        throw StudyOpenError(root_, "the study is open and was not removed");
    }
    log::info(kLog, "removed a study from the store");
}

LocalStore::OpenLease LocalStore::open(const std::string& studyInstanceUid) const {
    validateUid(studyInstanceUid);
    const std::string notHere = "the study is not in the store";
    if (!fs::is_directory(root_ / studyInstanceUid)) {
        throw InvalidArgumentError(root_, notHere);
    }
    const fs::path file = leaseFile(root_, studyInstanceUid);
    detail::FileLock lock = [&] {
        try {
            return detail::FileLock::wait(file, false, 10);
        } catch (const IoError&) {
            if (!fs::is_directory(root_ / studyInstanceUid)) {
                throw InvalidArgumentError(root_, notHere);  // removed meanwhile
            }
            throw;
        }
    }();
    if (!lock.stillAt(file) || !detail::touchStudy(indexFile(root_), studyInstanceUid)) {
        throw InvalidArgumentError(root_, notHere);
    }
    return {lock.release(), studyInstanceUid};
}

LocalStore::OpenLease::OpenLease(int fd, std::string uid) noexcept
    : fd_(fd), uid_(std::move(uid)) {}

LocalStore::OpenLease::OpenLease(OpenLease&& other) noexcept
    : fd_(std::exchange(other.fd_, -1)), uid_(std::move(other.uid_)) {}

LocalStore::OpenLease& LocalStore::OpenLease::operator=(OpenLease&& other) noexcept {
    if (this != &other) {
        if (fd_ >= 0) {
            ::close(fd_);
        }
        fd_ = std::exchange(other.fd_, -1);
        uid_ = std::move(other.uid_);
    }
    return *this;
}

LocalStore::OpenLease::~OpenLease() {
    if (fd_ >= 0) {
        ::close(fd_);
    }
}

}  // namespace vv::pacs
