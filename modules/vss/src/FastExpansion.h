// SPDX-License-Identifier: GPL-3.0-or-later
// Private to the fast VSS solver: local expansions of the far field over a
// target box, filled from source clusters (M2L), re-centred to the child
// boxes (L2L) and turned into the real polynomial the leaf kernel evaluates.
// M2L rotates the cluster to the real axis (the coefficients become real);
// prefix sums give O(m^3) per translation; D and N travel side by side in
// 4-wide vectors (V4, never passed by value: FastMath.h). shiftLocal and m2l
// are dispatched at run time (AVX2 / baseline builds of the same code).
#pragma once

#include <array>

#include "FastMath.h"
#include "FastSourceTree.h"
#include "FastTables.h"

namespace vv::vss::detail::fast {

/// Square coefficient array: entry [l * kS + l'] for l + l' <= kM.
using Square = std::array<Cx, kS * kS>;

/// A local expansion about centre t with scale a, the D and N parts side by side:
/// F(zeta) = sum_{l+l'<=degree} L[l][l'] (zeta/a)^l conj(zeta/a)^l', zeta = x - t,
/// stored in full (L[l'][l] = conj(L[l][l']) since F is real).
struct Local {
    Square d{};
    Square n{};
};

/// Shifts (exactly) the expansion src of degree deg from centre / scale
/// (t0, a0) to (t1, a1) and multiplies it by f (a change of the box scale);
/// writes the entries l + l' <= deg of loc (the others are left as they are).
void shiftLocal(const Local& src, Local& loc, int deg, const PowerTables& tab, double t0x,
                double t0y, double a0, double t1x, double t1y, double a1, double f);

/// Multipole-to-local: adds source node C (moments mD / mN of layout lay) to
/// the local expansion loc at centre (tx, ty) and scale a, truncated at total
/// degree mo (<= lay.degree) in (zeta, v), times wR = (S/R)^p; R = |t - c|.
void m2l(Local& loc, int mo, const PowerTables& tab, const MomentLayout& lay, const Cx* mD,
         const Cx* mN, const SrcNode& C, double tx, double ty, double a, double R, double wR);

/// The real polynomial c[i * kS + j] u^i v^j equal to F(u + iv) (u, v in units
/// of a) for the expansion part L of degree deg; c is overwritten in full.
void localToPoly(const Square& L, int deg, const PowerTables& tab, std::array<double, kS * kS>& c);

/// Bounds of a real polynomial sum c[i * kS + j] u^i v^j (total degree <= deg)
/// over |u|, |v| <= mu (>= 1) and of its first and second partial derivatives
/// in x = u * an, y = v * an: |P| <= sum |c_ij| mu^(i+j), |P_x| <= sum i |c_ij|
/// mu^(i+j-1) / an, |P_xx| <= sum i (i - 1) |c_ij| mu^(i+j-2) / an^2 (and the
/// same in y with j).
struct PolyBounds {
    double sum = 0.0;  ///< >= |P|
    double dx = 0.0;   ///< >= |dP/dx|
    double dy = 0.0;
    double dxx = 0.0;  ///< >= |d2P/dx2|
    double dyy = 0.0;
};
PolyBounds polyBounds(const std::array<double, kS * kS>& c, int deg, double an, double mu = 1.0);

}  // namespace vv::vss::detail::fast
