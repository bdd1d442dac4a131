// SPDX-License-Identifier: GPL-3.0-or-later
#include "cli/OutputFiles.h"

#include <QImage>
#include <system_error>

#include "cli/Cli.h"
#include "vv/core/Error.h"
#include "vv/report/ViewExport.h"

namespace vv::cli {

void checkOutputPath(const std::filesystem::path& output) {
    std::error_code ec;
    const std::filesystem::path folder = output.has_parent_path() ? output.parent_path() : ".";
    if (!std::filesystem::is_directory(folder, ec)) {
        throw OutputError(output.string() + ": cannot write: folder '" + folder.string() +
                          "' does not exist");
    }
    if (std::filesystem::is_directory(output, ec)) {
        throw OutputError(output.string() + ": cannot write: it is a folder");
    }
}

void ensureOutputFolder(const std::filesystem::path& folder) {
    std::error_code ec;
    std::filesystem::create_directories(folder, ec);
    if (!std::filesystem::is_directory(folder, ec)) {
        throw OutputError(folder.string() + ": cannot write: not a folder and cannot be made");
    }
}

void writePngOutput(const std::filesystem::path& output, const QImage& image) {
    try {
        report::writePng(output, image);
    } catch (const Error& e) {
        throw OutputError(e.what());
    }
}

}  // namespace vv::cli
