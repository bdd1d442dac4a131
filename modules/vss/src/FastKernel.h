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

/// Half-width of the distance table: it holds the offsets (dx, dy) from a
/// point to a tile pixel for points within kDistTableHalf of the tile origin
/// in x and in y: -kDistTableHalf <= dx, dy < kDistTableHalf + kLeafTile.
inline constexpr int kDistTableHalf = 128;
/// Its row stride and row count.
inline constexpr int kDistTableStride = 2 * kDistTableHalf + kLeafTile;

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
    /// When set (tile mode only): the weights of the first tableCount near
    /// points are read from this table, entry [(dy + kDistTableHalf) *
    /// kDistTableStride + dx + kDistTableHalf] = (dx^2 + dy^2)^(-p/2), and those
    /// of the others computed with s2 = 1: both in absolute scale, as the
    /// polynomial and errAbs must then be. Contour points and pixels are on the
    /// integer lattice, so a tile row's 16 weights of one point are 16
    /// consecutive entries: those of point k at row r start at
    /// tableOffset[k] + r * kDistTableStride, tableOffset[k] =
    /// (kDistTableHalf - y_k) * kDistTableStride + kDistTableHalf - x_k (|x_k|,
    /// |y_k| <= kDistTableHalf).
    const float* table = nullptr;
    const std::int32_t* tableOffset = nullptr;
    int tableCount = 0;
};

/// Evaluates z' for the rows in `a.rowMask` into z[16 * 16] (row-major) and sets
/// bit x of failRows[r] where the a-posteriori error check fails (or the
/// value is not finite): those pixels must be recomputed exactly.
void leafKernel(const LeafKernelArgs& a, float* z, std::uint32_t* failRows);

/// Points evaluated one per lane (the band boxes, FastBandBox.h): any
/// positions, 16 to a vector, the near points summed exactly and the far
/// polynomial, in one weight scale S^2 (the leaf's tile mode). With `bounds`
/// also, per evaluation point: m = min(floor2, squared distance to the
/// nearest of the points c0x, c0y (a subset of the near points: with every
/// other near point at least sqrt(floor2) away, a lower bound of the nearest
/// near point's)), that point's depth c (cFar when none is nearer than the
/// floor), A = sum_i w_i r_i and T = sum_i w_i r_i
/// |z_i - c| (r_i = S^2 / d_i^2: w_i / d_i^2 times S^2, for the bounds of the
/// second derivatives).
struct PointKernelArgs {
    int n = 0;  ///< evaluation points
    const float* ex =
        nullptr;  ///< their coordinates, n rounded up to 16 each (the pad read, not used)
    const float* ey = nullptr;
    const float* px = nullptr;  ///< near points (x, y, z - zref), `count` each, same origin
    const float* py = nullptr;
    const float* pz = nullptr;
    int count = 0;
    int degree = -1;               ///< far polynomial degree, -1: none
    const float* polyD = nullptr;  ///< as LeafKernelArgs
    const float* polyN = nullptr;
    float tu = 0.0F;  ///< polynomial centre and 1 / scale: u = (x - tu) * invA
    float tv = 0.0F;
    float invA = 1.0F;
    float s2 = 1.0F;  ///< S^2
    KernelPower power;
    bool bounds = false;
    int closeCount = 0;  ///< with bounds: the subset for m and c
    const float* c0x = nullptr;
    const float* c0y = nullptr;
    const float* c0z = nullptr;
    float floor2 = 0.0F;
    float cFar = 0.0F;
    /// Outputs, n rounded up to 16 each: near sums D, N; polynomial D, N (with
    /// degree >= 0); with bounds: m, c, A, T.
    float* dn = nullptr;
    float* nn = nullptr;
    float* pd = nullptr;
    float* pn = nullptr;
    float* dmin2 = nullptr;
    float* c = nullptr;
    float* a = nullptr;
    float* t = nullptr;
};

/// Evaluates the sums of PointKernelArgs at its n points (float, one
/// rounding per operation; contributions of points at distance 0 are Inf /
/// NaN: the caller's checks refuse them).
void pointKernel(const PointKernelArgs& a);

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
