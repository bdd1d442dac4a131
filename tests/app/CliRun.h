// SPDX-License-Identifier: GPL-3.0-or-later
// Shared by the CLI tests that call vv::cli::run in-process: the result of a
// run, a per-process scratch folder, and a count of lit pixels.
#pragma once

#include <unistd.h>

#include <QImage>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "cli/Cli.h"

namespace vv::test {

struct CliRunResult {
    int code;
    std::string out;
    std::string err;
};

/// `vesselview-cli ARGS...` in this process.
inline CliRunResult runCli(const std::vector<std::string>& args) {
    std::ostringstream out;
    std::ostringstream err;
    const int code = vv::cli::run(args, out, err);
    return {code, out.str(), err.str()};
}

/// <test-tmp>/<name>/run-<pid>: a folder of this test process.
inline std::filesystem::path processTestDir(const std::string& name) {
    return std::filesystem::path(VV_TEST_TMP) / name / ("run-" + std::to_string(::getpid()));
}

/// Pixels brighter than a dark background (sum of channels > 60).
inline long litPixels(const QImage& image) {
    long count = 0;
    for (int y = 0; y < image.height(); ++y) {
        for (int x = 0; x < image.width(); ++x) {
            const QRgb p = image.pixel(x, y);
            count += qRed(p) + qGreen(p) + qBlue(p) > 60 ? 1 : 0;
        }
    }
    return count;
}

}  // namespace vv::test
