// SPDX-License-Identifier: GPL-3.0-or-later
// The image sizes of `vesselview-cli bench` (--size WxH, --sizes WxH,WxH...).
#pragma once

#include <string>
#include <vector>

#include "evaluation/VssBenchmark.h"

namespace vv::cli {

/// One size "WxH", each side 1..8192. Throws UsageError naming `what` otherwise.
[[nodiscard]] evaluation::BenchSize parseBenchSize(const std::string& text,
                                                   const std::string& what);

/// A comma-separated list of sizes, e.g. "1280x720,1920x1080,3840x2160", in
/// the given order. Throws UsageError for an empty list or item, a bad size,
/// or a size given twice.
[[nodiscard]] std::vector<evaluation::BenchSize> parseBenchSizes(const std::string& text);

}  // namespace vv::cli
