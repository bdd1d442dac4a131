// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <algorithm>
#include <cctype>
#include <string_view>

namespace vv {

/// Whether `a` and `b` are the same text up to the case of ASCII letters
/// ("Viridis" and "viridis"; names, keys and file names, never prose: no
/// locale, and a byte outside ASCII must match exactly).
[[nodiscard]] inline bool equalsIgnoringCase(std::string_view a, std::string_view b) noexcept {
    return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
               return std::tolower(static_cast<unsigned char>(x)) ==
                      std::tolower(static_cast<unsigned char>(y));
           });
}

}  // namespace vv
