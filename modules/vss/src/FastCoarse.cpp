// SPDX-License-Identifier: GPL-3.0-or-later
// The coarse boxes of the fast VSS solver (FastCoarse.h): samples from the
// leaf kernel, the interpolation error bound, the bilinear interpolation.
#include "FastCoarse.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

#include "FastKernel.h"

namespace vv::vss::detail::fast {
namespace {

// coefficients below float's normal range lose at most 2^-149 each (<= 169 of them)
constexpr double kUnderflow = 1e-40;

}  // namespace

std::int64_t evalCoarseBox(const Region& rg, const BoxGeo& geo, const Local& far,
                           const LeafBounds& bounds) {
    const PowerTables& tab = *rg.tab;
    const double side = std::max(geo.maxx - geo.minx, geo.maxy - geo.miny);
    if (side < 2.0 * (kCoarseGrid - 1)) {
        return 0;  // samples closer than 2 pixels: the leaves are as cheap
    }
    const double h = side / (kCoarseGrid - 1);  // sample spacing, pixels
    const int deg = tab.degree;
    std::array<double, kS * kS> cD{};
    std::array<double, kS * kS> cN{};
    localToPoly(far.d, deg, tab, cD);
    localToPoly(far.n, deg, tab, cN);
    const PolyBounds bD = polyBounds(cD, deg, geo.an);
    const PolyBounds bN = polyBounds(cN, deg, geo.an);
    if (!(bD.sum + bN.sum <= 1e30)) {
        return 0;  // would not fit in float
    }
    const double gammaPoly = (3.0 * deg + 12.0) * kU * 1.01;
    // |computed N - z P_D ...|: as the leaf's farArith (FastLeaf.cpp), twice:
    // once for the samples' evaluation, once for the coefficients' rounding
    const double farArith = 2.0 * (gammaPoly * (bN.sum + (0.5 * rg.dz + kU) * bD.sum) +
                                   1e-11 * bounds.W * (1.0 + rg.dz) + kUnderflow);
    const double dArith = gammaPoly * bD.sum + 1e-11 * bounds.W + kUnderflow;
    const double h2 = h * h / 8.0;
    const double tolAll = rg.tol * (1.0 - 1e-6) - 16.0 * kU;
    // Error bound of every pixel when P_D >= dLow over the sample square.
    const auto errorBound = [&](double dLow) {
        const double fMax = bN.sum / dLow;  // >= |P_N / P_D|
        const double gx = (bN.dx + fMax * bD.dx) / dLow;
        const double gy = (bN.dy + fMax * bD.dy) / dLow;
        const double fxx = (bN.dxx + 2.0 * gx * bD.dx + fMax * bD.dxx) / dLow;
        const double fyy = (bN.dyy + 2.0 * gy * bD.dy + fMax * bD.dyy) / dLow;
        return (bounds.E + farArith) * (1.0 + 1e-6) / dLow + h2 * (fxx + fyy);
    };
    // A-priori: skip the samples when even the centre value would not do.
    if (!(cD[0] > 0.0) || !(errorBound(cD[0]) <= tolAll)) {
        return 0;
    }

    std::array<float, kS * kS> fD{};
    std::array<float, kS * kS> fN{};
    for (std::size_t i = 0; i < fD.size(); ++i) {
        fD[i] = static_cast<float>(cD[i]);
        fN[i] = static_cast<float>(cN[i]);
    }
    constexpr int kG = kCoarseGrid;
    std::array<float, kG * kG> z{};
    std::array<std::uint32_t, kG> fail{};
    std::array<float, kG * kG> sD{};
    std::array<float, kG * kG> sN{};
    const float none = 0.0F;
    LeafKernelArgs a;
    a.rows = kG;
    a.rowMask = (1U << kG) - 1U;
    a.px = &none;
    a.py = &none;
    a.pz = &none;
    a.count = 0;
    a.degree = deg;
    a.polyD = fD.data();
    a.polyN = fN.data();
    // sample (k, r) at (tx + (k - 7.5) h, ty + (r - 7.5) h): u = (k - 7.5) h / an
    a.tu = 0.5F * (kG - 1);
    a.tv = 0.5F * (kG - 1);
    a.invA = static_cast<float>(h / geo.an);
    a.perPixel = false;
    a.s2 = 1.0F;
    a.zref = static_cast<float>(rg.zref);
    a.zmin = rg.zminOut;
    a.zmax = rg.zmaxOut;
    a.tolRemaining = 1.0F;
    a.errAbs = 0.0F;
    a.power = rg.kp;
    a.sumD = sD.data();
    a.sumN = sN.data();
    leafKernel(a, z.data(), fail.data());

    // Lower bound of P_D over the square: the smallest sample less its
    // round-off and the interpolation error of P_D itself.
    double dMin = std::numeric_limits<double>::infinity();
    std::array<double, kG * kG> f{};
    for (std::size_t i = 0; i < f.size(); ++i) {
        const double d = sD[i];
        dMin = std::min(dMin, d);
        f[i] = static_cast<double>(sN[i]) / d;
        if (!std::isfinite(f[i])) {
            return 0;
        }
    }
    const double dLow = dMin - dArith - h2 * (bD.dxx + bD.dyy);
    if (!(dLow > 0.0) || !(errorBound(dLow) <= tolAll)) {
        return 0;
    }

    // Bilinear interpolation of the samples at every region pixel of the box:
    // the column of every pixel once, then per row the row's 16 values.
    const double xs0 = geo.tx - 0.5 * (kG - 1) * h;
    const double ys0 = geo.ty - 0.5 * (kG - 1) * h;
    const double invH = 1.0 / h;
    const int width = geo.maxx - geo.minx + 1;
    thread_local std::vector<int> colK;  // scratch, reused by every box of this thread
    thread_local std::vector<double> colT;
    colK.resize(static_cast<std::size_t>(width));
    colT.resize(static_cast<std::size_t>(width));
    for (int i = 0; i < width; ++i) {
        const double sx = (geo.minx + i - xs0) * invH;
        const int k = std::clamp(static_cast<int>(std::floor(sx)), 0, kG - 2);
        colK[static_cast<std::size_t>(i)] = k;
        colT[static_cast<std::size_t>(i)] = std::clamp(sx - k, 0.0, 1.0);
    }
    std::int64_t pixels = 0;
    std::array<double, kG> g{};
    for (int y = geo.miny; y <= geo.maxy; ++y) {
        const std::int32_t* lab = rg.labels.row(y) + geo.minx;
        float* o = rg.out.row(y) + geo.minx;
        const double sy = (y - ys0) * invH;
        const int r = std::clamp(static_cast<int>(std::floor(sy)), 0, kG - 2);
        const double ty = std::clamp(sy - r, 0.0, 1.0);
        const double* f0 = &f[static_cast<std::size_t>(r) * kG];
        const double* f1 = f0 + kG;
        for (int k = 0; k < kG; ++k) {
            g[static_cast<std::size_t>(k)] = rg.zref + (f0[k] + ty * (f1[k] - f0[k]));
        }
        for (int i = 0; i < width; ++i) {
            if (lab[i] != rg.id) {
                continue;
            }
            const auto k = static_cast<std::size_t>(colK[static_cast<std::size_t>(i)]);
            const double v = g[k] + colT[static_cast<std::size_t>(i)] * (g[k + 1] - g[k]);
            o[i] = std::clamp(static_cast<float>(v), rg.zminOut, rg.zmaxOut);
            ++pixels;
        }
    }
    return pixels;
}

}  // namespace vv::vss::detail::fast
