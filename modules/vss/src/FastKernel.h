// SPDX-License-Identifier: GPL-3.0-or-later
// Private to the fast VSS solver: the SIMD leaf kernel and its math.
#pragma once

#include <cstdint>

namespace vv::vss::detail {

/// Side of a leaf tile of target pixels; one kernel row = one 16-lane vector.
inline constexpr int kLeafTile = 16;
/// Highest total degree of the far-field polynomial handed to the kernel.
inline constexpr int kMaxPolyDegree = 12;

/// How the kernel raises r = S^2 / d^2 (<= 1) to the power p / 2.
/// squarings >= 0: p / 2 = 2^squarings exactly (r squared that many times);
/// squarings < 0: general p through the kernel's own log2 / exp2.
struct KernelPower {
    int squarings = -1;
    float halfP = 1.0F;
};

/// One leaf tile: near contour points evaluated exactly, the rest of the
/// region as a polynomial. Coordinates are relative to the tile origin.
struct LeafKernelArgs {
    int rows = 0;               ///< rows of the tile (<= 16)
    std::uint32_t rowMask = 0;  ///< bit r set: compute row r
    const float* px = nullptr;  ///< near points (x, y, z - zref), `count` each
    const float* py = nullptr;
    const float* pz = nullptr;
    int count = 0;
    int degree = -1;  ///< far polynomial degree, -1: none
    const float* polyD =
        nullptr;  ///< [(kMaxPolyDegree+1)^2], coefficient of u^i v^j at i*(kMaxPolyDegree+1)+j
    const float* polyN = nullptr;
    float tu = 0.0F;  ///< polynomial centre and 1 / scale: u = (x - tu) * invA
    float tv = 0.0F;
    float invA = 1.0F;
    bool perPixel = false;  ///< per-pixel weight scale (large p) instead of one per tile
    float s2 = 1.0F;  ///< tile mode: tile scale S^2; per-pixel mode: far scale S_F^2 (inf: none)
    float zref = 0.0F;
    float zmin = 0.0F;
    float zmax = 1.0F;
    float tolRemaining = 0.0F;  ///< allowed error per unit of D after arithmetic error
    float errAbs = 0.0F;    ///< tile mode: bound of the truncation + polynomial round-off (scaled)
    float farArith = 0.0F;  ///< per-pixel mode: polynomial round-off bound in S_F scale
    float log2DzE = -1000.0F;  ///< per-pixel mode: log2(dz * E) in leaf scale
    float log2LeafS2 = 0.0F;   ///< per-pixel mode: log2(S_leaf^2)
    KernelPower power;
    /// When set ([16 * 16] each, row-major): receive the computed sums D and
    /// N (the near points plus the polynomial, before the division) of the
    /// rows in rowMask (the coarse boxes, FastCoarse.h).
    float* sumD = nullptr;
    float* sumN = nullptr;
};

/// Evaluates z' for the rows in `a.rowMask` into z[16 * 16] (row-major) and sets
/// bit x of failRows[r] where the a-posteriori error check fails (or the
/// value is not finite): those pixels must be recomputed exactly.
void leafKernel(const LeafKernelArgs& a, float* z, std::uint32_t* failRows);

/// The kernel's log2 / exp2 (scalar wrappers of the vector code, for tests).
/// log2 of a normal x > 0: the mantissa part log2(m), m in [sqrt(1/2), sqrt(2)),
/// has absolute error <= kKernelLog2Error; the sum with the exponent adds one
/// rounding (|log2 x| * 2^-24). exp2: relative error <= kKernelExp2Error for
/// -124.5 <= x <= 0.5; exactly 0 below -125.5.
float kernelLog2(float x);
float kernelExp2(float x);
inline constexpr double kKernelLog2Error = 2.0e-7;
inline constexpr double kKernelExp2Error = 4.0e-7;

/// Name of the instruction set the kernel dispatches to ("avx512", "avx2", "generic").
const char* leafKernelIsa();

}  // namespace vv::vss::detail
