// SPDX-License-Identifier: GPL-3.0-or-later
// The point kernel of the fast VSS solver (FastKernel.h, pointKernel): the
// leaf kernel's sums at any 16 positions per vector instead of one tile row,
// with the bounds the band boxes need (FastBandBox.cpp). Compiled for
// AVX-512, AVX2+FMA and baseline x86-64 like FastKernel.cpp, dispatched at
// run time.
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string_view>

#include "FastKernel.h"
#include "FastKernelSimd.h"

namespace vv::vss::detail {
namespace {

VV_FAST_INLINE vf load(const float* p) {
    vf v;
    std::memcpy(&v, p, sizeof(v));
    return v;
}

VV_FAST_INLINE void store(float* p, vf v) {
    std::memcpy(p, &v, sizeof(v));
}

VV_FAST_INLINE vf absv(vf x) {
    return asFloat(asInt(x) & 0x7fffffff);
}

template <int Sq, bool Bounds>
VV_FAST_INLINE void pointBody(const PointKernelArgs& a) {
    constexpr int kStride = kMaxPolyDegree + 1;
    const float halfP = a.power.halfP;
    const int n = a.count;
    const float* __restrict px = a.px;
    const float* __restrict py = a.py;
    const float* __restrict pz = a.pz;
    vf s2e;
    vf s2f;
    const vf s2 = splat(a.s2);
    vlog2Parts(s2, s2e, s2f);
    for (int b = 0; b < a.n; b += kLanes) {
        const vf x = load(a.ex + b);
        const vf y = load(a.ey + b);
        vf zc = {};
        if constexpr (Bounds) {
            // the nearest point and its depth (first of equals), or the floor
            vf dmin = splat(a.floor2);
            zc = splat(a.cFar);
            for (int i = 0; i < a.closeCount; ++i) {
                const vf dx = x - a.c0x[i];
                const vf dy = y - a.c0y[i];
                const vf d2 = dx * dx + dy * dy;
                const vi m = d2 < dmin;
                dmin = m ? d2 : dmin;
                zc = m ? splat(a.c0z[i]) : zc;
            }
            store(a.dmin2 + b, dmin);
            store(a.c + b, zc);
        }
        vf accD = {};
        vf accN = {};
        vf accA = {};
        vf accT = {};
        int k = 0;
        if constexpr (Sq >= 0) {
            // two points per division: r = S^2 / (d2a d2b), then S^2/d2a = r d2b
            for (; k + 1 < n; k += 2) {
                const vf dxa = x - px[k];
                const vf dya = y - py[k];
                const vf dxb = x - px[k + 1];
                const vf dyb = y - py[k + 1];
                const vf d2a = dxa * dxa + dya * dya;
                const vf d2b = dxb * dxb + dyb * dyb;
                const vf r = s2 / (d2a * d2b);
                const vf ra = r * d2b;
                const vf rb = r * d2a;
                const vf wa = power<Sq>(ra, halfP);
                const vf wb = power<Sq>(rb, halfP);
                accD += wa + wb;
                accN += wa * pz[k] + wb * pz[k + 1];
                if constexpr (Bounds) {
                    const vf ta = wa * ra;
                    const vf tb = wb * rb;
                    accA += ta + tb;
                    accT += ta * absv(pz[k] - zc) + tb * absv(pz[k + 1] - zc);
                }
            }
        }
        for (; k < n; ++k) {
            const vf dx = x - px[k];
            const vf dy = y - py[k];
            const vf d2 = dx * dx + dy * dy;
            const vf w = weight<Sq>(d2, s2, s2e, s2f, halfP);
            accD += w;
            accN += w * pz[k];
            if constexpr (Bounds) {
                const vf t = w * (s2 / d2);
                accA += t;
                accT += t * absv(pz[k] - zc);
            }
        }
        store(a.dn + b, accD);
        store(a.nn + b, accN);
        if constexpr (Bounds) {
            store(a.a + b, accA);
            store(a.t + b, accT);
        }
        if (a.degree >= 0) {
            const vf u = (x - a.tu) * a.invA;
            const vf v = (y - a.tv) * a.invA;
            vf farD = {};
            vf farN = {};
            for (int i = a.degree; i >= 0; --i) {
                vf sD = splat(a.polyD[i * kStride + (a.degree - i)]);
                vf sN = splat(a.polyN[i * kStride + (a.degree - i)]);
                for (int j = a.degree - i - 1; j >= 0; --j) {
                    sD = sD * v + a.polyD[i * kStride + j];
                    sN = sN * v + a.polyN[i * kStride + j];
                }
                farD = farD * u + sD;
                farN = farN * u + sN;
            }
            store(a.pd + b, farD);
            store(a.pn + b, farN);
        }
    }
}

template <bool Bounds>
VV_FAST_INLINE void pointDispatch(const PointKernelArgs& a) {
    switch (a.power.squarings) {
        case 0:
            pointBody<0, Bounds>(a);
            break;
        case 1:
            pointBody<1, Bounds>(a);
            break;
        case 2:
            pointBody<2, Bounds>(a);
            break;
        case 3:
            pointBody<3, Bounds>(a);
            break;
        case 4:
            pointBody<4, Bounds>(a);
            break;
        case 5:
            pointBody<5, Bounds>(a);
            break;
        default:
            pointBody<-1, Bounds>(a);
            break;
    }
}

VV_FAST_INLINE void pointAll(const PointKernelArgs& a) {
    if (a.bounds) {
        pointDispatch<true>(a);
    } else {
        pointDispatch<false>(a);
    }
}

__attribute__((target("avx512f,avx512dq,avx512bw,avx512vl,avx2,fma,bmi,bmi2"))) void pointAvx512(
    const PointKernelArgs& a) {
    pointAll(a);
}

__attribute__((target("avx2,fma"))) void pointAvx2(const PointKernelArgs& a) {
    pointAll(a);
}

void pointGeneric(const PointKernelArgs& a) {
    pointAll(a);
}

using PointFn = void (*)(const PointKernelArgs&);

PointFn choosePoint() {
    const std::string_view isa = leafKernelIsa();  // the leaf kernel's choice
    if (isa == "avx512") {
        return &pointAvx512;
    }
    if (isa == "avx2") {
        return &pointAvx2;
    }
    return &pointGeneric;
}

}  // namespace

void pointKernel(const PointKernelArgs& a) {
    static const PointFn fn = choosePoint();
    fn(a);
}

}  // namespace vv::vss::detail
