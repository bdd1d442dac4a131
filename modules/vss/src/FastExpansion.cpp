// SPDX-License-Identifier: GPL-3.0-or-later
// The fast VSS solver's local expansions (FastExpansion.h): L2L, M2L and the
// polynomial form for the leaf kernel.
#include "FastExpansion.h"

#include <array>
#include <cmath>
#include <cstddef>

namespace vv::vss::detail::fast {

// Shift (exactly) a local expansion from centre/scale (t0, a0) to (t1, a1).
__attribute__((target_clones("arch=x86-64-v3", "default"))) void shiftLocal(
    const Local& src, Local& loc, int deg, const PowerTables& tab, double t0x, double t0y,
    double a0, double t1x, double t1y, double a1, double f) {
    const double alpha = a1 / a0;
    const Cx beta{(t1x - t0x) / a0, (t1y - t0y) / a0};
    // coef[l][j] = binom(l,j) alpha^j beta^(l-j), shared by D and N and both passes
    std::array<Cx, kS * kS> coef;
    tab.shiftCoefficients(alpha, beta, deg, coef);
    // t[j][l'] = sum_{l>=j} coef[l][j] L[l][l'];  L'[j][j'] = sum_{l'>=j'} conj(coef[l'][j'])
    // t[j][l'] with D and N side by side in V4
    std::array<V4, kS * kS> in;
    for (int l = 0; l <= deg; ++l) {
        for (int lp = 0; l + lp <= deg; ++lp) {
            const Cx d = src.d[l * kS + lp];
            const Cx n = src.n[l * kS + lp];
            in[l * kS + lp] = V4{d.re, d.im, n.re, n.im};
        }
    }
    std::array<V4, kS * kS> t;  // written and read for j + l' <= deg only
    for (int lp = 0; lp <= deg; ++lp) {
        for (int j = 0; j + lp <= deg; ++j) {
            V4 acc{0.0, 0.0, 0.0, 0.0};
            for (int l = j; l + lp <= deg; ++l) {
                cmulAdd4(acc, in[l * kS + lp], coef[l * kS + j]);
            }
            t[j * kS + lp] = acc;
        }
    }
    for (int j = 0; j <= deg; ++j) {
        for (int jp = 0; j + jp <= deg; ++jp) {
            V4 acc{0.0, 0.0, 0.0, 0.0};
            for (int lp = jp; j + lp <= deg; ++lp) {
                cmulAdd4(acc, t[j * kS + lp], conj(coef[lp * kS + jp]));
            }
            acc *= f;
            loc.d[j * kS + jp] = Cx{acc[0], acc[1]};
            loc.n[j * kS + jp] = Cx{acc[2], acc[3]};
        }
    }
}

// Multipole-to-local of source node C into the local expansion at (t, a), truncated
// at total degree mo in (zeta, v), times wR = (S/R)^p.
__attribute__((target_clones("arch=x86-64-v3", "default"))) void m2l(
    Local& loc, int mo, const PowerTables& tab, const MomentLayout& lay, const Cx* mD, const Cx* mN,
    const SrcNode& C, double tx, double ty, double a, double R, double wR) {
    const double wx = tx - C.cx;
    const double wy = ty - C.cy;
    const Cx er{wx / R, -wy / R};  // e^{-i theta}
    std::array<Cx, 2 * kS> rot{};  // rot[k] = e^{-i k theta}
    rot[0] = {1.0, 0.0};
    for (int k = 1; k <= mo; ++k) {
        rot[k] = rot[k - 1] * er;
    }
    const double ra = a / R;
    const double rs = C.sn / R;
    std::array<double, kS> pa{};
    std::array<double, kS> ps{};
    pa[0] = 1.0;
    ps[0] = 1.0;
    for (int k = 1; k <= mo; ++k) {
        pa[k] = pa[k - 1] * ra;
        ps[k] = ps[k - 1] * rs;
    }
    // g[l][r] = h[l][r] (a/R)^l (sn/R)^r, read for l + r <= mo only (hot: a
    // fill of g and pre below costs what keeping pre small gains)
    std::array<std::array<double, kS>, kS> g;  // NOLINT(cppcoreguidelines-pro-type-member-init)
    for (int l = 0; l <= mo; ++l) {
        for (int r = 0; l + r <= mo; ++r) {
            g[l][r] = tab.h[l][r] * pa[l] * ps[r];
        }
    }
    // rotated full moments Mt[r][r'] = M[r][r'] e^{-i(r-r')theta}, D and N side
    // by side as [D.re, D.im, N.re, N.im] (g is real: one 4-wide FMA per term)
    std::array<V4, kS * kS> mt;  // entries with r + r' <= mo are all written (hot: no fill)
    for (int r = 0; r <= mo; ++r) {
        for (int rp = 0; rp <= r && r + rp <= mo; ++rp) {
            const int ix = lay.idx[r][rp];
            V4 v;
            cmul4(v, V4{mD[ix].re, mD[ix].im, mN[ix].re, mN[ix].im}, rot[r - rp]);
            mt[r * kS + rp] = v;
            mt[rp * kS + r] = v * V4{1.0, -1.0, 1.0, -1.0};
        }
    }
    // Per l: the prefix sums P[r'][j] = sum_{r<=j} g[l][r] Mt[r][r'] (only the
    // prefixes used are written), then the sums over r' that use them. One l's
    // P at a time (5 KB) stays in the first-level cache; all of them at once
    // (70 KB) did not: 11-15 % of the time of a translation (m = 6, 10).
    // NOLINTNEXTLINE(cppcoreguidelines-pro-type-member-init): written before read
    std::array<V4, static_cast<std::size_t>(kS) * kS> pre;
    for (int l = 0; l <= mo; ++l) {
        for (int rp = 0; l + rp <= mo; ++rp) {
            V4 acc{0.0, 0.0, 0.0, 0.0};
            for (int r = 0; l + rp + r <= mo; ++r) {
                acc += g[l][r] * mt[r * kS + rp];
                pre[static_cast<std::size_t>(rp) * kS + static_cast<std::size_t>(r)] = acc;
            }
        }
        for (int lp = 0; lp <= l && l + lp <= mo; ++lp) {
            V4 acc{0.0, 0.0, 0.0, 0.0};
            for (int rp = 0; l + lp + rp <= mo; ++rp) {
                const auto j = static_cast<std::size_t>(mo - l - lp - rp);
                acc += g[lp][rp] * pre[static_cast<std::size_t>(rp) * kS + j];
            }
            V4 v;
            cmul4(v, acc, rot[l - lp]);
            v *= wR;
            loc.d[l * kS + lp] += Cx{v[0], v[1]};
            loc.n[l * kS + lp] += Cx{v[2], v[3]};
            if (lp != l) {
                loc.d[lp * kS + l] += Cx{v[0], -v[1]};
                loc.n[lp * kS + l] += Cx{v[2], -v[3]};
            }
        }
    }
}

// Real polynomial sum c[i][j] u^i v^j of F(u + iv) (u, v in units of a):
// F = sum_{l,l'} L[l][l'] (u+iv)^l (u-iv)^l', real, so the l < l' half is the
// conjugate of the l > l' half: F = sum_{l>=l'} (l == l' ? 1 : 2) Re(L (u+iv)^l (u-iv)^l').
void localToPoly(const Square& L, int deg, const PowerTables& tab, std::array<double, kS * kS>& c) {
    c.fill(0.0);
    for (int l = 0; l <= deg; ++l) {
        for (int lp = 0; lp <= l && l + lp <= deg; ++lp) {
            const Cx Lv = (l == lp ? 1.0 : 2.0) * L[l * kS + lp];
            const Cx* pc = &tab.poly[static_cast<std::size_t>((l * kS + lp) * kS)];
            const int n = l + lp;
            for (int a = 0; a <= n; ++a) {
                c[(n - a) * kS + a] += Lv.re * pc[a].re - Lv.im * pc[a].im;
            }
        }
    }
}

PolyBounds polyBounds(const std::array<double, kS * kS>& c, int deg, double an, double mu) {
    PolyBounds b;
    std::array<double, kS + 2> mp{};  // mp[n + 2] = mu^n, mp[0], mp[1] unused (times 0)
    mp[2] = 1.0;
    for (std::size_t n = 3; n < mp.size(); ++n) {
        mp[n] = mp[n - 1] * mu * (1.0 + 1e-15);
    }
    for (int i = 0; i <= deg; ++i) {
        for (int j = 0; i + j <= deg; ++j) {
            const double a = std::abs(c[(static_cast<std::size_t>(i) * kS) + j]);
            const auto n = static_cast<std::size_t>(i + j);
            b.sum += a * mp[n + 2];
            b.dx += i * a * mp[n + 1];
            b.dy += j * a * mp[n + 1];
            b.dxx += i * (i - 1) * a * mp[n];
            b.dyy += j * (j - 1) * a * mp[n];
        }
    }
    b.dx /= an;
    b.dy /= an;
    b.dxx /= an * an;
    b.dyy /= an * an;
    return b;
}

}  // namespace vv::vss::detail::fast
