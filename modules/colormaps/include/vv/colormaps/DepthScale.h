// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <cstdint>
#include <glm/glm.hpp>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

namespace vv::colormaps {

/// Depth colour scales for the Void Space Surface (VSS.md, "Shading on the
/// VSS"). t = 0 is the nearest depth, t = 1 the farthest. Like the parameter
/// colour maps, each is a table of sRGB control points interpolated linearly
/// in sRGB.
enum class DepthScale : std::uint8_t {
    /// Chromadepth: red near -> orange -> yellow -> green -> blue far (the
    /// hue order of the ChromaDepth glasses: long wavelengths appear near).
    Chromadepth,
    /// Pseudo-chromadepth: red near -> blue far, without the middle hues
    /// (the mix passes through violet).
    PseudoChromadepth,
    /// Dark-means-deep: white near -> black far; lightness only, so it is
    /// safe for colour-vision deficiency.
    DarkMeansDeep,
};

/// Every depth scale, in UI order.
[[nodiscard]] std::span<const DepthScale> allDepthScales() noexcept;

/// Stable lower-case identifier ("chromadepth", "pseudo-chromadepth",
/// "dark-means-deep"), used in settings.
[[nodiscard]] std::string_view name(DepthScale scale) noexcept;

/// The short command-line identifier ("cd", "pcd", "dmd").
[[nodiscard]] std::string_view shortName(DepthScale scale) noexcept;

/// Human-readable name ("Chromadepth").
[[nodiscard]] std::string_view displayName(DepthScale scale) noexcept;

/// The scale whose name() or shortName() equals `text`, ignoring ASCII case;
/// nullopt when none does.
[[nodiscard]] std::optional<DepthScale> depthScaleFromName(std::string_view text) noexcept;

/// The scale's sRGB colour (components in [0, 1]) at normalised depth `t`
/// (0 = near, 1 = far). t is clamped to [0, 1]; NaN gives the colour at 0.5
/// (a depth scale has no "no data": pixels without a VSS are not shaded at
/// all). Never throws.
[[nodiscard]] glm::vec3 sample(DepthScale scale, float t) noexcept;

/// A look-up table of `n` entries for a 1-D texture: entry i is
/// sample(scale, i / (n - 1)) in 8-bit sRGB, alpha 255.
/// Throws InvalidArgumentError when n < 2 or n > 65536.
[[nodiscard]] std::vector<glm::u8vec4> lut(DepthScale scale, int n);

}  // namespace vv::colormaps
