// SPDX-License-Identifier: GPL-3.0-or-later
// The frame's passes hand each other what they use as graph resources: one
// depth read-back for the solve and the depth range, the ranges and cue the
// shading passes read, declared render targets, the probe's nearest depth.
// GL tests: run under `xvfb-run -a` with QT_QPA_PLATFORM=xcb.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "RenderTestUtil.h"
#include "vv/core/Error.h"
#include "vv/render/FrameRenderer.h"
#include "vv/render/OffscreenRenderer.h"

namespace {

using ::testing::Contains;
using ::testing::Not;
using ::testing::UnorderedElementsAre;
using vv::render::FrameSettings;
using vv::render::MeshStyle;
using vv::render::ObjectStyle;
using vv::render::OffscreenOptions;
using vv::render::PassInfo;
using vv::render::PassState;
using vv::render::VesselCue;
using vv::render::test::FrameHarness;

const PassInfo& infoOf(const std::vector<PassInfo>& passes, const std::string& name) {
    const auto found = std::find_if(passes.begin(), passes.end(),
                                    [&](const PassInfo& pass) { return pass.name == name; });
    if (found == passes.end()) {
        throw std::runtime_error("no pass " + name);
    }
    return *found;
}

/// The names of the resources `pass` reads.
std::vector<std::string> readsOf(const std::vector<PassInfo>& passes, const std::string& pass) {
    std::vector<std::string> names;
    for (const auto& read : infoOf(passes, pass).reads) {
        names.push_back(read.resource);
    }
    return names;
}

/// The passes (not culled) that read resource `resource`.
std::vector<std::string> readersOf(const std::vector<PassInfo>& passes,
                                   const std::string& resource) {
    std::vector<std::string> readers;
    for (const PassInfo& pass : passes) {
        const bool reads = std::any_of(pass.reads.begin(), pass.reads.end(),
                                       [&](const auto& read) { return read.resource == resource; });
        if (reads && pass.state != PassState::Culled) {
            readers.push_back(pass.name);
        }
    }
    return readers;
}

class FrameDataFlowTest : public vv::render::test::GlRenderTest {
  protected:
    OffscreenOptions options(VesselCue cue, bool vss) const {
        OffscreenOptions o = vv::render::test::exactOptions(200, 150);
        o.display.vss.enabled = vss;
        o.display.cue.cue = cue;
        o.display.style.array.clear();
        return o;
    }
};

TEST_F(FrameDataFlowTest, TheSolveAndTheDepthRangeShareOneDepthReadBack) {
    auto renderer = makeRenderer();
    ASSERT_TRUE(renderer);
    const auto scene = vv::render::test::twoTubes(1.5F, 5.0F, 40, 16);
    static_cast<void>(renderer->render(scene, options(VesselCue::PseudoChromadepth, true)));
    const auto& passes = renderer->lastPasses();
    EXPECT_EQ(state(*renderer, "depth-readback"), PassState::Executed);
    EXPECT_EQ(state(*renderer, "depth-range"), PassState::Executed);
    EXPECT_EQ(state(*renderer, "vss-solve"), PassState::Executed);
    // Only the read-back pass reads the G-buffer's depth back; the solve and
    // the depth range take its CPU image.
    EXPECT_THAT(readersOf(passes, "linear-depth-image"),
                UnorderedElementsAre("vss-solve", "depth-range"));
    EXPECT_THAT(readsOf(passes, "depth-readback"), Contains("linear-depth"));
    EXPECT_THAT(readsOf(passes, "vss-solve"), Not(Contains("linear-depth")));
    EXPECT_THAT(readsOf(passes, "depth-range"), Not(Contains("linear-depth")));

    // Another cue: nothing is read back or solved again.
    static_cast<void>(renderer->render(scene, options(VesselCue::Fog, true)));
    EXPECT_EQ(state(*renderer, "depth-readback"), PassState::Cached);
    EXPECT_EQ(state(*renderer, "vss-solve"), PassState::Cached);
    EXPECT_EQ(state(*renderer, "depth-range"), PassState::Cached);
    EXPECT_EQ(state(*renderer, "vessel-shading"), PassState::Executed);

    // VSS and cue off: nobody needs the depth on the CPU.
    static_cast<void>(renderer->render(scene, options(VesselCue::None, false)));
    EXPECT_EQ(state(*renderer, "depth-readback"), PassState::Culled);
}

TEST_F(FrameDataFlowTest, ShadingPassesReadTheValuesTheyUse) {
    auto renderer = makeRenderer();
    ASSERT_TRUE(renderer);
    const auto scene = vv::render::test::twoTubes(1.5F, 5.0F, 40, 16);
    OffscreenOptions o = options(VesselCue::Fresnel, true);
    o.display.ao.enabled = true;
    ObjectStyle translucent;
    translucent.opacity = 0.5F;
    o.display.style.objects = {translucent};  // the near tube
    // A fixed VSS range, so that the cue's range tells the VSS's from the visible one.
    o.display.vss.range.mode = vv::vss::RangeMode::Fixed;
    o.display.vss.range.dmin = 1.0;
    o.display.vss.range.dmax = 100.0;
    static_cast<void>(renderer->render(scene, o));
    const auto& passes = renderer->lastPasses();
    // The cue's range: the shown VSS's, else the visible one.
    EXPECT_THAT(readsOf(passes, "vessel-shading"), Contains("shown-vss"));
    EXPECT_THAT(readsOf(passes, "vessel-shading"), Contains("visible-depth-range"));
    // The VSS's range and whether one is shown come with the height.
    EXPECT_THAT(readsOf(passes, "vss-shading"), Contains("shown-vss"));
    EXPECT_THAT(readsOf(passes, "ssao"), Contains("shown-vss"));
    // The translucent objects take the cue the vessels were shaded with.
    EXPECT_EQ(state(*renderer, "translucent"), PassState::Executed);
    EXPECT_THAT(readsOf(passes, "translucent"), Contains("vessel-cue"));
    EXPECT_THAT(readsOf(passes, "translucent"), Not(Contains("vessel-color")));
    // Render targets are declared, not attached by hand.
    EXPECT_EQ(infoOf(passes, "geometry").renderTargets, std::vector<std::string>{"gbuffer"});
    EXPECT_EQ(infoOf(passes, "translucent").renderTargets, std::vector<std::string>{"translucent"});
    // What the renderer reports comes from the frame's values.
    const auto range = renderer->lastCueDepthRange();
    ASSERT_TRUE(range.has_value());
    ASSERT_TRUE(renderer->vssStatus().shown);
    EXPECT_DOUBLE_EQ(renderer->vssStatus().dmin, 1.0);
    EXPECT_DOUBLE_EQ(renderer->vssStatus().dmax, 100.0);
    EXPECT_DOUBLE_EQ(range->first, 1.0);
    EXPECT_DOUBLE_EQ(range->second, 100.0);
}

/// The finite range of `depth`.
std::optional<std::pair<float, float>> finiteRange(const vv::Image<float>& depth) {
    float lo = std::numeric_limits<float>::infinity();
    float hi = -lo;
    for (int y = 0; y < depth.height(); ++y) {
        for (int x = 0; x < depth.width(); ++x) {
            if (std::isfinite(depth.row(y)[x])) {
                lo = std::min(lo, depth.row(y)[x]);
                hi = std::max(hi, depth.row(y)[x]);
            }
        }
    }
    return lo <= hi ? std::optional(std::make_pair(lo, hi)) : std::nullopt;
}

TEST_F(FrameDataFlowTest, TheProbesDepthRangeIsTheFramesWithOrWithoutAReadBack) {
    std::unique_ptr<FrameHarness> harness;
    try {
        harness = std::make_unique<FrameHarness>(160, 120);
    } catch (const vv::Error& e) {
        FAIL() << e.what();
    }
    harness->setScene(vv::render::test::twoTubes(1.5F, 5.0F, 40, 16));
    MeshStyle style;
    style.array.clear();
    FrameSettings settings;
    settings.ao.enabled = false;
    settings.antialiasing = false;
    vv::render::FrameRenderer& renderer = harness->renderer();
    EXPECT_FALSE(renderer.visibleDepthRange().has_value());  // no frame yet

    // With the VSS: the frame read the depth back for its solve.
    static_cast<void>(harness->render(style, settings));
    const auto solved = finiteRange(renderer.lastSolvedDepth());
    ASSERT_TRUE(solved.has_value());
    const auto withReadBack = renderer.visibleDepthRange();
    ASSERT_TRUE(withReadBack.has_value());
    EXPECT_EQ(*withReadBack, *solved);

    // Without the VSS nor a cue nothing read it back: read once on demand.
    settings.vss.enabled = false;
    static_cast<void>(harness->render(style, settings));
    EXPECT_EQ(infoOf(renderer.lastPasses(), "depth-readback").state, PassState::Culled);
    const auto onDemand = renderer.visibleDepthRange();
    ASSERT_TRUE(onDemand.has_value());
    EXPECT_EQ(*onDemand, *solved);
    EXPECT_EQ(renderer.visibleDepthRange(), onDemand);

    // And the probe finds the nearest vessel point at that depth.
    bool nearestSeen = false;
    for (int y = 0; y < 120 && !nearestSeen; ++y) {
        for (int x = 0; x < 160 && !nearestSeen; ++x) {
            const auto sample = renderer.probe(harness->camera(), x, y);
            nearestSeen = sample && sample->linearDepth == onDemand->first;
        }
    }
    EXPECT_TRUE(nearestSeen);
}

}  // namespace
