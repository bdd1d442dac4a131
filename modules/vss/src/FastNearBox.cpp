// SPDX-License-Identifier: GPL-3.0-or-later
// Near boxes of the fast VSS solver (FastNearBox.h): a box of the
// near-contour band evaluated on a coarse grid, its near points exactly.
//
// WHY. At 3840x2160 about four fifths of a solve is the band of leaf tiles
// next to the contours (docs/benchmarks/vss.md, "where the 4K time goes"):
// the band is a fixed number of pixels wide, so its tiles grow with the
// pixels, not with the contours, and each leaf of it pays M2L translations,
// an L2L shift and its near sums. Most of the band lies tens of pixels from
// the nearest contour point, where z' is smooth on the scale of a few pixels.
//
// WHAT IS INTERPOLATED. A box of level 1 (2) that passes clusters on to its
// children is evaluated on the grid of samples (X + h k, Y + h j), (X, Y) the
// corner of its region pixels' bounding box B, h = 4 or 2 (8 or 4), the
// larger when its estimate allows. The grid covers B: its square Q may reach
// up to h - 1 pixels beyond B on the far sides; when that would take 17
// columns (h = 2 at level 1, 4 at level 2, for a full box) it has 16 and the
// last pixels (< h) of a row are extrapolated from the last two columns
// (rows: up to 17, never extrapolated). One kernel call gives the near sums
// at all samples (the points' offsets and S^2 divided by h^2, a power of
// two, so the weights are those of the unscaled pixels, bit for bit), a
// second one the polynomial. In exact arithmetic the samples are
//     D = sum_near w_i + P_D,  N = sum_near w_i (z_i - zref) + P_N
// (near = the points of the clusters passed on; w_i = lambda (S / d_i)^p,
// lambda = (fl(S^2) / S^2)^(p/2); P_* the box's local expansion as
// polynomials with double coefficients), and at a region pixel z~ = zref +
// N / D is within E' / D of z' (E the box's truncation bound, valid on B;
// lambda adds <= dz (p + 2) u). Between samples, z~ is smooth: D and N are
// defined on all of Q (no near point in it, below) and the bound is of z~
// alone. With z_c the depth of the nearest near point and Nc = N - (z_c -
// zref) D, z~ = z_c + Nc / D; D and Nc are interpolated bilinearly (along x
// on the two sample rows, then along y).
//
// THE BOUND. Write ID = D(x) + dD, INc = Nc(x) + dN. Then
//     INc / ID - Nc / D = (dN - Fc dD) / ID,  Fc = Nc / D,
// and with |Fc| <= |INc / ID| + |error|:
//     |z_c + INc / ID - z~(x)| <= (eN + |INc / ID| eD) / (ID - eD)   (ID > eD)
// for any |dN| <= eN, |dD| <= eD. g - Iy Ix g = (g - Iy g) + Iy (g - Ix g)
// for g = D or Nc; by the Lagrange remainder of linear interpolation (or
// extrapolation) at t = (x - x_k) / h between samples x_k, x_k + h,
//     |g(x) - Ix g(x)| <= psi(t) max |g_xx|,  psi(t) = h^2 |t (1 - t)| / 2,
// the maximum over the hull of x_k, x_k + h and x (inside Q); Iy's weights
// are convex (t_y <= 1), Ix's sum to ax = |1 - t| + |t| in absolute value
// (1 inside, 2 t - 1 beyond the last column), so
//     |g - Iy Ix g| <= psi(t_y) max |g_yy| + psi(t_x) max |g_xx|
// over the cell's hull C (the cell of x, extended to x). The second
// derivatives:
//   - a near weight: d^2/dy^2 r^-p = p r^-(p+2) ((p+2) cos^2 - 1), so
//         |w_i,yy|, |w_i,xx| <= p (p + 1) w_i / d_i^2 <= p (p + 1) w_i / rho_i^2,
//     rho_i the distance of point i to B grown by 3 pixels (7 at level 2:
//     the larger spacing less one) on the far sides, which holds Q; the box
//     is not tried when a point (a node's box, first) is within 4 pixels;
//   - with G = max_i |z_i - z_c| / rho_i^2 (the LOCAL spread of depth over
//     distance squared, not the region's range) and rho = min rho_i:
//         |sum_near w_i'' (z_i - z_c)| <= p (p + 1) G Dn(xi),
//         |sum_near w_i''|             <= p (p + 1) Dn(xi) / rho^2,
//     Dn(xi) = sum_near w_i(xi), xi in C;
//   - Dn over C from the cell's four samples s: |xi - s| <= reach (h sqrt 2
//     inside, hypot(2h - 1, h) for an extrapolated pixel), so w_i(xi) /
//     w_i(s) = (d_i(s) / d_i(xi))^p <= (1 + reach / rho)^p =: kappa and
//         Dn(xi) <= kappa min_s Dn(s);
//   - the polynomials: with |u|, |v| <= mu = 1 + (reach of Q beyond B) / an
//     on Q, |P_xx| <= sum i (i - 1) |c_ij| mu^(i+j-2) / an^2 (and y with j;
//     Nc's coefficients are cN - (z_c - zref) cD, in double).
// The samples' arithmetic (float sums of K near points, each weight with
// relative error delta_w, as the leaf's check): |dDn| <= (delta_w +
// gamma_K) Dn, |dNn| <= (delta_w + gamma_K + 2u) max|z_i - zref| Dn (Dn the
// true sum, <= computed / (1 - delta_w - gamma_K)); the polynomial's
// gammaPoly sum |c_ij| mu^(i+j) + 1e-11 W (1 + dz) as the leaf's farArith;
// dNc = dN - (z_c - zref) dD; through the interpolation times ax. So per
// pixel, with Dm = kappa min over the cell's samples of Dn:
//     eD = psi_y (p(p+1) Dm / rho^2 + |P_D,yy|) + psi_x (p(p+1) Dm / rho^2 + |P_D,xx|) + ax arithD
//     eN = psi_y (p(p+1) G Dm + |P_Nc,yy|) + psi_x (p(p+1) G Dm + |P_Nc,xx|) + ax arithNc
// and the box is taken when EVERY region pixel of it has
//     eN + |INc / ID| eD + E (1 + 1e-6 + p u) <= (tol - dz (p + 2) u - 16 u) (ID - eD);
// else nothing is kept and the traversal descends as before. A cell without
// extrapolation is checked once for all its pixels (psi <= h^2 / 8 on both
// axes; ID >= its samples' smallest D; |INc / ID| <= its samples' largest
// |Nc / D|, INc / ID being monotone along each axis); a cell that fails
// that, and the extrapolated ones, pixel by pixel. The value is clamped to
// [zmin, zmax] like every pixel (only reduces the error). Boxes whose
// weights could leave float's range (the leaf's tile-scale rule) are not
// tried; nor those whose estimate h^2 / 4 p (p + 1) kappa 2 G is above
// tol / 2 (efficiency only: the bound above decides).
#include "FastNearBox.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>

#include "FastKernel.h"

namespace vv::vss::detail::fast {
namespace {

constexpr double kUnderflow = 1e-40;  // as the leaf: coefficients below float's normal range
constexpr int kG = kLeafTile;         // sample columns (kernel lanes), at most
constexpr int kR = kLeafTile + 1;     // sample rows, at most
constexpr std::size_t kSamples = static_cast<std::size_t>(kR) * kG;
constexpr std::size_t kSquare = static_cast<std::size_t>(kS) * kS;

// Index of sample (row j, column i) in a kR x kG sample array.
constexpr std::size_t sampleIndex(int j, int i) noexcept {
    return static_cast<std::size_t>(j) * kG + static_cast<std::size_t>(i);
}

struct Sample {
    double d = 0.0;     // D
    double nc = 0.0;    // Nc
    double errD = 0.0;  // arithmetic bounds
    double errNc = 0.0;
    double dnHi = 0.0;  // bound of the true near sum Dn
};

/// Interpolation position of pixel offset o (pixels from the grid origin)
/// on a grid of n samples h apart: cell k, fraction t (in [0, 1], up to
/// (2h - 1) / h beyond the last sample), psi = h^2 |t (1 - t)| / 2 and the
/// weights' absolute sum |1 - t| + |t|.
struct Axis {
    int k = 0;
    double t = 0.0;
    double psi = 0.0;
    double wsum = 1.0;
};

Axis axis(int o, int h, int n) {
    Axis a;
    a.k = std::min(o / h, n - 2);
    a.t = static_cast<double>(o - a.k * h) / h;
    a.psi = 0.5 * h * h * std::abs(a.t * (1.0 - a.t));
    a.wsum = std::abs(1.0 - a.t) + std::abs(a.t);
    return a;
}

// Scratch of one thread, reused by every box.
struct Scratch {
    std::vector<float> px, py, pz;  // the near points: offsets from the grid origin
    std::vector<double> rho2i;      // their squared distances to B grown by extMax
    std::vector<Axis> cols;         // the interpolation position of every column
};

Scratch& scratch() {
    thread_local Scratch s;
    return s;
}

// What the gathering of the near points found.
struct NearPoints {
    double rho2 = std::numeric_limits<double>::infinity();  // rho^2: the nearest one's rho2i
    double zc = 0.0;                                        // z_c - zref: its depth
    double zAbs = 0.0;                                      // max |z_i - zref|
};

// The near points (K of them): offsets from the grid origin (pixels), their
// distances to B grown by extMax, the nearest one's depth, max |z - zref|.
NearPoints gatherNearPoints(const Region& rg, const BoxGeo& geo, const std::vector<int>& near,
                            std::size_t nearCount, int extMax, Scratch& sc) {
    sc.px.resize(nearCount);
    sc.py.resize(nearCount);
    sc.pz.resize(nearCount);
    sc.rho2i.resize(nearCount);
    double rho2 = std::numeric_limits<double>::infinity();  // in registers, not through a struct
    double zc = 0.0;
    double zAbs = 0.0;
    std::size_t k = 0;
    for (const int nd : near) {
        const SrcNode& c = rg.tree.nodes[static_cast<std::size_t>(nd)];
        for (int i = c.begin; i < c.end; ++i, ++k) {
            const Point& q = rg.tree.pts[static_cast<std::size_t>(i)];
            sc.px[k] = static_cast<float>(q.x - geo.minx);
            sc.py[k] = static_cast<float>(q.y - geo.miny);
            sc.pz[k] = q.z;
            const double gx = std::max({0, q.x - (geo.maxx + extMax), geo.minx - q.x});
            const double gy = std::max({0, q.y - (geo.maxy + extMax), geo.miny - q.y});
            const double d2 = gx * gx + gy * gy;
            sc.rho2i[k] = d2;
            if (d2 < rho2) {
                rho2 = d2;
                zc = q.z;
            }
            zAbs = std::max(zAbs, std::abs(static_cast<double>(q.z)));
        }
    }
    return {rho2, zc, zAbs};
}

// G of the derivation: max |z_i - z_c| / rho_i^2, with a margin.
double localSpread(const Scratch& sc, std::size_t nearCount, double zc) {
    double spreadG = 0.0;
    for (std::size_t i = 0; i < nearCount; ++i) {
        spreadG = std::max(spreadG, std::abs(static_cast<double>(sc.pz[i]) - zc) / sc.rho2i[i]);
    }
    return spreadG * (1.0 + 1e-12);
}

// kappa = (1 + reach / rho)^p, with a margin.
double kappa(const PowerTables& tab, double rho, double reach) {
    const double r = (rho + reach) / rho;
    return tab.pw(r * r) * (1.0 + 1e-9);
}

// tol less the rounding of an interpolated pixel's value.
double interpolationTolerance(const Region& rg) {
    return rg.tol * (1.0 - 1e-6) - 16.0 * kU - rg.dz * (rg.tab->p + 2.0) * kU * 1.1;
}

// The spacing: the largest of hBig, hBig / 2 whose grid fits one kernel tile
// and whose estimate (the near part at a cell centre) is within tol / 2; 0
// when neither.
int chooseSpacing(const Region& rg, int hBig, int spanX, int spanY, const NearPoints& np,
                  double spreadG) {
    const double p = rg.tab->p;
    const double pp1 = p * (p + 1.0);
    const double rho = std::sqrt(np.rho2);
    const double tolAll = interpolationTolerance(rg);
    for (int hc = hBig; hc >= hBig / 2; hc /= 2) {
        const int cx = (spanX + hc - 1) / hc + 1;
        const int cy = (spanY + hc - 1) / hc + 1;
        // beyond 16 columns the last ones are extrapolated (at most h - 1 pixels)
        if (cx > kG + 1 || cy > kR || np.rho2 < 4.0 * hc * hc) {
            continue;
        }
        if (0.25 * hc * hc * pp1 * kappa(*rg.tab, rho, hc * std::sqrt(2.0)) * 2.0 * spreadG <=
            0.5 * tolAll * rg.budgetScale) {
            return hc;
        }
    }
    return 0;
}

// The grid of samples, h apart, nx x ny of them from (minx, miny).
struct NearGrid {
    int h = 0;
    int nx = 0, ny = 0;
    bool extrapolate = false;  // the pixels beyond the last column are extrapolated
};

// The grid covers B (Q = [minx, minx + h (nx - 1)] x [miny, miny + h (ny - 1)]
// reaches at most h - 1 pixels beyond it) but for 17 columns: then 16, and
// the pixels beyond the last one (< h) are extrapolated. None when it cannot.
std::optional<NearGrid> nearGrid(int h, int spanX, int spanY) {
    NearGrid g;
    g.h = h;
    g.extrapolate = (spanX + h - 1) / h + 1 > kG;
    g.nx = g.extrapolate ? kG : (spanX + h - 1) / h + 1;
    g.ny = (spanY + h - 1) / h + 1;
    if (g.nx < 2 || g.ny < 2 || spanX > h * kG - 1) {  // extrapolated by at most h - 1 pixels
        return std::nullopt;
    }
    return g;
}

// The kernel's sums at the samples, the near points' and the polynomial's
// apart (their z and fail outputs unused).
struct SampleSums {
    std::array<float, kSamples> dn{}, nn{};  // near sums D, N
    std::array<float, kSamples> pd{}, pn{};  // polynomial P_D, P_N (0 without one)
    std::array<float, kSamples> z{};
    std::array<std::uint32_t, kR> fail{};
};

// The near sums at every sample: the points' offsets and S^2 divided by h^2,
// a power of two, so the weights are those of the unscaled pixels, bit for
// bit. Returns the arguments, for the polynomial's call.
LeafKernelArgs sampleNearSums(const Region& rg, const NearGrid& g, std::size_t nearCount,
                              double sScale, Scratch& sc, SampleSums& sums) {
    const float invH = 1.0F / static_cast<float>(g.h);
    for (std::size_t i = 0; i < nearCount; ++i) {
        sc.px[i] *= invH;  // exact: a power of two
        sc.py[i] *= invH;
    }
    LeafKernelArgs a;
    a.rows = g.ny;
    a.rowMask = (1U << g.ny) - 1U;
    a.px = sc.px.data();
    a.py = sc.py.data();
    a.pz = sc.pz.data();
    a.count = static_cast<int>(nearCount);
    a.degree = -1;
    a.zref = static_cast<float>(rg.zref);
    a.zmin = rg.zminOut;
    a.zmax = rg.zmaxOut;
    a.power = rg.kp;
    a.perPixel = false;
    a.s2 = static_cast<float>(sScale * sScale) /
           static_cast<float>(g.h * g.h);  // exact: a power of two
    a.tolRemaining = 1.0F;
    a.errAbs = 0.0F;
    a.sumD = sums.dn.data();
    a.sumN = sums.nn.data();
    leafKernel(a, sums.z.data(), sums.fail.data());
    return a;
}

// The box's local expansion: bounds of P_D, of P_Nc (Nc's coefficients cN -
// (z_c - zref) cD, in double) and of P_N over Q, the float coefficients.
struct NearPoly {
    PolyBounds bD, bNc;
    double sumN = 0.0;  // P_N's bound
    std::array<float, kSquare> fD{}, fN{};
};

// poly from far over |u|, |v| <= mu; false when it would not fit in float.
bool nearPolynomial(const Local& far, const PowerTables& tab, const BoxGeo& geo, double zc,
                    double mu, NearPoly& poly) {
    const int deg = tab.degree;
    std::array<double, kSquare> cD{};
    std::array<double, kSquare> cN{};
    localToPoly(far.d, deg, tab, cD);
    localToPoly(far.n, deg, tab, cN);
    std::array<double, kSquare> cNc{};
    for (std::size_t i = 0; i < cNc.size(); ++i) {
        cNc[i] = cN[i] - zc * cD[i];
        poly.fD[i] = static_cast<float>(cD[i]);
        poly.fN[i] = static_cast<float>(cN[i]);
    }
    poly.bD = polyBounds(cD, deg, geo.an, mu);
    poly.bNc = polyBounds(cNc, deg, geo.an, mu);
    const PolyBounds bN = polyBounds(cN, deg, geo.an, mu);
    poly.sumN = bN.sum;
    return poly.bD.sum + poly.sumN <= 1e30;
}

// The polynomial at every sample: sample (k, j) at (minx + h k, miny + h j),
// u = (h k - (tx - minx)) / an.
void samplePolynomial(const LeafKernelArgs& nearArgs, const NearPoly& poly, const BoxGeo& geo,
                      int h, int degree, SampleSums& sums) {
    const float none = 0.0F;
    LeafKernelArgs b = nearArgs;
    b.px = &none;
    b.py = &none;
    b.pz = &none;
    b.count = 0;
    b.degree = degree;
    b.polyD = poly.fD.data();
    b.polyN = poly.fN.data();
    b.tu = static_cast<float>((geo.tx - geo.minx) / h);
    b.tv = static_cast<float>((geo.ty - geo.miny) / h);
    b.invA = static_cast<float>(h / geo.an);
    b.sumD = sums.pd.data();
    b.sumN = sums.pn.data();
    leafKernel(b, sums.z.data(), sums.fail.data());
}

// The arithmetic error constants of a box (the top of the file).
struct NearTolerances {
    double relNear = 0.0;  // delta_w + gamma_K: relative error of the near sums
    double dArith = 0.0;   // the polynomial's round-off at a sample, in D
    double nArith = 0.0;   // and in N
    double eTrunc = 0.0;   // E (1 + 1e-6 + p u): the truncation
    double tolAll = 0.0;   // tol less the rounding of an interpolated pixel's value
};

NearTolerances nearTolerances(const Region& rg, const LeafBounds& bounds, std::size_t nearCount,
                              bool hasPoly, const NearPoly& poly) {
    const double p = rg.tab->p;
    NearTolerances tl;
    const double gammaK = (static_cast<double>(nearCount) + 8.0) * kU * 1.01;
    tl.relNear = rg.deltaW + gammaK;
    const double gammaPoly = (3.0 * rg.tab->degree + 12.0) * kU * 1.01;
    tl.dArith = hasPoly ? gammaPoly * poly.bD.sum + 1e-11 * bounds.W + kUnderflow : 0.0;
    tl.nArith =
        hasPoly ? gammaPoly * poly.sumN + 1e-11 * bounds.W * (1.0 + rg.dz) + kUnderflow : 0.0;
    tl.eTrunc = bounds.E * (1.0 + 1e-6 + p * kU) + kUnderflow;
    tl.tolAll = interpolationTolerance(rg);
    return tl;
}

// Every sample's D, Nc and their arithmetic bounds.
void fillSamples(const SampleSums& sums, const NearGrid& g, const NearTolerances& tl,
                 const NearPoints& np, std::array<Sample, kSamples>& smp) {
    const double zc = np.zc;
    const double zcAbs = std::abs(zc);
    for (int j = 0; j < g.ny; ++j) {
        for (int i = 0; i < g.nx; ++i) {
            const auto s = sampleIndex(j, i);
            const double dnv = sums.dn[s];
            const double pdv = sums.pd[s];
            const double d = dnv + pdv;
            const double n = static_cast<double>(sums.nn[s]) + sums.pn[s];
            const double dnHi = dnv / (1.0 - tl.relNear);
            const double errD = tl.relNear * dnHi + tl.dArith + 1e-15 * (dnv + std::abs(pdv));
            const double errN =
                (tl.relNear + 2.0 * kU) * np.zAbs * dnHi + tl.nArith + 1e-15 * std::abs(n);
            Sample& o = smp[s];
            o.d = d;
            o.nc = n - zc * d;
            o.errD = errD;
            o.errNc = errN + zcAbs * errD + 1e-15 * (std::abs(n) + zcAbs * std::abs(d));
            o.dnHi = dnHi;
        }
    }
}

// What every cell's bound uses besides its samples and the tolerances.
struct CellTerms {
    double pp1 = 0.0;      // p (p + 1)
    double rho2 = 0.0;     // rho^2
    double spreadG = 0.0;  // G
    double kap = 0.0;      // kappa of a cell's pixels
    double kapOut = 0.0;   // kappa of an extrapolated pixel
    PolyBounds bD, bNc;    // P_D, P_Nc over Q
};

// The terms for spacing h: Dn over a cell from its samples grows by at most
// kappa (1 + reach / rho)^p, the reach h sqrt 2 inside, hypot(2h - 1, h) for
// an extrapolated pixel.
CellTerms cellTerms(const PowerTables& tab, const NearPoints& np, double spreadG, int h,
                    const NearPoly& poly) {
    const double rho = std::sqrt(np.rho2);
    CellTerms ct;
    ct.pp1 = tab.p * (tab.p + 1.0);
    ct.rho2 = np.rho2;
    ct.spreadG = spreadG;
    ct.kap = kappa(tab, rho, h * std::sqrt(2.0));
    ct.kapOut = kappa(tab, rho, std::hypot(2.0 * h - 1.0, static_cast<double>(h)));
    ct.bD = poly.bD;
    ct.bNc = poly.bNc;
    return ct;
}

// One cell's second-derivative factors and largest arithmetic bounds; ok
// when the whole cell passes.
struct CellBound {
    double aD = 0.0, aN = 0.0, errD = 0.0, errNc = 0.0;
    bool ok = false;
};

// Per cell: the second-derivative factors, the largest arithmetic bounds,
// and the check of the whole cell at once (psi <= h^2 / 8 on both axes,
// convex weights: ID >= the smallest D of its samples, and |INc / ID| <=
// the largest |Nc / D| of its samples, INc / ID being monotone along each
// axis); a cell that fails is checked pixel by pixel.
void cellBounds(const std::array<Sample, kSamples>& smp, const NearGrid& g, const CellTerms& ct,
                const NearTolerances& tl, std::array<CellBound, kSamples>& cell) {
    const double psiIn = g.h * g.h / 8.0;
    for (int j = 0; j + 1 < g.ny; ++j) {
        for (int i = 0; i + 1 < g.nx; ++i) {
            const Sample& s00 = smp[sampleIndex(j, i)];
            const Sample& s10 = smp[sampleIndex(j, i + 1)];
            const Sample& s01 = smp[sampleIndex(j + 1, i)];
            const Sample& s11 = smp[sampleIndex(j + 1, i + 1)];
            const bool edge = g.extrapolate && i + 2 == g.nx;  // checked pixel by pixel
            const double dm =
                (edge ? ct.kapOut : ct.kap) * std::min({s00.dnHi, s10.dnHi, s01.dnHi, s11.dnHi});
            CellBound& c = cell[sampleIndex(j, i)];
            c.aD = ct.pp1 * dm / ct.rho2;
            c.aN = ct.pp1 * ct.spreadG * dm;
            c.errD = std::max({s00.errD, s10.errD, s01.errD, s11.errD});
            c.errNc = std::max({s00.errNc, s10.errNc, s01.errNc, s11.errNc});
            const double dMin = std::min({s00.d, s10.d, s01.d, s11.d});
            const double fMax = std::max({std::abs(s00.nc / s00.d), std::abs(s10.nc / s10.d),
                                          std::abs(s01.nc / s01.d), std::abs(s11.nc / s11.d)});
            const double eD = psiIn * (2.0 * c.aD + ct.bD.dyy + ct.bD.dxx) + c.errD;
            const double eN = psiIn * (2.0 * c.aN + ct.bNc.dyy + ct.bNc.dxx) + c.errNc;
            c.ok =
                !edge && dMin - eD > 0.0 && eN + fMax * eD + tl.eTrunc <= tl.tolAll * (dMin - eD);
        }
    }
}

// The bound of one pixel of a cell that did not pass as a whole:
// (eN + |fc| eD + E') / (iD - eD) <= tolAll, without the division.
bool pixelPasses(const CellBound& c, const Axis& ax, const Axis& ay, double iD, double fc,
                 const CellTerms& ct, const NearTolerances& tl) {
    // ay.t <= 1: Iy's weights are convex; ax.wsum > 1 when extrapolated
    const double eD = ay.psi * (c.aD + ct.bD.dyy) + ax.psi * (c.aD + ct.bD.dxx) + ax.wsum * c.errD;
    const double eN =
        ay.psi * (c.aN + ct.bNc.dyy) + ax.psi * (c.aN + ct.bNc.dxx) + ax.wsum * c.errNc;
    return iD - eD > 0.0 && eN + std::abs(fc) * eD + tl.eTrunc <= tl.tolAll * (iD - eD);
}

// The interpolated samples and their cells' bounds.
struct NearSamples {
    std::array<Sample, kSamples> smp;
    std::array<CellBound, kSamples> cell;
};

// Every region pixel: the bound (where its cell did not pass as a whole),
// then the value. Returns the pixels written, 0 when one fails.
std::int64_t writePixels(const Region& rg, const BoxGeo& geo, const NearGrid& g,
                         const NearSamples& ns, const CellTerms& ct, const NearTolerances& tl,
                         double zc, Scratch& sc) {
    const int width = geo.maxx - geo.minx + 1;
    sc.cols.resize(static_cast<std::size_t>(width));
    for (int i = 0; i < width; ++i) {
        sc.cols[static_cast<std::size_t>(i)] = axis(i, g.h, g.nx);
    }
    const double zOut = rg.zref + zc;
    std::int64_t pixels = 0;
    std::array<double, kG> rowD{};
    std::array<double, kG> rowN{};
    for (int y = geo.miny; y <= geo.maxy; ++y) {
        const Axis ay = axis(y - geo.miny, g.h, g.ny);
        const std::int32_t* lab = rg.labels.row(y) + geo.minx;
        float* o = rg.out.row(y) + geo.minx;
        const Sample* r0 = &ns.smp[sampleIndex(ay.k, 0)];
        const Sample* r1 = r0 + kG;
        const CellBound* cr = &ns.cell[sampleIndex(ay.k, 0)];
        for (int c = 0; c < g.nx; ++c) {
            rowD[static_cast<std::size_t>(c)] = r0[c].d + ay.t * (r1[c].d - r0[c].d);
            rowN[static_cast<std::size_t>(c)] = r0[c].nc + ay.t * (r1[c].nc - r0[c].nc);
        }
        for (int i = 0; i < width; ++i) {
            if (lab[i] != rg.id) {
                continue;
            }
            const Axis& ax = sc.cols[static_cast<std::size_t>(i)];
            const auto kx = static_cast<std::size_t>(ax.k);
            const double iD = rowD[kx] + ax.t * (rowD[kx + 1] - rowD[kx]);
            const double iN = rowN[kx] + ax.t * (rowN[kx + 1] - rowN[kx]);
            const double fc = iN / iD;
            if (!cr[kx].ok && !pixelPasses(cr[kx], ax, ay, iD, fc, ct, tl)) {
                return 0;
            }
            o[i] = std::clamp(static_cast<float>(zOut + fc), rg.zminOut, rg.zmaxOut);
            ++pixels;
        }
    }
    return pixels;
}

}  // namespace

bool nearBoxHasRoom(const Region& rg, const BoxGeo& geo, int level, const std::vector<int>& nodes) {
    const int extMax = (level == 1 ? 4 : 8) - 1;  // as evalNearBox
    // a node whose box comes within 4 pixels: no room (checked again per point in evalNearBox)
    return std::ranges::all_of(nodes, [&](int nd) {
        const SrcNode& c = rg.tree.nodes[static_cast<std::size_t>(nd)];
        const int gx = std::max({0, c.bx0 - (geo.maxx + extMax), geo.minx - c.bx1});
        const int gy = std::max({0, c.by0 - (geo.maxy + extMax), geo.miny - c.by1});
        return gx * gx + gy * gy >= 16;
    });
}

std::int64_t evalNearBox(const Region& rg, const BoxGeo& geo, int level,
                         const std::vector<int>& near, const Local* far, const LeafBounds& bounds) {
    const PowerTables& tab = *rg.tab;
    const int spanX = geo.maxx - geo.minx;
    const int spanY = geo.maxy - geo.miny;
    // Sample spacings tried, largest first: level 1 (32 pixels) 4, 2; level 2 8, 4.
    const int hBig = level == 1 ? 4 : 8;
    const int extMax = hBig - 1;  // Q of either spacing lies in B grown by this
    if (!nearBoxHasRoom(rg, geo, level, near)) {
        return 0;
    }
    const std::size_t nearCount = pointCount(rg.tree, near);  // K of the derivation above
    Scratch& sc = scratch();
    const NearPoints np = gatherNearPoints(rg, geo, near, nearCount, extMax, sc);
    if (nearCount == 0 || !(np.rho2 >= 16.0)) {
        return 0;
    }
    const double rho = std::sqrt(np.rho2);
    const double spreadG = localSpread(sc, nearCount, np.zc);
    const int h = chooseSpacing(rg, hBig, spanX, spanY, np, spreadG);
    const std::optional<NearGrid> grid = h == 0 ? std::nullopt : nearGrid(h, spanX, spanY);
    if (!grid) {
        return 0;
    }
    const NearGrid& g = *grid;
    const double diagQ =
        std::hypot(static_cast<double>(h * (g.nx - 1)), static_cast<double>(h * (g.ny - 1)));
    if (tab.p * std::log2((rho + diagQ + 1.0) / bounds.S) > 60.0) {
        return 0;  // the leaf's tile-scale rule: weights stay in float's range
    }
    // |u|, |v| <= mu on Q (the polynomial's bounds beyond B)
    const double ext = std::max({0, h * (g.nx - 1) - spanX, h * (g.ny - 1) - spanY});
    const double mu = 1.0 + ext / geo.an * (1.0 + 1e-12);

    // Samples: the near sums and the polynomial separately.
    SampleSums sums;
    const LeafKernelArgs nearArgs = sampleNearSums(rg, g, nearCount, bounds.S, sc, sums);
    NearPoly poly;
    if (far != nullptr) {
        if (!nearPolynomial(*far, tab, geo, np.zc, mu, poly)) {
            return 0;  // would not fit in float
        }
        samplePolynomial(nearArgs, poly, geo, h, tab.degree, sums);
    }
    const NearTolerances tl = nearTolerances(rg, bounds, nearCount, far != nullptr, poly);
    const CellTerms ct = cellTerms(tab, np, spreadG, h, poly);

    NearSamples ns;
    fillSamples(sums, g, tl, np, ns.smp);
    cellBounds(ns.smp, g, ct, tl, ns.cell);
    return writePixels(rg, geo, g, ns, ct, tl, np.zc, sc);
}

}  // namespace vv::vss::detail::fast
