// SPDX-License-Identifier: GPL-3.0-or-later
#include "FileLock.h"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <thread>
#include <utility>

#include "vv/core/Error.h"

namespace vv::pacs::detail {

namespace {

int openLockFile(const std::filesystem::path& file) {
    // NOLINTNEXTLINE(cppcoreguidelines-pro-type-vararg): open(2) with a mode
    const int fd = ::open(file.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0600);
    if (fd < 0) {
        throw IoError(file, std::string("cannot open the lock file: ") + std::strerror(errno));
    }
    return fd;
}

}  // namespace

FileLock FileLock::wait(const std::filesystem::path& file, bool exclusive, int seconds) {
    FileLock lock(openLockFile(file));
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(seconds);
    while (::flock(lock.fd_, (exclusive ? LOCK_EX : LOCK_SH) | LOCK_NB) != 0) {
        if (errno != EWOULDBLOCK && errno != EINTR) {
            throw IoError(file, std::string("cannot lock: ") + std::strerror(errno));
        }
        if (std::chrono::steady_clock::now() > deadline) {
            throw IoError(
                file, "locked by another process for more than " + std::to_string(seconds) + " s");
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    return lock;
}

std::optional<FileLock> FileLock::tryExclusive(const std::filesystem::path& file) {
    FileLock lock(openLockFile(file));
    if (::flock(lock.fd_, LOCK_EX | LOCK_NB) != 0) {
        return std::nullopt;
    }
    return lock;
}

FileLock::FileLock(FileLock&& other) noexcept : fd_(std::exchange(other.fd_, -1)) {}

FileLock& FileLock::operator=(FileLock&& other) noexcept {
    if (this != &other) {
        if (fd_ >= 0) {
            ::close(fd_);
        }
        fd_ = std::exchange(other.fd_, -1);
    }
    return *this;
}

FileLock::~FileLock() {
    if (fd_ >= 0) {
        ::close(fd_);
    }
}

int FileLock::release() noexcept {
    return std::exchange(fd_, -1);
}

bool FileLock::stillAt(const std::filesystem::path& file) const noexcept {
    struct stat held {};
    struct stat named {};
    return fd_ >= 0 && ::fstat(fd_, &held) == 0 && ::stat(file.c_str(), &named) == 0 &&
           held.st_dev == named.st_dev && held.st_ino == named.st_ino;
}

}  // namespace vv::pacs::detail
