// SPDX-License-Identifier: GPL-3.0-or-later
// Private to vv::study: CSV fields and files as the study writes them.
#pragma once

#include <filesystem>
#include <string>

namespace vv::study::detail {

/// `text` as a CSV field: quoted (quotes doubled) when it holds a comma, a
/// quote or a line break (RFC 4180), else as it is.
[[nodiscard]] std::string csvField(const std::string& text);

/// Writes `text` to `file` atomically (writeAtomically). Throws IoError
/// naming `file` when it cannot be written.
void writeTextFile(const std::filesystem::path& file, const std::string& text);

}  // namespace vv::study::detail
