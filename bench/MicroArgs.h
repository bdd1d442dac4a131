// SPDX-License-Identifier: GPL-3.0-or-later
// Small helpers shared by the micro-benchmarks (vss_fast_micro, vss_solve_pfm).
#pragma once

#include <algorithm>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

namespace vv::bench {

/// "2,4,8" -> {2, 4, 8} (atof: no errors, a benchmark's own arguments).
inline std::vector<double> parseList(const char* s) {
    std::vector<double> v;
    std::stringstream ss(s);
    std::string item;
    while (std::getline(ss, item, ',')) {
        v.push_back(std::atof(item.c_str()));
    }
    return v;
}

/// The upper median of a non-empty sample.
inline double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

}  // namespace vv::bench
