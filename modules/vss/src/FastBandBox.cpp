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

// Pixels of region rows (bit x of rows[y]) inside [x0, x0 + w) x [y0, y0 + h).
bool hasPixels(const std::array<std::uint64_t, kBox>& rows, int ny, int x0, int y0, int w, int h) {
    const std::uint64_t m = ((std::uint64_t{1} << w) - 1U) << x0;
    for (int y = y0; y < std::min(ny, y0 + h); ++y) {
        if ((rows[static_cast<std::size_t>(y)] & m) != 0) {
            return true;
        }
    }
    return false;
}

constexpr std::size_t kPix = static_cast<std::size_t>(kBox) * kBox;
constexpr std::size_t kBuf = kPix + kPad;  // kernel buffers: every pixel, rounded up

// Scratch of one thread, reused by every band box.
struct Scratch {
    std::vector<float> px, py, pz, cx, cy, cz;
    std::vector<int> stack;
    std::array<std::vector<float>, 8> o{};  // kernel outputs
    std::vector<float> bx = std::vector<float>(kBuf), by = std::vector<float>(kBuf);
    std::vector<std::size_t> pend;
    std::vector<Cell> cells, next;
    std::vector<int> exact;  // packed (y << 8) | x
    std::array<Smp, kFineCount> smp{};
    std::array<bool, kFineCount> have{};
    std::array<float, kPix> pixD{}, pixN{};  // D, N of the pixels in `done`
    std::array<std::uint64_t, kBox> done{};
    Scratch() {
        for (auto& v : o) {
            v.resize(kBuf);
        }
    }
};

Scratch& scratch() {
    thread_local Scratch s;
    return s;
}

constexpr std::size_t fineIndex(int i, int j) noexcept {
    return static_cast<std::size_t>(j) * kFine + static_cast<std::size_t>(i);
}

// The bound of one cell (see the top of the file).
struct CellBound {
    bool ok = false;      // the whole cell passes
    bool usable = false;  // finite, rho > 0: per-pixel checks possible
    double c = 0.0;       // its constant
    double aD = 0.0, aN = 0.0, errD = 0.0, errNc = 0.0, ncxx = 0.0, ncyy = 0.0;
    std::array<const Smp*, 4> s{};  // corners 00, 10, 01, 11
};

}  // namespace

BandCounts evalBandBox(const Region& rg, const BoxGeo& geo, const std::vector<int>& near,
                       const Local* far, const LeafBounds& bounds) {
    BandCounts out;
    const PowerTables& tab = *rg.tab;
    const int spanX = geo.maxx - geo.minx;
    const int spanY = geo.maxy - geo.miny;
    if (spanX >= kBox || spanY >= kBox) {
        return out;
    }
    const double p = tab.p;
    const double pp1 = p * (p + 1.0);
    const double sScale = bounds.S;
    std::size_t nearCount = 0;
    for (const int nd : near) {
        nearCount += static_cast<std::size_t>(rg.tree.nodes[static_cast<std::size_t>(nd)].count());
    }
    if (nearCount == 0) {
        return out;
    }
    const int ncx = spanX / kHc + 1;  // coarse cells: they cover B, Q reaches <= kHc beyond it
    const int ncy = spanY / kHc + 1;
    Scratch& sc = scratch();
    // Near points relative to (minx, miny); the points of the source tree's
    // leaves within kClose of Q: the subset for the samples' nearest distance.
    sc.px.resize(nearCount);
    sc.py.resize(nearCount);
    sc.pz.resize(nearCount);
    sc.cx.clear();
    sc.cy.clear();
    sc.cz.clear();
    double dbm2 = std::numeric_limits<double>::infinity();
    double zAbs = 0.0;
    double cFar = 0.0;
    double farD2 = std::numeric_limits<double>::infinity();
    const int qx1 = geo.minx + kHc * ncx;  // Q's far corner
    const int qy1 = geo.miny + kHc * ncy;
    std::size_t k = 0;
    for (const int nd : near) {
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
    const double diagQ = std::hypot(static_cast<double>(kHc * ncx), static_cast<double>(kHc * ncy));
    if (p * std::log2((std::sqrt(dbm2) + diagQ + 1.0) / sScale) > 60.0) {
        return out;  // the leaf's tile-scale rule: weights stay in float's range
    }
    // Region pixels of the box, one bit per column.
    std::array<std::uint64_t, kBox> rows{};
    const int ny = spanY + 1;
    for (int y = 0; y < ny; ++y) {
        const std::int32_t* lab = rg.labels.row(geo.miny + y) + geo.minx;
        std::uint64_t bits = 0;
        for (int x = 0; x <= spanX; ++x) {
            bits |= static_cast<std::uint64_t>(lab[x] == rg.id ? 1U : 0U) << x;
        }
        rows[static_cast<std::size_t>(y)] = bits;
    }

    // The polynomial and its bounds over Q (mu) and over B (the exact pixels).
    const bool hasPoly = far != nullptr;
    const int deg = tab.degree;
    const double ext = std::max(kHc * ncx - spanX, kHc * ncy - spanY);
    const double mu = 1.0 + ext / geo.an * (1.0 + 1e-12);
    PolyBounds bD;
    PolyBounds bN;
    double sumD1 = 0.0;
    double sumN1 = 0.0;
    std::array<float, kSquare> fD{};
    std::array<float, kSquare> fN{};
    if (hasPoly) {
        std::array<double, kSquare> cD{};
        std::array<double, kSquare> cN{};
        localToPoly(far->d, deg, tab, cD);
        localToPoly(far->n, deg, tab, cN);
        for (std::size_t i = 0; i < kSquare; ++i) {
            fD[i] = static_cast<float>(cD[i]);
            fN[i] = static_cast<float>(cN[i]);
            sumD1 += std::abs(cD[i]);
            sumN1 += std::abs(cN[i]);
        }
        bD = polyBounds(cD, deg, geo.an, mu);
        bN = polyBounds(cN, deg, geo.an, mu);
        if (!(bD.sum + bN.sum <= 1e30)) {
            return out;  // would not fit in float
        }
    }
    const double gammaK = (static_cast<double>(nearCount) + 8.0) * kU * 1.01;
    const double relNear = rg.deltaW + gammaK;
    const double relA = 2.0 * (relNear + 8.0 * kU);
    const double gammaPoly = (3.0 * deg + 12.0) * kU * 1.01;
    const double dArith = hasPoly ? gammaPoly * bD.sum + 1e-11 * bounds.W + kUnderflow : 0.0;
    const double nArith =
        hasPoly ? gammaPoly * bN.sum + 1e-11 * bounds.W * (1.0 + rg.dz) + kUnderflow : 0.0;
    const double eTrunc = bounds.E * (1.0 + 1e-6 + p * kU) + kUnderflow;
    const double tolAll = rg.tol * (1.0 - 1e-6) - 16.0 * kU - rg.dz * (p + 2.0) * kU * 1.1;
    // an exact pixel: the leaf's tile-mode check
    const double farArith = hasPoly ? gammaPoly * (sumN1 + (0.5 * rg.dz + kU) * sumD1) +
                                          1e-11 * bounds.W * (1.0 + rg.dz)
                                    : 0.0;
    const double tolRem = rg.tol * (1.0 - 1e-6) - rg.dz * (rg.deltaW + gammaK) - 16.0 * kU;
    const double errAbs = (bounds.E + farArith) * (1.0 + 1e-6 + p * kU) + kUnderflow;
    const double invS2 = 1.0 / (sScale * sScale);

    PointKernelArgs ka;
    ka.px = sc.px.data();
    ka.py = sc.py.data();
    ka.pz = sc.pz.data();
    ka.count = static_cast<int>(nearCount);
    ka.s2 = static_cast<float>(sScale * sScale);
    ka.power = rg.kp;
    ka.closeCount = static_cast<int>(sc.cx.size());
    ka.c0x = sc.cx.data();
    ka.c0y = sc.cy.data();
    ka.c0z = sc.cz.data();
    ka.floor2 = static_cast<float>(kClose * kClose);
    ka.cFar = static_cast<float>(cFar);
    ka.ex = sc.bx.data();
    ka.ey = sc.by.data();
    ka.dn = sc.o[0].data();
    ka.nn = sc.o[1].data();
    ka.pd = sc.o[2].data();
    ka.pn = sc.o[3].data();
    ka.dmin2 = sc.o[4].data();
    ka.c = sc.o[5].data();
    ka.a = sc.o[6].data();
    ka.t = sc.o[7].data();
    if (hasPoly) {
        ka.degree = deg;
        ka.polyD = fD.data();
        ka.polyN = fN.data();
        ka.tu = static_cast<float>(geo.tx - geo.minx);
        ka.tv = static_cast<float>(geo.ty - geo.miny);
        ka.invA = static_cast<float>(1.0 / geo.an);
    }
    const auto run = [&](int n, bool withBounds) {
        for (int i = n; i < (n + kPad - 1) / kPad * kPad; ++i) {
            sc.bx[static_cast<std::size_t>(i)] = sc.bx[0];  // pad lanes: results unused
            sc.by[static_cast<std::size_t>(i)] = sc.by[0];
        }
        ka.n = n;
        ka.bounds = withBounds;
        if (!hasPoly) {
            std::fill_n(sc.o[2].begin(), n, 0.0F);
            std::fill_n(sc.o[3].begin(), n, 0.0F);
        }
        pointKernel(ka);
    };

    sc.have.fill(false);
    sc.done.fill(0U);
    // Evaluates the corners of the cells not evaluated yet.
    const auto sampleCorners = [&](const std::vector<Cell>& cells) {
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
            return;
        }
        for (std::size_t q = 0; q < sc.pend.size(); ++q) {
            sc.bx[q] = static_cast<float>(kHf * static_cast<int>(sc.pend[q] % kFine));
            sc.by[q] = static_cast<float>(kHf * static_cast<int>(sc.pend[q] / kFine));
        }
        run(static_cast<int>(sc.pend.size()), true);
        for (std::size_t q = 0; q < sc.pend.size(); ++q) {
            Smp& s = sc.smp[sc.pend[q]];
            const double dn = sc.o[0][q];
            const double pd = sc.o[2][q];
            s.d = dn + pd;
            s.n = static_cast<double>(sc.o[1][q]) + sc.o[3][q];
            s.a = static_cast<double>(sc.o[6][q]) * (1.0 + relA);
            s.t = static_cast<double>(sc.o[7][q]) * (1.0 + relA);
            s.good = std::isfinite(s.d) && std::isfinite(s.n) && s.d > 0.0 && std::isfinite(s.a) &&
                     std::isfinite(s.t);
            s.f = s.n / s.d;
            s.sq = std::sqrt(static_cast<double>(sc.o[4][q]));
            s.c = sc.o[5][q];
            const double dnHi = dn / (1.0 - relNear);
            s.errD = relNear * dnHi + dArith + 1e-15 * (dn + std::abs(pd));
            s.errN = (relNear + 2.0 * kU) * zAbs * dnHi + nArith + 1e-15 * std::abs(s.n);
        }
        out.samples += static_cast<std::int64_t>(sc.pend.size());
    };

    const double psiScale = rg.bandBoundScale;  // 1 but in tests
    const double psiOf2 = 0.5 * psiScale;       // h^2 t (1 - t) / 2 at t = 1/2, h = 2
    const auto bound = [&](const Cell& cl) {
        CellBound b;
        const double h = kHf * cl.st;
        b.s = {&sc.smp[fineIndex(cl.i, cl.j)], &sc.smp[fineIndex(cl.i + cl.st, cl.j)],
               &sc.smp[fineIndex(cl.i, cl.j + cl.st)],
               &sc.smp[fineIndex(cl.i + cl.st, cl.j + cl.st)]};
        if (!(b.s[0]->good && b.s[1]->good && b.s[2]->good && b.s[3]->good)) {
            return b;
        }
        std::size_t nearest = 0;
        double sqMax = b.s[0]->sq;
        for (std::size_t q = 1; q < 4; ++q) {
            nearest = b.s[q]->sq < b.s[nearest]->sq ? q : nearest;
            sqMax = std::max(sqMax, b.s[q]->sq);
        }
        const double rho =
            std::max(b.s[nearest]->sq - h * std::sqrt(0.5), sqMax - h * std::sqrt(2.0)) *
            (1.0 - 1e-12);
        if (!(rho > 0.0)) {
            return b;
        }
        b.c = b.s[nearest]->c;
        const double cAbs = std::abs(b.c);
        const double qF = 1.0 + h * std::sqrt(2.0) / rho;
        const double qN = 1.0 + h * std::sqrt(0.5) / rho;
        const double kFar = tab.pw(qF * qF) * qF * qF * (1.0 + 1e-9);
        const double kNear = tab.pw(qN * qN) * qN * qN * (1.0 + 1e-9);
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
            b.errNc = std::max(b.errNc,
                               s->errN + cAbs * s->errD + 1e-15 * (std::abs(s->n) + cAbs * s->d));
            dMin = std::min(dMin, s->d);
            fMax = std::max(fMax, std::abs(s->f - b.c));
        }
        fMax *= 1.0 + 1e-12;
        b.aD = pp1 * std::min(kFar * aMin, kNear * aMax) * invS2;
        b.aN = pp1 * std::min(kFar * tMin, kNear * tMax) * invS2;
        b.ncxx = bN.dxx + cAbs * bD.dxx;
        b.ncyy = bN.dyy + cAbs * bD.dyy;
        if (!std::isfinite(b.aD) || !std::isfinite(b.aN)) {
            return b;
        }
        b.usable = true;
        const double psi = h * h / 8.0 * psiScale;
        const double eD = psi * (2.0 * b.aD + bD.dxx + bD.dyy) + b.errD;
        const double eN = psi * (2.0 * b.aN + b.ncxx + b.ncyy) + b.errNc;
        b.ok = dMin - eD > 0.0 && eN + fMax * eD + eTrunc <= tolAll * (dMin - eD);
        return b;
    };

    const auto put = [&](int x, int y, double d, double n) {
        const auto i = static_cast<std::size_t>(y) * kBox + static_cast<std::size_t>(x);
        sc.pixD[i] = static_cast<float>(d);
        sc.pixN[i] = static_cast<float>(n);
        sc.done[static_cast<std::size_t>(y)] |= std::uint64_t{1} << x;
    };
    // Interpolates every region pixel of a passing cell.
    const auto fillCell = [&](const Cell& cl, const CellBound& b) {
        const int h = kHf * cl.st;
        const int x0 = kHf * cl.i;
        const int y0 = kHf * cl.j;
        const Smp& s00 = *b.s[0];
        const Smp& s10 = *b.s[1];
        const Smp& s01 = *b.s[2];
        const Smp& s11 = *b.s[3];
        const double invH = 1.0 / h;
        for (int y = y0; y < std::min(ny, y0 + h); ++y) {
            const double ty = (y - y0) * invH;
            const double d0 = s00.d + ty * (s01.d - s00.d);
            const double d1 = s10.d + ty * (s11.d - s10.d);
            const double n0 = s00.n + ty * (s01.n - s00.n);
            const double n1 = s10.n + ty * (s11.n - s10.n);
            const auto base = static_cast<std::size_t>(y) * kBox;
            for (int x = x0; x < std::min(spanX + 1, x0 + h); ++x) {
                const double tx = (x - x0) * invH;
                sc.pixD[base + static_cast<std::size_t>(x)] =
                    static_cast<float>(d0 + tx * (d1 - d0));
                sc.pixN[base + static_cast<std::size_t>(x)] =
                    static_cast<float>(n0 + tx * (n1 - n0));
            }
            const int x1 = std::min(spanX + 1, x0 + h);
            const std::uint64_t m = ((std::uint64_t{1} << (x1 - x0)) - 1U) << x0;
            sc.done[static_cast<std::size_t>(y)] |= rows[static_cast<std::size_t>(y)] & m;
        }
    };

    std::vector<Cell>& cells = sc.cells;
    std::vector<Cell>& next = sc.next;
    cells.clear();
    for (int j = 0; j < 2 * ncy; ++j) {  // start with cells of 4 (cells of 8 rarely pass)
        for (int i = 0; i < 2 * ncx; ++i) {
            if (hasPixels(rows, ny, 4 * i, 4 * j, 4, 4)) {
                cells.push_back(Cell{2 * i, 2 * j, 2});
            }
        }
    }
    std::vector<int>& exact = sc.exact;
    exact.clear();
    while (!cells.empty()) {
        sampleCorners(cells);
        next.clear();
        for (const Cell& cl : cells) {
            const CellBound b = bound(cl);
            if (b.ok) {
                fillCell(cl, b);
                continue;
            }
            if (cl.st > 1) {
                const int half = cl.st / 2;
                const int hp = kHf * half;
                for (const int dj : {0, half}) {
                    for (const int di : {0, half}) {
                        if (hasPixels(rows, ny, kHf * (cl.i + di), kHf * (cl.j + dj), hp, hp)) {
                            next.push_back(Cell{cl.i + di, cl.j + dj, half});
                        }
                    }
                }
                continue;
            }
            // A failing cell of 2: pixel by pixel.
            const int x0 = kHf * cl.i;
            const int y0 = kHf * cl.j;
            const Smp& s00 = *b.s[0];
            for (int y = y0; y < std::min(ny, y0 + kHf); ++y) {
                for (int x = x0; x < std::min(spanX + 1, x0 + kHf); ++x) {
                    if (((rows[static_cast<std::size_t>(y)] >> x) & 1U) == 0) {
                        continue;
                    }
                    if (x == x0 && y == y0) {  // the sample itself: an exact evaluation
                        if (std::isfinite(s00.d) && std::isfinite(s00.n) &&
                            s00.d * tolRem >= errAbs) {
                            put(x, y, s00.d, s00.n);
                            continue;
                        }
                    } else if (b.usable) {
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
                        const double eD = psiY * (b.aD + bD.dyy) + psiX * (b.aD + bD.dxx) + b.errD;
                        const double eN = psiY * (b.aN + b.ncyy) + psiX * (b.aN + b.ncxx) + b.errNc;
                        if (iD - eD > 0.0 &&
                            eN + std::abs(fc) * eD + eTrunc <= tolAll * (iD - eD)) {
                            put(x, y, iD, iN);
                            continue;
                        }
                    }
                    exact.push_back((y << 8) | x);
                }
            }
        }
        cells.swap(next);
    }
    // The pixels summed exactly, checked like a leaf's.
    std::int64_t written = 0;
    if (!exact.empty()) {
        for (std::size_t q = 0; q < exact.size(); ++q) {
            sc.bx[q] = static_cast<float>(exact[q] & 0xff);
            sc.by[q] = static_cast<float>(exact[q] >> 8);
        }
        run(static_cast<int>(exact.size()), false);
        for (std::size_t q = 0; q < exact.size(); ++q) {
            const int x = exact[q] & 0xff;
            const int y = exact[q] >> 8;
            const double d = static_cast<double>(sc.o[0][q]) + sc.o[2][q];
            const double nv = static_cast<double>(sc.o[1][q]) + sc.o[3][q];
            if (std::isfinite(d) && std::isfinite(nv) && d * tolRem >= errAbs) {
                put(x, y, d, nv);
            } else {
                rg.out(geo.minx + x, geo.miny + y) = exactPixel(rg, geo.minx + x, geo.miny + y);
                ++written;
                ++out.fallbackPixels;
            }
        }
    }
    // Every pixel with its D and N: the value.
    const auto zref = static_cast<float>(rg.zref);
    for (int y = 0; y < ny; ++y) {
        const std::uint64_t bits = sc.done[static_cast<std::size_t>(y)];
        if (bits == 0) {
            continue;
        }
        float* o = rg.out.row(geo.miny + y) + geo.minx;
        const float* dd = &sc.pixD[static_cast<std::size_t>(y) * kBox];
        const float* nn = &sc.pixN[static_cast<std::size_t>(y) * kBox];
        for (int x = 0; x <= spanX; ++x) {
            if (((bits >> x) & 1U) != 0) {
                o[x] = std::clamp(zref + nn[x] / dd[x], rg.zminOut, rg.zmaxOut);
            }
        }
        written += std::popcount(bits);
    }
    out.exactPixels = static_cast<std::int64_t>(exact.size());
    out.pixels = written;
    return out;
}

}  // namespace vv::vss::detail::fast
