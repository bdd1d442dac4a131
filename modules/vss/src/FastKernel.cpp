// SPDX-License-Identifier: GPL-3.0-or-later
// The leaf kernel of the fast VSS solver (see FastSolver.cpp for the design).
// Written with GCC vector extensions (16 float lanes = one tile row) and
// compiled three times: AVX-512, AVX2+FMA and baseline x86-64, dispatched at
// run time, so PCs without AVX2 still run it.
#include "FastKernel.h"

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>

#include "FastKernelSimd.h"

namespace vv::vss::detail {
namespace {

// 16 floats from any address. Always inlined (no lambda: a lambda is a call
// at -O0, and a vector returned across the kernels' ISAs is read from the
// wrong place; FastKernelSimd.h).
VV_FAST_INLINE vf loadUnaligned(const float* p) {
    vf w;
    __builtin_memcpy(&w, p, sizeof(vf));
    return w;
}

// Near sums of one tile row from the distance table (LeafKernelArgs::table):
// one unaligned 16-float load per point; two partial sums per accumulator,
// each taking two points at once, so that fewer additions wait on the one
// before (their rounding error is within the sequential sum's bound, gamma_K,
// which the check charges).
VV_FAST_INLINE void tableRowSums(const LeafKernelArgs& a, int row, vf& accD, vf& accN) {
    const float* __restrict rowBase = a.table + static_cast<std::ptrdiff_t>(row) * kDistTableStride;
    const std::int32_t* __restrict off = a.tableOffset;
    const float* __restrict pz = a.pz;
    const int n = a.tableCount;
    vf d0 = {};
    vf d1 = {};
    vf n0 = {};
    vf n1 = {};
    int k = 0;
    for (; k + 3 < n; k += 4) {
        const vf w0 = loadUnaligned(rowBase + off[k]);
        const vf w1 = loadUnaligned(rowBase + off[k + 1]);
        const vf w2 = loadUnaligned(rowBase + off[k + 2]);
        const vf w3 = loadUnaligned(rowBase + off[k + 3]);
        d0 += w0 + w2;
        d1 += w1 + w3;
        n0 += w0 * pz[k] + w2 * pz[k + 2];
        n1 += w1 * pz[k + 1] + w3 * pz[k + 3];
    }
    for (; k < n; ++k) {
        const vf w = loadUnaligned(rowBase + off[k]);
        d0 += w;
        n0 += w * pz[k];
    }
    accD = d0 + d1;
    accN = n0 + n1;
}

// The far polynomial by columns: d[j] lane i = the coefficient of u^i v^j of
// D (n: of N), zero for i + j > degree.
constexpr int kPolyStride = kMaxPolyDegree + 1;
static_assert(kPolyStride <= kLanes);
struct PolyColumns {
    std::array<vf, kPolyStride> d;
    std::array<vf, kPolyStride> n;
};

VV_FAST_INLINE PolyColumns polyColumns(const LeafKernelArgs& a) {
    PolyColumns c{};
    for (int j = 0; j <= a.degree; ++j) {
        for (int i = 0; i + j <= a.degree; ++i) {
            c.d[j][i] = a.polyD[i * kPolyStride + j];
            c.n[j][i] = a.polyN[i * kPolyStride + j];
        }
    }
    return c;
}

// The polynomials at one row (v) and its 16 pixels (u): first the row's
// coefficients of u^i, every i at once (lane i), by Horner in v over the
// columns (the zero terms above degree - i leave each lane with exactly the
// scalar Horner's operations), then Horner in u.
VV_FAST_INLINE void rowPolynomial(const PolyColumns& c, int degree, float v, vf u, vf& farD,
                                  vf& farN) {
    vf rowD = c.d[degree];
    vf rowN = c.n[degree];
    for (int j = degree - 1; j >= 0; --j) {
        rowD = rowD * v + c.d[j];
        rowN = rowN * v + c.n[j];
    }
    alignas(64) std::array<float, kLanes> cD{};
    alignas(64) std::array<float, kLanes> cN{};
    __builtin_memcpy(cD.data(), &rowD, sizeof(vf));
    __builtin_memcpy(cN.data(), &rowN, sizeof(vf));
    farD = splat(cD[degree]);
    farN = splat(cN[degree]);
    for (int i = degree - 1; i >= 0; --i) {
        farD = farD * u + cD[i];
        farN = farN * u + cN[i];
    }
}

template <int Sq, bool PerPixel, bool Table>
VV_FAST_INLINE void kernelBody(const LeafKernelArgs& a, float* zOut, std::uint32_t* failRows) {
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
    const PolyColumns cols = polyColumns(a);
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
        if constexpr (Table) {
            tableRowSums(a, row, accD, accN);
            k = a.tableCount;  // the rest computed, in the same (absolute) scale: s2 = 1
        }
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
            rowPolynomial(cols, a.degree, (yr - a.tv) * a.invA, u, farD, farN);
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

template <bool PerPixel, bool Table>
VV_FAST_INLINE void dispatchPower(const LeafKernelArgs& a, float* z, std::uint32_t* f) {
    switch (a.power.squarings) {
        case 0:
            kernelBody<0, PerPixel, Table>(a, z, f);
            break;
        case 1:
            kernelBody<1, PerPixel, Table>(a, z, f);
            break;
        case 2:
            kernelBody<2, PerPixel, Table>(a, z, f);
            break;
        case 3:
            kernelBody<3, PerPixel, Table>(a, z, f);
            break;
        case 4:
            kernelBody<4, PerPixel, Table>(a, z, f);
            break;
        case 5:
            kernelBody<5, PerPixel, Table>(a, z, f);
            break;
        default:
            kernelBody<-1, PerPixel, Table>(a, z, f);
            break;
    }
}

VV_FAST_INLINE void kernelAll(const LeafKernelArgs& a, float* z, std::uint32_t* f) {
    if (a.table != nullptr && !a.perPixel) {
        dispatchPower<false, true>(a, z, f);
    } else if (a.perPixel) {
        dispatchPower<true, false>(a, z, f);
    } else {
        dispatchPower<false, false>(a, z, f);
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
