// SPDX-License-Identifier: GPL-3.0-or-later
// Vessel cues (pass 5) and legends (pass 6). The GL tests render offscreen
// with a real OpenGL 4.1 context: run under `xvfb-run -a` with
// QT_QPA_PLATFORM=xcb. Without a GL context they fail (they never skip).
#include <gtest/gtest.h>

#include <QColor>
#include <QFont>
#include <QFontMetricsF>
#include <QGuiApplication>
#include <QImage>
#include <cmath>
#include <memory>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "RenderTestUtil.h"
#include "vv/core/Error.h"
#include "vv/render/LegendPainter.h"
#include "vv/render/OffscreenRenderer.h"

namespace {

using vv::render::OffscreenOptions;
using vv::render::OffscreenRenderer;
using vv::render::PassState;
using vv::render::VesselCue;

/// Near tube on top (z = +5), far tube below (z = -5); the default camera
/// looks down -z with +y up. The near one carries an array "speed" (m/s).
vv::scene::Scene twoTubes() {
    vv::scene::Scene scene = vv::render::test::twoTubes(1.5F, 5.0F, 40, 16);
    for (auto& mesh : scene.meshes) {
        vv::scene::DataArray speed;
        speed.name = "speed";
        speed.unit = "m/s";
        speed.components = 1;
        for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
            speed.values.push_back(mesh.positions[i].x * 0.1F + 2.0F);
        }
        mesh.pointArrays.push_back(std::move(speed));
    }
    return scene;
}

glm::vec3 rgb(QRgb p) {
    return vv::render::test::toVec(p);
}

float distance(QRgb a, QRgb b) {
    return glm::length(rgb(a) - rgb(b));
}

class VesselCueTest : public vv::render::test::GlRenderTest {
  protected:
    static void keep(const QImage& image, const std::string& name) {
        vv::render::test::saveImage(image, "cue-", name);
    }

    OffscreenOptions options(VesselCue cue, bool vss = false) const {
        OffscreenOptions o;
        o.width = 320;
        o.height = 240;
        o.display.background = background_;
        o.display.vss.enabled = vss;
        o.display.cue.cue = cue;
        o.display.style.array.clear();
        return o;
    }

    /// The vessel rows [first, last] of the top (near) and bottom (far) tube
    /// in column x of a VSS-off image.
    std::pair<std::pair<int, int>, std::pair<int, int>> tubeRows(const QImage& image, int x) const {
        std::vector<std::pair<int, int>> runs;
        for (int y = 0; y < image.height(); ++y) {
            const bool vessel = image.pixel(x, y) != backgroundRgb_;
            if (vessel && (runs.empty() || runs.back().second != y - 1)) {
                runs.emplace_back(y, y);
            } else if (vessel) {
                runs.back().second = y;
            }
        }
        EXPECT_EQ(runs.size(), 2U) << "two tubes expected in column " << x;
        if (runs.size() != 2) {
            return {{0, 0}, {0, 0}};
        }
        return {runs[0], runs[1]};
    }
};

TEST_F(VesselCueTest, DepthColourCuesPaintTheNearTubeRedAndTheFarTubeBlue) {
    auto renderer = makeRenderer();
    ASSERT_TRUE(renderer);
    const auto scene = twoTubes();
    const QImage none = renderer->render(scene, options(VesselCue::None));
    keep(none, "none");
    const int x = none.width() / 2;
    const auto [near, far] = tubeRows(none, x);
    const int nearRow = (near.first + near.second) / 2;
    const int farRow = (far.first + far.second) / 2;
    for (const VesselCue cue : {VesselCue::Chromadepth, VesselCue::PseudoChromadepth}) {
        const QImage image = renderer->render(scene, options(cue));
        keep(image, std::string(name(cue)));
        const glm::vec3 n = rgb(image.pixel(x, nearRow));
        const glm::vec3 f = rgb(image.pixel(x, farRow));
        // Near = the red end, far = the blue end: hue order red before blue.
        EXPECT_GT(n.r, n.b + 0.3F) << name(cue);
        EXPECT_GT(f.b, f.r + 0.3F) << name(cue);
        EXPECT_GT(n.r - n.b, f.r - f.b + 0.6F) << name(cue);
        // Same silhouettes as without a cue.
        EXPECT_EQ(image.pixel(x, near.first - 1), backgroundRgb_);
        EXPECT_NE(image.pixel(x, near.first), backgroundRgb_);
    }
}

TEST_F(VesselCueTest, NoneEqualsThePreviousOutputAndLeavesNoStateBehind) {
    auto renderer = makeRenderer();
    ASSERT_TRUE(renderer);
    const auto scene = twoTubes();
    OffscreenOptions plain;  // no cue field touched: what render() drew before cues existed
    plain.width = 320;
    plain.height = 240;
    plain.display.background = background_;
    plain.display.vss.enabled = false;
    const QImage before = renderer->render(scene, plain);
    const QImage none = renderer->render(scene, options(VesselCue::None));
    EXPECT_EQ(before, none);
    for (const VesselCue cue : {VesselCue::Chromadepth, VesselCue::Fog, VesselCue::Fresnel}) {
        const QImage image = renderer->render(scene, options(cue));
        EXPECT_NE(image, none) << name(cue);
    }
    EXPECT_EQ(renderer->render(scene, options(VesselCue::None)), none);
    EXPECT_FALSE(renderer->lastCueDepthRange().has_value());
}

TEST_F(VesselCueTest, FogMovesTheFarTubeTowardsTheBackgroundButNotTheNearOne) {
    auto renderer = makeRenderer();
    ASSERT_TRUE(renderer);
    const auto scene = twoTubes();
    const QImage none = renderer->render(scene, options(VesselCue::None));
    const QImage fog = renderer->render(scene, options(VesselCue::Fog));
    keep(fog, "fog");
    const int x = none.width() / 2;
    const auto [near, far] = tubeRows(none, x);
    const int nearRow = (near.first + near.second) / 2;
    const int farRow = (far.first + far.second) / 2;
    const float farBefore = distance(none.pixel(x, farRow), backgroundRgb_);
    const float farAfter = distance(fog.pixel(x, farRow), backgroundRgb_);
    EXPECT_LT(farAfter, 0.5F * farBefore);
    // The nearest point has t = 0: no fog there.
    EXPECT_LT(
        distance(fog.pixel(x, near.first + (near.second - near.first) / 2), none.pixel(x, nearRow)),
        0.08F);
}

TEST_F(VesselCueTest, FresnelChangesSilhouettesMoreThanTheInterior) {
    auto renderer = makeRenderer();
    ASSERT_TRUE(renderer);
    const auto scene = twoTubes();
    const QImage none = renderer->render(scene, options(VesselCue::None));
    const QImage fresnel = renderer->render(scene, options(VesselCue::Fresnel));
    keep(fresnel, "fresnel");
    const int x = none.width() / 2;
    const auto rows = tubeRows(none, x);
    for (const auto& [first, last] : {rows.first, rows.second}) {
        const int centre = (first + last) / 2;
        const float edge = std::max(distance(none.pixel(x, first), fresnel.pixel(x, first)),
                                    distance(none.pixel(x, last), fresnel.pixel(x, last)));
        const float middle = distance(none.pixel(x, centre), fresnel.pixel(x, centre));
        EXPECT_GT(edge, middle + 0.1F) << "tube rows " << first << ".." << last;
        EXPECT_LT(middle, 0.06F);  // the interior keeps its colour
    }
}

TEST_F(VesselCueTest, CueChangesReshadeWithoutSolvingAndShareTheVssDepthRange) {
    auto renderer = makeRenderer();
    ASSERT_TRUE(renderer);
    const auto scene = twoTubes();
    static_cast<void>(renderer->render(scene, options(VesselCue::None, true)));
    EXPECT_EQ(state(*renderer, "vss-solve"), PassState::Executed);
    bool first = true;
    for (const VesselCue cue : {VesselCue::PseudoChromadepth, VesselCue::Fog, VesselCue::Fresnel,
                                VesselCue::Chromadepth, VesselCue::None}) {
        static_cast<void>(renderer->render(scene, options(cue, true)));
        EXPECT_EQ(state(*renderer, "vss-solve"), PassState::Cached) << name(cue);
        EXPECT_EQ(state(*renderer, "geometry"), PassState::Cached) << name(cue);
        EXPECT_EQ(state(*renderer, "vessel-shading"), PassState::Executed) << name(cue);
        if (cue != VesselCue::None) {
            EXPECT_EQ(state(*renderer, "depth-range"),
                      first ? PassState::Executed : PassState::Cached);
            first = false;
            const auto range = renderer->lastCueDepthRange();
            ASSERT_TRUE(range.has_value());
            const auto& status = renderer->vssStatus();
            ASSERT_TRUE(status.shown);
            EXPECT_DOUBLE_EQ(range->first, status.dmin);
            EXPECT_DOUBLE_EQ(range->second, status.dmax);
        }
    }
    // Without the VSS: the visible range, the same numbers here, no solve.
    static_cast<void>(renderer->render(scene, options(VesselCue::None, true)));
    const double dmin = renderer->vssStatus().dmin;
    const double dmax = renderer->vssStatus().dmax;
    static_cast<void>(renderer->render(scene, options(VesselCue::PseudoChromadepth)));
    EXPECT_EQ(state(*renderer, "vss-solve"), PassState::Culled);
    // Same view as the cue frames above: the read-back range is reused.
    EXPECT_EQ(state(*renderer, "depth-range"), PassState::Cached);
    const auto visible = renderer->lastCueDepthRange();
    ASSERT_TRUE(visible.has_value());
    EXPECT_NEAR(visible->first, dmin, 1e-4);
    EXPECT_NEAR(visible->second, dmax, 1e-4);
    // A new viewport re-reads it.
    auto resized = options(VesselCue::Fog);
    resized.width = 200;
    static_cast<void>(renderer->render(scene, resized));
    EXPECT_EQ(state(*renderer, "depth-range"), PassState::Executed);
    static_cast<void>(renderer->render(scene, resized));
    EXPECT_EQ(state(*renderer, "depth-range"), PassState::Cached);
    // The near tube's top is about 5 + 1.5 in front of the far tube's: dmax - dmin > 10.
    EXPECT_GT(dmax - dmin, 10.0);
}

TEST_F(VesselCueTest, LegendsArePaintedExactlyWhenTheirScalesAreUsed) {
    auto renderer = makeRenderer();
    ASSERT_TRUE(renderer);
    const auto scene = twoTubes();
    const QRectF area(0.0, 0.0, 320.0, 240.0);
    const auto differsInside = [](const QImage& a, const QImage& b, const QRectF& box) {
        long differing = 0;
        const QRect r = box.toAlignedRect().intersected(a.rect());
        for (int y = r.top(); y <= r.bottom(); ++y) {
            for (int x = r.left(); x <= r.right(); ++x) {
                differing += a.pixel(x, y) != b.pixel(x, y) ? 1 : 0;
            }
        }
        return differing;
    };
    struct Case {
        bool vss;
        std::string array;
        bool depthLegend;
        bool parameterLegend;
    };
    for (const Case& c : {Case{false, "", false, false}, Case{true, "", true, false},
                          Case{false, "speed", false, true}, Case{true, "speed", true, true}}) {
        auto o = options(VesselCue::None, c.vss);
        o.display.style.array = c.array;
        o.display.legends = false;
        const QImage off = renderer->render(scene, o);
        o.display.legends = true;
        const QImage on = renderer->render(scene, o);
        keep(on, "legends-" + std::string(c.vss ? "vss" : "novss") + "-" +
                     (c.array.empty() ? "noarray" : c.array));
        vv::render::Legends expected;
        if (c.depthLegend) {
            expected.depth = vv::render::DepthLegend{};
        }
        if (c.parameterLegend) {
            expected.parameter = vv::render::ParameterLegend{};
        }
        const auto layout = vv::render::legendLayout(area, expected);
        if (!c.depthLegend && !c.parameterLegend) {
            EXPECT_EQ(on, off) << "no legend expected";
            continue;
        }
        if (c.depthLegend) {
            EXPECT_GT(differsInside(on, off, layout.depth), 200) << c.vss << c.array;
        }
        if (c.parameterLegend) {
            EXPECT_GT(differsInside(on, off, layout.parameter), 200) << c.vss << c.array;
        }
        // Nothing outside the legend boxes changes (the centre stays free).
        QImage masked = on;
        for (const QRectF& box : {layout.depth, layout.parameter}) {
            const QRect r = box.toAlignedRect().adjusted(-1, -1, 1, 1).intersected(on.rect());
            for (int y = r.top(); y <= r.bottom(); ++y) {
                for (int x = r.left(); x <= r.right(); ++x) {
                    masked.setPixel(x, y, off.pixel(x, y));
                }
            }
        }
        EXPECT_EQ(masked, off) << c.vss << c.array;
    }
}

/// The depth legend over [dmin, dmax] from the frontmost vessel.
vv::render::DepthLegend depthLegend(double dmin, double dmax) {
    vv::render::DepthLegend legend;
    legend.dmin = dmin;
    legend.dmax = dmax;
    return legend;
}

TEST(LegendTicksTest, DepthLabelsRunFromZeroAtDminToTheRangeAtDmax) {
    const auto ticks = vv::render::depthLegendTicks(depthLegend(100.0, 130.0));
    ASSERT_GE(ticks.size(), 2U);
    EXPECT_DOUBLE_EQ(ticks.front().value, 0.0);
    EXPECT_DOUBLE_EQ(ticks.front().position, 0.0);
    EXPECT_EQ(ticks.front().label, "0");
    EXPECT_DOUBLE_EQ(ticks.back().value, 30.0);
    EXPECT_DOUBLE_EQ(ticks.back().position, 1.0);
    EXPECT_EQ(ticks.back().label, "30");
    std::vector<std::string> labels;
    for (std::size_t i = 0; i < ticks.size(); ++i) {
        labels.push_back(ticks[i].label.toStdString());
        EXPECT_NEAR(ticks[i].position, ticks[i].value / 30.0, 1e-12);
        if (i > 0) {
            EXPECT_GT(ticks[i].value, ticks[i - 1].value);
        }
    }
    EXPECT_EQ(labels, (std::vector<std::string>{"0", "10", "20", "30"}));

    const auto odd = vv::render::depthLegendTicks(depthLegend(10.0, 33.4));
    std::vector<std::string> oddLabels;
    for (const auto& t : odd) {
        oddLabels.push_back(t.label.toStdString());
    }
    // One precision for the whole legend: the end's 3 significant digits.
    EXPECT_EQ(oddLabels, (std::vector<std::string>{"0.0", "10.0", "23.4"}));
    EXPECT_NEAR(odd[1].position, 10.0 / 23.4, 1e-12);

    // A flat scene: one tick, 0.
    const auto flat = vv::render::depthLegendTicks(depthLegend(42.0, 42.0));
    ASSERT_EQ(flat.size(), 1U);
    EXPECT_EQ(flat.front().label, "0");
}

TEST(LegendTicksTest, ViewingDistanceLabelsRunFromNearToFar) {
    vv::render::DepthLegend fixed = depthLegend(100.0, 130.0);
    fixed.reference = vv::render::DepthReference::Camera;
    const auto ticks = vv::render::depthLegendTicks(fixed);
    std::vector<std::string> labels;
    for (const auto& t : ticks) {
        labels.push_back(t.label.toStdString());
        EXPECT_NEAR(t.position, (t.value - 100.0) / 30.0, 1e-12);
    }
    EXPECT_EQ(labels, (std::vector<std::string>{"100", "110", "120", "130"}));
}

TEST(LegendTicksTest, ParameterTicksKeepBothEndsAndNiceValuesBetween) {
    const auto ticks = vv::render::legendTicks(0.450075, 1.30846);
    ASSERT_GE(ticks.size(), 3U);
    EXPECT_EQ(ticks.front().label, "0.45");
    EXPECT_EQ(ticks.back().label, "1.31");
    for (std::size_t i = 1; i + 1 < ticks.size(); ++i) {
        EXPECT_GT(ticks[i].position, 0.0);
        EXPECT_LT(ticks[i].position, 1.0);
        const double steps = ticks[i].value / 0.25;
        EXPECT_NEAR(steps, std::round(steps), 1e-9) << ticks[i].label.toStdString();
    }
    std::vector<std::string> labels;
    for (const auto& t : vv::render::legendTicks(1.0, 3.0)) {
        labels.push_back(t.label.toStdString());
    }
    EXPECT_EQ(labels, (std::vector<std::string>{"1.0", "1.5", "2.0", "2.5", "3.0"}));
    // One precision for every label: the 0.25 grid's two decimals.
    const auto big = vv::render::legendTicks(99.0685, 100.0);
    for (const auto& t : big) {
        EXPECT_EQ(t.label.size() - t.label.indexOf('.'), 3) << t.label.toStdString();
    }
    EXPECT_EQ(big.front().label, "99.07");
    EXPECT_EQ(big.back().label, "100.00");
}

TEST(LegendTicksTest, LegendsForFollowTheFrame) {
    const auto scene = twoTubes();
    vv::render::MeshStyle style;
    vv::render::FrameSettings settings;
    vv::render::VssFrameStatus status;
    status.shown = true;
    status.dmin = 20.0;
    status.dmax = 45.0;
    settings.vss.enabled = true;
    settings.vss.scale = vv::colormaps::DepthScale::DarkMeansDeep;
    auto legends = vv::render::legendsFor(&scene, style, std::nullopt, settings, status, {});
    ASSERT_TRUE(legends.depth.has_value());
    EXPECT_EQ(legends.depth->scale, vv::colormaps::DepthScale::DarkMeansDeep);
    EXPECT_DOUBLE_EQ(legends.depth->dmin, 20.0);
    EXPECT_DOUBLE_EQ(legends.depth->dmax, 45.0);
    EXPECT_FALSE(legends.parameter.has_value());

    settings.vss.enabled = false;
    EXPECT_TRUE(vv::render::legendsFor(&scene, style, std::nullopt, settings, status, {}).empty());

    style.array = "speed";
    style.colorMap = vv::colormaps::ColorMap::Inferno;
    legends =
        vv::render::legendsFor(&scene, style, std::make_pair(1.0F, 3.0F), settings, status, {});
    EXPECT_FALSE(legends.depth.has_value());
    ASSERT_TRUE(legends.parameter.has_value());
    EXPECT_EQ(legends.parameter->unit, "m/s");
    EXPECT_EQ(vv::render::parameterLegendTitle(*legends.parameter), "speed (m/s)");
    EXPECT_FLOAT_EQ(legends.parameter->max, 3.0F);

    // A vessel cue that colours by depth: its scale, the cue's range; the
    // parameter colours are replaced, so no parameter legend.
    settings.cue.cue = VesselCue::PseudoChromadepth;
    legends = vv::render::legendsFor(&scene, style, std::make_pair(1.0F, 3.0F), settings, status,
                                     std::make_pair(5.0, 9.0));
    ASSERT_TRUE(legends.depth.has_value());
    EXPECT_EQ(legends.depth->scale, vv::colormaps::DepthScale::PseudoChromadepth);
    EXPECT_DOUBLE_EQ(legends.depth->dmax, 9.0);
    EXPECT_FALSE(legends.parameter.has_value());
}

TEST(VesselCueNamesTest, RoundTripAndUnknown) {
    for (const VesselCue cue : vv::render::allVesselCues()) {
        EXPECT_EQ(vv::render::vesselCueFromName(name(cue)), cue);
    }
    EXPECT_EQ(vv::render::vesselCueFromName("Vessel-PCD"), VesselCue::PseudoChromadepth);
    EXPECT_FALSE(vv::render::vesselCueFromName("pcd").has_value());
    EXPECT_EQ(vv::render::allVesselCues().size(), 5U);
}

}  // namespace
