// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>

#include "vv/core/Error.h"
#include "vv/demo/DemoTree.h"
#include "vv/render/DepthRasterizer.h"
#include "vv/render/ViewPresets.h"

namespace {

using vv::Image;
using vv::render::AnatomicalView;
using vv::render::ViewPreset;

constexpr int kWidth = 640;
constexpr int kHeight = 360;

/// The default demo tree, made once (it takes a moment).
const vv::scene::Scene& demoScene() {
    static const vv::scene::Scene scene = [] {
        vv::scene::Scene s;
        s.meshes.push_back(vv::demo::generateDemoMesh());
        return s;
    }();
    return scene;
}

struct Silhouette {
    int minX = 1 << 30;
    int minY = 1 << 30;
    int maxX = -1;
    int maxY = -1;
    long pixels = 0;
    std::array<bool, 4> touches{};  ///< left, top, right, bottom border
    int crossings = 0;              ///< vessel runs along the border, once around
};

Silhouette silhouette(const Image<float>& depth) {
    Silhouette s;
    const int w = depth.width();
    const int h = depth.height();
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            if (!std::isfinite(depth(x, y))) {
                continue;
            }
            ++s.pixels;
            s.minX = std::min(s.minX, x);
            s.maxX = std::max(s.maxX, x);
            s.minY = std::min(s.minY, y);
            s.maxY = std::max(s.maxY, y);
        }
    }
    s.touches = {s.minX == 0, s.minY == 0, s.maxX == w - 1, s.maxY == h - 1};
    std::vector<bool> ring;
    for (int x = 0; x < w; ++x) {
        ring.push_back(std::isfinite(depth(x, 0)));
    }
    for (int y = 0; y < h; ++y) {
        ring.push_back(std::isfinite(depth(w - 1, y)));
    }
    for (int x = w - 1; x >= 0; --x) {
        ring.push_back(std::isfinite(depth(x, h - 1)));
    }
    for (int y = h - 1; y >= 0; --y) {
        ring.push_back(std::isfinite(depth(0, y)));
    }
    for (std::size_t i = 0; i < ring.size(); ++i) {
        s.crossings += ring[i] && !ring[(i + ring.size() - 1) % ring.size()] ? 1 : 0;
    }
    return s;
}

Image<float> depthOf(ViewPreset preset) {
    const auto camera = vv::render::presetCamera(demoScene(), kWidth, kHeight, preset);
    return vv::render::rasterizeDepth(demoScene(), camera);
}

TEST(ViewPresetsTest, NamesRoundTrip) {
    ASSERT_EQ(vv::render::allViewPresets().size(), 3U);
    for (const ViewPreset p : vv::render::allViewPresets()) {
        EXPECT_EQ(vv::render::parseViewPreset(vv::render::toString(p)), p);
    }
    EXPECT_EQ(vv::render::toString(ViewPreset::Far), "far");
    EXPECT_EQ(vv::render::toString(ViewPreset::Medium), "medium");
    EXPECT_EQ(vv::render::toString(ViewPreset::Close), "close");
    EXPECT_EQ(vv::render::viewPresetFromName("CLOSE"), ViewPreset::Close);
    EXPECT_EQ(vv::render::viewPresetFromName("Medium"), ViewPreset::Medium);
    EXPECT_FALSE(vv::render::viewPresetFromName("near").has_value());
    EXPECT_FALSE(vv::render::viewPresetFromName("").has_value());
    EXPECT_FALSE(vv::render::viewPresetFromName("far ").has_value());
    try {
        (void)vv::render::parseViewPreset("sideways");
        FAIL() << "no exception";
    } catch (const vv::InvalidArgumentError& e) {
        EXPECT_NE(std::string(e.what()).find("sideways"), std::string::npos);
        EXPECT_NE(std::string(e.what()).find("medium"), std::string::npos);
    }
}

TEST(ViewPresetsTest, CloserPresetsAreCloser) {
    const auto& scene = demoScene();
    const auto far = vv::render::presetCamera(scene, kWidth, kHeight, ViewPreset::Far);
    const auto medium = vv::render::presetCamera(scene, kWidth, kHeight, ViewPreset::Medium);
    const auto close = vv::render::presetCamera(scene, kWidth, kHeight, ViewPreset::Close);
    EXPECT_GT(far.distance(), medium.distance());
    EXPECT_GT(medium.distance(), close.distance());
    EXPECT_FLOAT_EQ(medium.distance(),
                    far.distance() * vv::render::presetDistanceFactor(ViewPreset::Medium));
    for (const auto* c : {&far, &medium, &close}) {
        EXPECT_EQ(c->viewportWidth(), kWidth);
        EXPECT_EQ(c->viewportHeight(), kHeight);
        const glm::vec3 centre = scene.bounds().center();
        EXPECT_FLOAT_EQ(c->target().x, centre.x);
        EXPECT_FLOAT_EQ(c->target().y, centre.y);
        EXPECT_FLOAT_EQ(c->target().z, centre.z);
        // Near and far planes hold the whole scene.
        EXPECT_GT(c->farPlane(), c->distance() + scene.bounds().radius());
    }
}

TEST(ViewPresetsTest, FarKeepsTheTreeOutOfTheOuterMargin) {
    const Image<float> depth = depthOf(ViewPreset::Far);
    const Silhouette s = silhouette(depth);
    ASSERT_GT(s.pixels, 1000);
    // No vessel pixel in the outer 5 % ...
    EXPECT_GE(s.minX, kWidth / 20);
    EXPECT_GE(s.minY, kHeight / 20);
    EXPECT_LE(s.maxX, kWidth - 1 - kWidth / 20);
    EXPECT_LE(s.maxY, kHeight - 1 - kHeight / 20);
    EXPECT_EQ(s.crossings, 0);
    // ... and the fit is tight: on some side the tree reaches the 10 % line.
    const int mx = static_cast<int>(kWidth * vv::render::kFarViewMargin);
    const int my = static_cast<int>(kHeight * vv::render::kFarViewMargin);
    const int slack = 3;
    const bool tight = s.minX <= mx + slack || s.maxX >= kWidth - 1 - mx - slack ||
                       s.minY <= my + slack || s.maxY >= kHeight - 1 - my - slack;
    EXPECT_TRUE(tight) << s.minX << " " << s.minY << " " << s.maxX << " " << s.maxY;
}

TEST(ViewPresetsTest, MediumTouchesTheBorderAndCloseCrossesItOnSeveralSides) {
    const Silhouette medium = silhouette(depthOf(ViewPreset::Medium));
    const Silhouette close = silhouette(depthOf(ViewPreset::Close));
    EXPECT_GE(medium.crossings, 1);
    EXPECT_GE(close.crossings, medium.crossings);
    EXPECT_GE(close.crossings, 6);
    int sides = 0;
    for (const bool t : close.touches) {
        sides += t ? 1 : 0;
    }
    EXPECT_GE(sides, 3);
    EXPECT_GT(close.pixels, medium.pixels / 2);
}

TEST(ViewPresetsTest, BoxOverloadPutsEveryCornerInsideTheCentralPart) {
    vv::Aabb box;
    box.extend(glm::vec3(-30.0F, 5.0F, -2.0F));
    box.extend(glm::vec3(50.0F, 45.0F, 12.0F));
    const glm::quat turned = glm::angleAxis(0.6F, glm::normalize(glm::vec3(0.3F, 1.0F, 0.1F)));
    for (const glm::quat& rotation : {glm::quat(1.0F, 0.0F, 0.0F, 0.0F), turned}) {
        const auto camera = vv::render::presetCamera(box, 800, 500, ViewPreset::Far, rotation);
        const glm::mat4 pv = camera.projectionMatrix() * camera.viewMatrix();
        float extent = 0.0F;
        for (int i = 0; i < 8; ++i) {
            const glm::vec4 corner{(i & 1) != 0 ? box.max.x : box.min.x,
                                   (i & 2) != 0 ? box.max.y : box.min.y,
                                   (i & 4) != 0 ? box.max.z : box.min.z, 1.0F};
            const glm::vec4 clip = pv * corner;
            ASSERT_GT(clip.w, 0.0F);
            extent = std::max({extent, std::abs(clip.x / clip.w), std::abs(clip.y / clip.w)});
        }
        // Inside the central 80 %, and touching it (a tight fit).
        EXPECT_LE(extent, 0.8F + 1e-4F);
        EXPECT_GE(extent, 0.8F - 1e-3F);
        EXPECT_NEAR(glm::dot(camera.rotation(), rotation), 1.0F, 1e-5F);
    }
    // Empty bounds behave as the unit sphere: a finite, positive distance.
    const auto empty = vv::render::presetCamera(vv::Aabb{}, 100, 100, ViewPreset::Close);
    EXPECT_TRUE(std::isfinite(empty.distance()));
    EXPECT_GT(empty.distance(), 0.0F);
    const auto noMesh = vv::render::presetCamera(vv::scene::Scene{}, 100, 100, ViewPreset::Far);
    EXPECT_TRUE(std::isfinite(noMesh.distance()));
    EXPECT_GT(noMesh.distance(), 0.0F);
}

/// A small axis-aligned box (12 triangles) centred at `c` with half-size `h`.
void addBox(vv::scene::Mesh& mesh, const glm::vec3& c, float h) {
    const auto base = static_cast<std::uint32_t>(mesh.positions.size());
    for (int i = 0; i < 8; ++i) {
        mesh.positions.emplace_back(c.x + ((i & 1) != 0 ? h : -h), c.y + ((i & 2) != 0 ? h : -h),
                                    c.z + ((i & 4) != 0 ? h : -h));
    }
    constexpr std::array<std::uint32_t, 36> kFaces{0, 1, 3, 0, 3, 2, 4, 6, 7, 4, 7, 5,
                                                   0, 4, 5, 0, 5, 1, 2, 3, 7, 2, 7, 6,
                                                   0, 2, 6, 0, 6, 4, 1, 5, 7, 1, 7, 3};
    for (const std::uint32_t i : kFaces) {
        mesh.indices.push_back(base + i);
    }
}

/// Centre of the pixels within 0.5 of the smallest depth of `depth` (the
/// front face of the nearest object); (-1, -1) when nothing is drawn.
glm::vec2 nearestCentroid(const Image<float>& depth) {
    float nearest = std::numeric_limits<float>::infinity();
    for (int y = 0; y < depth.height(); ++y) {
        for (int x = 0; x < depth.width(); ++x) {
            nearest = std::min(nearest, depth(x, y));
        }
    }
    glm::dvec2 sum{0.0};
    long n = 0;
    for (int y = 0; y < depth.height(); ++y) {
        for (int x = 0; x < depth.width(); ++x) {
            if (std::isfinite(depth(x, y)) && depth(x, y) < nearest + 0.5F) {
                sum += glm::dvec2(x + 0.5, y + 0.5);
                ++n;
            }
        }
    }
    return n == 0 ? glm::vec2(-1.0F) : glm::vec2(sum / static_cast<double>(n));
}

/// Pixel coordinates (origin top-left, +y down) of world point `p` seen by `camera`.
glm::vec2 pixelOf(const vv::render::Camera& camera, const glm::vec3& p) {
    const glm::vec4 clip = camera.projectionMatrix() * camera.viewMatrix() * glm::vec4(p, 1.0F);
    const glm::vec2 ndc = glm::vec2(clip) / clip.w;
    return {(ndc.x + 1.0F) * 0.5F * static_cast<float>(camera.viewportWidth()),
            (1.0F - ndc.y) * 0.5F * static_cast<float>(camera.viewportHeight())};
}

TEST(ViewPresetsTest, AnatomicalNamesRoundTrip) {
    ASSERT_EQ(vv::render::allAnatomicalViews().size(), 6U);
    for (const AnatomicalView v : vv::render::allAnatomicalViews()) {
        EXPECT_EQ(vv::render::anatomicalViewFromName(vv::render::toString(v)), v);
        const auto named = vv::render::namedViewFromName(vv::render::toString(v));
        ASSERT_TRUE(named.has_value());
        EXPECT_EQ(named->preset, ViewPreset::Far);
        ASSERT_TRUE(named->rotation.has_value());
        EXPECT_NEAR(std::abs(glm::dot(*named->rotation, vv::render::anatomicalRotation(v))), 1.0F,
                    1e-6F);
    }
    EXPECT_EQ(vv::render::anatomicalViewFromName("Superior"), AnatomicalView::Superior);
    EXPECT_FALSE(vv::render::anatomicalViewFromName("far").has_value());
    EXPECT_FALSE(vv::render::anatomicalViewFromName("front").has_value());
    const auto close = vv::render::namedViewFromName("CLOSE");
    ASSERT_TRUE(close.has_value());
    EXPECT_EQ(close->preset, ViewPreset::Close);
    EXPECT_FALSE(close->rotation.has_value()) << "the scene's home orientation";
    EXPECT_FALSE(vv::render::namedViewFromName("sideways").has_value());
    EXPECT_EQ(vv::render::namedViewNames(),
              "far, medium, close, anterior, posterior, left, right, superior, inferior");
}

TEST(ViewPresetsTest, AnatomicalCamerasLookFromTheirSide) {
    vv::Aabb box;
    box.extend(glm::vec3(-40.0F, -20.0F, -60.0F));
    box.extend(glm::vec3(40.0F, 30.0F, 60.0F));
    for (const AnatomicalView v : vv::render::allAnatomicalViews()) {
        SCOPED_TRACE(std::string(vv::render::toString(v)));
        const glm::vec3 side = vv::render::anatomicalSide(v);
        const glm::vec3 up = vv::render::anatomicalUp(v);
        EXPECT_NEAR(glm::length(side), 1.0F, 1e-6F);
        EXPECT_NEAR(glm::dot(side, up), 0.0F, 1e-6F);
        const auto camera = vv::render::presetCamera(box, 400, 300, ViewPreset::Far,
                                                     vv::render::anatomicalRotation(v));
        EXPECT_NEAR(glm::dot(camera.forward(), -side), 1.0F, 1e-5F);
        EXPECT_NEAR(glm::dot(camera.up(), up), 1.0F, 1e-5F);
        // The eye is on that side of the box, outside it.
        const glm::vec3 offset = camera.eye() - box.center();
        EXPECT_GT(glm::dot(offset, side), 0.0F);
        EXPECT_NEAR(glm::length(glm::cross(offset, side)), 0.0F, 1e-3F * glm::length(offset));
        const glm::vec3 eye = camera.eye();
        EXPECT_FALSE(glm::all(glm::greaterThanEqual(eye, box.min)) &&
                     glm::all(glm::lessThanEqual(eye, box.max)));
    }
    // The radiological conventions: the anterior view shows the patient's left
    // (+x) on the screen's right, and so does the inferior view.
    const glm::vec3 left{1.0F, 0.0F, 0.0F};
    const auto right = [](AnatomicalView v) {
        return vv::render::anatomicalRotation(v) * glm::vec3(1.0F, 0.0F, 0.0F);
    };
    EXPECT_NEAR(glm::dot(right(AnatomicalView::Anterior), left), 1.0F, 1e-5F);
    EXPECT_NEAR(glm::dot(right(AnatomicalView::Inferior), left), 1.0F, 1e-5F);
    EXPECT_NEAR(glm::dot(right(AnatomicalView::Posterior), left), -1.0F, 1e-5F);
    EXPECT_NEAR(glm::dot(right(AnatomicalView::Superior), left), -1.0F, 1e-5F);
}

TEST(ViewPresetsTest, AnatomicalViewsSeeTheMarkersWhereTheyShouldBe) {
    // A box in the middle and markers on the patient's left (+x), anterior
    // (-y) and superior (+z) sides; nothing on the right, posterior, inferior.
    const glm::vec3 leftMarker{30.0F, 0.0F, 0.0F};
    const glm::vec3 anteriorMarker{0.0F, -30.0F, 0.0F};
    const glm::vec3 superiorMarker{0.0F, 0.0F, 30.0F};
    vv::scene::Scene scene;
    vv::scene::Mesh mesh;
    addBox(mesh, glm::vec3(0.0F), 10.0F);
    for (const glm::vec3& m : {leftMarker, anteriorMarker, superiorMarker}) {
        addBox(mesh, m, 3.0F);
    }
    scene.meshes.push_back(std::move(mesh));
    const int w = 320;
    const int h = 240;
    for (const AnatomicalView v : vv::render::allAnatomicalViews()) {
        SCOPED_TRACE(std::string(vv::render::toString(v)));
        const auto camera = vv::render::presetCamera(scene, w, h, ViewPreset::Far,
                                                     vv::render::anatomicalRotation(v));
        const Image<float> depth = vv::render::rasterizeDepth(scene, camera);
        // The nearest front face is the marker on the camera's side, or the
        // middle box where that side has none.
        const glm::vec3 side = vv::render::anatomicalSide(v);
        glm::vec3 nearest{0.0F};
        for (const glm::vec3& m : {leftMarker, anteriorMarker, superiorMarker}) {
            if (glm::dot(m, side) > 1.0F) {
                nearest = m;
            }
        }
        const float halfSize = nearest == glm::vec3(0.0F) ? 10.0F : 3.0F;
        const glm::vec2 expected = pixelOf(camera, nearest + halfSize * side);
        const glm::vec2 found = nearestCentroid(depth);
        EXPECT_NEAR(found.x, expected.x, 1.5F);
        EXPECT_NEAR(found.y, expected.y, 1.5F);
    }
    // Screen layout: from the front the left marker is right of the middle box
    // and the superior one above it; from above, anterior is up.
    const auto anterior = vv::render::presetCamera(
        scene, w, h, ViewPreset::Far, vv::render::anatomicalRotation(AnatomicalView::Anterior));
    const glm::vec2 middle = pixelOf(anterior, glm::vec3(0.0F));
    EXPECT_GT(pixelOf(anterior, leftMarker).x, middle.x + 20.0F);
    EXPECT_LT(pixelOf(anterior, superiorMarker).y, middle.y - 20.0F);
    const auto superior = vv::render::presetCamera(
        scene, w, h, ViewPreset::Far, vv::render::anatomicalRotation(AnatomicalView::Superior));
    EXPECT_LT(pixelOf(superior, anteriorMarker).y, pixelOf(superior, glm::vec3(0.0F)).y - 20.0F);
    EXPECT_LT(pixelOf(superior, leftMarker).x, pixelOf(superior, glm::vec3(0.0F)).x - 20.0F);
}

}  // namespace
