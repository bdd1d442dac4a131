// SPDX-License-Identifier: GPL-3.0-or-later
#include "cli/BenchSizes.h"

#include <algorithm>

#include "cli/Arguments.h"
#include "cli/Cli.h"

namespace vv::cli {

evaluation::BenchSize parseBenchSize(const std::string& text, const std::string& what) {
    const auto [w, h] = parseSize(text, what, 1, 8192);
    return evaluation::BenchSize{w, h};
}

std::vector<evaluation::BenchSize> parseBenchSizes(const std::string& text) {
    std::vector<evaluation::BenchSize> sizes;
    for (const std::string& item : splitList(text, "bench: --sizes")) {
        const evaluation::BenchSize size = parseBenchSize(item, "bench: --sizes");
        if (std::find(sizes.begin(), sizes.end(), size) != sizes.end()) {
            throw UsageError("bench: --sizes: " + item + " given twice");
        }
        sizes.push_back(size);
    }
    return sizes;
}

}  // namespace vv::cli
