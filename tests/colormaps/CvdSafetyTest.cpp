// SPDX-License-Identifier: GPL-3.0-or-later
// Which ramps are safe for colour-vision deficiency. For each ramp and each
// of normal vision, protanopia, deuteranopia and tritanopia (Machado et al.
// 2009, severity 1.0):
//  - lightness: the 256-entry LUT, as seen, is strictly monotonic in CIELAB L*;
//  - steps: a legend cut into kLegendSteps equal steps (kLegendSteps + 1
//    colours at t = i / kLegendSteps) has every adjacent pair at least
//    kMinStepDelta apart in CIEDE2000, as seen.
// cividis, viridis and dark-means-deep pass; the full chromadepth scale does
// not (its L* peaks at yellow, and red-green dichromats see its near and far
// halves merge), which is why the colour-blind-safe mode replaces it.
#include <gtest/gtest.h>

#include <cstdio>
#include <functional>
#include <string>
#include <vector>

#include "vv/colormaps/ColorMap.h"
#include "vv/colormaps/ColorVision.h"
#include "vv/colormaps/DepthScale.h"

namespace vv::colormaps {
namespace {

/// A legend's bar read as steps: 10 equal steps (11 tick colours).
constexpr int kLegendSteps = 10;
/// Adjacent legend steps must differ by at least this CIEDE2000 (about 3
/// just-noticeable differences: clearly distinct at a glance).
constexpr double kMinStepDelta = 3.0;
constexpr int kLutSize = 256;

struct Ramp {
    std::string name;
    std::function<glm::vec3(float)> sample;
};

std::vector<glm::dvec3> samples(const Ramp& ramp, int count) {
    std::vector<glm::dvec3> out;
    for (int i = 0; i < count; ++i) {
        out.emplace_back(ramp.sample(static_cast<float>(i) / static_cast<float>(count - 1)));
    }
    return out;
}

Ramp mapRamp(ColorMap map) {
    return {std::string(name(map)), [map](float t) { return sample(map, t); }};
}

Ramp scaleRamp(DepthScale scale) {
    return {std::string(name(scale)), [scale](float t) { return sample(scale, t); }};
}

class SafeRamp : public ::testing::TestWithParam<int> {};

std::vector<Ramp> safeRamps() {
    return {mapRamp(ColorMap::Cividis), mapRamp(ColorMap::Viridis),
            scaleRamp(DepthScale::DarkMeansDeep)};
}

TEST_P(SafeRamp, StaysMonotonicAndDistinctUnderEveryColorVision) {
    const Ramp ramp = safeRamps().at(static_cast<std::size_t>(GetParam()));
    const auto lut = samples(ramp, kLutSize);
    const auto steps = samples(ramp, kLegendSteps + 1);
    for (const ColorVision vision : allColorVisions()) {
        const RampCheck fine = checkRamp(lut, vision);
        EXPECT_TRUE(fine.monotonicLightness) << ramp.name << " / " << name(vision);
        const RampCheck legend = checkRamp(steps, vision);
        EXPECT_TRUE(legend.monotonicLightness) << ramp.name << " / " << name(vision);
        EXPECT_GE(legend.minAdjacentDelta, kMinStepDelta)
            << ramp.name << " / " << name(vision) << ": steps " << legend.minAdjacentIndex << "-"
            << legend.minAdjacentIndex + 1;
        std::printf("%-16s %-13s min step dE00 %.2f  L* %.1f..%.1f\n", ramp.name.c_str(),
                    std::string(name(vision)).c_str(), legend.minAdjacentDelta,
                    legend.lightness.front(), legend.lightness.back());
        // No two legend steps (adjacent or not) form a red/green confusion pair.
        EXPECT_TRUE(findRedGreenConfusions(steps).empty()) << ramp.name;
    }
}

std::string safeRampName(const ::testing::TestParamInfo<int>& param) {
    static const std::vector<std::string> kNames{"Cividis", "Viridis", "DarkMeansDeep"};
    return kNames.at(static_cast<std::size_t>(param.param));
}

INSTANTIATE_TEST_SUITE_P(CvdSafety, SafeRamp, ::testing::Values(0, 1, 2), safeRampName);

TEST(CvdSafety, FullChromadepthIsNotSafe) {
    const Ramp ramp = scaleRamp(DepthScale::Chromadepth);
    const auto lut = samples(ramp, kLutSize);
    const auto steps = samples(ramp, kLegendSteps + 1);
    for (const ColorVision vision : allColorVisions()) {
        const RampCheck legend = checkRamp(steps, vision);
        std::printf("%-16s %-13s min step dE00 %.2f  monotonic %d\n", ramp.name.c_str(),
                    std::string(name(vision)).c_str(), legend.minAdjacentDelta,
                    legend.monotonicLightness);
        // Red (near) -> yellow -> blue (far): lightness rises, then falls, for everyone.
        EXPECT_FALSE(checkRamp(lut, vision).monotonicLightness) << name(vision);
    }
    // Protanopes see two adjacent legend steps (orange -> yellow) collapse.
    EXPECT_LT(checkRamp(steps, ColorVision::Protanopia).minAdjacentDelta, kMinStepDelta);
    // Red-green dichromats confuse steps of different depth (e.g. orange near, green far).
    const auto confusions = findRedGreenConfusions(steps);
    std::printf("chromadepth red/green confusion pairs among the legend steps: %zu\n",
                confusions.size());
    EXPECT_FALSE(confusions.empty());
}

TEST(CvdSafety, PseudoChromadepthIsNotSafeEither) {
    // Red -> violet -> blue: lightness dips in the middle, so depth order is
    // not readable from lightness for anyone.
    const auto lut = samples(scaleRamp(DepthScale::PseudoChromadepth), kLutSize);
    const auto steps = samples(scaleRamp(DepthScale::PseudoChromadepth), kLegendSteps + 1);
    for (const ColorVision vision : allColorVisions()) {
        const RampCheck legend = checkRamp(steps, vision);
        std::printf("%-16s %-13s min step dE00 %.2f  monotonic %d\n", "pcd",
                    std::string(name(vision)).c_str(), legend.minAdjacentDelta,
                    checkRamp(lut, vision).monotonicLightness);
        EXPECT_FALSE(checkRamp(lut, vision).monotonicLightness) << name(vision);
    }
}

}  // namespace
}  // namespace vv::colormaps
