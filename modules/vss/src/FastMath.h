// SPDX-License-Identifier: GPL-3.0-or-later
// Branch-free float log2 / exp2 approximations that GCC vectorises (no table,
// no libm call), for the weight w = exp2(-p/2 * log2(d^2 / dmin^2)).
#pragma once

#include <algorithm>
#include <bit>
#include <cstdint>

namespace vv::vss::detail {

/// log2(t) for finite normal t > 0. t = 2^e * m with m in [sqrt(1/2), sqrt(2))
/// (found with integer operations on the bits, no branch); log2 m =
/// 2/ln 2 * atanh(s), s = (m - 1) / (m + 1), |s| <= 0.1716, from the odd series
/// s + s^3/3 + ... + s^9/9 (truncation below 3e-9 relative to log2 m). The rest
/// is float round-off: tests/vss/FastMathTest.cpp measures and bounds it
/// (absolute error below 2e-7 for t in [1/2, 2], relative below 2e-7 beyond).
[[gnu::always_inline]] inline float fastLog2(float t) noexcept {
    const auto bits = std::bit_cast<std::int32_t>(t);
    const std::int32_t e = (bits - 0x3f3504f3) >> 23;  // 0x3f3504f3 = sqrt(1/2)
    const float m = std::bit_cast<float>(bits - e * (1 << 23));
    const float s = (m - 1.0F) / (m + 1.0F);
    const float s2 = s * s;
    // 2/ln2 * (1 + s2/3 + s2^2/5 + s2^3/7 + s2^4/9)
    constexpr float c1 = 2.88539008F;   // 2/ln2
    constexpr float c3 = 0.961796694F;  // 2/ln2 / 3
    constexpr float c5 = 0.577078016F;  // 2/ln2 / 5
    constexpr float c7 = 0.412198583F;  // 2/ln2 / 7
    constexpr float c9 = 0.320598898F;  // 2/ln2 / 9
    const float poly = c1 + s2 * (c3 + s2 * (c5 + s2 * (c7 + s2 * c9)));
    return static_cast<float>(e) + s * poly;
}

/// exp2(a) for a <= 0.5 (the weights' range), a > -2^31. Returns exactly 0 for
/// a <= -126 (where exp2 is below 1.2e-38: nothing next to the nearest weight 1)
/// and never a denormal. a = i + f with i = trunc(a) (<= 0), f in (-1, 0.5];
/// 2^f = 2^-1/4 * 2^g, g = f + 1/4 in (-3/4, 3/4], from the Taylor series of
/// e^(g ln 2) to degree 8 (truncation below 1e-8 relative); relative error
/// below 2e-7 in total (measured in tests/vss/FastMathTest.cpp).
/// Only integer min / masks: a float compare (which may trap) or a branch
/// would keep GCC from vectorising the caller's loop.
[[gnu::always_inline]] inline float fastExp2(float a) noexcept {
    const auto i = static_cast<std::int32_t>(a);  // truncates towards 0
    const float g = (a - static_cast<float>(i)) + 0.25F;
    // c_k = 2^-1/4 * ln2^k / k!
    constexpr float k0 = 0.840896415F;
    constexpr float k1 = 0.582864979F;
    constexpr float k2 = 0.202005609F;
    constexpr float k3 = 0.0466732060F;
    constexpr float k4 = 0.00808785029F;
    constexpr float k5 = 0.00112121412F;
    constexpr float k6 = 0.000129527735F;
    constexpr float k7 = 0.0000128259692F;
    constexpr float k8 = 0.00000111128555F;
    const float p =
        k0 + g * (k1 + g * (k2 + g * (k3 + g * (k4 + g * (k5 + g * (k6 + g * (k7 + g * k8)))))));
    const std::int32_t clamped = std::max(i, -125);
    const std::int32_t bits = std::bit_cast<std::int32_t>(p) + clamped * (1 << 23);
    return std::bit_cast<float>(bits & -static_cast<std::int32_t>(i >= -125));
}

}  // namespace vv::vss::detail
