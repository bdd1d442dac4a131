// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/core/AtomicFile.h"

#include <fcntl.h>
#include <unistd.h>

#include <atomic>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <system_error>

#include "vv/core/Error.h"

namespace vv {

namespace fs = std::filesystem;

namespace {

/// " (no space left on device: the disk is full)" when the file system of
/// `folder` has (almost) no room left, else empty: a failed write says why.
/// Called before the partial file is removed, while it still fills the disk.
std::string diskFullNote(const fs::path& folder) {
    std::error_code ec;
    const fs::space_info space = fs::space(folder, ec);
    constexpr std::uintmax_t kAlmostFull = 64 * 1024;
    if (ec || (space.available >= kAlmostFull && space.free >= kAlmostFull)) {
        return {};
    }
    return " (no space left on device: the disk is full)";
}

/// Asks the kernel to put `path` (a file or a folder) on the disk now:
/// without it a power cut can leave a renamed file empty or the rename
/// itself undone. Returns false when it could not.
bool flushToDisk(const fs::path& path) {
    // NOLINTNEXTLINE(cppcoreguidelines-pro-type-vararg): POSIX's open(2)
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) {
        return false;
    }
    const bool flushed = ::fsync(fd) == 0;
    ::close(fd);
    return flushed;
}

}  // namespace

void writeAtomically(const fs::path& target, const std::function<void(const fs::path&)>& write) {
    static std::atomic<unsigned> counter{0};
    const fs::path folder = target.has_parent_path() ? target.parent_path() : fs::path(".");
    std::error_code ec;
    if (!fs::is_directory(folder, ec)) {
        throw IoError(target, "cannot write: folder '" + folder.string() + "' does not exist");
    }
    if (fs::is_directory(target, ec)) {
        throw IoError(target, "cannot write: it is a folder");
    }
    const fs::path temporary =
        folder / ("." + target.filename().string() + ".tmp-" + std::to_string(::getpid()) + "-" +
                  std::to_string(counter.fetch_add(1)));
    try {
        write(temporary);
    } catch (const IoError& e) {
        const std::string full = diskFullNote(folder);
        fs::remove(temporary, ec);
        if (full.empty()) {
            throw;
        }
        throw IoError(target, e.problem() + full);
    } catch (...) {
        fs::remove(temporary, ec);
        throw;
    }
    if (!fs::exists(temporary, ec)) {
        const std::string full = diskFullNote(folder);
        throw IoError(target,
                      "cannot write: nothing was written" +
                          (full.empty() ? std::string(" (no permission or disk full?)") : full));
    }
    // The bytes on the disk before the name points at them, and the new
    // name on the disk after: a power cut leaves the old file or the new.
    if (!flushToDisk(temporary)) {
        fs::remove(temporary, ec);
        throw IoError(target, "cannot write: the file cannot be flushed to the disk");
    }
    fs::rename(temporary, target, ec);
    if (ec) {
        fs::remove(temporary, ec);
        throw IoError(target, "cannot write: " + ec.message());
    }
    static_cast<void>(
        flushToDisk(folder));  // some file systems cannot sync a folder; the rename stands
}

void writeFileAtomically(const fs::path& target, std::string_view contents) {
    writeAtomically(target, [&](const fs::path& temporary) {
        std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
        out.write(contents.data(), static_cast<std::streamsize>(contents.size()));
        out.flush();
        if (!out) {
            throw IoError(target, "cannot write the file");
        }
    });
}

}  // namespace vv
