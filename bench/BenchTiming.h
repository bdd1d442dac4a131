// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// What the micro-benchmarks share: the wall time of one call.

#include <chrono>

namespace vv::bench {

/// Wall-clock milliseconds that f() takes.
template <typename F>
double millisecondsOf(F&& f) {
    const auto start = std::chrono::steady_clock::now();
    f();
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
        .count();
}

}  // namespace vv::bench
