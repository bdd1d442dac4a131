// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <array>
#include <cstdint>
#include <glm/glm.hpp>
#include <span>
#include <string_view>
#include <vector>

/// Colour science for checking that what VesselView shows stays readable with
/// colour-vision deficiency (CVD): sRGB <-> linear RGB, CIELAB (D65),
/// the CIEDE2000 colour difference, and the Machado, Oliveira & Fernandes
/// (2009) simulation of protanopia, deuteranopia and tritanopia. Plain C++,
/// no Qt, no GL; every function here is pure and never throws.
namespace vv::colormaps {

/// How a viewer sees colours: normal trichromacy or one of the three
/// dichromacies (severity 1.0 of Machado et al. 2009).
enum class ColorVision : std::uint8_t {
    Normal,
    Protanopia,    ///< no L cones: red-green confusion, reds look dark
    Deuteranopia,  ///< no M cones: red-green confusion (the most common CVD)
    Tritanopia,    ///< no S cones: blue-yellow confusion
};

/// Every kind, Normal first.
[[nodiscard]] std::span<const ColorVision> allColorVisions() noexcept;

/// "normal", "protanopia", "deuteranopia", "tritanopia".
[[nodiscard]] std::string_view name(ColorVision vision) noexcept;

/// A CIELAB colour (D65 white, 2 degree observer): L* in [0, 100], a*, b*.
struct Lab {
    double l = 0.0;
    double a = 0.0;
    double b = 0.0;
};

/// The sRGB transfer function (IEC 61966-2-1): an encoded component in
/// [0, 1] to linear light, and back. Inputs outside [0, 1] are clamped.
[[nodiscard]] double srgbToLinear(double encoded) noexcept;
[[nodiscard]] double linearToSrgb(double linear) noexcept;
[[nodiscard]] glm::dvec3 srgbToLinear(const glm::dvec3& srgb) noexcept;
[[nodiscard]] glm::dvec3 linearToSrgb(const glm::dvec3& linear) noexcept;

/// CIELAB of an sRGB colour (components in [0, 1], clamped), through CIE XYZ
/// with the sRGB primaries and the D65 white point (Xn, Yn, Zn) = (0.95047,
/// 1, 1.08883). White gives (100, 0, 0), black (0, 0, 0).
[[nodiscard]] Lab srgbToLab(const glm::dvec3& srgb) noexcept;

/// The CIEDE2000 colour difference (CIE 142-2001) with kL = kC = kH = 1,
/// implemented as in Sharma, Wu & Dalal (2005), "The CIEDE2000 color-difference
/// formula: implementation notes, supplementary test data, and mathematical
/// observations" (Color Res. Appl. 30(1)), including their notes on the hue
/// angle's discontinuity. Symmetric; 0 for equal colours. About 1 is a just
/// noticeable difference; 2-3 perceptible at a glance.
[[nodiscard]] double ciede2000(const Lab& first, const Lab& second) noexcept;
/// ciede2000() of two sRGB colours.
[[nodiscard]] double ciede2000(const glm::dvec3& srgbFirst, const glm::dvec3& srgbSecond) noexcept;

/// The Machado, Oliveira & Fernandes (2009) simulation matrix for `vision`
/// at severity 1.0, row-major (out_i = sum_j m[i][j] * in_j), applied to
/// linear RGB. The identity for Normal. Each row sums to 1 (within the
/// published 6 decimals), so neutral greys stay neutral.
[[nodiscard]] const std::array<std::array<double, 3>, 3>& machadoMatrix(
    ColorVision vision) noexcept;

/// How `srgb` (components in [0, 1]) looks to a viewer with `vision`: linear
/// RGB through machadoMatrix(), clamped to [0, 1], back to sRGB.
[[nodiscard]] glm::dvec3 simulate(ColorVision vision, const glm::dvec3& srgb) noexcept;

/// What checkRamp() found about a sequence of colours (e.g. a legend's steps).
struct RampCheck {
    /// L* of every step, as seen with the checked vision.
    std::vector<double> lightness;
    /// L* strictly increases or strictly decreases along the ramp (by more
    /// than the given tolerance at each step).
    bool monotonicLightness = false;
    /// The smallest CIEDE2000 between adjacent steps, as seen, and the index
    /// i of the pair (i, i + 1) where it occurs.
    double minAdjacentDelta = 0.0;
    int minAdjacentIndex = 0;
};

/// Checks the sRGB colours `steps` (in ramp order, at least 2) as seen with
/// `vision`: monotonic lightness (each adjacent L* difference at least
/// `lightnessTolerance` in the ramp's direction) and the smallest adjacent
/// CIEDE2000. Fewer than 2 steps give an empty, non-monotonic result.
[[nodiscard]] RampCheck checkRamp(std::span<const glm::dvec3> steps, ColorVision vision,
                                  double lightnessTolerance = 0.0);

/// A colour of an image and the fraction of the pixels that have it.
struct PaletteEntry {
    glm::dvec3 srgb{0.0};  ///< the mean sRGB colour of the pixels in the bin
    double fraction = 0.0;
};

/// The dominant colours of an image: every 8-bit sRGB pixel falls into a
/// bin of an even `levels`^3 grid (levels in [2, 256], clamped); bins holding
/// at least `minFraction` of the pixels are returned (most frequent first),
/// each with the mean colour of its pixels. Empty for no pixels.
[[nodiscard]] std::vector<PaletteEntry> dominantColors(std::span<const glm::u8vec3> pixels,
                                                       int levels = 16, double minFraction = 0.002);

/// When two colours count as a red/green confusion pair (see
/// findRedGreenConfusions()).
struct ConfusionCriteria {
    /// A normal viewer tells them apart clearly: CIEDE2000 at least this.
    double minNormalDelta = 10.0;
    /// A protanope or deuteranope cannot: the simulated colours' CIEDE2000
    /// is below this.
    double maxSimulatedDelta = 3.0;
};

/// A pair of colours a normal viewer separates but a red-green dichromat does not.
struct ConfusionPair {
    glm::dvec3 first{0.0};
    glm::dvec3 second{0.0};
    ColorVision vision = ColorVision::Normal;  ///< Protanopia or Deuteranopia
    double normalDelta = 0.0;                  ///< CIEDE2000 for normal vision
    double simulatedDelta = 0.0;               ///< CIEDE2000 as simulated for `vision`
};

/// Red/green confusion pairs among `colors` (sRGB): pairs (a, b) with
/// ciede2000(a, b) >= criteria.minNormalDelta whose protanopia or
/// deuteranopia simulations (simulate()) differ by less than
/// criteria.maxSimulatedDelta. Such pairs carry information (e.g. depth or
/// a parameter) only through the red-green opponent channel, which these
/// viewers lack. Each unordered pair is reported at most once (with the
/// vision where the simulated difference is smaller). O(n^2) in the colours.
[[nodiscard]] std::vector<ConfusionPair> findRedGreenConfusions(
    std::span<const glm::dvec3> colors, const ConfusionCriteria& criteria = {});

}  // namespace vv::colormaps
