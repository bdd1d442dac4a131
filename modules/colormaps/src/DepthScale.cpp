// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/colormaps/DepthScale.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <string>

#include "vv/colormaps/ColorMap.h"
#include "vv/core/AsciiText.h"
#include "vv/core/Error.h"

namespace vv::colormaps {

namespace {

struct Stop {
    float t;
    glm::vec3 color;
};

// Chromadepth: the spectral order red, orange, yellow, green, blue with the
// hues spread so that each reads as its own depth band. Channels stay a
// little below full saturation so that lighting still shows on them.
constexpr std::array kChromadepth{
    Stop{0.00F, {0.90F, 0.08F, 0.06F}},  // red
    Stop{0.22F, {0.98F, 0.50F, 0.05F}},  // orange
    Stop{0.42F, {0.98F, 0.88F, 0.10F}},  // yellow
    Stop{0.66F, {0.20F, 0.72F, 0.22F}},  // green
    Stop{1.00F, {0.12F, 0.28F, 0.92F}},  // blue
};

// Pseudo-chromadepth: red to blue only (Ropinski et al. 2006).
constexpr std::array kPseudoChromadepth{
    Stop{0.00F, {0.92F, 0.10F, 0.08F}},
    Stop{1.00F, {0.10F, 0.20F, 0.92F}},
};

// Dark-means-deep: white near, black far.
constexpr std::array kDarkMeansDeep{
    Stop{0.00F, {1.0F, 1.0F, 1.0F}},
    Stop{1.00F, {0.0F, 0.0F, 0.0F}},
};

constexpr std::array kAll{DepthScale::Chromadepth, DepthScale::PseudoChromadepth,
                          DepthScale::DarkMeansDeep};

template <std::size_t N>
glm::vec3 interpolate(const std::array<Stop, N>& stops, float t) noexcept {
    if (!(t > stops.front().t)) {
        return stops.front().color;
    }
    for (std::size_t i = 1; i < N; ++i) {
        if (t <= stops[i].t) {
            const float f = (t - stops[i - 1].t) / (stops[i].t - stops[i - 1].t);
            return stops[i - 1].color + f * (stops[i].color - stops[i - 1].color);
        }
    }
    return stops.back().color;
}

}  // namespace

std::span<const DepthScale> allDepthScales() noexcept {
    return kAll;
}

std::string_view name(DepthScale scale) noexcept {
    switch (scale) {
        case DepthScale::Chromadepth:
            return "chromadepth";
        case DepthScale::PseudoChromadepth:
            return "pseudo-chromadepth";
        case DepthScale::DarkMeansDeep:
            return "dark-means-deep";
    }
    return "chromadepth";
}

std::string_view shortName(DepthScale scale) noexcept {
    switch (scale) {
        case DepthScale::Chromadepth:
            return "cd";
        case DepthScale::PseudoChromadepth:
            return "pcd";
        case DepthScale::DarkMeansDeep:
            return "dmd";
    }
    return "cd";
}

std::string_view displayName(DepthScale scale) noexcept {
    switch (scale) {
        case DepthScale::Chromadepth:
            return "Chromadepth";
        case DepthScale::PseudoChromadepth:
            return "Pseudo-chromadepth";
        case DepthScale::DarkMeansDeep:
            return "Dark means deep";
    }
    return "Chromadepth";
}

std::optional<DepthScale> depthScaleFromName(std::string_view text) noexcept {
    for (const auto scale : kAll) {
        if (equalsIgnoringCase(text, name(scale)) || equalsIgnoringCase(text, shortName(scale))) {
            return scale;
        }
    }
    return std::nullopt;
}

glm::vec3 sample(DepthScale scale, float t) noexcept {
    if (std::isnan(t)) {
        t = 0.5F;
    }
    t = std::clamp(t, 0.0F, 1.0F);
    switch (scale) {
        case DepthScale::Chromadepth:
            return interpolate(kChromadepth, t);
        case DepthScale::PseudoChromadepth:
            return interpolate(kPseudoChromadepth, t);
        case DepthScale::DarkMeansDeep:
            return interpolate(kDarkMeansDeep, t);
    }
    return interpolate(kChromadepth, t);
}

std::vector<glm::u8vec4> lut(DepthScale scale, int n) {
    if (n < 2 || n > 65536) {
        throw InvalidArgumentError("a depth-scale table needs 2..65536 entries, got " +
                                   std::to_string(n));
    }
    std::vector<glm::u8vec4> table(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) {
        table[static_cast<std::size_t>(i)] =
            toRgba8(sample(scale, static_cast<float>(i) / static_cast<float>(n - 1)));
    }
    return table;
}

}  // namespace vv::colormaps
