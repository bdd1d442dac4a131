// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <filesystem>
#include <functional>
#include <string_view>

namespace vv {

/// Writes a file atomically: `write` receives a temporary path in the same
/// folder as `target` and must create the complete file there; on success
/// the temporary file is renamed onto `target` (atomic on POSIX), so readers
/// see either the old file or the whole new one, never a partial one. The
/// temporary file is flushed to the disk (fsync) before the rename and the
/// folder after it, so a power cut, too, leaves the old file or the new one.
/// If `write` throws, the temporary file is removed and the exception passes
/// through; `target` is left untouched.
/// Throws IoError (naming `target`) when the folder does not exist, is not
/// writable, or the rename fails.
void writeAtomically(const std::filesystem::path& target,
                     const std::function<void(const std::filesystem::path& temporary)>& write);

/// writeAtomically() of `contents`, byte for byte. Throws IoError naming
/// `target` as writeAtomically() does, and when the bytes cannot be written.
void writeFileAtomically(const std::filesystem::path& target, std::string_view contents);

}  // namespace vv
