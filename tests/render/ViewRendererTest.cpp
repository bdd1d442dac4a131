// SPDX-License-Identifier: GPL-3.0-or-later
// The one view renderer of the viewer and the offscreen path: a scene is
// uploaded once per content, the offscreen renderer keeps its meshes across
// renders of the same content (tiles, report views) and uploads a changed
// scene again; the settle step. Needs a display (xvfb-run, QT_QPA_PLATFORM=xcb).
#include <gtest/gtest.h>

#include <QImage>
#include <QOffscreenSurface>
#include <QOpenGLContext>
#include <QOpenGLFramebufferObject>
#include <cmath>
#include <memory>

#include "RenderTestUtil.h"
#include "TestMeshes.h"
#include "vv/render/OffscreenRenderer.h"
#include "vv/render/ViewRenderer.h"

namespace vv::render {
namespace {

/// Two tubes with a "wss" array rising along x.
scene::Scene tubesWithWss() {
    scene::Scene scene = test::twoTubes(1.5F, 2.0F, 32, 32);
    for (scene::Mesh& mesh : scene.meshes) {
        scene::DataArray wss{"wss", "Pa", 1, {}, false, false};
        for (const glm::vec3& p : mesh.positions) {
            wss.values.push_back(p.x);
        }
        mesh.pointArrays.push_back(std::move(wss));
    }
    return scene;
}

OffscreenOptions optionsFor(int width, int height) {
    OffscreenOptions options = test::exactOptions(width, height);
    options.display.style.array = "wss";
    options.display.style.range = std::make_pair(-10.0F, 10.0F);
    return options;
}

VssSettings vssOff() {
    VssSettings settings;
    settings.enabled = false;
    return settings;
}

class OffscreenUploadTest : public test::GlRenderTest {};

TEST_F(OffscreenUploadTest, TheSameContentIsUploadedOnceAndAChangedSceneAgain) {
    auto renderer = makeRenderer();
    ASSERT_TRUE(renderer);
    const scene::Scene scene = tubesWithWss();
    const OffscreenOptions options = optionsFor(96, 64);
    EXPECT_EQ(renderer->sceneUploads(), 0U);
    const QImage first = renderer->render(scene, options);
    EXPECT_EQ(renderer->sceneUploads(), 1U);
    // Another view, the depth only, and a copy of the scene in another
    // object: the meshes on the GPU serve them all.
    OffscreenOptions other = options;
    other.camera = OffscreenRenderer::cameraFor(scene, options);
    other.camera->rotateView(0.4F, glm::vec3(0.0F, 1.0F, 0.0F));
    (void)renderer->render(scene, other);
    (void)renderer->renderDepth(scene, options);
    const auto copy = std::make_unique<scene::Scene>(scene);
    const QImage again = renderer->render(*copy, options);
    EXPECT_EQ(renderer->sceneUploads(), 1U);
    EXPECT_EQ(again, first);

    // New values of the shown array, same geometry: new content too, and
    // the colours follow (the per-vertex values are the GPU's copy).
    scene::Scene recoloured = scene;
    for (float& v : recoloured.meshes[1].pointArrays[0].values) {
        v = -v;
    }
    const QImage flipped = renderer->render(recoloured, options);
    EXPECT_EQ(renderer->sceneUploads(), 2U);
    EXPECT_NE(flipped, first);

    // Moved vertices are new content: uploaded, and drawn where they are now.
    scene::Scene moved = scene;
    for (glm::vec3& p : moved.meshes[0].positions) {
        p.y += 1.0F;
    }
    const QImage shifted = renderer->render(moved, options);
    EXPECT_EQ(renderer->sceneUploads(), 3U);
    EXPECT_NE(shifted, first);
    // What a fresh renderer draws of it.
    auto fresh = makeRenderer();
    ASSERT_TRUE(fresh);
    EXPECT_EQ(fresh->render(recoloured, options), flipped);
}

TEST_F(OffscreenUploadTest, TheCallersSceneIsNotKeptBetweenRenders) {
    auto renderer = makeRenderer();
    ASSERT_TRUE(renderer);
    const OffscreenOptions options = optionsFor(64, 48);
    QImage first;
    {
        const auto scene = std::make_unique<scene::Scene>(tubesWithWss());
        first = renderer->render(*scene, options);
    }  // gone: a render of the same content must not read it
    const scene::Scene again = tubesWithWss();
    EXPECT_EQ(renderer->render(again, options), first);
    EXPECT_EQ(renderer->sceneUploads(), 1U);
}

TEST_F(OffscreenUploadTest, AnAttachedSceneKeepsItsClosuresForCulling) {
    auto renderer = makeRenderer();
    ASSERT_TRUE(renderer);
    const OffscreenOptions options = optionsFor(64, 48);
    scene::Scene closed;
    closed.meshes.push_back(vv::test::cube(glm::vec3(-1.0F), 2.0F));
    (void)renderer->render(closed, options);
    EXPECT_EQ(renderer->lastCulledMeshes(), 1U);
    // Another object of the same content: culled as well (it is the
    // closures' mesh now), without an upload.
    const scene::Scene copy = closed;
    renderer->clearCache();  // so that the geometry pass draws again
    (void)renderer->render(copy, options);
    EXPECT_EQ(renderer->lastCulledMeshes(), 1U);
    EXPECT_EQ(renderer->sceneUploads(), 1U);
}

/// A ViewRenderer in its own context, drawing into an FBO.
class ViewRendererTest : public test::GlRenderTest {
  protected:
    void SetUp() override {
        ASSERT_TRUE(test::makeGl41Current(surface_, context_))
            << "no OpenGL 4.1 context (run under xvfb-run, QT_QPA_PLATFORM=xcb)";
        fbo_ = std::make_unique<QOpenGLFramebufferObject>(kWidth, kHeight);
        view_.initialize();
        camera_.setViewport(kWidth, kHeight);
    }
    void TearDown() override {
        view_.release();
        fbo_.reset();
        context_.doneCurrent();
    }
    [[nodiscard]] FrameTarget target() const { return {fbo_->handle(), kWidth, kHeight}; }

    static constexpr int kWidth = 96;
    static constexpr int kHeight = 72;
    QOffscreenSurface surface_;
    QOpenGLContext context_;
    std::unique_ptr<QOpenGLFramebufferObject> fbo_;
    ViewRenderer view_;
    Camera camera_;
};

TEST_F(ViewRendererTest, AScenePassesToTheGpuWithTheNextFrameOnly) {
    const auto scene = std::make_shared<const scene::Scene>(tubesWithWss());
    camera_.fit(scene->bounds());
    view_.setScene(scene);
    EXPECT_EQ(view_.sceneUploads(), 0U);  // no frame yet
    (void)view_.render(camera_, target());
    EXPECT_EQ(view_.sceneUploads(), 1U);
    (void)view_.render(camera_, target());
    EXPECT_EQ(view_.sceneUploads(), 1U);
    // Set without a fingerprint, even the same object is new content.
    const std::uint64_t revision = view_.sceneRevision();
    view_.setScene(scene);
    EXPECT_NE(view_.sceneRevision(), revision);
    (void)view_.render(camera_, target());
    EXPECT_EQ(view_.sceneUploads(), 2U);
    // With its fingerprint: uploaded once, then only attached.
    const std::uint64_t fingerprint = sceneFingerprint(*scene);
    view_.setScene(scene, fingerprint);
    (void)view_.render(camera_, target());
    view_.setScene(std::make_shared<const scene::Scene>(*scene), fingerprint);
    (void)view_.render(camera_, target());
    EXPECT_EQ(view_.sceneUploads(), 3U);
    EXPECT_EQ(view_.sceneRevision(), fingerprint);
}

TEST_F(ViewRendererTest, ADetachedSceneIsNotDrawnButItsMeshesStay) {
    const auto scene = std::make_shared<const scene::Scene>(tubesWithWss());
    camera_.fit(scene->bounds());
    view_.setAoSettings(AoSettings{.enabled = false, .radius = 3.0F, .strength = 0.8F});
    view_.setAntialiasing(false);
    view_.setVssSettings(vssOff());
    view_.setScene(scene, sceneFingerprint(*scene));
    (void)view_.render(camera_, target());
    const QImage shown = fbo_->toImage();
    ASSERT_NE(shown.pixel(kWidth / 2, kHeight / 4), shown.pixel(0, 0)) << "no tube drawn";
    view_.detachScene();
    view_.setBackground({0.0F, 0.0F, 1.0F});  // a new frame, not a cached one
    (void)view_.render(camera_, target());
    const QImage empty = fbo_->toImage().convertToFormat(QImage::Format_RGB32);
    int drawn = 0;
    for (int y = 0; y < kHeight; ++y) {
        for (int x = 0; x < kWidth; ++x) {
            drawn += empty.pixel(x, y) != qRgb(0, 0, 255) ? 1 : 0;
        }
    }
    EXPECT_EQ(drawn, 0) << "pixels of the detached scene";
    view_.setBackground(kDefaultBackground);
    view_.setScene(scene, sceneFingerprint(*scene));
    (void)view_.render(camera_, target());
    EXPECT_EQ(fbo_->toImage(), shown);
    EXPECT_EQ(view_.sceneUploads(), 1U);
}

TEST_F(ViewRendererTest, SettlingAfterAFullSizePreviewRequestsTheSolveElseDrawsItsGBuffer) {
    const auto scene = std::make_shared<const scene::Scene>(tubesWithWss());
    camera_.fit(scene->bounds());
    view_.setSolveMode(FrameRenderer::SolveMode::Asynchronous);
    view_.setScene(scene);
    view_.refinement().setInteractiveScale(1.0F);
    int madeCurrent = 0;
    const auto makeCurrent = [&] { ++madeCurrent; };

    // A full-size preview frame read back this view's depth: settling starts
    // the exact solve from it, without GL.
    ASSERT_TRUE(view_.refinement().cameraMoved());
    (void)view_.render(camera_, target());
    ASSERT_TRUE(view_.refinement().settle());
    EXPECT_EQ(view_.settle(camera_, target(), makeCurrent), SettleResult::Requested);
    EXPECT_EQ(madeCurrent, 0);
    EXPECT_EQ(view_.solvesRequestedOnSettle(), 1U);

    // A reduced preview frame's depth is not this view's: settling draws the
    // full G-buffer (the context made current first) and submits its solve.
    view_.refinement().setInteractiveScale(0.5F);
    camera_.rotateView(0.3F, glm::vec3(0.0F, 1.0F, 0.0F));
    ASSERT_TRUE(view_.refinement().cameraMoved());
    (void)view_.render(camera_, target());
    ASSERT_TRUE(view_.refinement().settle());
    const auto submitted = view_.frameRenderer().solveCounters().submitted;
    EXPECT_EQ(view_.settle(camera_, target(), makeCurrent), SettleResult::Prepared);
    EXPECT_EQ(madeCurrent, 1);
    EXPECT_EQ(view_.solvesPreparedOnSettle(), 1U);
    EXPECT_EQ(view_.frameRenderer().solveCounters().submitted, submitted + 1);
    view_.frameRenderer().waitForSolves();

    // With the VSS off there is nothing to start: the next frame follows.
    view_.setVssSettings(vssOff());
    ASSERT_TRUE(view_.refinement().cameraMoved());
    ASSERT_TRUE(view_.refinement().settle());
    EXPECT_EQ(view_.settle(camera_, target(), makeCurrent), SettleResult::None);
}

TEST_F(ViewRendererTest, HidingAnObjectReSolvesTheVssOnTheWorkerAndAnArrayDoesNot) {
    const auto scene = std::make_shared<const scene::Scene>(tubesWithWss());
    camera_.fit(scene->bounds());
    view_.setSolveMode(FrameRenderer::SolveMode::Asynchronous);
    view_.setScene(scene);
    MeshStyle style = view_.style();
    style.array = "wss";
    view_.setStyle(style);
    const auto settled = [&] {
        (void)view_.render(camera_, target());
        view_.frameRenderer().waitForSolves();
        (void)view_.render(camera_, target());  // shows the finished solve
        return view_.frameRenderer().shownHeight();
    };
    const Image<float> both = settled();
    ASSERT_EQ(both.width(), kWidth);
    const auto solves = [&] { return view_.frameRenderer().solveCounters().submitted; };
    const auto before = solves();

    // Another array: the same depth, no new solve.
    style.array.clear();
    view_.setStyle(style);
    (void)settled();
    EXPECT_EQ(solves(), before);

    // One tube hidden: its pixels are void now, and the VSS is solved again
    // (before, the worker's frame of the same camera counted as this view's,
    // and the hidden tube's old depths stayed on screen as VSS).
    style.hidden = {1};
    view_.setStyle(style);
    const Image<float> one = settled();
    EXPECT_GT(solves(), before);
    int changed = 0;
    for (int y = 0; y < kHeight; ++y) {
        for (int x = 0; x < kWidth; ++x) {
            const float a = both(x, y);
            const float b = one(x, y);
            changed += std::isfinite(a) && std::isfinite(b) && std::abs(a - b) > 1e-3F ? 1 : 0;
        }
    }
    EXPECT_GT(changed, kWidth * kHeight / 20) << "the VSS did not change with the hidden tube";
}

}  // namespace
}  // namespace vv::render
