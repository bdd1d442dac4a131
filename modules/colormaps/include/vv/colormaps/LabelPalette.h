// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <glm/glm.hpp>
#include <span>

namespace vv::colormaps {

/// The qualitative palette of label (categorical) arrays: Okabe & Ito's
/// "colour universal design" palette (Okabe & Ito 2008, also Wong 2011,
/// Nature Methods 8:441), chosen because every pair of its colours stays
/// distinguishable under protanopia, deuteranopia and tritanopia, so the
/// colour-blind-safe mode keeps it unchanged. Two of its eight colours are
/// left out, by a rule tests/colormaps/LabelPaletteTest.cpp checks:
///  - yellow (#F0E442): a label colour must differ from the chromadepth
///    depth scale's yellow, which the VSS shows behind the vessels, by
///    CIEDE2000 >= 15 (yellow is 7.1 away), so a label never merges with it;
///  - black (#000000): a label colour must have CIE L* >= 30, so it reads
///    on the dark background and in shadowed, unlit parts of the surface.
/// What is left, in order: reddish purple (a hue the chromadepth scale never
/// shows, for the first label, often the root vessel), sky blue, bluish
/// green, vermillion, blue, orange (sRGB in [0, 1]). Label k (in ascending label order) has
/// colour k modulo the palette's size, so more labels than colours repeat.
[[nodiscard]] std::span<const glm::vec3> labelPalette() noexcept;

/// The colour of the label with index `index` (0 = the smallest label value):
/// labelPalette()[index % size]. Never throws.
[[nodiscard]] glm::vec3 labelColor(std::size_t index) noexcept;

/// The colours of the planning's three diameters wherever they are drawn
/// (the GUI's profile and cross-section, the report's figures), from the
/// same palette: equivalent blue, minimum vermillion, maximum bluish green.
struct DiameterColors {
    glm::vec3 equivalent;
    glm::vec3 minimum;
    glm::vec3 maximum;
};
[[nodiscard]] DiameterColors diameterColors() noexcept;

}  // namespace vv::colormaps
