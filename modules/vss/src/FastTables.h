// SPDX-License-Identifier: GPL-3.0-or-later
// Private to the fast VSS solver: the constants its parts share and the tables
// that depend on the power p only (built once per solver): the remainder
// series of the error bound, the M2L / L2L coefficients, the polynomial
// expansion of the local expansions, and the weight w = ratio2^(p/2).
#pragma once

#include <array>
#include <memory>
#include <vector>

#include "FastKernel.h"
#include "FastMath.h"

namespace vv::vss::detail::fast {

inline constexpr int kM = kMaxPolyDegree;  ///< highest expansion degree
inline constexpr int kS = kM + 1;          ///< stride of square coefficient arrays
inline constexpr double kU = 0x1p-24;      ///< unit round-off of float
inline constexpr int kMaxTerms = 512;      ///< terms of the remainder series we tabulate

/// Tables for one power p > 0 (finite; the solver checks it). Immutable after
/// construction: shared by every thread of a solve. pw() and chooseOrder()
/// are called per cluster and per point: they stay inline here.
struct PowerTables {
    double p = 2.0;
    double halfP = 1.0;
    int degree = kM;                             // local expansion degree used
    std::vector<double> c;                       // c_n = (p)_n / n!: coefficients of (1-q)^-p
    std::vector<double> ratio;                   // max(1, (p+n)/(n+1)) >= t[n+1]/(q t[n])
    std::array<std::array<double, kS>, kS> h{};  // h[l][r] = (-1)^l (p/2)_{l+r} / (l! r!)
    std::array<std::array<double, kS>, kS> binom{};
    // poly[(l * kS + l') * kS + a]: (u+iv)^l (u-iv)^l' = sum_a coefficient * u^(l+l'-a) v^a
    // (complex, for l + l' <= kM)
    std::vector<Cx> poly;

    int squarings = -1;  // p/2 = 2^squarings exactly (0..5), else -1

    /// ratio2^(p/2): by squarings when p/2 is a power of two (exact up to
    /// rounding), else exp2 / log2 (relative error < 1e-13, FastMath.h).
    [[nodiscard]] double pw(double ratio2) const {
        if (squarings >= 0) {
            double w = ratio2;
            for (int i = 0; i < squarings; ++i) {
                w *= w;
            }
            return w;
        }
        return powHalf(ratio2, halfP);
    }

    /// coef[r * kS + j] = binom(r, j) alpha^j beta^(r-j) for j <= r <= deg: the
    /// coefficients of (alpha v + beta)^r = sum_j coef[r][j] v^j, with which
    /// moments (M2M) and local expansions (L2L) change centre and scale.
    /// Always inlined: its callers are target_clones (FastMath.h).
    [[gnu::always_inline]] void shiftCoefficients(double alpha, Cx beta, int deg,
                                                  std::array<Cx, kS * kS>& coef) const {
        std::array<Cx, kS> bp;
        std::array<double, kS> ap;
        bp[0] = {1.0, 0.0};
        ap[0] = 1.0;
        for (int r = 1; r <= deg; ++r) {
            bp[r] = bp[r - 1] * beta;
            ap[r] = ap[r - 1] * alpha;
        }
        for (int r = 0; r <= deg; ++r) {
            for (int j = 0; j <= r; ++j) {
                coef[r * kS + j] = (binom[r][j] * ap[j]) * bp[r - j];
            }
        }
    }

    /// Builds every table for p (no checks: p is positive and finite). Chooses
    /// the expansion degree: 10 for p <= 16, 8 above.
    explicit PowerTables(double pIn);

    /// Smallest order m' in [0, degree] whose remainder tail
    /// tau_m'(q) = sum_{n>m'} c_n q^n is <= limit; -1 if none. tauOut = tau_m'(q).
    /// The terms beyond the last one summed are bounded by a geometric series:
    /// t[n+1] / t[n] = q (p+n)/(n+1) <= q ratio[n] for every later n.
    int chooseOrder(double q, double limit, double& tauOut) const {
        if (!(q < 1.0) || limit <= 0.0) {
            return -1;
        }
        std::array<double, kS + 1> t;  // t[n] = c_n q^n, n <= degree + 1 (hot: no fill)
        t[0] = 1.0;
        double qn = 1.0;
        for (int n = 1; n <= degree + 1; ++n) {
            qn *= q;
            t[static_cast<std::size_t>(n)] = c[static_cast<std::size_t>(n)] * qn;
        }
        double term = t[static_cast<std::size_t>(degree + 1)];
        double tail = 0.0;
        for (int n = degree + 1;; ++n) {
            tail += term;
            if (tail > limit) {
                return -1;  // the tail is at least this partial sum
            }
            const double r = q * ratio[static_cast<std::size_t>(n)];
            if (r < 0.875) {
                tail += term * r / (1.0 - r);
                break;
            }
            if (n >= kMaxTerms) {
                return -1;
            }
            qn *= q;
            term = c[static_cast<std::size_t>(n + 1)] * qn;
        }
        tail *= 1.0 + 1e-12;
        if (!(tail <= limit)) {
            return -1;
        }
        // tail(m'-1) = tail(m') + t[m']: walk down while it still fits
        int m = degree;
        while (m > 0 && tail + t[static_cast<std::size_t>(m)] <= limit) {
            tail += t[static_cast<std::size_t>(m)];
            --m;
        }
        tauOut = tail;
        return m;
    }
};

/// The weights (dx^2 + dy^2)^(-p/2) of every lattice offset a leaf tile's
/// kernel can meet (FastKernel.h, LeafKernelArgs::table): kDistTableStride^2
/// floats, each the float nearest PowerTables::pw(1 / d^2) (relative error
/// <= u plus pw's); read-only, shared by every thread. The tables of the last
/// four p are kept for the process (296 KB each; a solver is made per frame,
/// and building one takes 0.2-0.7 ms). nullptr when the table's smallest
/// weight would leave float's normal range (p above ~12). Thread-safe.
[[nodiscard]] std::shared_ptr<const std::vector<float>> distanceTable(const PowerTables& tab);

/// Whether weights down to distance d stay in float's normal range with room
/// for the tile's polynomial (2^-96).
[[nodiscard]] bool distanceTableFits(double p, double d);

}  // namespace vv::vss::detail::fast
