// SPDX-License-Identifier: GPL-3.0-or-later
// Private to the fast VSS solver: the vector math of its SIMD kernels
// (FastKernel.cpp, FastPointKernel.cpp), 16 float lanes in GCC vector
// extensions. Included into each kernel file, compiled there for AVX-512,
// AVX2 and baseline x86-64; everything is always inlined (see below).
#pragma once

#include <cstdint>

#include "FastKernel.h"

namespace vv::vss::detail {
namespace {  // NOLINT(cert-dcl59-cpp,google-build-namespaces): per kernel file, per ISA

using vf = float __attribute__((vector_size(64)));
using vi = std::int32_t __attribute__((vector_size(64)));
using vu = std::uint32_t __attribute__((vector_size(64)));
inline constexpr int kLanes = 16;
static_assert(kLanes == kLeafTile);

// Every function below that takes or returns a vector is always inlined: the
// kernel is compiled for AVX-512, AVX2 and baseline in one file, and each ISA
// passes a 64-byte vector by value differently (zmm / 2 ymm / memory), so an
// out-of-line call between them would read its arguments from the wrong place
// (what -Wno-psabi silences). The same goes for library templates: an -O0
// build does not inline std::bit_cast<vi>(vf), and the AVX-512 kernel calling
// the baseline instantiation read a null pointer (UBSan in the asan preset);
// asInt / asFloat use the builtin behind it, which is no call at any -O.
#define VV_FAST_INLINE inline __attribute__((always_inline))

VV_FAST_INLINE vi asInt(vf x) {
    return __builtin_bit_cast(vi, x);
}

VV_FAST_INLINE vf asFloat(vi x) {
    return __builtin_bit_cast(vf, x);
}

VV_FAST_INLINE vf splat(float v) {
    return vf{} + v;
}

// log2(x) for normal x > 0, split into the exact exponent e and the mantissa
// part f = log2(m), m in [sqrt(1/2), sqrt(2)). f = (m-1) * Q(m-1) with Q a
// degree-8 Chebyshev fit of log2(1+x)/x on [sqrt(1/2)-1, sqrt(2)-1]
// (approximation error 1.5e-8; with float round-off |error| <= kKernelLog2Error,
// checked exhaustively over all mantissas in FastSolverTest).
VV_FAST_INLINE void vlog2Parts(vf x, vf& e, vf& f) {
    const vi bits = asInt(x);
    vi ex = (bits >> 23) - 127;
    const vf m0 = asFloat((bits & 0x007fffff) | 0x3f800000);
    const vi big = m0 > 1.41421356F;
    const vf m = big ? m0 * 0.5F : m0;
    ex -= big;  // big is -1 where true
    const vf t = m - 1.0F;
    vf q = splat(-0.10749789664F);
    q = q * t + 0.18476033507F;
    q = q * t - 0.19138837616F;
    q = q * t + 0.20485764749F;
    q = q * t - 0.23960812193F;
    q = q * t + 0.28855256146F;
    q = q * t - 0.36069654181F;
    q = q * t + 0.48089852032F;
    q = q * t - 0.72134735448F;
    q = q * t + 1.44269504F;
    // int -> float for |ex| < 2^22 through the 1.5 * 2^23 bias
    e = asFloat(ex + 0x4B400000) - 12582912.0F;
    f = t * q;
}

VV_FAST_INLINE vf vlog2(vf x) {
    vf e;
    vf f;
    vlog2Parts(x, e, f);
    return e + f;
}

// 2^a for a <= ~0.5: a = k + f, f in [-0.5, 0.5], 2^f by a degree-6 Chebyshev
// fit (relative error 2.5e-9; with round-off <= kKernelExp2Error), 2^k by
// exponent arithmetic. Results below 2^-125 are returned as 0.
VV_FAST_INLINE vf vexp2(vf a) {
    const vf magic = splat(12582912.0F);  // 1.5 * 2^23: rounds to an integer
    const vf ac = a < -127.0F ? splat(-127.0F) : a;
    const vf t = ac + magic;
    const vf k = t - magic;
    const vf f = ac - k;
    vf p = splat(0.000154614447F);
    p = p * f + 0.00134004282F;
    p = p * f + 0.00961805668F;
    p = p * f + 0.0555032723F;
    p = p * f + 0.240226509F;
    p = p * f + 0.693147207F;
    p = p * f + 1.0F;
    const vi ki = asInt(t) - 0x4B400000;
    // exponent arithmetic in unsigned lanes: lanes with a out of range (e.g.
    // d = 0 at a contour pixel of the tile, not a region pixel; its result is
    // discarded) wrap instead of overflowing a signed int (UB; UBSan).
    const vu bitsR = __builtin_bit_cast(vu, p) + (__builtin_bit_cast(vu, ki) << 23);
    const vf r = __builtin_bit_cast(vf, bitsR);
    return ki < -125 ? vf{} : r;
}

// r^(p/2) for 0 < r <= 1 (r = S^2 / d^2).
template <int Sq>
VV_FAST_INLINE vf power(vf r, float halfP) {
    if constexpr (Sq >= 0) {
        (void)halfP;
        vf w = r;
        for (int i = 0; i < Sq; ++i) {
            w = w * w;
        }
        return w;
    } else {
        vf e;
        vf f;
        vlog2Parts(r, e, f);
        return vexp2((e + f) * halfP);
    }
}

// Weight of a near point for S^2 = s2 (per lane) and log2 parts of s2.
template <int Sq>
VV_FAST_INLINE vf weight(vf d2, vf s2, vf s2e, vf s2f, float halfP) {
    if constexpr (Sq >= 0) {
        (void)s2e;
        (void)s2f;
        return power<Sq>(s2 / d2, halfP);
    } else {
        (void)s2;
        vf e;
        vf f;
        vlog2Parts(d2, e, f);
        return vexp2(((s2e - e) + (s2f - f)) * halfP);
    }
}

}  // namespace
}  // namespace vv::vss::detail
