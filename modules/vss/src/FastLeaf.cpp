// SPDX-License-Identifier: GPL-3.0-or-later
// The fast VSS solver's leaf tiles (FastLeaf.h): near points and polynomial
// handed to the SIMD kernel, the a-posteriori check, the exact fall-backs.
#include "FastLeaf.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include "FastKernel.h"

namespace vv::vss::detail::fast {

__attribute__((noinline)) float exactPixel(const Region& rg, int x, int y) {
    double dmin2 = std::numeric_limits<double>::infinity();
    for (const Point& q : rg.tree.pts) {
        const double dx = static_cast<double>(x) - q.x;
        const double dy = static_cast<double>(y) - q.y;
        dmin2 = std::min(dmin2, dx * dx + dy * dy);
    }
    dmin2 = std::max(dmin2, 1e-300);
    double D = 0.0;
    double N = 0.0;
    for (const Point& q : rg.tree.pts) {
        const double dx = static_cast<double>(x) - q.x;
        const double dy = static_cast<double>(y) - q.y;
        const double d2 = std::max(dx * dx + dy * dy, 1e-300);
        const double w = rg.tab->pw(dmin2 / d2);
        D += w;
        N += w * static_cast<double>(q.z);
    }
    const double z = rg.zref + N / D;
    return std::clamp(static_cast<float>(z), rg.zminOut, rg.zmaxOut);
}

LeafCounts evalLeaf(const Region& rg, int ix, int iy, const BoxGeo& geo,
                    const std::vector<int>& nearNodes, const Local* far, const LeafBounds& bounds) {
    const bool hasLocal = far != nullptr;
    const double S = bounds.S;
    const double E = bounds.E;
    const double W = bounds.W;
    const double Sexp = bounds.Sexp;
    const PowerTables& tab = *rg.tab;
    const int X0 = rg.rx0 + ix * kLeafTile;
    const int Y0 = rg.ry0 + iy * kLeafTile;
    const int cols = std::min(kLeafTile, rg.rx1 - X0);
    const int rows = std::min(kLeafTile, rg.ry1 - Y0);
    std::uint32_t rowMask = 0;
    for (int r = 0; r < rows; ++r) {
        const std::int32_t* lab = rg.labels.row(Y0 + r) + X0;
        for (int c = 0; c < cols; ++c) {
            if (lab[c] == rg.id) {
                rowMask |= 1U << r;
                break;
            }
        }
    }
    // near points, relative to the tile origin
    std::size_t K = 0;
    for (int nd : nearNodes) {
        K += static_cast<std::size_t>(rg.tree.nodes[static_cast<std::size_t>(nd)].count());
    }
    thread_local std::vector<float> px;  // scratch, reused by every leaf of this thread
    thread_local std::vector<float> py;
    thread_local std::vector<float> pz;
    if (px.size() < K) {
        px.resize(K);
        py.resize(K);
        pz.resize(K);
    }
    double dbm2 = std::numeric_limits<double>::infinity();  // nearest point to the pixel box
    std::size_t k = 0;
    for (int nd : nearNodes) {
        const SrcNode& c = rg.tree.nodes[static_cast<std::size_t>(nd)];
        for (int i = c.begin; i < c.end; ++i) {
            const Point& q = rg.tree.pts[static_cast<std::size_t>(i)];
            px[k] = static_cast<float>(q.x - X0);
            py[k] = static_cast<float>(q.y - Y0);
            pz[k] = q.z;
            ++k;
            const double gx = std::max({0, q.x - geo.maxx, geo.minx - q.x});
            const double gy = std::max({0, q.y - geo.maxy, geo.miny - q.y});
            dbm2 = std::min(dbm2, gx * gx + gy * gy);
        }
    }
    const int deg = tab.degree;
    std::array<double, kS * kS> cD{};
    std::array<double, kS * kS> cN{};
    double sumD = 0.0;
    double sumN = 0.0;
    if (hasLocal) {
        localToPoly(far->d, deg, tab, cD);
        localToPoly(far->n, deg, tab, cN);
        for (int i = 0; i < kS * kS; ++i) {
            sumD += std::abs(cD[static_cast<std::size_t>(i)]);
            sumN += std::abs(cN[static_cast<std::size_t>(i)]);
        }
    }
    const double diag = std::hypot(static_cast<double>(geo.maxx - geo.minx),
                                   static_cast<double>(geo.maxy - geo.miny));
    const bool tileMode = K > 0 && tab.p * std::log2((std::sqrt(dbm2) + diag + 1.0) / S) <= 60.0;
    const double gammaK = (static_cast<double>(K) + 8.0) * kU * 1.01;
    const double gammaPoly = (3.0 * deg + 12.0) * kU * 1.01;
    const double deltaAll = rg.deltaW * (tileMode ? 1.0 : 2.0);
    const double tolRem = rg.tol * (1.0 - 1e-6) - rg.dz * (deltaAll + gammaK) - 16.0 * kU;
    const double farArith =
        gammaPoly * (sumN + (0.5 * rg.dz + kU) * sumD) + 1e-11 * W * (1.0 + rg.dz);
    // coefficients below float's normal range lose at most 2^-149 each (<= 169 of them)
    constexpr double kUnderflow = 1e-40;

    LeafKernelArgs a;
    a.rows = rows;
    a.rowMask = rowMask;
    a.px = px.data();
    a.py = py.data();
    a.pz = pz.data();
    a.count = static_cast<int>(K);
    a.zref = static_cast<float>(rg.zref);
    a.zmin = rg.zminOut;
    a.zmax = rg.zmaxOut;
    a.power = rg.kp;
    a.tolRemaining = static_cast<float>(tolRem);
    std::array<float, kS * kS> fD{};
    std::array<float, kS * kS> fN{};
    bool allFail = tolRem <= 0.0;
    double polyScale = 1.0;
    if (tileMode) {
        a.perPixel = false;
        a.s2 = static_cast<float>(S * S);
        // (1 + p u): the near weights use S^2 rounded to float
        a.errAbs = static_cast<float>((E + farArith) * (1.0 + 1e-6 + tab.p * kU) + kUnderflow);
    } else {
        a.perPixel = true;
        if (hasLocal) {
            polyScale = tab.pw((Sexp * Sexp) / (S * S));
            a.s2 = static_cast<float>(Sexp * Sexp);
            if (!std::isfinite(polyScale) || !std::isfinite(a.s2)) {
                allFail = true;
            }
        } else {
            a.s2 = std::numeric_limits<float>::infinity();
        }
        a.farArith = static_cast<float>(farArith * polyScale * (1.0 + 1e-6) + kUnderflow);
        if (!std::isfinite(a.farArith)) {
            allFail = true;
        }
        const double margin = 1e-4 + tab.halfP * 4e-6;
        a.log2DzE = E > 0.0 ? static_cast<float>(std::log2(E) + margin) : -1000.0F;
        a.log2LeafS2 = static_cast<float>(std::log2(S * S));
    }
    if (hasLocal && (sumD + sumN) * polyScale > 1e30) {
        allFail = true;  // would not fit in float (not seen in practice): be exact
    }
    if (hasLocal) {
        a.degree = deg;
        for (int i = 0; i < kS * kS; ++i) {
            fD[static_cast<std::size_t>(i)] =
                static_cast<float>(cD[static_cast<std::size_t>(i)] * polyScale);
            fN[static_cast<std::size_t>(i)] =
                static_cast<float>(cN[static_cast<std::size_t>(i)] * polyScale);
        }
        a.polyD = fD.data();
        a.polyN = fN.data();
        a.tu = static_cast<float>(geo.tx - X0);
        a.tv = static_cast<float>(geo.ty - Y0);
        a.invA = static_cast<float>(1.0 / geo.an);
    }
    std::array<float, kLeafTile * kLeafTile> z{};
    std::array<std::uint32_t, kLeafTile> fail{};
    if (!allFail) {
        leafKernel(a, z.data(), fail.data());
    }
    // Safety net: when many pixels of the tile fail the check, evaluate the whole
    // tile exactly (every contour point of the region, no expansion) with the
    // kernel before falling back to the per-pixel double-precision sum.
    std::array<float, kLeafTile * kLeafTile> z2{};
    std::array<std::uint32_t, kLeafTile> fail2{};
    bool haveExactTile = false;
    std::uint32_t anyFail = allFail ? 1U : 0U;
    for (int r = 0; r < rows; ++r) {
        anyFail |= fail[static_cast<std::size_t>(r)];
    }
    if (anyFail != 0) {  // else no pixel failed: skip the count (the common case)
        int nFail = 0;
        for (int r = 0; r < rows; ++r) {
            if (((rowMask >> r) & 1U) == 0) {
                continue;
            }
            const std::int32_t* lab = rg.labels.row(Y0 + r) + X0;
            for (int c = 0; c < cols; ++c) {
                nFail += (lab[c] == rg.id &&
                          (allFail || ((fail[static_cast<std::size_t>(r)] >> c) & 1U) != 0))
                             ? 1
                             : 0;
            }
        }
        const double nAll = rg.n;
        const double tolAll = rg.tol * (1.0 - 1e-6) -
                              rg.dz * (2.0 * rg.deltaW + (nAll + 8.0) * kU * 1.01) - 16.0 * kU;
        if (nFail > 16 && tolAll > 0.0 && nAll < 1e7) {
            thread_local std::vector<float> ax;
            thread_local std::vector<float> ay;
            thread_local std::vector<float> az;
            const std::size_t nn = rg.tree.pts.size();
            ax.resize(nn);
            ay.resize(nn);
            az.resize(nn);
            for (std::size_t i = 0; i < nn; ++i) {
                const Point& q = rg.tree.pts[i];
                ax[i] = static_cast<float>(q.x - X0);
                ay[i] = static_cast<float>(q.y - Y0);
                az[i] = q.z;
            }
            LeafKernelArgs b = a;
            b.px = ax.data();
            b.py = ay.data();
            b.pz = az.data();
            b.count = static_cast<int>(nn);
            b.degree = -1;
            b.perPixel = true;
            b.s2 = std::numeric_limits<float>::infinity();
            b.farArith = 0.0F;
            b.log2DzE = -1000.0F;
            b.tolRemaining = static_cast<float>(tolAll);
            leafKernel(b, z2.data(), fail2.data());
            haveExactTile = true;
        }
    }
    std::int64_t pixels = 0;
    std::int64_t fallbacks = 0;
    for (int r = 0; r < rows; ++r) {
        if (((rowMask >> r) & 1U) == 0) {
            continue;
        }
        const std::int32_t* lab = rg.labels.row(Y0 + r) + X0;
        float* o = rg.out.row(Y0 + r) + X0;
        for (int c = 0; c < cols; ++c) {
            if (lab[c] != rg.id) {
                continue;
            }
            ++pixels;
            if (allFail || ((fail[static_cast<std::size_t>(r)] >> c) & 1U) != 0) {
                ++fallbacks;
                if (haveExactTile && ((fail2[static_cast<std::size_t>(r)] >> c) & 1U) == 0) {
                    o[c] = z2[static_cast<std::size_t>(r * kLeafTile + c)];
                } else {
                    o[c] = exactPixel(rg, X0 + c, Y0 + r);
                }
            } else {
                o[c] = z[static_cast<std::size_t>(r * kLeafTile + c)];
            }
        }
    }
    LeafCounts counts;
    counts.pixels = pixels;
    counts.fallbackPixels = fallbacks;
    counts.nearPairs = static_cast<std::int64_t>(K) * std::popcount(rowMask);
    counts.perPixel = !tileMode;
    counts.exactTile = haveExactTile;
    return counts;
}

}  // namespace vv::vss::detail::fast
