// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <string>

#include "vv/core/Error.h"
#include "vv/io/DemoTree.h"
#include "vv/render/DepthRasterizer.h"
#include "vv/render/ViewPresets.h"

namespace {

using vv::Image;
using vv::render::ViewPreset;

constexpr int kWidth = 640;
constexpr int kHeight = 360;

/// The default demo tree, made once (it takes a moment).
const vv::io::Scene& demoScene() {
    static const vv::io::Scene scene = [] {
        vv::io::Scene s;
        s.meshes.push_back(vv::io::generateDemoMesh());
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
    const auto noMesh = vv::render::presetCamera(vv::io::Scene{}, 100, 100, ViewPreset::Far);
    EXPECT_TRUE(std::isfinite(noMesh.distance()));
    EXPECT_GT(noMesh.distance(), 0.0F);
}

}  // namespace
