// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/core/AtomicFile.h"

#include <unistd.h>

#include <atomic>
#include <string>
#include <system_error>

#include "vv/core/Error.h"

namespace vv {

namespace fs = std::filesystem;

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
    } catch (...) {
        fs::remove(temporary, ec);
        throw;
    }
    if (!fs::exists(temporary, ec)) {
        throw IoError(target, "cannot write: nothing was written (no permission or disk full?)");
    }
    fs::rename(temporary, target, ec);
    if (ec) {
        fs::remove(temporary, ec);
        throw IoError(target, "cannot write: " + ec.message());
    }
}

}  // namespace vv
