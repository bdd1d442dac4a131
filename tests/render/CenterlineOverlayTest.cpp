// SPDX-License-Identifier: GPL-3.0-or-later
// Centrelines over a view (vv/render/CenterlineOverlay.h): a vessel's axis is
// seen through its own wall and hidden behind another vessel in front; the
// lines carry the colour map's colour of their diameter, or their branch's
// colour; the legend says which. No GL: the depth is the CPU rasteriser's.
#include <gtest/gtest.h>

#include <QColor>
#include <QImage>
#include <cmath>
#include <cstddef>
#include <glm/glm.hpp>
#include <limits>
#include <vector>

#include "GlTestSupport.h"
#include "vv/colormaps/LabelPalette.h"
#include "vv/core/Error.h"
#include "vv/demo/TubePhantom.h"
#include "vv/render/CenterlineOverlay.h"
#include "vv/render/DepthRasterizer.h"

namespace vv::render {
namespace {

constexpr double kRadius = 2.0;
constexpr double kLength = 40.0;

/// A closed cylinder of kRadius along the world direction `along` (x or y),
/// centred on `centre`.
scene::Mesh cylinder(const glm::dvec3& centre, bool alongX) {
    demo::TubePhantomOptions o;
    o.radiusMm = kRadius;
    o.lengthMm = kLength;
    o.targetTriangles = 4000;
    scene::Mesh mesh = demo::makeTubePhantom(o).mesh;  // along +z from the origin
    for (auto& p : mesh.positions) {
        const glm::dvec3 q(p);
        const double s = q.z - kLength / 2.0;
        // Rotations (determinant +1), so the triangles keep facing outwards.
        const glm::dvec3 turned = alongX ? glm::dvec3(s, q.x, q.y) : glm::dvec3(q.y, s, q.x);
        p = glm::vec3(centre + turned);
    }
    return mesh;
}

/// The axis of cylinder(centre, true) as a line of points every 0.5 mm,
/// each claiming `radius`.
OverlayPolyline axisAlongX(const glm::dvec3& centre, float radius, int branch = 0) {
    OverlayPolyline line;
    line.branch = branch;
    for (double x = -kLength / 2.0 + 1.0; x <= kLength / 2.0 - 1.0; x += 0.5) {
        line.points.emplace_back(centre + glm::dvec3(x, 0.0, 0.0));
        line.radiiMm.push_back(radius);
    }
    return line;
}

/// Looking down -z at the scene, 400 x 300 pixels.
Camera topCamera(const scene::Scene& scene) {
    Camera camera;
    camera.setViewport(400, 300);
    camera.fit(scene.bounds());
    return camera;
}

TEST(CenterlineOverlay, AnAxisShowsThroughItsOwnWallButNotBehindAnotherVessel) {
    // A vessel along x at z = 0, another along y crossing in front of it.
    scene::Scene scene;
    scene.meshes.push_back(cylinder({0.0, 0.0, 0.0}, true));
    scene.meshes.push_back(cylinder({0.0, 0.0, 8.0}, false));
    const Camera camera = topCamera(scene);
    const Image<float> depth = rasterizeDepth(scene, camera);

    const OverlayPolyline line = axisAlongX({0.0, 0.0, 0.0}, static_cast<float>(kRadius));
    const std::vector<bool> shown = visiblePoints(line, camera, depth);
    ASSERT_EQ(shown.size(), line.points.size());
    int under = 0;
    for (std::size_t i = 0; i < shown.size(); ++i) {
        const double x = line.points[i].x;
        if (std::abs(x) > kRadius + 1.0) {
            EXPECT_TRUE(shown[i]) << "x = " << x << ": behind its own wall only";
        } else if (std::abs(x) < kRadius - 0.5) {
            EXPECT_FALSE(shown[i]) << "x = " << x << ": behind the vessel in front";
            ++under;
        }
    }
    EXPECT_GT(under, 4);

    // The same line claiming a vessel far thinner than the wall in front of
    // it lies too deep to be its own vessel's axis: hidden everywhere.
    const OverlayPolyline thin = axisAlongX({0.0, 0.0, 0.0}, 0.1F);
    for (const bool s : visiblePoints(thin, camera, depth)) {
        EXPECT_FALSE(s);
    }
}

TEST(CenterlineOverlay, LinesCarryTheMapColourOfTheirDiameterOrTheirBranchColour) {
    test::ensureGuiApplication();  // the branch numbers need fonts
    // No surface: every point is visible (background at its pixel).
    scene::Scene scene;
    scene.meshes.push_back(cylinder({0.0, 0.0, 0.0}, true));
    const Camera camera = topCamera(scene);
    Image<float> depth(400, 300, std::numeric_limits<float>::infinity());
    // Diameters growing from 2 to 6 mm along the line.
    OverlayPolyline line = axisAlongX({0.0, 0.0, 0.0}, 1.0F);
    const std::size_t n = line.points.size();
    for (std::size_t i = 0; i < n; ++i) {
        line.radiiMm[i] = 1.0F + 2.0F * static_cast<float>(i) / static_cast<float>(n - 1);
    }
    CenterlineOverlay overlay;
    overlay.lines = {line};
    overlay.min = 2.0F;
    overlay.max = 6.0F;
    overlay.map = colormaps::ColorMap::Inferno;

    QImage image(400, 300, QImage::Format_RGB32);
    image.fill(QColor(128, 128, 128));
    paintCenterlines(image, camera, depth, overlay, 1.0);
    int checked = 0;
    for (const std::size_t i : {n / 4, n / 2, 3 * n / 4}) {
        // The line runs along the image's middle row (the camera looks down -z at its axis).
        const glm::vec4 clip =
            camera.projectionMatrix() * camera.viewMatrix() * glm::vec4(line.points[i], 1.0F);
        const int x = static_cast<int>((clip.x / clip.w * 0.5F + 0.5F) * 400.0F);
        const int y = static_cast<int>((0.5F - clip.y / clip.w * 0.5F) * 300.0F);
        const float t = (2.0F * line.radiiMm[i] - overlay.min) / (overlay.max - overlay.min);
        const glm::vec3 want = colormaps::sample(overlay.map, t);
        const QColor got = image.pixelColor(x, y);
        // One segment's colour is its two ends' mean: within one step of 0.5 mm.
        EXPECT_NEAR(got.redF(), want.r, 0.04) << "point " << i;
        EXPECT_NEAR(got.greenF(), want.g, 0.04) << "point " << i;
        EXPECT_NEAR(got.blueF(), want.b, 0.04) << "point " << i;
        ++checked;
    }
    EXPECT_EQ(checked, 3);

    overlay.colouring = CenterlineColouring::Branch;
    overlay.lines.front().branch = 3;
    image.fill(QColor(128, 128, 128));
    paintCenterlines(image, camera, depth, overlay, 1.0);
    const glm::vec3 branch = colormaps::labelColor(3);
    const QColor got = image.pixelColor(100, 150);
    EXPECT_NEAR(got.redF(), branch.r, 0.02);
    EXPECT_NEAR(got.greenF(), branch.g, 0.02);
    EXPECT_NEAR(got.blueF(), branch.b, 0.02);
}

TEST(CenterlineOverlay, TheLegendSaysWhatTheColoursMean) {
    CenterlineOverlay overlay;
    overlay.lines.push_back(axisAlongX({0.0, 0.0, 0.0}, 1.0F));
    overlay.min = 1.5F;
    overlay.max = 7.25F;
    overlay.map = colormaps::ColorMap::Cividis;
    const auto legend = centerlineLegend(overlay);
    ASSERT_TRUE(legend.has_value());
    EXPECT_EQ(legend->title, "Centreline: inscribed diameter (mm)");
    EXPECT_FLOAT_EQ(legend->min, 1.5F);
    EXPECT_FLOAT_EQ(legend->max, 7.25F);
    EXPECT_EQ(legend->map, colormaps::ColorMap::Cividis);
    EXPECT_TRUE(legend->labels.empty());

    // Beside a parameter legend it goes above it; alone it is the parameter legend.
    Legends legends;
    addCenterlineLegend(legends, overlay);
    ASSERT_TRUE(legends.parameter.has_value());
    EXPECT_EQ(legends.parameter->title, legend->title);
    Legends withArray;
    withArray.parameter = ParameterLegend{};
    withArray.parameter->name = "wss";
    addCenterlineLegend(withArray, overlay);
    EXPECT_EQ(withArray.parameter->name, "wss");
    ASSERT_EQ(withArray.moreParameters.size(), 1U);
    EXPECT_EQ(withArray.moreParameters.front().title, legend->title);

    // Branch colours are named by the numbers on the lines, not by a legend;
    // no lines, no legend.
    overlay.colouring = CenterlineColouring::Branch;
    EXPECT_FALSE(centerlineLegend(overlay).has_value());
    overlay.colouring = CenterlineColouring::InscribedDiameter;
    overlay.lines.clear();
    EXPECT_FALSE(centerlineLegend(overlay).has_value());
    Legends none;
    addCenterlineLegend(none, overlay);
    EXPECT_TRUE(none.empty());
}

TEST(CenterlineOverlay, MismatchedInputsAreRefused) {
    test::ensureGuiApplication();
    scene::Scene scene;
    scene.meshes.push_back(cylinder({0.0, 0.0, 0.0}, true));
    const Camera camera = topCamera(scene);
    const Image<float> small(200, 150, 1.0F);
    const OverlayPolyline line = axisAlongX({0.0, 0.0, 0.0}, 1.0F);
    EXPECT_THROW(static_cast<void>(visiblePoints(line, camera, small)), InvalidArgumentError);
    OverlayPolyline uneven = line;
    uneven.radiiMm.pop_back();
    const Image<float> depth(400, 300, 1.0F);
    EXPECT_THROW(static_cast<void>(visiblePoints(uneven, camera, depth)), InvalidArgumentError);
    CenterlineOverlay overlay;
    overlay.lines = {line};
    QImage image(300, 300, QImage::Format_RGB32);
    EXPECT_THROW(paintCenterlines(image, camera, depth, overlay, 1.0), InvalidArgumentError);
}

}  // namespace
}  // namespace vv::render
