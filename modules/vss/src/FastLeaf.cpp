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
namespace {

// coefficients below float's normal range lose at most 2^-149 each (<= 169 of them)
constexpr double kUnderflow = 1e-40;
constexpr std::size_t kSquare = static_cast<std::size_t>(kS) * kS;
constexpr std::size_t kTilePixels = static_cast<std::size_t>(kLeafTile) * kLeafTile;

// The tile in the images: origin, size and the rows with region pixels.
struct LeafTile {
    int x0 = 0, y0 = 0;  // origin (X0, Y0)
    int cols = 0, rows = 0;
    std::uint32_t rowMask = 0;  // bit r: row r has region pixels
};

LeafTile leafTile(const Region& rg, int ix, int iy) {
    LeafTile t;
    t.x0 = rg.rx0 + ix * kLeafTile;
    t.y0 = rg.ry0 + iy * kLeafTile;
    t.cols = std::min(kLeafTile, rg.rx1 - t.x0);
    t.rows = std::min(kLeafTile, rg.ry1 - t.y0);
    for (int r = 0; r < t.rows; ++r) {
        const std::int32_t* lab = rg.labels.row(t.y0 + r) + t.x0;
        for (int c = 0; c < t.cols; ++c) {
            if (lab[c] == rg.id) {
                t.rowMask |= 1U << r;
                break;
            }
        }
    }
    return t;
}

// Row r's failure bits (bit c: pixel c failed), all set when every pixel fails.
std::uint32_t failBits(const std::array<std::uint32_t, kLeafTile>& fail, bool allFail, int r) {
    return allFail ? ~0U : fail[static_cast<std::size_t>(r)];
}

// Scratch of one thread, reused by every leaf.
struct Scratch {
    std::vector<float> px, py, pz;   // the near points, relative to the tile origin
    std::vector<std::int32_t> toff;  // their distance-table offsets (FastKernel.h)
    std::vector<float> ax, ay, az;   // every contour point of the region, likewise
};

Scratch& scratch() {
    thread_local Scratch s;
    return s;
}

// The near points: their squared distance to the pixel box (the nearest),
// how many come first because the distance table holds every offset of them
// to a tile pixel, and the largest distance of any to the tile's origin.
struct NearExtent {
    double dbm2 = std::numeric_limits<double>::infinity();
    std::size_t inTable = 0;
    double dmax = 0.0;
};

// x^2 + y^2 without overflow for any image size.
std::int64_t squared(int x, int y) {
    return static_cast<std::int64_t>(x) * x + static_cast<std::int64_t>(y) * y;
}

// The near points (K of them) relative to the tile origin, those within the
// distance table first, with their table indices.
NearExtent gatherNearPoints(const Region& rg, const BoxGeo& geo, const std::vector<int>& nearNodes,
                            std::size_t count, const LeafTile& t, Scratch& sc) {
    if (sc.px.size() < count) {
        sc.px.resize(count);
        sc.py.resize(count);
        sc.pz.resize(count);
        sc.toff.resize(count);
    }
    NearExtent ext;
    std::size_t front = 0;     // points within the table fill from the front
    std::size_t back = count;  // the others from the back
    std::int64_t d2max = 0;
    std::int64_t dbm2 = std::numeric_limits<std::int64_t>::max();
    for (int nd : nearNodes) {
        const SrcNode& c = rg.tree.nodes[static_cast<std::size_t>(nd)];
        for (int i = c.begin; i < c.end; ++i) {
            const Point& q = rg.tree.pts[static_cast<std::size_t>(i)];
            const int x = q.x - t.x0;
            const int y = q.y - t.y0;
            const bool in = std::abs(x) <= kDistTableHalf && std::abs(y) <= kDistTableHalf;
            const std::size_t k = in ? front++ : --back;
            sc.px[k] = static_cast<float>(x);
            sc.py[k] = static_cast<float>(y);
            sc.pz[k] = q.z;
            sc.toff[k] = (kDistTableHalf - y) * kDistTableStride + kDistTableHalf - x;
            d2max = std::max(d2max, squared(x, y));
            const int gx = std::max(0, std::max(q.x - geo.maxx, geo.minx - q.x));
            const int gy = std::max(0, std::max(q.y - geo.maxy, geo.miny - q.y));
            dbm2 = std::min(dbm2, squared(gx, gy));
        }
    }
    if (count > 0) {
        ext.dbm2 = static_cast<double>(dbm2);
    }
    ext.inTable = front;
    ext.dmax = std::sqrt(static_cast<double>(d2max));
    return ext;
}

// The tile's local expansion as polynomials (zero without one) and the sums
// of their |c_ij|.
struct LeafPoly {
    bool has = false;
    std::array<double, kSquare> cD{}, cN{};
    double sumD = 0.0, sumN = 0.0;
};

void leafPolynomial(const Local* far, const PowerTables& tab, LeafPoly& poly) {
    poly.has = far != nullptr;
    if (!poly.has) {
        return;
    }
    localToPoly(far->d, tab.degree, tab, poly.cD);
    localToPoly(far->n, tab.degree, tab, poly.cN);
    double sumD = 0.0;  // in registers, not through poly
    double sumN = 0.0;
    for (std::size_t i = 0; i < kSquare; ++i) {
        sumD += std::abs(poly.cD[i]);
        sumN += std::abs(poly.cN[i]);
    }
    poly.sumD = sumD;
    poly.sumN = sumN;
}

// The check's mode and constants (the comment at the top of FastSolver.cpp).
struct LeafTolerances {
    bool tileMode = false;  // one weight scale for the tile (else one per pixel)
    double tolRem = 0.0;    // tol per unit of D left after the near sums' arithmetic
    double farArith = 0.0;  // the polynomial's round-off
};

LeafTolerances leafTolerances(const Region& rg, const BoxGeo& geo, const LeafBounds& bounds,
                              const LeafPoly& poly, std::size_t count, double dbm2) {
    const PowerTables& tab = *rg.tab;
    LeafTolerances tl;
    const double diag = std::hypot(static_cast<double>(geo.maxx - geo.minx),
                                   static_cast<double>(geo.maxy - geo.miny));
    tl.tileMode = count > 0 && tab.p * std::log2((std::sqrt(dbm2) + diag + 1.0) / bounds.S) <= 60.0;
    const double gammaK = (static_cast<double>(count) + 8.0) * kU * 1.01;
    const double gammaPoly = (3.0 * tab.degree + 12.0) * kU * 1.01;
    const double deltaAll = rg.deltaW * (tl.tileMode ? 1.0 : 2.0);
    tl.tolRem = rg.tol * (1.0 - 1e-6) - rg.dz * (deltaAll + gammaK) - 16.0 * kU;
    tl.farArith =
        gammaPoly * (poly.sumN + (0.5 * rg.dz + kU) * poly.sumD) + 1e-11 * bounds.W * (1.0 + rg.dz);
    return tl;
}

// The kernel's arguments and the float coefficients they point at (not to
// be copied); allFail: the kernel is not run, every pixel is exact.
struct KernelInput {
    LeafKernelArgs args;
    std::array<float, kSquare> fD{}, fN{};
    bool allFail = false;
    KernelInput() = default;
    KernelInput(const KernelInput&) = delete;
    KernelInput(KernelInput&&) = delete;
    KernelInput& operator=(const KernelInput&) = delete;
    KernelInput& operator=(KernelInput&&) = delete;
    ~KernelInput() = default;
};

// Whether the tile's near weights come from the distance table (in absolute
// scale): in tile mode, with S^-p (the polynomial's scale then) and the
// farthest near point's weight far inside float's range.
const float* distanceTable(const Region& rg, const LeafBounds& bounds, const LeafTolerances& tl,
                           const NearExtent& ext) {
    if (rg.dist == nullptr || !tl.tileMode || ext.inTable == 0 ||
        rg.tab->p * std::log2(bounds.S) > 72.0 ||
        !distanceTableFits(rg.tab->p, ext.dmax + 2.0 * kLeafTile)) {
        return nullptr;
    }
    return rg.dist;
}

// The weights' scale: one for the tile, or per pixel (large p, far from
// the points; the polynomial then scaled to S_F), or none with the distance
// table (true weights: the polynomial and E scaled by S^-p). Returns the
// polynomial's scale.
double setWeightScale(const Region& rg, const LeafBounds& bounds, const LeafTolerances& tl,
                      bool hasLocal, KernelInput& in) {
    const PowerTables& tab = *rg.tab;
    LeafKernelArgs& a = in.args;
    double polyScale = 1.0;
    if (a.table != nullptr) {
        a.perPixel = false;
        a.s2 = 1.0F;  // the computed near weights in absolute scale too
        polyScale = tab.pw(1.0 / (bounds.S * bounds.S));
        a.errAbs =
            static_cast<float>((bounds.E + tl.farArith) * polyScale * (1.0 + 1e-6) + kUnderflow);
        return polyScale;
    }
    if (tl.tileMode) {
        a.perPixel = false;
        a.s2 = static_cast<float>(bounds.S * bounds.S);
        // (1 + p u): the near weights use S^2 rounded to float
        a.errAbs =
            static_cast<float>((bounds.E + tl.farArith) * (1.0 + 1e-6 + tab.p * kU) + kUnderflow);
        return polyScale;
    }
    a.perPixel = true;
    if (hasLocal) {
        polyScale = tab.pw((bounds.Sexp * bounds.Sexp) / (bounds.S * bounds.S));
        a.s2 = static_cast<float>(bounds.Sexp * bounds.Sexp);
        if (!std::isfinite(polyScale) || !std::isfinite(a.s2)) {
            in.allFail = true;
        }
    } else {
        a.s2 = std::numeric_limits<float>::infinity();
    }
    a.farArith = static_cast<float>(tl.farArith * polyScale * (1.0 + 1e-6) + kUnderflow);
    if (!std::isfinite(a.farArith)) {
        in.allFail = true;
    }
    const double margin = 1e-4 + tab.halfP * 4e-6;
    a.log2DzE = bounds.E > 0.0 ? static_cast<float>(std::log2(bounds.E) + margin) : -1000.0F;
    a.log2LeafS2 = static_cast<float>(std::log2(bounds.S * bounds.S));
    return polyScale;
}

// Fills in: the near points, the check's constants, the weight scale and the
// polynomial (its coefficients times polyScale).
void setUpKernel(const Region& rg, const BoxGeo& geo, const LeafTile& t, const LeafBounds& bounds,
                 const LeafPoly& poly, const LeafTolerances& tl, std::size_t count,
                 const Scratch& sc, const NearExtent& ext, KernelInput& in) {
    LeafKernelArgs& a = in.args;
    a.table = distanceTable(rg, bounds, tl, ext);
    if (a.table != nullptr) {
        a.tableOffset = sc.toff.data();
        a.tableCount = static_cast<int>(ext.inTable);
    }
    a.rows = t.rows;
    a.rowMask = t.rowMask;
    a.px = sc.px.data();
    a.py = sc.py.data();
    a.pz = sc.pz.data();
    a.count = static_cast<int>(count);
    a.zref = static_cast<float>(rg.zref);
    a.zmin = rg.zminOut;
    a.zmax = rg.zmaxOut;
    a.power = rg.kp;
    a.tolRemaining = static_cast<float>(tl.tolRem);
    in.allFail = tl.tolRem <= 0.0;
    const double polyScale = setWeightScale(rg, bounds, tl, poly.has, in);
    if (poly.has && (poly.sumD + poly.sumN) * polyScale > 1e30) {
        in.allFail = true;  // would not fit in float (not seen in practice): be exact
    }
    if (poly.has) {
        a.degree = rg.tab->degree;
        for (std::size_t i = 0; i < kSquare; ++i) {
            in.fD[i] = static_cast<float>(poly.cD[i] * polyScale);
            in.fN[i] = static_cast<float>(poly.cN[i] * polyScale);
        }
        a.polyD = in.fD.data();
        a.polyN = in.fN.data();
        a.tu = static_cast<float>(geo.tx - t.x0);
        a.tv = static_cast<float>(geo.ty - t.y0);
        a.invA = static_cast<float>(1.0 / geo.an);
    }
}

// The kernel's values and failure bits of a tile.
struct TileValues {
    std::array<float, kTilePixels> z{};
    std::array<std::uint32_t, kLeafTile> fail{};
};

// Region pixels of the tile that failed the check.
int countFailures(const Region& rg, const LeafTile& t, const TileValues& v, bool allFail) {
    int nFail = 0;
    for (int r = 0; r < t.rows; ++r) {
        if (((t.rowMask >> r) & 1U) == 0) {
            continue;
        }
        const std::int32_t* lab = rg.labels.row(t.y0 + r) + t.x0;
        const std::uint32_t rowFail = failBits(v.fail, allFail, r);
        for (int c = 0; c < t.cols; ++c) {
            nFail += (lab[c] == rg.id && ((rowFail >> c) & 1U) != 0) ? 1 : 0;
        }
    }
    return nFail;
}

// Safety net: when many pixels of the tile fail the check, evaluate the whole
// tile exactly (every contour point of the region, no expansion) with the
// kernel before falling back to the per-pixel double-precision sum. Returns
// whether it did (into exact).
bool exactTile(const Region& rg, const LeafTile& t, const KernelInput& in, const TileValues& v,
               Scratch& sc, TileValues& exact) {
    std::uint32_t anyFail = in.allFail ? 1U : 0U;
    for (int r = 0; r < t.rows; ++r) {
        anyFail |= v.fail[static_cast<std::size_t>(r)];
    }
    if (anyFail == 0) {  // no pixel failed: skip the count (the common case)
        return false;
    }
    const int nFail = countFailures(rg, t, v, in.allFail);
    const double nAll = rg.n;
    const double tolAll =
        rg.tol * (1.0 - 1e-6) - rg.dz * (2.0 * rg.deltaW + (nAll + 8.0) * kU * 1.01) - 16.0 * kU;
    if (!(nFail > 16 && tolAll > 0.0 && nAll < 1e7)) {
        return false;
    }
    const std::size_t nn = rg.tree.pts.size();
    sc.ax.resize(nn);
    sc.ay.resize(nn);
    sc.az.resize(nn);
    for (std::size_t i = 0; i < nn; ++i) {
        const Point& q = rg.tree.pts[i];
        sc.ax[i] = static_cast<float>(q.x - t.x0);
        sc.ay[i] = static_cast<float>(q.y - t.y0);
        sc.az[i] = q.z;
    }
    LeafKernelArgs b = in.args;
    b.px = sc.ax.data();
    b.py = sc.ay.data();
    b.pz = sc.az.data();
    b.count = static_cast<int>(nn);
    b.degree = -1;
    b.perPixel = true;
    b.table = nullptr;  // every contour point: beyond the table
    b.s2 = std::numeric_limits<float>::infinity();
    b.farArith = 0.0F;
    b.log2DzE = -1000.0F;
    b.tolRemaining = static_cast<float>(tolAll);
    leafKernel(b, exact.z.data(), exact.fail.data());
    return true;
}

// Writes every region pixel of the tile: the kernel's value, or for one that
// failed the exact tile's (when it has one that passed) or the
// double-precision sum. Returns how many pixels it wrote, how many failed.
struct Written {
    std::int64_t pixels = 0;
    std::int64_t fallbacks = 0;
};

Written writePixels(const Region& rg, const LeafTile& t, const TileValues& v, bool allFail,
                    const TileValues* exact) {
    std::int64_t pixels = 0;  // in registers, not through a struct
    std::int64_t fallbacks = 0;
    for (int r = 0; r < t.rows; ++r) {
        if (((t.rowMask >> r) & 1U) == 0) {
            continue;
        }
        const std::int32_t* lab = rg.labels.row(t.y0 + r) + t.x0;
        float* o = rg.out.row(t.y0 + r) + t.x0;
        const std::uint32_t rowFail = failBits(v.fail, allFail, r);
        for (int c = 0; c < t.cols; ++c) {
            if (lab[c] != rg.id) {
                continue;
            }
            ++pixels;
            const auto i = static_cast<std::size_t>(r) * kLeafTile + static_cast<std::size_t>(c);
            if (((rowFail >> c) & 1U) != 0) {
                ++fallbacks;
                if (exact != nullptr &&
                    ((exact->fail[static_cast<std::size_t>(r)] >> c) & 1U) == 0) {
                    o[c] = exact->z[i];
                } else {
                    o[c] = exactPixel(rg, t.x0 + c, t.y0 + r);
                }
            } else {
                o[c] = v.z[i];
            }
        }
    }
    return {pixels, fallbacks};
}

}  // namespace

__attribute__((noinline)) float exactPixel(const Region& rg, int x, int y) {
    double dmin2 = std::numeric_limits<double>::infinity();
    for (const Point& q : rg.tree.pts) {
        const double dx = static_cast<double>(x) - q.x;
        const double dy = static_cast<double>(y) - q.y;
        dmin2 = std::min(dmin2, dx * dx + dy * dy);
    }
    dmin2 = std::max(dmin2, 1e-300);
    double sumD = 0.0;
    double sumN = 0.0;
    for (const Point& q : rg.tree.pts) {
        const double dx = static_cast<double>(x) - q.x;
        const double dy = static_cast<double>(y) - q.y;
        const double d2 = std::max(dx * dx + dy * dy, 1e-300);
        const double w = rg.tab->pw(dmin2 / d2);
        sumD += w;
        sumN += w * static_cast<double>(q.z);
    }
    const double z = rg.zref + sumN / sumD;
    return std::clamp(static_cast<float>(z), rg.zminOut, rg.zmaxOut);
}

LeafCounts evalLeaf(const Region& rg, int ix, int iy, const BoxGeo& geo,
                    const std::vector<int>& nearNodes, const Local* far, const LeafBounds& bounds) {
    const LeafTile t = leafTile(rg, ix, iy);
    const std::size_t count = pointCount(rg.tree, nearNodes);
    Scratch& sc = scratch();
    const NearExtent ext = gatherNearPoints(rg, geo, nearNodes, count, t, sc);
    LeafPoly poly;
    leafPolynomial(far, *rg.tab, poly);
    const LeafTolerances tl = leafTolerances(rg, geo, bounds, poly, count, ext.dbm2);
    KernelInput in;
    setUpKernel(rg, geo, t, bounds, poly, tl, count, sc, ext, in);
    TileValues v;
    if (!in.allFail) {
        leafKernel(in.args, v.z.data(), v.fail.data());
    }
    TileValues exact;
    const bool haveExact = exactTile(rg, t, in, v, sc, exact);

    const Written written = writePixels(rg, t, v, in.allFail, haveExact ? &exact : nullptr);
    LeafCounts counts;
    counts.pixels = written.pixels;
    counts.fallbackPixels = written.fallbacks;
    counts.nearPairs = static_cast<std::int64_t>(count) * std::popcount(t.rowMask);
    counts.tablePairs =
        in.allFail ? 0 : static_cast<std::int64_t>(in.args.tableCount) * std::popcount(t.rowMask);
    counts.perPixel = !tl.tileMode;
    counts.exactTile = haveExact;
    return counts;
}

}  // namespace vv::vss::detail::fast
