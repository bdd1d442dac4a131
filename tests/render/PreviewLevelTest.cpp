// SPDX-License-Identifier: GPL-3.0-or-later
// choosePreviewLevel: which simplified copy a moving frame of a given size draws.
#include <gtest/gtest.h>

#include <QOffscreenSurface>
#include <QOpenGLContext>
#include <cstddef>
#include <memory>
#include <vector>

#include "RenderTestUtil.h"
#include "TestMeshes.h"
#include "vv/core/Error.h"
#include "vv/meshio/MeshSimplify.h"
#include "vv/render/MeshRenderer.h"
#include "vv/scene/MeshTopology.h"

namespace vv::render {
namespace {

TEST(PreviewLevelTest, NoLevelsMeansTheFullMeshes) {
    EXPECT_EQ(choosePreviewLevel({}, 1280LL * 720LL), 0U);
}

TEST(PreviewLevelTest, TheFinestLevelWithAboutOneTrianglePerFourPixels) {
    const std::vector<std::size_t> levels = {60000, 20000};
    // 1280x720 (921,600 px) takes 60k triangles; 640x360 (230,400 px), a
    // moving frame at half size, 20k (its geometry pass costs a third).
    EXPECT_EQ(choosePreviewLevel(levels, 1280LL * 720LL), 1U);
    EXPECT_EQ(choosePreviewLevel(levels, 640LL * 360LL), 2U);
    // Exactly at the limit still takes the finer one; a pixel row less does not.
    EXPECT_EQ(choosePreviewLevel(levels, 60000LL * kPixelsPerPreviewTriangle), 1U);
    EXPECT_EQ(choosePreviewLevel(levels, 60000LL * kPixelsPerPreviewTriangle - 1), 2U);
    // 538x302 and the smallest interactive frames take the coarser one.
    EXPECT_EQ(choosePreviewLevel(levels, 538LL * 302LL), 2U);
    EXPECT_EQ(choosePreviewLevel(levels, 320LL * 180LL), 2U);
}

TEST(PreviewLevelTest, TinyOrEmptyFramesTakeTheCoarsestLevel) {
    const std::vector<std::size_t> levels = {9000, 3000, 1000};
    EXPECT_EQ(choosePreviewLevel(levels, 0), 3U);
    EXPECT_EQ(choosePreviewLevel(levels, -5), 3U);
    EXPECT_EQ(choosePreviewLevel(levels, 3000LL * kPixelsPerPreviewTriangle), 2U);
    EXPECT_EQ(choosePreviewLevel(std::vector<std::size_t>{5000}, 10), 1U);
}

/// A current OpenGL 4.1 core context for MeshRenderer's uploads.
class PreviewScenesTest : public test::GlRenderTest {
  protected:
    void SetUp() override {
        ASSERT_TRUE(test::makeGl41Current(surface_, context_))
            << "no OpenGL 4.1 context (run under xvfb-run, QT_QPA_PLATFORM=xcb)";
        meshes_.initialize();
    }
    void TearDown() override {
        meshes_.release();
        context_.doneCurrent();
    }

    static std::size_t trianglesOf(const scene::Scene& scene) {
        std::size_t n = 0;
        for (const scene::Mesh& mesh : scene.meshes) {
            n += mesh.triangleCount();
        }
        return n;
    }

    QOffscreenSurface surface_;
    QOpenGLContext context_;
    MeshRenderer meshes_;
};

TEST_F(PreviewScenesTest, LevelsAreKeptFinestFirstAndChosenBySize) {
    const auto scene = std::make_shared<const scene::Scene>(test::twoTubes(1.0F, 2.0F, 48, 48));
    const std::size_t full = trianglesOf(*scene);
    meshes_.setScene(scene);
    const std::uint64_t afterScene = meshes_.shadingRevision();
    auto fine = std::make_shared<const scene::Scene>(meshio::simplifiedScene(*scene, full / 2));
    auto coarse = std::make_shared<const scene::Scene>(meshio::simplifiedScene(*scene, full / 8));
    // Any order, null entries left out.
    meshes_.setPreviewScenes({coarse, nullptr, fine});
    EXPECT_NE(meshes_.shadingRevision(), afterScene);
    ASSERT_TRUE(meshes_.hasPreviewScene());
    const std::vector<std::size_t> levels = meshes_.previewTriangles();
    ASSERT_EQ(levels.size(), 2U);
    EXPECT_EQ(levels[0], trianglesOf(*fine));
    EXPECT_EQ(levels[1], trianglesOf(*coarse));
    EXPECT_GT(levels[0], levels[1]);
    EXPECT_EQ(meshes_.previewLevelFor(1LL << 40), 1U);
    EXPECT_EQ(meshes_.previewLevelFor(1), 2U);

    // A new style changes the shading revision; a new scene drops the levels.
    const std::uint64_t beforeStyle = meshes_.shadingRevision();
    meshes_.setStyle(MeshStyle{});
    EXPECT_NE(meshes_.shadingRevision(), beforeStyle);
    meshes_.setScene(scene);
    EXPECT_FALSE(meshes_.hasPreviewScene());
    EXPECT_EQ(meshes_.previewLevelFor(1), 0U);
}

TEST_F(PreviewScenesTest, ACopyWithAnotherMeshCountIsRefusedAndNoneIsKept) {
    const auto scene = std::make_shared<const scene::Scene>(test::twoTubes(1.0F, 2.0F, 24, 24));
    meshes_.setScene(scene);
    auto good = std::make_shared<const scene::Scene>(meshio::simplifiedScene(*scene, 200));
    auto oneMesh = std::make_shared<scene::Scene>();
    oneMesh->meshes.push_back(scene->meshes.front());
    EXPECT_THROW(meshes_.setPreviewScenes({good, oneMesh}), InvalidArgumentError);
    EXPECT_FALSE(meshes_.hasPreviewScene());
    meshes_.setPreviewScene(good);
    EXPECT_TRUE(meshes_.hasPreviewScene());
    meshes_.setPreviewScene(nullptr);
    EXPECT_FALSE(meshes_.hasPreviewScene());
}

TEST_F(PreviewScenesTest, ClosuresAreHandedInPerLevelAndEveryUploadStartsOpen) {
    // One closed cube (outward) and one open tube.
    auto scene = std::make_shared<scene::Scene>();
    scene->meshes.push_back(vv::test::cube(glm::vec3(0.0F), 2.0F));
    scene->meshes.push_back(test::makeTube(1.0F, -10.0F, 20.0F, 3.0F, 0.0F, 24, 24));
    // Everything Open (two-sided) until the closures come in.
    meshes_.setScene(scene);
    EXPECT_EQ(meshes_.surfaceClosure(0, 0), scene::SurfaceClosure::Open);
    EXPECT_EQ(meshes_.surfaceClosure(0, 2), std::nullopt);
    EXPECT_EQ(meshes_.surfaceClosure(1, 0), std::nullopt);
    auto copy = std::make_shared<const scene::Scene>(*scene);
    meshes_.setPreviewScene(copy);
    EXPECT_EQ(meshes_.surfaceClosure(1, 0), scene::SurfaceClosure::Open);
    const std::vector<scene::SurfaceClosure> closures = scene::surfaceClosures(*scene);
    ASSERT_EQ(closures, (std::vector<scene::SurfaceClosure>{scene::SurfaceClosure::ClosedOutward,
                                                            scene::SurfaceClosure::Open}));
    meshes_.setSurfaceClosures(0, closures);
    meshes_.setSurfaceClosures(1, closures);
    EXPECT_EQ(meshes_.surfaceClosure(0, 0), scene::SurfaceClosure::ClosedOutward);
    EXPECT_EQ(meshes_.surfaceClosure(1, 0), scene::SurfaceClosure::ClosedOutward);
    EXPECT_EQ(meshes_.surfaceClosure(1, 1), scene::SurfaceClosure::Open);
    // Wrong counts and missing levels are refused.
    EXPECT_THROW(meshes_.setSurfaceClosures(0, {scene::SurfaceClosure::Open}),
                 InvalidArgumentError);
    EXPECT_THROW(meshes_.setSurfaceClosures(2, closures), InvalidArgumentError);
    // A new upload starts Open again.
    meshes_.setScene(scene);
    EXPECT_EQ(meshes_.surfaceClosure(0, 0), scene::SurfaceClosure::Open);
}

}  // namespace
}  // namespace vv::render
