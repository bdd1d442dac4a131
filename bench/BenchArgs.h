// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// The command lines of the small bench programs: "--name value" pairs and
// volume dimensions.

#include <cstdio>
#include <functional>
#include <glm/glm.hpp>
#include <stdexcept>
#include <string>

namespace vv::bench {

/// "COLUMNS,ROWS,SLICES", each >= 8. Throws std::invalid_argument naming `option`.
inline glm::ivec3 parseDims(const std::string& text, const std::string& option = "--dims") {
    glm::ivec3 d{0};
    if (std::sscanf(text.c_str(), "%d,%d,%d", &d.x, &d.y, &d.z) != 3 || d.x < 8 || d.y < 8 ||
        d.z < 8) {
        throw std::invalid_argument(option + " wants COLUMNS,ROWS,SLICES, each >= 8: " + text);
    }
    return d;
}

/// Calls take(name, value) for each "--name value" pair of the arguments;
/// take returns false for a name it does not know. Throws
/// std::invalid_argument for a missing value or an unknown option.
inline void forEachOption(int argc, char** argv,
                          const std::function<bool(const std::string&, const std::string&)>& take) {
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (i + 1 >= argc) {
            throw std::invalid_argument("missing value after " + a);
        }
        if (!take(a, argv[++i])) {
            throw std::invalid_argument("unknown option " + a);
        }
    }
}

}  // namespace vv::bench
