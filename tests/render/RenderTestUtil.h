// SPDX-License-Identifier: GPL-3.0-or-later
// Helpers shared by the GL render tests (offscreen, real OpenGL 4.1 context):
// the QGuiApplication / renderer fixture, tube test scenes, option set-up and
// pixel helpers.
#pragma once

#include <gtest/gtest.h>

#include <QImage>
#include <QOffscreenSurface>
#include <QOpenGLContext>
#include <QOpenGLFramebufferObject>
#include <QRgb>
#include <cstdint>
#include <glm/glm.hpp>
#include <memory>
#include <string>
#include <vector>

#include "GlTestSupport.h"
#include "vv/render/FrameRenderer.h"
#include "vv/render/OffscreenRenderer.h"
#include "vv/scene/Mesh.h"

namespace vv::render::test {

using vv::test::ensureGuiApplication;
using vv::test::makeGl41Current;
/// A renderer, or a test failure naming why there is none.
inline std::unique_ptr<OffscreenRenderer> makeRenderer() {
    return vv::test::makeOffscreenRenderer();
}

/// The state of pass `pass` in the renderer's last frame (a failure if absent).
PassState passState(const OffscreenRenderer& renderer, const std::string& pass);

/// Saves `image` as VV_TEST_TMP/<prefix><name>.png for people to look at.
void saveImage(const QImage& image, const std::string& prefix, const std::string& name);

/// An open tube of `radius` along x (x0 .. x0 + length), axis at (y, z).
vv::scene::Mesh makeTube(float radius, float x0, float length, float y, float z, int segments,
                         int rings);

/// A near tube on top (y = 3, z = +z) and a far tube below (y = -3, z = -z), x in -10 .. 10.
vv::scene::Scene twoTubes(float radius, float z, int segments, int rings);

/// Options of the given size on the test background, AO and FXAA off (exact pixels).
OffscreenOptions exactOptions(int width, int height);

/// An 8-bit pixel as a colour in [0, 1].
glm::vec3 toVec(QRgb p);

/// A FrameRenderer in its own context, drawing into an FBO, so that a test can
/// read the object id of every pixel (FrameRenderer::probe) beside its colour.
class FrameHarness {
  public:
    /// Throws RenderError when there is no OpenGL 4.1 context.
    FrameHarness(int width, int height);
    ~FrameHarness();
    FrameHarness(const FrameHarness&) = delete;
    FrameHarness& operator=(const FrameHarness&) = delete;
    FrameHarness(FrameHarness&&) = delete;
    FrameHarness& operator=(FrameHarness&&) = delete;

    /// Shows `scene` with the camera fitted to it.
    void setScene(const vv::scene::Scene& scene);
    /// Draws a frame of `style` and `settings`; its pixels.
    QImage render(const MeshStyle& style, const FrameSettings& settings);
    /// Object id per pixel of the last frame, rows top-down like the image.
    std::vector<std::uint32_t> objectIds();

    FrameRenderer& renderer() noexcept { return renderer_; }
    [[nodiscard]] const Camera& camera() const noexcept { return camera_; }

  private:
    int width_;
    int height_;
    QOffscreenSurface surface_;
    QOpenGLContext context_;
    std::unique_ptr<QOpenGLFramebufferObject> fbo_;
    FrameRenderer renderer_;
    Camera camera_;
};

/// Base fixture: a QGuiApplication for the suite, the test background and renderer helpers.
class GlRenderTest : public ::testing::Test {
  protected:
    /// Creates the QGuiApplication once per process.
    static void SetUpTestSuite() { ensureGuiApplication(); }

    /// A renderer, or a test failure naming why there is none.
    static std::unique_ptr<OffscreenRenderer> makeRenderer() { return test::makeRenderer(); }

    /// The state of `pass` in the last frame.
    static PassState state(const OffscreenRenderer& renderer, const std::string& pass) {
        return passState(renderer, pass);
    }

    /// VSS off, no AO / FXAA, the test background: exact pixels.
    [[nodiscard]] FrameSettings flatSettings() const {
        FrameSettings s;
        s.background = background_;
        s.vss.enabled = false;
        s.ao.enabled = false;
        s.antialiasing = false;
        return s;
    }

    // Exactly representable in 8 bits, so cleared pixels compare equal.
    const glm::vec3 background_{26.0F / 255.0F, 51.0F / 255.0F, 77.0F / 255.0F};
    const QRgb backgroundRgb_ = qRgb(26, 51, 77);
};

}  // namespace vv::render::test
