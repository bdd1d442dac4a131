// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <cstdint>
#include <glm/glm.hpp>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

namespace vv::colormaps {

/// The colour maps VesselView knows. Every map is a table of sRGB control
/// points interpolated linearly in sRGB; adding a map means adding an enum
/// value here and its table in ColorMap.cpp (allColorMaps() lists them all, in
/// the order the UI shows them).
enum class ColorMap : std::uint8_t {
    Viridis,  ///< matplotlib's viridis: perceptually uniform, dark purple -> yellow
    Cividis,  ///< matplotlib's cividis: viridis-like, optimised for colour-vision deficiency
    Inferno,  ///< matplotlib's inferno: perceptually uniform, black -> purple -> orange -> pale
              ///< yellow
    /// Diverging blue -> white -> red (ColorBrewer's RdBu, 11 classes, reversed so that low
    /// values are blue): for signed values or deviations around a centre value.
    BlueWhiteRed,
};

/// Every map, in UI order.
[[nodiscard]] std::span<const ColorMap> allColorMaps() noexcept;

/// Stable lower-case identifier ("viridis", "cividis", "inferno", "blue-white-red"), used
/// in settings and on the command line.
[[nodiscard]] std::string_view name(ColorMap map) noexcept;

/// Human-readable name ("Viridis").
[[nodiscard]] std::string_view displayName(ColorMap map) noexcept;

/// The map whose name() equals `text`, ignoring ASCII case (for blue-white-red also
/// "bwr" and "diverging"); nullopt when none does.
[[nodiscard]] std::optional<ColorMap> colorMapFromName(std::string_view text) noexcept;

/// The colour a map stands for "no data" (NaN values). It is chosen to be
/// absent from the map itself, so missing values never read as a value. For
/// viridis, cividis and inferno it is a light neutral grey, sRGB (0.80, 0.80, 0.80); for
/// blue-white-red (whose centre is a light neutral) a mid grey, sRGB (0.50, 0.50, 0.50).
/// sample() returns it for NaN; renderers that handle NaN themselves (the GPU
/// shaders, which cannot rely on NaN arithmetic) must use the same colour.
[[nodiscard]] glm::vec3 noDataColor(ColorMap map) noexcept;

/// The map's sRGB colour (components in [0, 1]) at `t`. t is clamped to
/// [0, 1] (so -inf gives the first colour and +inf the last); NaN gives
/// noDataColor(map). Never throws.
[[nodiscard]] glm::vec3 sample(ColorMap map, float t) noexcept;

/// A look-up table of `n` entries for a 1-D texture: entry i is
/// sample(map, i / (n - 1)) in 8-bit sRGB, alpha 255. Entry 0 is the map's
/// first colour and entry n - 1 its last.
/// Throws InvalidArgumentError when n < 2 or n > 65536.
[[nodiscard]] std::vector<glm::u8vec4> lut(ColorMap map, int n);

/// Discrete bins: 0 = a continuous map; 2..kMaxBins = the value range split
/// into `bins` equal bins, bin i showing the map's colour at i / (bins - 1)
/// (so the first bin has the map's first colour and the last bin its last).
inline constexpr int kMaxBins = 256;

/// Throws InvalidArgumentError unless bins == 0 or 2 <= bins <= kMaxBins.
void validateBins(int bins);

/// The bin of `t` (clamped to [0, 1]) among `bins` equal bins:
/// min(floor(t * bins), bins - 1); 0 for NaN or bins < 2.
[[nodiscard]] int binIndex(float t, int bins) noexcept;

/// Like sample(map, t), but with `bins` discrete bins (see kMaxBins): every t
/// in bin i gives sample(map, i / (bins - 1)). bins < 2 is continuous. NaN
/// gives noDataColor(map). lut(map, bins) holds exactly the bins' colours.
[[nodiscard]] glm::vec3 sample(ColorMap map, float t, int bins) noexcept;

/// Converts an sRGB colour in [0, 1] to 8-bit RGBA (rounded, clamped; alpha 255).
[[nodiscard]] glm::u8vec4 toRgba8(const glm::vec3& srgb) noexcept;

/// CIE 1976 lightness L* in [0, 100] of an sRGB colour (D65 white), used to
/// check and to order maps by lightness.
[[nodiscard]] float cieLightness(const glm::vec3& srgb) noexcept;

}  // namespace vv::colormaps
