// SPDX-License-Identifier: GPL-3.0-or-later
// Back-face culling: the decision without GL (cullableFaces), and with a real
// context that a culled G-buffer and image equal the unculled ones (up to
// pixels where a ray grazes a silhouette).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <limits>

#include "RenderTestUtil.h"
#include "TestMeshes.h"
#include "vv/demo/DemoTree.h"
#include "vv/render/BackFaceCulling.h"
#include "vv/render/OffscreenRenderer.h"
#include "vv/scene/MeshTopology.h"

namespace vv::render {
namespace {

using vv::test::cube;
using vv::test::flipAll;
using vv::test::merged;

/// test::makeTube with both ends capped by a fan: closed, wound like the
/// tube (clockwise seen from outside).
scene::Mesh cappedTube(float radius, float x0, float length, float y, float z) {
    constexpr int kSegments = 24;
    constexpr int kRings = 8;
    scene::Mesh mesh = test::makeTube(radius, x0, length, y, z, kSegments, kRings);
    mesh.normals.clear();
    const auto segs = static_cast<std::uint32_t>(kSegments);
    const auto first = static_cast<std::uint32_t>(mesh.positions.size());
    mesh.positions.emplace_back(x0, y, z);
    mesh.positions.emplace_back(x0 + length, y, z);
    const std::uint32_t last = segs * kRings;  // first vertex of the last ring
    for (std::uint32_t j = 0; j < segs; ++j) {
        const std::uint32_t next = (j + 1) % segs;
        mesh.indices.insert(mesh.indices.end(), {first, j, next});
        mesh.indices.insert(mesh.indices.end(), {first + 1, last + next, last + j});
    }
    return mesh;
}

struct View {
    glm::mat4 view;
    glm::mat4 projection;
};

View looking(glm::vec3 eye, glm::vec3 at, float nearPlane) {
    return {glm::lookAt(eye, at, glm::vec3(0.0F, 0.0F, 1.0F)),
            glm::perspective(glm::radians(40.0F), 1.25F, nearPlane, 100.0F)};
}

CullFace decide(const scene::Mesh& mesh, const View& v) {
    return cullableFaces(mesh, scene::surfaceClosure(mesh), mesh.bounds(), v.view, v.projection);
}

TEST(BackFaceCullingTest, AClosedSurfaceSeenFromOutsideCullsItsBackOrItsFrontIfInward) {
    const scene::Mesh outward = cube(glm::vec3(0.0F));
    const View v = looking({4.0F, 3.0F, 2.0F}, {0.5F, 0.5F, 0.5F}, 0.1F);
    EXPECT_EQ(decide(outward, v), CullFace::Back);
    scene::Mesh inward = outward;
    flipAll(inward);
    EXPECT_EQ(decide(inward, v), CullFace::Front);
    // A mirrored projection turns the screen's winding around.
    const View mirrored{v.view,
                        glm::scale(glm::mat4(1.0F), glm::vec3(-1.0F, 1.0F, 1.0F)) * v.projection};
    EXPECT_EQ(decide(outward, mirrored), CullFace::Front);
    EXPECT_EQ(decide(inward, mirrored), CullFace::Back);
}

TEST(BackFaceCullingTest, AnOpenSurfaceIsNeverCulled) {
    scene::Mesh open = cube(glm::vec3(0.0F));
    open.indices.resize(open.indices.size() - 6);  // one face removed
    EXPECT_EQ(decide(open, looking({4.0F, 3.0F, 2.0F}, {0.5F, 0.5F, 0.5F}, 0.1F)), CullFace::None);
}

TEST(BackFaceCullingTest, AnEyeInsideTheSolidOrANearPlaneThroughItCullsNothing) {
    const scene::Mesh mesh = cube(glm::vec3(0.0F));
    // Inside: every surface it sees is a back face.
    EXPECT_EQ(decide(mesh, looking({0.5F, 0.5F, 0.5F}, {0.5F, 2.0F, 0.5F}, 0.01F)), CullFace::None);
    // Outside, but the near plane (at y = 0.5) cuts the cube: through the cut
    // the inside walls show.
    EXPECT_EQ(decide(mesh, looking({0.5F, -2.0F, 0.5F}, {0.5F, 2.0F, 0.5F}, 2.5F)), CullFace::None);
    // The same camera with the near plane before the cube (y = -0.5).
    EXPECT_EQ(decide(mesh, looking({0.5F, -2.0F, 0.5F}, {0.5F, 2.0F, 0.5F}, 1.5F)), CullFace::Back);
}

TEST(BackFaceCullingTest, AnEyeBetweenPartsCountsTheWindingToKnowItIsOutside) {
    // Two cubes; the eye between them is inside the mesh's bounds.
    const scene::Mesh two = merged(cube(glm::vec3(0.0F)), cube(glm::vec3(3.0F, 0.0F, 0.0F)));
    EXPECT_EQ(decide(two, looking({2.0F, 0.5F, 0.5F}, {4.0F, 0.5F, 0.5F}, 0.01F)), CullFace::Back);
    // Inside the second cube.
    EXPECT_EQ(decide(two, looking({3.5F, 0.5F, 0.5F}, {5.0F, 0.5F, 0.5F}, 0.01F)), CullFace::None);
    // Near the first cube's wall, the near-plane rectangle touching it.
    EXPECT_EQ(decide(two, looking({1.01F, 0.5F, 0.5F}, {-4.0F, 0.5F, 0.5F}, 0.01F)),
              CullFace::None);
    // A hollow box: a big outward cube around a small inward one is one
    // surface with an outward part and an inward part, so it is open to culling.
    scene::Mesh cavity = cube(glm::vec3(1.0F), 1.0F);
    flipAll(cavity);
    const scene::Mesh hollow = merged(cube(glm::vec3(0.0F), 3.0F), cavity);
    EXPECT_EQ(scene::surfaceClosure(hollow), scene::SurfaceClosure::Open);
    EXPECT_EQ(decide(hollow, looking({6.0F, 5.0F, 4.0F}, {1.5F, 1.5F, 1.5F}, 0.1F)),
              CullFace::None);
}

TEST(BackFaceCullingTest, NonFiniteMatricesCullNothing) {
    const scene::Mesh mesh = cube(glm::vec3(0.0F));
    View v = looking({4.0F, 3.0F, 2.0F}, {0.5F, 0.5F, 0.5F}, 0.1F);
    v.view[3][0] = std::numeric_limits<float>::quiet_NaN();
    EXPECT_EQ(decide(mesh, v), CullFace::None);
    EXPECT_EQ(cullableFaces(mesh, scene::SurfaceClosure::ClosedOutward, mesh.bounds(),
                            glm::mat4(0.0F), glm::mat4(1.0F)),
              CullFace::None);
}

/// Renders each case with culling off and on; the linear depth and the
/// image must be the same, bit for bit.
class CulledRenderTest : public test::GlRenderTest {
  protected:
    struct Result {
        Image<float> depth;
        QImage image;
        std::size_t culled = 0;
    };
    Result renderWith(OffscreenRenderer& renderer, const scene::Scene& scene,
                      const OffscreenOptions& options, bool culling) {
        renderer.setBackFaceCulling(culling);
        Result r;
        r.depth = renderer.renderDepth(scene, options);
        r.culled = renderer.lastCulledMeshes();
        r.image = renderer.render(scene, options);
        return r;
    }
    /// Expects the same results up to grazing pixels and returns how many
    /// meshes the culled render culled. Where a ray grazes a silhouette, the
    /// rasteriser's snapping can give a pixel to the back face as well as to
    /// the front one, a hair nearer or farther: such pixels are allowed, one
    /// in a thousand, each within 1e-3 of its depth. A wrong face culled
    /// would move every vessel pixel to the far side.
    std::size_t expectSame(const scene::Scene& scene, const OffscreenOptions& options,
                           const std::string& name) {
        auto renderer = makeRenderer();
        if (!renderer) {
            return 0;
        }
        const Result off = renderWith(*renderer, scene, options, false);
        const Result on = renderWith(*renderer, scene, options, true);
        EXPECT_EQ(off.culled, 0U) << name;
        long different = 0;
        long vessel = 0;
        double worst = 0.0;  // relative depth difference
        for (int y = 0; y < off.depth.height(); ++y) {
            for (int x = 0; x < off.depth.width(); ++x) {
                const float a = off.depth(x, y);
                const float b = on.depth(x, y);
                vessel += std::isfinite(a) ? 1 : 0;
                if (a == b || (std::isinf(a) && std::isinf(b))) {
                    continue;
                }
                ++different;
                worst = std::max(worst, std::isfinite(a) && std::isfinite(b)
                                            ? std::abs(static_cast<double>(a) - b) / std::abs(a)
                                            : std::numeric_limits<double>::infinity());
            }
        }
        EXPECT_GT(vessel, 0) << name << ": nothing drawn";
        EXPECT_LE(different, std::max(2L, vessel / 1000))
            << name << ": culling changed the depth of " << different << " of " << vessel
            << " vessel pixels";
        EXPECT_LE(worst, 1e-3) << name << ": largest relative depth change";
        long changed = 0;  // image pixels off by more than 2 levels in a channel
        for (int y = 0; y < off.image.height(); ++y) {
            for (int x = 0; x < off.image.width(); ++x) {
                const QRgb a = off.image.pixel(x, y);
                const QRgb b = on.image.pixel(x, y);
                const int d =
                    std::max({std::abs(qRed(a) - qRed(b)), std::abs(qGreen(a) - qGreen(b)),
                              std::abs(qBlue(a) - qBlue(b))});
                changed += d > 2 ? 1 : 0;
            }
        }
        EXPECT_LE(changed, std::max(2L, vessel / 1000))
            << name << ": culling changed " << changed << " image pixels";
        test::saveImage(on.image, "culling_", name);
        return on.culled;
    }
};

TEST_F(CulledRenderTest, TheDemoTreeFromOutsideIsCulledAndLooksTheSame) {
    demo::DemoTreeOptions demo;
    demo.generations = 4;
    demo.maxTriangles = 60000;
    scene::Scene scene;
    scene.meshes.push_back(demo::generateDemoMesh(demo));
    ASSERT_EQ(scene::surfaceClosure(scene.meshes[0]), scene::SurfaceClosure::ClosedOutward);
    OffscreenOptions options = test::exactOptions(320, 240);
    options.display.style.array = "wss";
    options.display.vss.enabled = true;
    EXPECT_EQ(expectSame(scene, options, "demo_far"), 1U);
    // Close: the eye inside the tree's bounds, between the vessels.
    Camera close = OffscreenRenderer::cameraFor(scene, options);
    close.zoom(6.0F);
    options.camera = close;
    (void)expectSame(scene, options, "demo_close");
}

TEST_F(CulledRenderTest, EachSceneIsCulledByItsOwnClosures) {
    // One renderer, one mesh each: the closed tube, the same tube open (its
    // caps removed: the inside shows through the ends), then closed again.
    // Closures kept from the previous scene would cull the open one.
    scene::Scene closed;
    closed.meshes.push_back(cappedTube(2.0F, -10.0F, 20.0F, 0.0F, 0.0F));
    scene::Scene open = closed;
    open.meshes[0].indices.resize(open.meshes[0].indices.size() - 6 * 24);
    ASSERT_EQ(scene::surfaceClosure(open.meshes[0]), scene::SurfaceClosure::Open);
    auto renderer = makeRenderer();
    ASSERT_TRUE(renderer);
    const OffscreenOptions options = test::exactOptions(120, 90);
    (void)renderer->renderDepth(closed, options);
    EXPECT_EQ(renderer->lastCulledMeshes(), 1U);
    (void)renderer->renderDepth(open, options);
    EXPECT_EQ(renderer->lastCulledMeshes(), 0U);
    (void)renderer->renderDepth(closed, options);
    EXPECT_EQ(renderer->lastCulledMeshes(), 1U);
}

TEST_F(CulledRenderTest, InsideAClosedTubeNothingIsCulledAndTheWallsShow) {
    scene::Scene scene;
    scene.meshes.push_back(cappedTube(2.0F, -10.0F, 20.0F, 0.0F, 0.0F));
    ASSERT_EQ(scene::surfaceClosure(scene.meshes[0]), scene::SurfaceClosure::ClosedInward);
    OffscreenOptions options = test::exactOptions(160, 120);
    Camera outside = OffscreenRenderer::cameraFor(scene, options);
    options.camera = outside;
    EXPECT_EQ(expectSame(scene, options, "tube_outside"), 1U);
    // The eye 1 mm from the axis, inside the tube, looking at its wall.
    Camera inside = outside;
    inside.setTarget(glm::vec3(0.0F));
    inside.setRotation(glm::quat(1.0F, 0.0F, 0.0F, 0.0F));
    inside.setDistance(1.0F);
    ASSERT_LT(glm::length(glm::vec2(inside.eye().y, inside.eye().z)), 2.0F);
    options.camera = inside;
    EXPECT_EQ(expectSame(scene, options, "tube_inside"), 0U);
}

TEST_F(CulledRenderTest, BetweenTwoClosedTubesBothAreCulled) {
    scene::Scene scene;
    scene.meshes.push_back(cappedTube(1.0F, -10.0F, 20.0F, 3.0F, 0.0F));
    scene.meshes.push_back(cappedTube(1.0F, -10.0F, 20.0F, -3.0F, 0.0F));
    OffscreenOptions options = test::exactOptions(160, 120);
    // The eye between them, inside the scene's bounds, looking down -x with a
    // wide field of view.
    Camera between = OffscreenRenderer::cameraFor(scene, options);
    between.setTarget(glm::vec3(-2.0F, 0.0F, 0.0F));
    between.setRotation(glm::angleAxis(glm::radians(90.0F), glm::vec3(0.0F, 1.0F, 0.0F)));
    between.setDistance(0.5F);
    between.setFieldOfView(120.0F);
    ASSERT_NEAR(between.forward().x, -1.0F, 1e-5F);
    options.camera = between;
    EXPECT_EQ(expectSame(scene, options, "between"), 2U);
}

}  // namespace
}  // namespace vv::render
