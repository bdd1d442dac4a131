// SPDX-License-Identifier: GPL-3.0-or-later
// Band boxes of the fast VSS solver (FastBandBox.h): a 32-pixel box of the
// near-contour band on an adaptive grid, cell by cell.
//
// WHY. The near boxes (FastNearBox.cpp) take a box only when every pixel of
// it passes their bound, and only when its nearest near point is >= 4 pixels
// away: a box with a contour inside or next to it is descended whole to its
// leaf tiles, each paying M2L translations, an L2L shift and 16 rows of near
// sums, although most of its pixels are tens of pixels from the points that
// made it a near box (docs/benchmarks/vss.md, "Sixth step": at 3840x2160 half
// of the near tiles' pixels are >= 32 pixels from their nearest near point).
//
// WHAT IS COMPUTED. The box's near points (all points of the clusters it
// could not expand, K) and its local expansion P are evaluated, one point per
// kernel lane (pointKernel), at samples of a grid with origin (X, Y), the
// corner of the region pixels' bounding box B, and spacing 2; the grid
// reaches at most 8 pixels beyond B on the far sides (Q). Cells of 4 x 4
// pixels are tried first (cells of 8 passed too rarely to pay: measured); a
// cell whose bound fails is split into four of spacing 2; a cell of 2 that
// fails is checked pixel by pixel, and
// the pixels that fail that are summed exactly (the K points and P at the
// pixel, checked like a leaf pixel; a pixel failing that check gets the
// double-precision sum over every contour point). Only the samples of cells
// with region pixels are evaluated.
//
// THE BOUND (per cell of side h, corners s; as FastNearBox.cpp's, with the
// second derivatives of the near sums taken from sums computed AT THE
// SAMPLES instead of the box's nearest distance and a depth spread). With
// any constant c, z~ = c + Nc / D, Nc = N - c D, both interpolated
// bilinearly; for ID = D + dD, INc = Nc + dN, |dD| <= eD, |dN| <= eN:
//     |c + INc / ID - z~(x)| <= (eN + |INc / ID| eD) / (ID - eD),
// and g - Iy Ix g <= (h^2 / 8) (max_C |g_xx| + max_C |g_yy|) inside a cell C.
//   - Near weights w_i = (S / d_i)^p: |w_i,xx|, |w_i,yy| <= p (p + 1) w_i / d_i^2,
//     so |Dn''| <= p (p + 1) A(xi), |Nc_near''| <= p (p + 1) T(xi) with
//     A = sum w_i / d_i^2 and T = sum w_i |z_i - c| / d_i^2.
//   - rho_C, a lower bound of every point's distance to C: from the samples'
//     m_s = min(16^2, squared distance to the nearest near point of the
//     source-tree nodes within 16 pixels of Q) (the others are >= 16 pixels
//     from every sample; exact: integer coordinates),
//     rho_C = max(min_s sqrt m_s - h / sqrt 2, max_s sqrt m_s - h sqrt 2)
//     (every xi of C is within h / sqrt 2 of some corner and within h sqrt 2
//     of each). The cell is refused unless rho_C > 0.
//   - A and T over C from the corners: d_i(s) <= d_i(xi) + |xi - s| gives
//     w_i(xi) / d_i(xi)^2 <= (1 + |xi - s| / rho_C)^(p+2) w_i(s) / d_i(s)^2, so
//         max_C A <= min(k(h sqrt 2) min_s A(s), k(h / sqrt 2) max_s A(s)),
//     k(r) = (1 + r / rho_C)^(p+2), and the same for T.
//   - The kernel gives at each sample A and T_s with c_s the depth of the
//     sample's nearest point (of those); a cell uses c = c_s of its corner nearest to the
//     points and T(s) <= T_s(s) + |c - c_s| A(s). Float sums of K terms >= 0:
//     true values <= computed (1 + 2 (delta_w + gamma_K + 8 u)).
//   - The polynomial: |P_xx| <= sum i (i-1) |c_ij| mu^(i+j-2) / an^2 over Q
//     (|u|, |v| <= mu = 1 + (reach beyond B) / an), and P_Nc = P_N - c P_D.
//   - The samples' arithmetic as FastNearBox.cpp (relative delta_w + gamma_K
//     for the near sums, gammaPoly sum |c_ij| mu^(i+j) + 1e-11 W for P).
// So a cell passes as a whole when, with Dmin / Fmax the smallest D / largest
// |Nc / D| of its corners and the largest arithmetic bounds of its corners,
//     eD = h^2/8 (2 p(p+1) maxA + |P_D,xx| + |P_D,yy|) + errD,
//     eN = h^2/8 (2 p(p+1) maxT + |P_Nc,xx| + |P_Nc,yy|) + errNc,
//     eN + Fmax eD + E (1 + 1e-6 + p u) <= (tol - dz (p + 2) u - 16 u) (Dmin - eD).
// A pixel of a cell of 2 that fails is checked alone with psi = h^2 t (1-t) / 2
// per axis (0 on the samples' rows and columns; a pixel ON a sample is an
// exact evaluation and gets the leaf's check). The value is clamped to
// [zmin, zmax] like every pixel. Boxes whose weights could leave float's
// range with one scale (the leaf's tile-scale rule over Q) are not tried.
#include "FastBandBox.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstddef>
#include <limits>

#include "FastKernel.h"

namespace vv::vss::detail::fast {
namespace {

constexpr double kUnderflow = 1e-40;   // as the leaf: coefficients below float's normal range
constexpr int kBox = 32;               // pixels per side of a band box (level 1)
constexpr int kHf = 2;                 // finest spacing
constexpr int kHc = 8;                 // coarsest spacing
constexpr int kFine = kBox / kHf + 1;  // samples per side at the finest spacing
constexpr std::size_t kFineCount = static_cast<std::size_t>(kFine) * kFine;
constexpr std::size_t kSquare = static_cast<std::size_t>(kS) * kS;
constexpr int kPad = kLeafTile;  // kernel lanes
constexpr int kClose = 16;       // points farther from Q: their distance bounded by this
constexpr std::size_t kPix = static_cast<std::size_t>(kBox) * kBox;
constexpr std::size_t kBuf = kPix + kPad;  // kernel buffers: every pixel, rounded up

// One sample, as the cells' bounds use it.
struct Smp {
    double d = 0.0, n = 0.0;  // D, N (near sums plus polynomial)
    double f = 0.0;           // N / D
    double sq = 0.0;          // sqrt of the nearest squared distance m_s
    double c = 0.0;           // depth of that point
    double a = 0.0, t = 0.0;  // upper bounds of A, T_s (times S^2)
    double errD = 0.0, errN = 0.0;
    bool good = false;  // finite, D > 0
};

struct Cell {
    int i = 0, j = 0, st = 0;  // corner in fine indices, stride (h / kHf)
};

constexpr std::size_t fineIndex(int i, int j) noexcept {
    return static_cast<std::size_t>(j) * kFine + static_cast<std::size_t>(i);
}

// The box's extent: its region pixels' bounding box B (spanX + 1 by spanY + 1
// pixels) and the coarse cells (of kHc pixels) that cover it; their square Q
// reaches at most kHc pixels beyond B on the far sides.
struct BandGrid {
    int spanX = 0, spanY = 0;
    int ncx = 0, ncy = 0;  // coarse cells per row, per column
};

BandGrid bandGrid(const BoxGeo& geo) {
    BandGrid g;
    g.spanX = geo.maxx - geo.minx;
    g.spanY = geo.maxy - geo.miny;
    g.ncx = g.spanX / kHc + 1;
    g.ncy = g.spanY / kHc + 1;
    return g;
}

// The box's region pixels: bit x of rows[y] is pixel (minx + x, miny + y).
struct BoxPixels {
    std::array<std::uint64_t, kBox> rows{};
    int width = 0;   // spanX + 1
    int height = 0;  // spanY + 1
};

BoxPixels regionPixels(const Region& rg, const BoxGeo& geo, const BandGrid& grid) {
    BoxPixels pix;
    pix.width = grid.spanX + 1;
    pix.height = grid.spanY + 1;
    for (int y = 0; y < pix.height; ++y) {
        const std::int32_t* lab = rg.labels.row(geo.miny + y) + geo.minx;
        std::uint64_t bits = 0;
        for (int x = 0; x < pix.width; ++x) {
            bits |= static_cast<std::uint64_t>(lab[x] == rg.id ? 1U : 0U) << x;
        }
        pix.rows[static_cast<std::size_t>(y)] = bits;
    }
    return pix;
}

// Region pixels inside [x0, x0 + w) x [y0, y0 + h).
bool hasPixels(const BoxPixels& pix, int x0, int y0, int w, int h) {
    const std::uint64_t m = ((std::uint64_t{1} << w) - 1U) << x0;
    for (int y = y0; y < std::min(pix.height, y0 + h); ++y) {
        if ((pix.rows[static_cast<std::size_t>(y)] & m) != 0) {
            return true;
        }
    }
    return false;
}

// The point kernel's outputs (PointKernelArgs), one entry per evaluation point.
struct KernelOutputs {
    std::vector<float> dn = std::vector<float>(kBuf);     // near sums D
    std::vector<float> nn = std::vector<float>(kBuf);     // near sums N
    std::vector<float> pd = std::vector<float>(kBuf);     // polynomial P_D
    std::vector<float> pn = std::vector<float>(kBuf);     // polynomial P_N
    std::vector<float> dmin2 = std::vector<float>(kBuf);  // m_s
    std::vector<float> c = std::vector<float>(kBuf);      // depth of the nearest close point
    std::vector<float> a = std::vector<float>(kBuf);      // A (times S^2)
    std::vector<float> t = std::vector<float>(kBuf);      // T_s (times S^2)
};

// Scratch of one thread, reused by every band box.
struct Scratch {
    std::vector<float> px, py, pz;  // the near points, relative to (minx, miny)
    std::vector<float> cx, cy, cz;  // the close points (the samples' nearest distance)
    std::vector<int> stack;         // source nodes still to walk
    std::vector<float> bx = std::vector<float>(kBuf),
                       by = std::vector<float>(kBuf);  // kernel points
    KernelOutputs o;
    std::vector<std::size_t> pend;  // samples to evaluate (fine indices)
    std::vector<Cell> cells, next;  // cells of this pass, of the next
    std::vector<int> exact;         // pixels to sum exactly, packed (y << 8) | x
    std::array<Smp, kFineCount> smp{};
    std::array<bool, kFineCount> have{};     // smp[s] evaluated
    std::array<float, kPix> pixD{}, pixN{};  // D, N of the pixels in `done`
    std::array<std::uint64_t, kBox> done{};  // pixels with their D and N, bit x of done[y]
};

Scratch& scratch() {
    thread_local Scratch s;
    return s;
}

// What the gathering of the points found.
struct NearPoints {
    double dbm2 = std::numeric_limits<double>::infinity();  // nearest near point to B, squared
    double zAbs = 0.0;                                      // max |z_i - zref| of the near points
    double cFar = 0.0;  // depth of the nearest node beyond kClose of Q (the kernel's c then)
};

// Adds the points of the leaves under node nd within kClose of Q to the close
// points; of the nodes beyond, the nearest (first found) gives cFar, its
// squared distance farD2.
void addClosePoints(const Region& rg, const BoxGeo& geo, const BandGrid& grid, int nd, Scratch& sc,
                    double& farD2, double& cFar) {
    const int qx1 = geo.minx + kHc * grid.ncx;  // Q's far corner
    const int qy1 = geo.miny + kHc * grid.ncy;
    sc.stack.assign(1, nd);
    while (!sc.stack.empty()) {
        const SrcNode& c = rg.tree.nodes[static_cast<std::size_t>(sc.stack.back())];
        sc.stack.pop_back();
        const int gx = std::max({0, c.bx0 - qx1, geo.minx - c.bx1});
        const int gy = std::max({0, c.by0 - qy1, geo.miny - c.by1});
        const double g2 = static_cast<double>(gx) * gx + static_cast<double>(gy) * gy;
        if (g2 >= kClose * kClose) {
            if (g2 < farD2) {
                farD2 = g2;
                cFar = 0.5 * (static_cast<double>(c.zmin) + c.zmax);
            }
            continue;
        }
        if (c.child >= 0) {
            sc.stack.push_back(c.child + 1);
            sc.stack.push_back(c.child);
            continue;
        }
        for (int i = c.begin; i < c.end; ++i) {
            const Point& q = rg.tree.pts[static_cast<std::size_t>(i)];
            sc.cx.push_back(static_cast<float>(q.x - geo.minx));
            sc.cy.push_back(static_cast<float>(q.y - geo.miny));
            sc.cz.push_back(q.z);
        }
    }
}

// Near points relative to (minx, miny); the points of the source tree's
// leaves within kClose of Q: the subset for the samples' nearest distance.
NearPoints gatherPoints(const Region& rg, const BoxGeo& geo, const BandGrid& grid,
                        const std::vector<int>& near, std::size_t nearCount, Scratch& sc) {
    sc.px.resize(nearCount);
    sc.py.resize(nearCount);
    sc.pz.resize(nearCount);
    sc.cx.clear();
    sc.cy.clear();
    sc.cz.clear();
    NearPoints np;
    double farD2 = std::numeric_limits<double>::infinity();
    double dbm2 = np.dbm2;  // in registers, not through np
    double zAbs = np.zAbs;
    std::size_t k = 0;
    for (const int nd : near) {
        addClosePoints(rg, geo, grid, nd, sc, farD2, np.cFar);
        const SrcNode& c = rg.tree.nodes[static_cast<std::size_t>(nd)];
        for (int i = c.begin; i < c.end; ++i, ++k) {
            const Point& q = rg.tree.pts[static_cast<std::size_t>(i)];
            sc.px[k] = static_cast<float>(q.x - geo.minx);
            sc.py[k] = static_cast<float>(q.y - geo.miny);
            sc.pz[k] = q.z;
            const double gx = std::max({0, q.x - geo.maxx, geo.minx - q.x});
            const double gy = std::max({0, q.y - geo.maxy, geo.miny - q.y});
            dbm2 = std::min(dbm2, gx * gx + gy * gy);
            zAbs = std::max(zAbs, std::abs(static_cast<double>(q.z)));
        }
    }
    np.dbm2 = dbm2;
    np.zAbs = zAbs;
    return np;
}

// The leaf's tile-scale rule over Q: the weights stay in float's range.
bool weightsFitFloat(double p, double dbm2, const BandGrid& grid, double sScale) {
    const double diagQ =
        std::hypot(static_cast<double>(kHc * grid.ncx), static_cast<double>(kHc * grid.ncy));
    return !(p * std::log2((std::sqrt(dbm2) + diagQ + 1.0) / sScale) > 60.0);
}

// The box's local expansion as polynomials: the float coefficients the
// kernel evaluates, their bounds over Q (mu) for the cells and the sums of
// their |c_ij| (over B) for the exact pixels.
struct BandPoly {
    bool has = false;  // there is a local expansion (else P = 0)
    PolyBounds bD, bN;
    double sumD1 = 0.0, sumN1 = 0.0;
    std::array<float, kSquare> fD{}, fN{};
};

// Fills poly from far (nullptr: none); false when it would not fit in float.
bool bandPolynomial(const Local* far, const PowerTables& tab, const BoxGeo& geo,
                    const BandGrid& grid, BandPoly& poly) {
    poly.has = far != nullptr;
    if (!poly.has) {
        return true;
    }
    const int deg = tab.degree;
    const double ext = std::max(kHc * grid.ncx - grid.spanX, kHc * grid.ncy - grid.spanY);
    const double mu = 1.0 + ext / geo.an * (1.0 + 1e-12);
    std::array<double, kSquare> cD{};
    std::array<double, kSquare> cN{};
    localToPoly(far->d, deg, tab, cD);
    localToPoly(far->n, deg, tab, cN);
    double sumD1 = 0.0;  // in registers, not through poly
    double sumN1 = 0.0;
    for (std::size_t i = 0; i < kSquare; ++i) {
        poly.fD[i] = static_cast<float>(cD[i]);
        poly.fN[i] = static_cast<float>(cN[i]);
        sumD1 += std::abs(cD[i]);
        sumN1 += std::abs(cN[i]);
    }
    poly.sumD1 = sumD1;
    poly.sumN1 = sumN1;
    poly.bD = polyBounds(cD, deg, geo.an, mu);
    poly.bN = polyBounds(cN, deg, geo.an, mu);
    return poly.bD.sum + poly.bN.sum <= 1e30;
}

// The arithmetic error constants of a box (the top of the file).
struct BandTolerances {
    double relNear = 0.0;  // delta_w + gamma_K: relative error of the near sums
    double relA = 0.0;     // of A and T
    double dArith = 0.0;   // the polynomial's round-off at a sample, in D
    double nArith = 0.0;   // and in N
    double eTrunc = 0.0;   // E (1 + 1e-6 + p u): the truncation
    double tolAll = 0.0;   // tol less the rounding of an interpolated pixel's value
    double tolRem = 0.0;   // an exact pixel: the leaf's tile-mode check
    double errAbs = 0.0;   // its truncation and polynomial round-off
};

BandTolerances bandTolerances(const Region& rg, const LeafBounds& bounds, const BandPoly& poly,
                              std::size_t nearCount) {
    const double p = rg.tab->p;
    const int deg = rg.tab->degree;
    BandTolerances tl;
    const double gammaK = (static_cast<double>(nearCount) + 8.0) * kU * 1.01;
    tl.relNear = rg.deltaW + gammaK;
    tl.relA = 2.0 * (tl.relNear + 8.0 * kU);
    const double gammaPoly = (3.0 * deg + 12.0) * kU * 1.01;
    tl.dArith = poly.has ? gammaPoly * poly.bD.sum + 1e-11 * bounds.W + kUnderflow : 0.0;
    tl.nArith =
        poly.has ? gammaPoly * poly.bN.sum + 1e-11 * bounds.W * (1.0 + rg.dz) + kUnderflow : 0.0;
    tl.eTrunc = bounds.E * (1.0 + 1e-6 + p * kU) + kUnderflow;
    tl.tolAll = rg.tol * (1.0 - 1e-6) - 16.0 * kU - rg.dz * (p + 2.0) * kU * 1.1;
    const double farArith = poly.has ? gammaPoly * (poly.sumN1 + (0.5 * rg.dz + kU) * poly.sumD1) +
                                           1e-11 * bounds.W * (1.0 + rg.dz)
                                     : 0.0;
    tl.tolRem = rg.tol * (1.0 - 1e-6) - rg.dz * (rg.deltaW + gammaK) - 16.0 * kU;
    tl.errAbs = (bounds.E + farArith) * (1.0 + 1e-6 + p * kU) + kUnderflow;
    return tl;
}

// What every cell's bound uses besides its corners and the tolerances.
struct CellTerms {
    const PowerTables* tab = nullptr;  // its pw: k(r) = (1 + r / rho)^(p+2)
    double pp1 = 0.0;                  // p (p + 1)
    double invS2 = 0.0;                // 1 / S^2: A and T come times S^2
    double psiScale = 1.0;             // 1 but in tests (Region::bandBoundScale)
    PolyBounds bD, bN;                 // P_D, P_N over Q
};

CellTerms cellTerms(const Region& rg, const LeafBounds& bounds, const BandPoly& poly) {
    CellTerms ct;
    ct.tab = rg.tab;
    ct.pp1 = rg.tab->p * (rg.tab->p + 1.0);
    ct.invS2 = 1.0 / (bounds.S * bounds.S);
    ct.psiScale = rg.bandBoundScale;
    ct.bD = poly.bD;
    ct.bN = poly.bN;
    return ct;
}

// The point kernel over the box's near points and polynomial: its arguments
// point at the scratch (points in bx, by; outputs in o) and at poly.
struct BandKernel {
    PointKernelArgs args;
    bool hasPoly = false;
};

BandKernel bandKernel(const Region& rg, const BoxGeo& geo, const LeafBounds& bounds,
                      std::size_t nearCount, const NearPoints& np, const BandPoly& poly,
                      Scratch& sc) {
    BandKernel k;
    PointKernelArgs& ka = k.args;
    ka.px = sc.px.data();
    ka.py = sc.py.data();
    ka.pz = sc.pz.data();
    ka.count = static_cast<int>(nearCount);
    ka.s2 = static_cast<float>(bounds.S * bounds.S);
    ka.power = rg.kp;
    ka.closeCount = static_cast<int>(sc.cx.size());
    ka.c0x = sc.cx.data();
    ka.c0y = sc.cy.data();
    ka.c0z = sc.cz.data();
    ka.floor2 = static_cast<float>(kClose * kClose);
    ka.cFar = static_cast<float>(np.cFar);
    ka.ex = sc.bx.data();
    ka.ey = sc.by.data();
    ka.dn = sc.o.dn.data();
    ka.nn = sc.o.nn.data();
    ka.pd = sc.o.pd.data();
    ka.pn = sc.o.pn.data();
    ka.dmin2 = sc.o.dmin2.data();
    ka.c = sc.o.c.data();
    ka.a = sc.o.a.data();
    ka.t = sc.o.t.data();
    k.hasPoly = poly.has;
    if (poly.has) {
        ka.degree = rg.tab->degree;
        ka.polyD = poly.fD.data();
        ka.polyN = poly.fN.data();
        ka.tu = static_cast<float>(geo.tx - geo.minx);
        ka.tv = static_cast<float>(geo.ty - geo.miny);
        ka.invA = static_cast<float>(1.0 / geo.an);
    }
    return k;
}

// Runs the kernel at the first n points of sc.bx, sc.by (with the bounds'
// sums m, c, A, T when withBounds).
void runKernel(BandKernel& k, Scratch& sc, int n, bool withBounds) {
    for (int i = n; i < (n + kPad - 1) / kPad * kPad; ++i) {
        sc.bx[static_cast<std::size_t>(i)] = sc.bx[0];  // pad lanes: results unused
        sc.by[static_cast<std::size_t>(i)] = sc.by[0];
    }
    k.args.n = n;
    k.args.bounds = withBounds;
    if (!k.hasPoly) {
        std::fill_n(sc.o.pd.begin(), n, 0.0F);
        std::fill_n(sc.o.pn.begin(), n, 0.0F);
    }
    pointKernel(k.args);
}

// Sample s from the kernel's outputs at lane q and its arithmetic bounds.
void setSample(Smp& s, const KernelOutputs& o, std::size_t q, const BandTolerances& tl,
               double zAbs) {
    const double dn = o.dn[q];
    const double pd = o.pd[q];
    s.d = dn + pd;
    s.n = static_cast<double>(o.nn[q]) + o.pn[q];
    s.a = static_cast<double>(o.a[q]) * (1.0 + tl.relA);
    s.t = static_cast<double>(o.t[q]) * (1.0 + tl.relA);
    s.good = std::isfinite(s.d) && std::isfinite(s.n) && s.d > 0.0 && std::isfinite(s.a) &&
             std::isfinite(s.t);
    s.f = s.n / s.d;
    s.sq = std::sqrt(static_cast<double>(o.dmin2[q]));
    s.c = o.c[q];
    const double dnHi = dn / (1.0 - tl.relNear);
    s.errD = tl.relNear * dnHi + tl.dArith + 1e-15 * (dn + std::abs(pd));
    s.errN = (tl.relNear + 2.0 * kU) * zAbs * dnHi + tl.nArith + 1e-15 * std::abs(s.n);
}

// Evaluates the corners of the cells not evaluated yet; returns how many.
std::int64_t sampleCorners(const std::vector<Cell>& cells, const BandTolerances& tl, double zAbs,
                           BandKernel& kernel, Scratch& sc) {
    sc.pend.clear();
    for (const Cell& c : cells) {
        for (const int dj : {0, c.st}) {
            for (const int di : {0, c.st}) {
                const std::size_t s = fineIndex(c.i + di, c.j + dj);
                if (!sc.have[s]) {
                    sc.have[s] = true;
                    sc.pend.push_back(s);
                }
            }
        }
    }
    if (sc.pend.empty()) {
        return 0;
    }
    for (std::size_t q = 0; q < sc.pend.size(); ++q) {
        sc.bx[q] = static_cast<float>(kHf * static_cast<int>(sc.pend[q] % kFine));
        sc.by[q] = static_cast<float>(kHf * static_cast<int>(sc.pend[q] / kFine));
    }
    runKernel(kernel, sc, static_cast<int>(sc.pend.size()), true);
    for (std::size_t q = 0; q < sc.pend.size(); ++q) {
        setSample(sc.smp[sc.pend[q]], sc.o, q, tl, zAbs);
    }
    return static_cast<std::int64_t>(sc.pend.size());
}

// The bound of one cell (see the top of the file).
struct CellBound {
    bool ok = false;      // the whole cell passes
    bool usable = false;  // finite, rho > 0: per-pixel checks possible
    double c = 0.0;       // its constant
    double aD = 0.0, aN = 0.0, errD = 0.0, errNc = 0.0, ncxx = 0.0, ncyy = 0.0;
    std::array<const Smp*, 4> s{};  // corners 00, 10, 01, 11
};

CellBound cellBound(const Cell& cl, const Scratch& sc, const CellTerms& ct,
                    const BandTolerances& tl) {
    CellBound b;
    const double h = kHf * cl.st;
    b.s = {&sc.smp[fineIndex(cl.i, cl.j)], &sc.smp[fineIndex(cl.i + cl.st, cl.j)],
           &sc.smp[fineIndex(cl.i, cl.j + cl.st)], &sc.smp[fineIndex(cl.i + cl.st, cl.j + cl.st)]};
    if (!(b.s[0]->good && b.s[1]->good && b.s[2]->good && b.s[3]->good)) {
        return b;
    }
    // rho_C from the corners' nearest distances; c from the corner nearest to the points
    std::size_t nearest = 0;
    double sqMax = b.s[0]->sq;
    for (std::size_t q = 1; q < 4; ++q) {
        nearest = b.s[q]->sq < b.s[nearest]->sq ? q : nearest;
        sqMax = std::max(sqMax, b.s[q]->sq);
    }
    const double rho =
        std::max(b.s[nearest]->sq - h * std::sqrt(0.5), sqMax - h * std::sqrt(2.0)) * (1.0 - 1e-12);
    if (!(rho > 0.0)) {
        return b;
    }
    b.c = b.s[nearest]->c;
    const double cAbs = std::abs(b.c);
    const double qF = 1.0 + h * std::sqrt(2.0) / rho;
    const double qN = 1.0 + h * std::sqrt(0.5) / rho;
    const double kFar = ct.tab->pw(qF * qF) * qF * qF * (1.0 + 1e-9);
    const double kNear = ct.tab->pw(qN * qN) * qN * qN * (1.0 + 1e-9);
    double aMin = std::numeric_limits<double>::infinity();
    double aMax = 0.0;
    double tMin = aMin;
    double tMax = 0.0;
    double dMin = aMin;
    double fMax = 0.0;
    for (const Smp* s : b.s) {
        const double tq = s->t + std::abs(b.c - s->c) * s->a;
        aMin = std::min(aMin, s->a);
        aMax = std::max(aMax, s->a);
        tMin = std::min(tMin, tq);
        tMax = std::max(tMax, tq);
        b.errD = std::max(b.errD, s->errD);
        b.errNc =
            std::max(b.errNc, s->errN + cAbs * s->errD + 1e-15 * (std::abs(s->n) + cAbs * s->d));
        dMin = std::min(dMin, s->d);
        fMax = std::max(fMax, std::abs(s->f - b.c));
    }
    fMax *= 1.0 + 1e-12;
    b.aD = ct.pp1 * std::min(kFar * aMin, kNear * aMax) * ct.invS2;
    b.aN = ct.pp1 * std::min(kFar * tMin, kNear * tMax) * ct.invS2;
    b.ncxx = ct.bN.dxx + cAbs * ct.bD.dxx;
    b.ncyy = ct.bN.dyy + cAbs * ct.bD.dyy;
    if (!std::isfinite(b.aD) || !std::isfinite(b.aN)) {
        return b;
    }
    b.usable = true;
    const double psi = h * h / 8.0 * ct.psiScale;
    const double eD = psi * (2.0 * b.aD + ct.bD.dxx + ct.bD.dyy) + b.errD;
    const double eN = psi * (2.0 * b.aN + b.ncxx + b.ncyy) + b.errNc;
    b.ok = dMin - eD > 0.0 && eN + fMax * eD + tl.eTrunc <= tl.tolAll * (dMin - eD);
    return b;
}

// Keeps D and N of box pixel (x, y) for its value.
void keepPixel(Scratch& sc, int x, int y, double d, double n) {
    const auto i = static_cast<std::size_t>(y) * kBox + static_cast<std::size_t>(x);
    sc.pixD[i] = static_cast<float>(d);
    sc.pixN[i] = static_cast<float>(n);
    sc.done[static_cast<std::size_t>(y)] |= std::uint64_t{1} << x;
}

// Interpolates every region pixel of a passing cell.
void fillCell(const Cell& cl, const CellBound& b, const BoxPixels& pix, Scratch& sc) {
    const int h = kHf * cl.st;
    const int x0 = kHf * cl.i;
    const int y0 = kHf * cl.j;
    const Smp& s00 = *b.s[0];
    const Smp& s10 = *b.s[1];
    const Smp& s01 = *b.s[2];
    const Smp& s11 = *b.s[3];
    const double invH = 1.0 / h;
    for (int y = y0; y < std::min(pix.height, y0 + h); ++y) {
        const double ty = (y - y0) * invH;
        const double d0 = s00.d + ty * (s01.d - s00.d);
        const double d1 = s10.d + ty * (s11.d - s10.d);
        const double n0 = s00.n + ty * (s01.n - s00.n);
        const double n1 = s10.n + ty * (s11.n - s10.n);
        const auto base = static_cast<std::size_t>(y) * kBox;
        for (int x = x0; x < std::min(pix.width, x0 + h); ++x) {
            const double tx = (x - x0) * invH;
            sc.pixD[base + static_cast<std::size_t>(x)] = static_cast<float>(d0 + tx * (d1 - d0));
            sc.pixN[base + static_cast<std::size_t>(x)] = static_cast<float>(n0 + tx * (n1 - n0));
        }
        const int x1 = std::min(pix.width, x0 + h);
        const std::uint64_t m = ((std::uint64_t{1} << (x1 - x0)) - 1U) << x0;
        sc.done[static_cast<std::size_t>(y)] |= pix.rows[static_cast<std::size_t>(y)] & m;
    }
}

// The four quarters of a failing cell with region pixels, for the next pass.
void splitCell(const Cell& cl, const BoxPixels& pix, std::vector<Cell>& next) {
    const int half = cl.st / 2;
    const int hp = kHf * half;
    for (const int dj : {0, half}) {
        for (const int di : {0, half}) {
            if (hasPixels(pix, kHf * (cl.i + di), kHf * (cl.j + dj), hp, hp)) {
                next.push_back(Cell{cl.i + di, cl.j + dj, half});
            }
        }
    }
}

// Pixel (x, y) between the samples of a cell of 2 with corner (x0, y0), alone
// (psi = h^2 t (1 - t) / 2 per axis, 0 on the samples' rows and columns):
// kept when it passes.
bool keepInterpolated(int x, int y, int x0, int y0, const CellBound& b, const CellTerms& ct,
                      const BandTolerances& tl, Scratch& sc) {
    const double psiOf2 = 0.5 * ct.psiScale;  // h^2 t (1 - t) / 2 at t = 1/2, h = 2
    const Smp& s00 = *b.s[0];
    const Smp& s10 = *b.s[1];
    const Smp& s01 = *b.s[2];
    const Smp& s11 = *b.s[3];
    const bool midX = x != x0;
    const bool midY = y != y0;
    const double tx = midX ? 0.5 : 0.0;
    const double ty = midY ? 0.5 : 0.0;
    const double psiX = midX ? psiOf2 : 0.0;
    const double psiY = midY ? psiOf2 : 0.0;
    const double d0 = s00.d + ty * (s01.d - s00.d);
    const double d1 = s10.d + ty * (s11.d - s10.d);
    const double n0 = s00.n + ty * (s01.n - s00.n);
    const double n1 = s10.n + ty * (s11.n - s10.n);
    const double iD = d0 + tx * (d1 - d0);
    const double iN = n0 + tx * (n1 - n0);
    const double fc = iN / iD - b.c;
    const double eD = psiY * (b.aD + ct.bD.dyy) + psiX * (b.aD + ct.bD.dxx) + b.errD;
    const double eN = psiY * (b.aN + b.ncyy) + psiX * (b.aN + b.ncxx) + b.errNc;
    if (iD - eD > 0.0 && eN + std::abs(fc) * eD + tl.eTrunc <= tl.tolAll * (iD - eD)) {
        keepPixel(sc, x, y, iD, iN);
        return true;
    }
    return false;
}

// A failing cell of 2, pixel by pixel: a pixel ON a sample is an exact
// evaluation and gets the leaf's check; the pixels that fail go to sc.exact.
void checkPixels(const Cell& cl, const CellBound& b, const BoxPixels& pix, const CellTerms& ct,
                 const BandTolerances& tl, Scratch& sc) {
    const int x0 = kHf * cl.i;
    const int y0 = kHf * cl.j;
    const Smp& s00 = *b.s[0];
    for (int y = y0; y < std::min(pix.height, y0 + kHf); ++y) {
        for (int x = x0; x < std::min(pix.width, x0 + kHf); ++x) {
            if (((pix.rows[static_cast<std::size_t>(y)] >> x) & 1U) == 0) {
                continue;
            }
            if (x == x0 && y == y0) {  // the sample itself: an exact evaluation
                if (std::isfinite(s00.d) && std::isfinite(s00.n) &&
                    s00.d * tl.tolRem >= tl.errAbs) {
                    keepPixel(sc, x, y, s00.d, s00.n);
                    continue;
                }
            } else if (b.usable && keepInterpolated(x, y, x0, y0, b, ct, tl, sc)) {
                continue;
            }
            sc.exact.push_back((y << 8) | x);
        }
    }
}

// The adaptive grid: cells of 4 over the region pixels first (cells of 8
// rarely pass); per pass, the cells' corners are sampled, the cells that pass
// filled, the others split, those of 2 checked pixel by pixel. Returns the
// samples evaluated.
std::int64_t evalCells(const BoxPixels& pix, const BandGrid& grid, const CellTerms& ct,
                       const BandTolerances& tl, double zAbs, BandKernel& kernel, Scratch& sc) {
    std::vector<Cell>& cells = sc.cells;
    std::vector<Cell>& next = sc.next;
    cells.clear();
    for (int j = 0; j < 2 * grid.ncy; ++j) {
        for (int i = 0; i < 2 * grid.ncx; ++i) {
            if (hasPixels(pix, 4 * i, 4 * j, 4, 4)) {
                cells.push_back(Cell{2 * i, 2 * j, 2});
            }
        }
    }
    sc.exact.clear();
    std::int64_t samples = 0;
    while (!cells.empty()) {
        samples += sampleCorners(cells, tl, zAbs, kernel, sc);
        next.clear();
        for (const Cell& cl : cells) {
            const CellBound b = cellBound(cl, sc, ct, tl);
            if (b.ok) {
                fillCell(cl, b, pix, sc);
            } else if (cl.st > 1) {
                splitCell(cl, pix, next);
            } else {
                checkPixels(cl, b, pix, ct, tl, sc);
            }
        }
        cells.swap(next);
    }
    return samples;
}

// The pixels summed exactly (the near points and the polynomial at the
// pixel), checked like a leaf's; one failing that gets the double-precision
// sum over every contour point, written at once. Returns those.
std::int64_t sumExactPixels(const Region& rg, const BoxGeo& geo, const BandTolerances& tl,
                            BandKernel& kernel, Scratch& sc) {
    const std::vector<int>& exact = sc.exact;
    if (exact.empty()) {
        return 0;
    }
    for (std::size_t q = 0; q < exact.size(); ++q) {
        sc.bx[q] = static_cast<float>(exact[q] & 0xff);
        sc.by[q] = static_cast<float>(exact[q] >> 8);
    }
    runKernel(kernel, sc, static_cast<int>(exact.size()), false);
    std::int64_t fallbacks = 0;
    for (std::size_t q = 0; q < exact.size(); ++q) {
        const int x = exact[q] & 0xff;
        const int y = exact[q] >> 8;
        const double d = static_cast<double>(sc.o.dn[q]) + sc.o.pd[q];
        const double nv = static_cast<double>(sc.o.nn[q]) + sc.o.pn[q];
        if (std::isfinite(d) && std::isfinite(nv) && d * tl.tolRem >= tl.errAbs) {
            keepPixel(sc, x, y, d, nv);
        } else {
            rg.out(geo.minx + x, geo.miny + y) = exactPixel(rg, geo.minx + x, geo.miny + y);
            ++fallbacks;
        }
    }
    return fallbacks;
}

// Every pixel with its D and N: the value. Returns the pixels written.
std::int64_t writeValues(const Region& rg, const BoxGeo& geo, const BoxPixels& pix,
                         const Scratch& sc) {
    std::int64_t written = 0;
    const auto zref = static_cast<float>(rg.zref);
    for (int y = 0; y < pix.height; ++y) {
        const std::uint64_t bits = sc.done[static_cast<std::size_t>(y)];
        if (bits == 0) {
            continue;
        }
        float* o = rg.out.row(geo.miny + y) + geo.minx;
        const float* dd = &sc.pixD[static_cast<std::size_t>(y) * kBox];
        const float* nn = &sc.pixN[static_cast<std::size_t>(y) * kBox];
        for (int x = 0; x < pix.width; ++x) {
            if (((bits >> x) & 1U) != 0) {
                o[x] = std::clamp(zref + nn[x] / dd[x], rg.zminOut, rg.zmaxOut);
            }
        }
        written += std::popcount(bits);
    }
    return written;
}

}  // namespace

BandCounts evalBandBox(const Region& rg, const BoxGeo& geo, const std::vector<int>& near,
                       const Local* far, const LeafBounds& bounds) {
    BandCounts out;
    const BandGrid grid = bandGrid(geo);
    if (grid.spanX >= kBox || grid.spanY >= kBox) {
        return out;
    }
    const std::size_t nearCount = pointCount(rg.tree, near);
    if (nearCount == 0) {
        return out;
    }
    Scratch& sc = scratch();
    const NearPoints np = gatherPoints(rg, geo, grid, near, nearCount, sc);
    if (!weightsFitFloat(rg.tab->p, np.dbm2, grid, bounds.S)) {
        return out;
    }
    const BoxPixels pix = regionPixels(rg, geo, grid);
    BandPoly poly;
    if (!bandPolynomial(far, *rg.tab, geo, grid, poly)) {
        return out;  // would not fit in float
    }
    const BandTolerances tl = bandTolerances(rg, bounds, poly, nearCount);
    const CellTerms ct = cellTerms(rg, bounds, poly);
    BandKernel kernel = bandKernel(rg, geo, bounds, nearCount, np, poly, sc);

    sc.have.fill(false);
    sc.done.fill(0U);
    out.samples = evalCells(pix, grid, ct, tl, np.zAbs, kernel, sc);
    out.fallbackPixels = sumExactPixels(rg, geo, tl, kernel, sc);
    out.exactPixels = static_cast<std::int64_t>(sc.exact.size());
    out.pixels = out.fallbackPixels + writeValues(rg, geo, pix, sc);
    return out;
}

}  // namespace vv::vss::detail::fast
