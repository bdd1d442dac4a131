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
    const double p = tab.p;
    const double pp1 = p * (p + 1.0);
    const double sScale = bounds.S;  // S of the derivation above
    // The near points: offsets from the grid origin (pixels), their
    // distances to B grown by extMax, the nearest one's depth, max |z - zref|.
    if (!nearBoxHasRoom(rg, geo, level, near)) {
        return 0;
    }
    std::size_t nearCount = 0;  // K of the derivation above
    for (const int nd : near) {
        nearCount += static_cast<std::size_t>(rg.tree.nodes[static_cast<std::size_t>(nd)].count());
    }
    thread_local std::vector<float> px;  // scratch, reused by every box of this thread
    thread_local std::vector<float> py;
    thread_local std::vector<float> pz;
    thread_local std::vector<double> rho2i;
    px.resize(nearCount);
    py.resize(nearCount);
    pz.resize(nearCount);
    rho2i.resize(nearCount);
    double rho2 = std::numeric_limits<double>::infinity();
    double zc = 0.0;  // z_c - zref
    double zAbs = 0.0;
    std::size_t k = 0;
    for (const int nd : near) {
        const SrcNode& c = rg.tree.nodes[static_cast<std::size_t>(nd)];
        for (int i = c.begin; i < c.end; ++i, ++k) {
            const Point& q = rg.tree.pts[static_cast<std::size_t>(i)];
            px[k] = static_cast<float>(q.x - geo.minx);
            py[k] = static_cast<float>(q.y - geo.miny);
            pz[k] = q.z;
            const double gx = std::max({0, q.x - (geo.maxx + extMax), geo.minx - q.x});
            const double gy = std::max({0, q.y - (geo.maxy + extMax), geo.miny - q.y});
            const double d2 = gx * gx + gy * gy;
            rho2i[k] = d2;
            if (d2 < rho2) {
                rho2 = d2;
                zc = q.z;
            }
            zAbs = std::max(zAbs, std::abs(static_cast<double>(q.z)));
        }
    }
    if (nearCount == 0 || !(rho2 >= 16.0)) {
        return 0;
    }
    const double rho = std::sqrt(rho2);
    double spreadG = 0.0;  // G above: max |z_i - z_c| / rho_i^2
    for (std::size_t i = 0; i < nearCount; ++i) {
        spreadG = std::max(spreadG, std::abs(static_cast<double>(pz[i]) - zc) / rho2i[i]);
    }
    spreadG *= 1.0 + 1e-12;
    const double tolAll = rg.tol * (1.0 - 1e-6) - 16.0 * kU - rg.dz * (p + 2.0) * kU * 1.1;
    const auto kappa = [&](double reach) {
        const double r = (rho + reach) / rho;
        return tab.pw(r * r) * (1.0 + 1e-9);
    };
    // The spacing: the largest whose grid fits one kernel tile and whose
    // estimate (the near part at a cell centre) is within tol / 2.
    int h = 0;
    for (int hc = hBig; hc >= hBig / 2; hc /= 2) {
        const int cx = (spanX + hc - 1) / hc + 1;
        const int cy = (spanY + hc - 1) / hc + 1;
        // beyond 16 columns the last ones are extrapolated (at most h - 1 pixels)
        if (cx > kG + 1 || cy > kR || rho2 < 4.0 * hc * hc) {
            continue;
        }
        if (0.25 * hc * hc * pp1 * kappa(hc * std::sqrt(2.0)) * 2.0 * spreadG <=
            0.5 * tolAll * rg.budgetScale) {
            h = hc;
            break;
        }
    }
    if (h == 0) {
        return 0;
    }
    // The grid covers B (Q = [minx, minx + h (nx - 1)] x [miny, miny + h (ny - 1)]
    // reaches at most h - 1 pixels beyond it) but for 17 columns: then 16,
    // and the pixels beyond the last one (< h) are extrapolated.
    const bool extrapolate = (spanX + h - 1) / h + 1 > kG;
    const int nx = extrapolate ? kG : (spanX + h - 1) / h + 1;
    const int ny = (spanY + h - 1) / h + 1;
    if (nx < 2 || ny < 2 || spanX > h * kG - 1) {  // extrapolated by at most h - 1 pixels
        return 0;
    }
    const double diagQ =
        std::hypot(static_cast<double>(h * (nx - 1)), static_cast<double>(h * (ny - 1)));
    if (p * std::log2((rho + diagQ + 1.0) / sScale) > 60.0) {
        return 0;  // the leaf's tile-scale rule: weights stay in float's range
    }
    const double kap = kappa(h * std::sqrt(2.0));
    const double kapOut = kappa(std::hypot(2.0 * h - 1.0, static_cast<double>(h)));
    // |u|, |v| <= mu on Q (the polynomial's bounds beyond B)
    const double ext = std::max({0, h * (nx - 1) - spanX, h * (ny - 1) - spanY});
    const double mu = 1.0 + ext / geo.an * (1.0 + 1e-12);
    const float invH = 1.0F / static_cast<float>(h);
    for (std::size_t i = 0; i < nearCount; ++i) {
        px[i] *= invH;  // exact: a power of two
        py[i] *= invH;
    }

    // Samples: the near sums and the polynomial separately.
    std::array<float, kSamples> dn{};
    std::array<float, kSamples> nn{};
    std::array<float, kSamples> pd{};
    std::array<float, kSamples> pn{};
    std::array<float, kSamples> zs{};
    std::array<std::uint32_t, kR> fs{};
    LeafKernelArgs a;
    a.rows = ny;
    a.rowMask = (1U << ny) - 1U;
    a.px = px.data();
    a.py = py.data();
    a.pz = pz.data();
    a.count = static_cast<int>(nearCount);
    a.degree = -1;
    a.zref = static_cast<float>(rg.zref);
    a.zmin = rg.zminOut;
    a.zmax = rg.zmaxOut;
    a.power = rg.kp;
    a.perPixel = false;
    a.s2 =
        static_cast<float>(sScale * sScale) / static_cast<float>(h * h);  // exact: a power of two
    a.tolRemaining = 1.0F;
    a.errAbs = 0.0F;
    a.sumD = dn.data();
    a.sumN = nn.data();
    leafKernel(a, zs.data(), fs.data());
    const bool hasPoly = far != nullptr;
    const int deg = tab.degree;
    PolyBounds bD;
    PolyBounds bNc;
    double sumN = 0.0;
    if (hasPoly) {
        std::array<double, kSquare> cD{};
        std::array<double, kSquare> cN{};
        localToPoly(far->d, deg, tab, cD);
        localToPoly(far->n, deg, tab, cN);
        std::array<double, kSquare> cNc{};
        std::array<float, kSquare> fD{};
        std::array<float, kSquare> fN{};
        for (std::size_t i = 0; i < cNc.size(); ++i) {
            cNc[i] = cN[i] - zc * cD[i];
            fD[i] = static_cast<float>(cD[i]);
            fN[i] = static_cast<float>(cN[i]);
        }
        bD = polyBounds(cD, deg, geo.an, mu);
        bNc = polyBounds(cNc, deg, geo.an, mu);
        const PolyBounds bN = polyBounds(cN, deg, geo.an, mu);
        sumN = bN.sum;
        if (!(bD.sum + sumN <= 1e30)) {
            return 0;  // would not fit in float
        }
        const float none = 0.0F;
        LeafKernelArgs b = a;
        b.px = &none;
        b.py = &none;
        b.pz = &none;
        b.count = 0;
        b.degree = deg;
        b.polyD = fD.data();
        b.polyN = fN.data();
        // sample (k, j) at (minx + h k, miny + h j): u = (h k - (tx - minx)) / an
        b.tu = static_cast<float>((geo.tx - geo.minx) / h);
        b.tv = static_cast<float>((geo.ty - geo.miny) / h);
        b.invA = static_cast<float>(h / geo.an);
        b.sumD = pd.data();
        b.sumN = pn.data();
        leafKernel(b, zs.data(), fs.data());
    }
    const double gammaK = (static_cast<double>(nearCount) + 8.0) * kU * 1.01;
    const double relNear = rg.deltaW + gammaK;
    const double gammaPoly = (3.0 * deg + 12.0) * kU * 1.01;
    const double dArith = hasPoly ? gammaPoly * bD.sum + 1e-11 * bounds.W + kUnderflow : 0.0;
    const double nArith =
        hasPoly ? gammaPoly * sumN + 1e-11 * bounds.W * (1.0 + rg.dz) + kUnderflow : 0.0;
    const double eTrunc = bounds.E * (1.0 + 1e-6 + p * kU) + kUnderflow;
    const double zcAbs = std::abs(zc);

    std::array<Sample, kSamples> smp;
    for (int j = 0; j < ny; ++j) {
        for (int i = 0; i < nx; ++i) {
            const auto s = sampleIndex(j, i);
            const double dnv = dn[s];
            const double pdv = pd[s];
            const double d = dnv + pdv;
            const double n = static_cast<double>(nn[s]) + pn[s];
            const double dnHi = dnv / (1.0 - relNear);
            const double errD = relNear * dnHi + dArith + 1e-15 * (dnv + std::abs(pdv));
            const double errN = (relNear + 2.0 * kU) * zAbs * dnHi + nArith + 1e-15 * std::abs(n);
            Sample& o = smp[s];
            o.d = d;
            o.nc = n - zc * d;
            o.errD = errD;
            o.errNc = errN + zcAbs * errD + 1e-15 * (std::abs(n) + zcAbs * std::abs(d));
            o.dnHi = dnHi;
        }
    }
    // Per cell: the second-derivative factors, the largest arithmetic bounds,
    // and the check of the whole cell at once (psi <= h^2 / 8 on both axes,
    // convex weights: ID >= the smallest D of its samples, and |INc / ID| <=
    // the largest |Nc / D| of its samples, INc / ID being monotone along each
    // axis); a cell that fails is checked pixel by pixel.
    struct Cell {
        double aD = 0.0, aN = 0.0, errD = 0.0, errNc = 0.0;
        bool ok = false;
    };
    std::array<Cell, kSamples> cell;
    const double psiIn = h * h / 8.0;
    for (int j = 0; j + 1 < ny; ++j) {
        for (int i = 0; i + 1 < nx; ++i) {
            const Sample& s00 = smp[sampleIndex(j, i)];
            const Sample& s10 = smp[sampleIndex(j, i + 1)];
            const Sample& s01 = smp[sampleIndex(j + 1, i)];
            const Sample& s11 = smp[sampleIndex(j + 1, i + 1)];
            const bool edge = extrapolate && i + 2 == nx;  // checked pixel by pixel
            const double dm =
                (edge ? kapOut : kap) * std::min({s00.dnHi, s10.dnHi, s01.dnHi, s11.dnHi});
            Cell& c = cell[sampleIndex(j, i)];
            c.aD = pp1 * dm / rho2;
            c.aN = pp1 * spreadG * dm;
            c.errD = std::max({s00.errD, s10.errD, s01.errD, s11.errD});
            c.errNc = std::max({s00.errNc, s10.errNc, s01.errNc, s11.errNc});
            const double dMin = std::min({s00.d, s10.d, s01.d, s11.d});
            const double fMax = std::max({std::abs(s00.nc / s00.d), std::abs(s10.nc / s10.d),
                                          std::abs(s01.nc / s01.d), std::abs(s11.nc / s11.d)});
            const double eD = psiIn * (2.0 * c.aD + bD.dyy + bD.dxx) + c.errD;
            const double eN = psiIn * (2.0 * c.aN + bNc.dyy + bNc.dxx) + c.errNc;
            c.ok = !edge && dMin - eD > 0.0 && eN + fMax * eD + eTrunc <= tolAll * (dMin - eD);
        }
    }

    // Every region pixel: the bound (where its cell did not pass as a
    // whole), then the value.
    const int width = spanX + 1;
    thread_local std::vector<Axis> cols;
    cols.resize(static_cast<std::size_t>(width));
    for (int i = 0; i < width; ++i) {
        cols[static_cast<std::size_t>(i)] = axis(i, h, nx);
    }
    const double zOut = rg.zref + zc;
    std::int64_t pixels = 0;
    std::array<double, kG> rowD{};
    std::array<double, kG> rowN{};
    for (int y = geo.miny; y <= geo.maxy; ++y) {
        const Axis ay = axis(y - geo.miny, h, ny);
        const std::int32_t* lab = rg.labels.row(y) + geo.minx;
        float* o = rg.out.row(y) + geo.minx;
        const Sample* r0 = &smp[sampleIndex(ay.k, 0)];
        const Sample* r1 = r0 + kG;
        const Cell* cr = &cell[sampleIndex(ay.k, 0)];
        for (int c = 0; c < nx; ++c) {
            rowD[static_cast<std::size_t>(c)] = r0[c].d + ay.t * (r1[c].d - r0[c].d);
            rowN[static_cast<std::size_t>(c)] = r0[c].nc + ay.t * (r1[c].nc - r0[c].nc);
        }
        for (int i = 0; i < width; ++i) {
            if (lab[i] != rg.id) {
                continue;
            }
            const Axis& ax = cols[static_cast<std::size_t>(i)];
            const auto kx = static_cast<std::size_t>(ax.k);
            const double iD = rowD[kx] + ax.t * (rowD[kx + 1] - rowD[kx]);
            const double iN = rowN[kx] + ax.t * (rowN[kx + 1] - rowN[kx]);
            const double fc = iN / iD;
            const Cell& c = cr[kx];
            if (!c.ok) {
                // ay.t <= 1: Iy's weights are convex; ax.wsum > 1 when extrapolated
                const double eD =
                    ay.psi * (c.aD + bD.dyy) + ax.psi * (c.aD + bD.dxx) + ax.wsum * c.errD;
                const double eN =
                    ay.psi * (c.aN + bNc.dyy) + ax.psi * (c.aN + bNc.dxx) + ax.wsum * c.errNc;
                // (eN + |fc| eD + E') / (iD - eD) <= tolAll, without the division
                if (!(iD - eD > 0.0) || !(eN + std::abs(fc) * eD + eTrunc <= tolAll * (iD - eD))) {
                    return 0;
                }
            }
            o[i] = std::clamp(static_cast<float>(zOut + fc), rg.zminOut, rg.zmaxOut);
            ++pixels;
        }
    }
    return pixels;
}

}  // namespace vv::vss::detail::fast
