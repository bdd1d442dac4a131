// SPDX-License-Identifier: GPL-3.0-or-later
// The leaf kernel of the fast VSS solver (see FastSolver.cpp for the design).
// Written with GCC vector extensions (16 float lanes = one tile row) and
// compiled three times: AVX-512, AVX2+FMA and baseline x86-64, dispatched at
// run time, so PCs without AVX2 still run it.
#include "FastKernel.h"

#include <cmath>
#include <cstdint>
#include <limits>

#include "FastKernelSimd.h"

namespace vv::vss::detail {
namespace {

template <int Sq, bool PerPixel>
VV_FAST_INLINE void kernelBody(const LeafKernelArgs& a, float* zOut, std::uint32_t* failRows) {
    constexpr int kStride = kMaxPolyDegree + 1;
    const vf lane = {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15};
    const vf u = (lane - a.tu) * a.invA;
    const float halfP = a.power.halfP;
    const int n = a.count;
    const float* __restrict px = a.px;
    const float* __restrict py = a.py;
    const float* __restrict pz = a.pz;
    const bool hasFarScale = a.s2 < std::numeric_limits<float>::infinity();
    float s2e1 = 0.0F;
    float s2f1 = 0.0F;
    if (!PerPixel) {
        vf e;
        vf f;
        vlog2Parts(splat(a.s2), e, f);
        s2e1 = e[0];
        s2f1 = f[0];
    }
    for (int row = 0; row < a.rows; ++row) {
        failRows[row] = 0;
        if (((a.rowMask >> row) & 1U) == 0) {
            continue;
        }
        const float yr = static_cast<float>(row);
        vf s2 = splat(a.s2);
        vf s2e = splat(s2e1);
        vf s2f = splat(s2f1);
        if constexpr (PerPixel) {
            vf dmin = splat(std::numeric_limits<float>::infinity());
            for (int i = 0; i < n; ++i) {
                const float dy = yr - py[i];
                const vf dx = lane - px[i];
                const vf d2 = dx * dx + dy * dy;
                dmin = d2 < dmin ? d2 : dmin;
            }
            s2 = dmin < s2 ? dmin : s2;
            vlog2Parts(s2, s2e, s2f);
        }
        vf accD = {};
        vf accN = {};
        int k = 0;
        if constexpr (Sq >= 0) {
            // two points per division: r = S^2 / (d2a d2b), then S^2/d2a = r d2b
            for (; k + 1 < n; k += 2) {
                const float dya = yr - py[k];
                const float dyb = yr - py[k + 1];
                const vf dxa = lane - px[k];
                const vf dxb = lane - px[k + 1];
                const vf d2a = dxa * dxa + dya * dya;
                const vf d2b = dxb * dxb + dyb * dyb;
                const vf r = s2 / (d2a * d2b);
                const vf wa = power<Sq>(r * d2b, halfP);
                const vf wb = power<Sq>(r * d2a, halfP);
                accD += wa + wb;
                accN += wa * pz[k] + wb * pz[k + 1];
            }
        }
        for (; k < n; ++k) {
            const float dy = yr - py[k];
            const vf dx = lane - px[k];
            const vf d2 = dx * dx + dy * dy;
            const vf w = weight<Sq>(d2, s2, s2e, s2f, halfP);
            accD += w;
            accN += w * pz[k];
        }
        vf farD = {};
        vf farN = {};
        if (a.degree >= 0) {
            const float v = (yr - a.tv) * a.invA;
            float cD[kStride];
            float cN[kStride];
            for (int i = 0; i <= a.degree; ++i) {
                float sD = 0.0F;
                float sN = 0.0F;
                for (int j = a.degree - i; j >= 0; --j) {
                    sD = sD * v + a.polyD[i * kStride + j];
                    sN = sN * v + a.polyN[i * kStride + j];
                }
                cD[i] = sD;
                cN[i] = sN;
            }
            farD = splat(cD[a.degree]);
            farN = splat(cN[a.degree]);
            for (int i = a.degree - 1; i >= 0; --i) {
                farD = farD * u + cD[i];
                farN = farN * u + cN[i];
            }
        }
        vf ok;
        vf d;
        vf nn;
        if constexpr (PerPixel) {
            vf f = {};
            if (hasFarScale && a.degree >= 0) {
                f = power<Sq>(s2 / a.s2, halfP);
            }
            d = accD + f * farD;
            nn = accN + f * farN;
            // dz*E*(S_x/S_leaf)^p + farArith*f <= tolRemaining*D, in log2.
            const vf rhs = d * a.tolRemaining - f * a.farArith;
            const vf lhs = a.log2DzE + ((s2e + s2f) - a.log2LeafS2) * halfP;
            const vf rhsSafe = rhs > 1e-37F ? rhs : splat(1.0F);
            const vf l2 = vlog2(rhsSafe);
            const vi pass = (rhs > 1e-37F) & (lhs <= l2 - 1e-4F);
            ok = asFloat(pass);
        } else {
            d = accD + farD;
            nn = accN + farN;
            const vi pass = d * a.tolRemaining >= a.errAbs;
            ok = asFloat(pass);
        }
        if (a.sumD != nullptr) {
            for (int x = 0; x < kLanes; ++x) {
                a.sumD[row * kLanes + x] = d[x];
                a.sumN[row * kLanes + x] = nn[x];
            }
        }
        vf z = a.zref + nn / d;
        const vi finite = (z >= a.zmin - 1.0F) & (z <= a.zmax + 1.0F);  // false for NaN / Inf
        z = z < a.zmin ? splat(a.zmin) : z;
        z = z > a.zmax ? splat(a.zmax) : z;
        const vi good = asInt(ok) & finite;
        std::uint32_t fail = 0;
        for (int x = 0; x < kLanes; ++x) {
            zOut[row * kLanes + x] = z[x];
            // Two statements on purpose: GCC 12 at -O0 with -fsanitize=shift,bounds
            // miscompiles a vector subscript inside the shift's operand (the
            // bounds check reads a garbage index: false "index 1065353216 out of
            // bounds" and a SEGV in the asan preset). No cost when optimised
            // (vss_fast_micro: same CPU time).
            const std::uint32_t bad = good[x] == 0 ? 1U : 0U;
            fail |= bad << x;
        }
        failRows[row] = fail;
    }
}

using KernelFn = void (*)(const LeafKernelArgs&, float*, std::uint32_t*);

template <bool PerPixel>
VV_FAST_INLINE void dispatchPower(const LeafKernelArgs& a, float* z, std::uint32_t* f) {
    switch (a.power.squarings) {
        case 0:
            kernelBody<0, PerPixel>(a, z, f);
            break;
        case 1:
            kernelBody<1, PerPixel>(a, z, f);
            break;
        case 2:
            kernelBody<2, PerPixel>(a, z, f);
            break;
        case 3:
            kernelBody<3, PerPixel>(a, z, f);
            break;
        case 4:
            kernelBody<4, PerPixel>(a, z, f);
            break;
        case 5:
            kernelBody<5, PerPixel>(a, z, f);
            break;
        default:
            kernelBody<-1, PerPixel>(a, z, f);
            break;
    }
}

VV_FAST_INLINE void kernelAll(const LeafKernelArgs& a, float* z, std::uint32_t* f) {
    if (a.perPixel) {
        dispatchPower<true>(a, z, f);
    } else {
        dispatchPower<false>(a, z, f);
    }
}

__attribute__((target("avx512f,avx512dq,avx512bw,avx512vl,avx2,fma,bmi,bmi2"))) void kernelAvx512(
    const LeafKernelArgs& a, float* z, std::uint32_t* f) {
    kernelAll(a, z, f);
}

__attribute__((target("avx2,fma"))) void kernelAvx2(const LeafKernelArgs& a, float* z,
                                                    std::uint32_t* f) {
    kernelAll(a, z, f);
}

void kernelGeneric(const LeafKernelArgs& a, float* z, std::uint32_t* f) {
    kernelAll(a, z, f);
}

struct Dispatch {
    KernelFn fn;
    const char* name;
};

Dispatch chooseKernel() {
    __builtin_cpu_init();
    if (__builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512dq") &&
        __builtin_cpu_supports("avx512bw") && __builtin_cpu_supports("avx512vl") &&
        __builtin_cpu_supports("fma")) {
        return {&kernelAvx512, "avx512"};
    }
    if (__builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma")) {
        return {&kernelAvx2, "avx2"};
    }
    return {&kernelGeneric, "generic"};
}

const Dispatch& dispatch() {
    static const Dispatch d = chooseKernel();
    return d;
}

}  // namespace

void leafKernel(const LeafKernelArgs& a, float* z, std::uint32_t* failRows) {
    dispatch().fn(a, z, failRows);
}

const char* leafKernelIsa() {
    return dispatch().name;
}

float kernelLog2(float x) {
    return vlog2(splat(x))[0];
}

float kernelExp2(float x) {
    return vexp2(splat(x))[0];
}

}  // namespace vv::vss::detail
