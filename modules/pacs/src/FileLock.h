// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// Advisory file locks (flock) shared by every process using one store: the
// store lock (<root>/.lock, held while committing and cleaning up) and the
// study leases (<study>/.open, shared while the study is open).

#include <filesystem>
#include <optional>

namespace vv::pacs::detail {

/// An open file with a flock on it; unlocked and closed on destruction.
class FileLock {
  public:
    /// Waits at most `seconds` for the lock (shared or exclusive) on `file`,
    /// creating the file (0600) when missing. Throws IoError when the file
    /// cannot be opened or the lock is not had in time.
    static FileLock wait(const std::filesystem::path& file, bool exclusive, int seconds);
    /// The exclusive lock on `file` when no one holds any lock on it now.
    /// Throws IoError when the file cannot be opened.
    static std::optional<FileLock> tryExclusive(const std::filesystem::path& file);

    FileLock(FileLock&& other) noexcept;
    FileLock& operator=(FileLock&& other) noexcept;
    FileLock(const FileLock&) = delete;
    FileLock& operator=(const FileLock&) = delete;
    ~FileLock();

    /// Hands the descriptor over (the lock stays until it is closed).
    [[nodiscard]] int release() noexcept;
    /// True while the file is the one at `file` (not removed or replaced).
    [[nodiscard]] bool stillAt(const std::filesystem::path& file) const noexcept;

  private:
    explicit FileLock(int fd) noexcept : fd_(fd) {}
    int fd_ = -1;
};

}  // namespace vv::pacs::detail
