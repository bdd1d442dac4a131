// SPDX-License-Identifier: GPL-3.0-or-later
// Per-object styles (colour, opacity, array), the translucent pass, the
// legends of several arrays and the light direction. GL tests: run under
// `xvfb-run -a` with QT_QPA_PLATFORM=xcb; without a GL context they fail.
#include <gtest/gtest.h>

#include <QImage>
#include <cmath>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "RenderTestUtil.h"
#include "vv/core/Error.h"
#include "vv/render/FrameRenderer.h"
#include "vv/render/LegendPainter.h"
#include "vv/render/MeshRenderer.h"
#include "vv/render/OffscreenRenderer.h"

namespace {

using vv::render::LightAngles;
using vv::render::MeshStyle;
using vv::render::ObjectStyle;
using vv::render::OffscreenOptions;
using vv::render::PassState;
using vv::render::test::FrameHarness;

/// Adds a point array `name` = a * x + b to every mesh.
void addArray(vv::scene::Scene& scene, const std::string& name, float a, float b) {
    for (auto& mesh : scene.meshes) {
        vv::scene::DataArray array;
        array.name = name;
        array.unit = "u";
        array.components = 1;
        for (const auto& p : mesh.positions) {
            array.values.push_back(a * p.x + b);
        }
        mesh.pointArrays.push_back(std::move(array));
    }
}

/// The near tube on top (mesh 0, z = +4) and the far one below (mesh 1), with
/// arrays "speed" (1..3) and "pressure" (100..300).
vv::scene::Scene scene() {
    vv::scene::Scene s = vv::render::test::twoTubes(1.5F, 4.0F, 40, 16);
    addArray(s, "speed", 0.1F, 2.0F);
    addArray(s, "pressure", 10.0F, 200.0F);
    return s;
}

class ObjectStyleTest : public vv::render::test::GlRenderTest {
  protected:
    OffscreenOptions options(bool vss) const {
        OffscreenOptions o = vv::render::test::exactOptions(240, 180);
        o.display.background = background_;
        o.display.vss.enabled = vss;
        o.display.style.array.clear();
        return o;
    }
    /// A 160 x 120 harness, or a test failure naming why there is none.
    static std::unique_ptr<FrameHarness> makeHarness() {
        try {
            return std::make_unique<FrameHarness>(160, 120);
        } catch (const vv::Error& e) {
            ADD_FAILURE() << e.what();
            return nullptr;
        }
    }
    static void keep(const QImage& image, const std::string& name) {
        vv::render::test::saveImage(image, "objects-", name);
    }
};

TEST(LightAnglesTest, DirectionsFollowAzimuthAndElevation) {
    const auto near = [](glm::vec3 a, glm::vec3 b) { return glm::length(a - b) < 1e-5F; };
    EXPECT_TRUE(near(vv::render::lightDirection({0.0F, 0.0F}), {0.0F, 0.0F, 1.0F}));
    EXPECT_TRUE(near(vv::render::lightDirection({90.0F, 0.0F}), {1.0F, 0.0F, 0.0F}));
    EXPECT_TRUE(near(vv::render::lightDirection({-90.0F, 0.0F}), {-1.0F, 0.0F, 0.0F}));
    EXPECT_TRUE(near(vv::render::lightDirection({0.0F, 90.0F}), {0.0F, 1.0F, 0.0F}));
    // The default is the key light every pass used before it could move.
    EXPECT_TRUE(
        near(vv::render::lightDirection(LightAngles{}), vv::render::sceneLighting().direction));
    EXPECT_THROW(static_cast<void>(vv::render::lightDirection({181.0F, 0.0F})),
                 vv::InvalidArgumentError);
    EXPECT_THROW(static_cast<void>(vv::render::lightDirection({0.0F, -91.0F})),
                 vv::InvalidArgumentError);
    EXPECT_THROW(static_cast<void>(vv::render::lightDirection({std::nanf(""), 0.0F})),
                 vv::InvalidArgumentError);
}

TEST(MeshStyleTest, ObjectsResolveTheirArrayAndOpacity) {
    MeshStyle style;
    style.array = "speed";
    style.objects.resize(3);
    style.objects[1].array = "";
    style.objects[2].array = "pressure";
    style.objects[2].opacity = 0.5F;
    EXPECT_EQ(style.arrayOf(0), "speed");
    EXPECT_EQ(style.arrayOf(1), "");
    EXPECT_EQ(style.arrayOf(2), "pressure");
    EXPECT_EQ(style.arrayOf(7), "speed");  // beyond the list: the scene's style
    EXPECT_TRUE(style.opaque(0));
    EXPECT_TRUE(style.translucent(2));
    EXPECT_FALSE(style.opaque(2));
    const auto key = style.geometryKey();
    style.objects[0].color = glm::vec3(0.0F, 1.0F, 0.0F);  // colour: not in the G-buffer
    EXPECT_EQ(style.geometryKey(), key);
    style.objects[0].array = "pressure";
    EXPECT_NE(style.geometryKey(), key);
    style.objects[1].opacity = 0.0F;  // fully transparent = hidden
    EXPECT_FALSE(style.visible(1));
    EXPECT_FALSE(style.translucent(1));
    style.objects[1].opacity = 1.5F;
    EXPECT_THROW(vv::render::validateStyle(style), vv::InvalidArgumentError);
}

TEST_F(ObjectStyleTest, ObjectColourChangesOnlyThatObjectsPixels) {
    const auto harness = makeHarness();
    ASSERT_TRUE(harness);
    harness->setScene(scene());
    MeshStyle style;
    style.array.clear();
    const QImage before = harness->render(style, flatSettings());
    const auto ids = harness->objectIds();
    style.objects.resize(1);
    style.objects[0].color = glm::vec3(0.1F, 0.8F, 0.2F);
    const QImage after = harness->render(style, flatSettings());
    keep(after, "colour");
    int changedOwn = 0;
    int own = 0;
    int others = 0;
    for (int y = 0; y < before.height(); ++y) {
        for (int x = 0; x < before.width(); ++x) {
            const std::uint32_t id = ids[static_cast<std::size_t>(y * before.width() + x)];
            const bool changed = before.pixel(x, y) != after.pixel(x, y);
            if (id == 1U) {
                ++own;
                changedOwn += changed ? 1 : 0;
                if (changed) {
                    EXPECT_GT(qGreen(after.pixel(x, y)), qRed(after.pixel(x, y)));
                }
            } else {
                ++others;
                EXPECT_FALSE(changed) << "pixel " << x << "," << y << " of object " << id;
            }
        }
    }
    EXPECT_GT(own, 500);
    EXPECT_GT(others, 500);
    EXPECT_GT(changedOwn, own * 95 / 100);
    // A colour is no geometry: the G-buffer was reused.
    const auto& passes = harness->renderer().lastPasses();
    for (const auto& pass : passes) {
        if (pass.name == "geometry") {
            EXPECT_EQ(pass.state, PassState::Cached);
        }
    }
}

TEST_F(ObjectStyleTest, AnObjectsOwnArrayColoursOnlyItWithItsOwnRange) {
    const auto harness = makeHarness();
    ASSERT_TRUE(harness);
    const vv::scene::Scene s = scene();
    harness->setScene(s);
    MeshStyle style;
    style.array = "speed";
    style.lighting = false;  // exact colour-map colours
    const QImage before = harness->render(style, flatSettings());
    const auto ids = harness->objectIds();
    style.objects.resize(2);
    style.objects[1].array = "pressure";
    const QImage after = harness->render(style, flatSettings());
    keep(after, "array");
    // "pressure" is "speed" * 100 over the same x: with its own automatic
    // range the colours are the same (both span their own min..max) ...
    int own = 0;
    for (int y = 0; y < before.height(); ++y) {
        for (int x = 0; x < before.width(); ++x) {
            const std::uint32_t id = ids[static_cast<std::size_t>(y * before.width() + x)];
            own += id == 2U ? 1 : 0;
            EXPECT_LE(glm::length(vv::render::test::toVec(before.pixel(x, y)) -
                                  vv::render::test::toVec(after.pixel(x, y))),
                      0.02F)
                << x << "," << y;
        }
    }
    EXPECT_GT(own, 500);
    const auto range = harness->renderer().meshRenderer().objectRange(1);
    ASSERT_TRUE(range.has_value());
    EXPECT_NEAR(range->first, 100.0F, 1e-3F);
    EXPECT_NEAR(range->second, 300.0F, 1e-3F);
    // ... and None shows the material colour on that object only.
    style.objects[1].array = "";
    const QImage none = harness->render(style, flatSettings());
    int changed = 0;
    for (int y = 0; y < none.height(); ++y) {
        for (int x = 0; x < none.width(); ++x) {
            const std::uint32_t id = ids[static_cast<std::size_t>(y * none.width() + x)];
            if (id == 2U) {
                changed += none.pixel(x, y) != after.pixel(x, y) ? 1 : 0;
            } else {
                EXPECT_EQ(none.pixel(x, y), after.pixel(x, y));
            }
        }
    }
    EXPECT_GT(changed, own * 9 / 10);
}

TEST_F(ObjectStyleTest, HalfOpacityShowsTheVssThroughAndZeroHides) {
    auto renderer = makeRenderer();
    ASSERT_TRUE(renderer);
    const vv::scene::Scene s = scene();
    // Where the near tube is: the pixels it covers alone, without a VSS.
    OffscreenOptions alone = options(false);
    alone.display.style.hidden = {1};
    const QImage nearTube = renderer->render(s, alone);
    OffscreenOptions o = options(true);
    const QImage opaque = renderer->render(s, o);
    EXPECT_EQ(state(*renderer, "translucent"), PassState::Culled);
    o.display.style.hidden = {0};
    const QImage hidden = renderer->render(s, o);
    o.display.style.hidden.clear();
    o.display.style.objects.resize(1);
    o.display.style.objects[0].opacity = 0.5F;
    const QImage half = renderer->render(s, o);
    EXPECT_EQ(state(*renderer, "translucent"), PassState::Executed);
    keep(half, "half");
    // The near tube's centre: half its own colour, half what is behind it.
    const int x = half.width() / 2;
    int checked = 0;
    for (int y = 0; y < half.height() / 2; ++y) {
        const glm::vec3 a = vv::render::test::toVec(opaque.pixel(x, y));
        const glm::vec3 b = vv::render::test::toVec(hidden.pixel(x, y));
        if (nearTube.pixel(x, y) == backgroundRgb_ || glm::length(a - b) < 0.2F) {
            continue;  // not on the near tube, or too alike to tell
        }
        const glm::vec3 h = vv::render::test::toVec(half.pixel(x, y));
        EXPECT_LE(glm::length(h - 0.5F * (a + b)), 0.03F) << "row " << y;
        ++checked;
    }
    EXPECT_GT(checked, 5);
    // What shows through is the VSS, not the background.
    EXPECT_NE(hidden.pixel(x, half.height() / 4), backgroundRgb_);
    o.display.style.objects[0].opacity = 0.0F;
    EXPECT_EQ(renderer->render(s, o), hidden);
    EXPECT_EQ(state(*renderer, "translucent"), PassState::Culled);
}

TEST_F(ObjectStyleTest, ASecondArrayAddsASecondLegend) {
    vv::scene::Scene s = scene();
    MeshStyle style;
    style.array = "speed";
    vv::render::FrameSettings settings;
    settings.vss.enabled = false;
    const vv::render::VssFrameStatus status;
    const auto range = std::make_pair(1.0F, 3.0F);
    auto legends = vv::render::legendsFor(&s, style, range, settings, status, {});
    ASSERT_TRUE(legends.parameter.has_value());
    EXPECT_TRUE(legends.moreParameters.empty());
    style.objects.resize(2);
    style.objects[1].array = "pressure";
    legends = vv::render::legendsFor(&s, style, range, settings, status, {});
    ASSERT_TRUE(legends.parameter.has_value());
    EXPECT_EQ(legends.parameter->name, "speed");
    ASSERT_EQ(legends.moreParameters.size(), 1U);
    EXPECT_EQ(legends.moreParameters[0].name, "pressure");
    // Its own range: over the objects that show it (mesh 1 only).
    const auto own = vv::render::objectArrayRange(s, style, "pressure");
    ASSERT_TRUE(own.has_value());
    EXPECT_FLOAT_EQ(legends.moreParameters[0].min, own->first);
    EXPECT_FLOAT_EQ(legends.moreParameters[0].max, own->second);
    const auto layout = vv::render::legendLayout(QRectF(0, 0, 800, 600), legends);
    ASSERT_EQ(layout.moreParameters.size(), 1U);
    EXPECT_FALSE(layout.moreParameters[0].intersects(layout.parameter));
    EXPECT_LT(layout.moreParameters[0].bottom(), layout.parameter.top());
    // Painted: the image differs inside the second box.
    QImage with(800, 600, QImage::Format_RGB32);
    with.fill(Qt::white);
    QImage without = with;
    vv::render::paintLegends(with, legends);
    legends.moreParameters.clear();
    vv::render::paintLegends(without, legends);
    const QRect box = layout.moreParameters[0].toRect();
    EXPECT_NE(with.copy(box), without.copy(box));
    // No object shows an array: no parameter legend.
    style.objects[0].array = "";
    style.objects[1].array = "";
    legends = vv::render::legendsFor(&s, style, range, settings, status, {});
    EXPECT_FALSE(legends.parameter.has_value());
    EXPECT_TRUE(legends.moreParameters.empty());
    // Only the other array shown: it is the (single) parameter legend.
    style.objects[1].array = "pressure";
    legends = vv::render::legendsFor(&s, style, range, settings, status, {});
    ASSERT_TRUE(legends.parameter.has_value());
    EXPECT_EQ(legends.parameter->name, "pressure");
    EXPECT_TRUE(legends.moreParameters.empty());
}

TEST_F(ObjectStyleTest, LightDirectionReshadesVesselsAndVssWithoutANewSolve) {
    auto renderer = makeRenderer();
    ASSERT_TRUE(renderer);
    const vv::scene::Scene s = scene();
    const QImage vesselsOnly = renderer->render(s, options(false));
    OffscreenOptions o = options(true);
    const QImage before = renderer->render(s, o);
    EXPECT_EQ(state(*renderer, "vss-solve"), PassState::Executed);
    o.display.style.light = LightAngles{60.0F, -40.0F};
    const QImage after = renderer->render(s, o);
    keep(before, "light-default");
    keep(after, "light-moved");
    EXPECT_EQ(state(*renderer, "vss-solve"), PassState::Cached);
    EXPECT_EQ(state(*renderer, "geometry"), PassState::Cached);
    EXPECT_EQ(state(*renderer, "vessel-shading"), PassState::Executed);
    EXPECT_EQ(state(*renderer, "vss-shading"), PassState::Executed);
    int vesselChanged = 0;
    int vssChanged = 0;
    for (int y = 0; y < before.height(); ++y) {
        for (int x = 0; x < before.width(); ++x) {
            const bool vessel = vesselsOnly.pixel(x, y) != backgroundRgb_;
            const bool vss = !vessel && before.pixel(x, y) != backgroundRgb_;
            const bool changed = glm::length(vv::render::test::toVec(before.pixel(x, y)) -
                                             vv::render::test::toVec(after.pixel(x, y))) > 0.05F;
            vesselChanged += vessel && changed ? 1 : 0;
            vssChanged += vss && changed ? 1 : 0;
        }
    }
    EXPECT_GT(vesselChanged, 300);
    EXPECT_GT(vssChanged, 300);
    // Back to the default: the first image again.
    o.display.style.light = LightAngles{};
    EXPECT_EQ(renderer->render(s, o), before);
}

}  // namespace
