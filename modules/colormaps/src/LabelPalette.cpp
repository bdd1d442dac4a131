// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/colormaps/LabelPalette.h"

#include <array>

namespace vv::colormaps {

namespace {

constexpr glm::vec3 rgb(int r, int g, int b) {
    return {static_cast<float>(r) / 255.0F, static_cast<float>(g) / 255.0F,
            static_cast<float>(b) / 255.0F};
}

// Okabe-Ito without yellow and black (LabelPalette.h says why).
// The hue the chromadepth scale never shows (purple) first, its orange last.
constexpr std::array kPalette{
    rgb(204, 121, 167),  // reddish purple
    rgb(86, 180, 233),   // sky blue
    rgb(0, 158, 115),    // bluish green
    rgb(213, 94, 0),     // vermillion
    rgb(0, 114, 178),    // blue
    rgb(230, 159, 0),    // orange
};

}  // namespace

std::span<const glm::vec3> labelPalette() noexcept {
    return kPalette;
}

glm::vec3 labelColor(std::size_t index) noexcept {
    return kPalette[index % kPalette.size()];
}

DiameterColors diameterColors() noexcept {
    return {kPalette[4], kPalette[3], kPalette[2]};
}

}  // namespace vv::colormaps
