// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <filesystem>

class QImage;

/// The commands' outputs: checked before long work, written atomically;
/// failures are OutputErrors (Cli.h: exit code 4).
namespace vv::cli {

/// Throws OutputError when `output` cannot be a new file: its folder does not
/// exist or it is a folder. Call before long work.
void checkOutputPath(const std::filesystem::path& output);

/// Makes `folder` when missing. Throws OutputError when it cannot be made or
/// is not a folder.
void ensureOutputFolder(const std::filesystem::path& folder);

/// Writes `image` as PNG to `output` atomically (report::writePng). Throws
/// OutputError naming the file when it cannot be written.
void writePngOutput(const std::filesystem::path& output, const QImage& image);

}  // namespace vv::cli
