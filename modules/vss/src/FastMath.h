// SPDX-License-Identifier: GPL-3.0-or-later
// The VSS solvers' math helpers: branch-free float log2 / exp2 approximations
// that GCC vectorises (no table, no libm call), for the brute solver's weight
// w = exp2(-p/2 * log2(d^2 / dmin^2)); and, for the fast solver's traversal
// and expansions, double log2 / exp2 with known error, a small complex type
// and a two-complex vector type.
#pragma once

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

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

// ---------------------------------------------------------------- complex numbers
// A small complex type: std::complex<double> multiplication goes through a
// NaN-recovering library call without -ffast-math; our values are finite.
// Trivial on purpose: scratch arrays of Cx are not zero-filled (Cx{} is zero).
struct Cx {
    double re;
    double im;
};
inline Cx operator+(Cx a, Cx b) {
    return {a.re + b.re, a.im + b.im};
}
inline Cx operator*(Cx a, Cx b) {
    return {a.re * b.re - a.im * b.im, a.re * b.im + a.im * b.re};
}
inline Cx operator*(double s, Cx a) {
    return {s * a.re, s * a.im};
}
inline Cx conj(Cx a) {
    return {a.re, -a.im};
}
inline Cx& operator+=(Cx& a, Cx b) {
    a.re += b.re;
    a.im += b.im;
    return a;
}

// Two complex numbers side by side (D and N parts): [a.re, a.im, b.re, b.im].
//
// A V4 never crosses a call boundary by value. The fast solver is compiled for
// baseline x86-64 and, in its target_clones functions (FastSourceTree.cpp,
// FastExpansion.cpp), for x86-64-v3 as well, and the two pass a 32-byte vector
// differently (baseline: in memory; AVX: in a ymm register; GCC's -Wpsabi
// note). An out-of-line helper taking or returning a V4 by value, called from
// an AVX clone, reads its argument from the wrong place: at -O0 (the asan
// preset, nothing inlined) cmul4(V4, Cx) crashed exactly so. Hence the helpers below take and give V4 by reference
// and are always inlined, so the optimised code is the same as before.
using V4 = double __attribute__((vector_size(32)));
// out = v * c per complex half
[[gnu::always_inline]] inline void cmul4(V4& out, const V4& v, Cx c) {
    const V4 sw = __builtin_shufflevector(v, v, 1, 0, 3, 2);
    out = v * c.re + sw * V4{-c.im, c.im, -c.im, c.im};
}
// acc += v * c per complex half
[[gnu::always_inline]] inline void cmulAdd4(V4& acc, const V4& v, Cx c) {
    const V4 sw = __builtin_shufflevector(v, v, 1, 0, 3, 2);
    acc += v * c.re + sw * V4{-c.im, c.im, -c.im, c.im};
}

// ---------------------------------------------------------------- fast scalar powers
// log2 / exp2 in double for the bounds of the traversal (the C library's pow
// would take a fifth of the run time). log2: t = (m-1)/(m+1), |t| <= 0.1716,
// 2/ln2 * atanh(t) to t^17 (truncation < 1e-15). exp2: 2^f, |f| <= 1/2, Taylor
// to degree 11 (truncation < 3e-13), times 2^k. Relative error of
// exp2(y log2 x) below 1e-13 for |y log2 x| < 2000; every bound that uses
// them carries a relative margin of 1e-9.
inline double log2d(double x) {
    // x > 0 finite; normal range only (the ratios here are within 1e-300 .. 1e300)
    const auto bits = std::bit_cast<std::uint64_t>(x);
    int e = static_cast<int>((bits >> 52) & 0x7ff) - 1023;
    double m = std::bit_cast<double>((bits & 0x000fffffffffffffULL) | 0x3ff0000000000000ULL);
    if (m > 1.4142135623730951) {
        m *= 0.5;
        ++e;
    }
    const double t = (m - 1.0) / (m + 1.0);
    const double t2 = t * t;
    constexpr double kInvOdd[9] = {1.0,      1.0 / 3,  1.0 / 5,  1.0 / 7, 1.0 / 9,
                                   1.0 / 11, 1.0 / 13, 1.0 / 15, 1.0 / 17};
    double s = kInvOdd[8];
    for (int k = 7; k >= 0; --k) {
        s = s * t2 + kInvOdd[k];
    }
    return static_cast<double>(e) + 2.8853900817779268 * t * s;  // 2/ln2
}
inline double exp2d(double y) {
    if (y < -1000.0) {
        return y < -1100.0 ? 0.0 : std::exp2(y);  // denormal range: the library
    }
    if (y > 1020.0) {
        return y > 1100.0 ? std::numeric_limits<double>::infinity() : std::exp2(y);
    }
    const double k = std::floor(y + 0.5);
    const double g = (y - k) * 0.69314718055994531;
    // e^g, |g| <= 0.347: Taylor to degree 11 (truncation < 3e-13 relative),
    // evaluated in two interleaved halves to shorten the dependency chain
    const double g2 = g * g;
    const double even =
        1.0 + g2 * (1.0 / 2 +
                    g2 * (1.0 / 24 + g2 * (1.0 / 720 + g2 * (1.0 / 40320 + g2 * (1.0 / 3628800)))));
    const double odd =
        1.0 +
        g2 * (1.0 / 6 +
              g2 * (1.0 / 120 + g2 * (1.0 / 5040 + g2 * (1.0 / 362880 + g2 * (1.0 / 39916800)))));
    const double s = even + g * odd;
    // s in [0.7, 1.42]: scale by 2^k through the exponent field (k in [-1000, 1020])
    return std::bit_cast<double>(std::bit_cast<std::uint64_t>(s) +
                                 (static_cast<std::uint64_t>(static_cast<std::int64_t>(k)) << 52));
}
// (ratio2)^(p/2) for squared-distance ratios.
inline double powHalf(double ratio2, double halfP) {
    return exp2d(halfP * log2d(ratio2));
}

}  // namespace vv::vss::detail
