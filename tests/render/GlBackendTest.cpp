// SPDX-License-Identifier: GPL-3.0-or-later
// The GL backend's pieces of the render graph: framebuffers for declared
// render targets, programs with cached uniform locations. GL tests: run
// under `xvfb-run -a` with QT_QPA_PLATFORM=xcb.
#include <gtest/gtest.h>

#include <QOffscreenSurface>
#include <QOpenGLContext>
#include <QOpenGLFunctions_4_1_Core>
#include <memory>
#include <utility>

#include "RenderTestUtil.h"
#include "vv/core/Error.h"
#include "vv/render/GlFramebufferCache.h"
#include "vv/render/GlResources.h"
#include "vv/render/Program.h"

namespace {

using vv::render::GlResourceAllocator;
using vv::render::GlTexture;
using vv::render::Program;
using vv::render::RenderTarget;
using vv::render::Texture;
using vv::render::TextureDescriptor;
using vv::render::TextureFormat;

class GlBackendTest : public vv::render::test::GlRenderTest {
  protected:
    void SetUp() override {
        ASSERT_TRUE(vv::render::test::makeGl41Current(surface_, context_))
            << "no OpenGL 4.1 context (run under xvfb-run with QT_QPA_PLATFORM=xcb)";
    }
    void TearDown() override { context_.doneCurrent(); }

    QOffscreenSurface surface_;
    QOpenGLContext context_;
};

TEST_F(GlBackendTest, ARenderTargetGetsOneFramebufferUntilATextureDies) {
    auto& gl = vv::render::currentGl41();
    GlResourceAllocator allocator;
    const TextureDescriptor colourFormat{8, 4, TextureFormat::RGBA16F, 1};
    const TextureDescriptor depthFormat{8, 4, TextureFormat::Depth32F, 1};
    Texture colour(colourFormat, allocator.createTexture(colourFormat));
    auto depth = std::make_unique<Texture>(depthFormat, allocator.createTexture(depthFormat));
    const RenderTarget both{
        .name = "translucent", .colors = {&colour}, .depth = depth.get(), .width = 8, .height = 4};
    auto& framebuffers = allocator.framebuffers();
    const unsigned fbo = framebuffers.framebuffer(both);
    EXPECT_NE(fbo, 0U);
    EXPECT_TRUE(gl.glIsFramebuffer(fbo));
    EXPECT_EQ(framebuffers.framebuffer(both), fbo);  // kept
    EXPECT_EQ(framebuffers.size(), 1U);
    // One colour texture alone draws through its own framebuffer.
    const RenderTarget alone{
        .name = "colour", .colors = {&colour}, .depth = nullptr, .width = 8, .height = 4};
    EXPECT_EQ(framebuffers.framebuffer(alone), colour.objectAs<GlTexture>().framebuffer());
    EXPECT_EQ(framebuffers.size(), 1U);

    // The depth texture dies: its framebuffer goes with it.
    depth.reset();
    EXPECT_EQ(framebuffers.size(), 0U);
    EXPECT_FALSE(gl.glIsFramebuffer(fbo));
}

TEST_F(GlBackendTest, AWrappedFramebufferIsATargetOnlyOnItsOwn) {
    GlResourceAllocator allocator;
    const TextureDescriptor format{8, 4, TextureFormat::RGBA8, 1};
    Texture screen(format, std::make_shared<GlTexture>(format, 0U));
    Texture colour(format, allocator.createTexture(format));
    const RenderTarget alone{
        .name = "output", .colors = {&screen}, .depth = nullptr, .width = 8, .height = 4};
    EXPECT_EQ(allocator.framebuffers().framebuffer(alone), 0U);
    const RenderTarget mixed{
        .name = "mixed", .colors = {&colour, &screen}, .depth = nullptr, .width = 8, .height = 4};
    EXPECT_THROW(static_cast<void>(allocator.framebuffers().framebuffer(mixed)), vv::RenderError);
}

TEST_F(GlBackendTest, AProgramFindsItsUniformsAndSetsThem) {
    auto& gl = vv::render::currentGl41();
    Program program(gl, ":/vv/shaders/fullscreen.vert", ":/vv/shaders/fxaa.frag", "FXAA");
    ASSERT_TRUE(program.valid());
    const int color = program.location("uColor");
    EXPECT_GE(color, 0);
    EXPECT_EQ(color, gl.glGetUniformLocation(program.id(), "uColor"));
    EXPECT_EQ(program.location("uColor"), color);
    EXPECT_EQ(program.location("uNoSuchUniform"), -1);
    program.use();
    program.set("uColor", 3);
    GLint value = -1;
    gl.glGetUniformiv(program.id(), color, &value);
    EXPECT_EQ(value, 3);
    gl.glUseProgram(0);

    Program moved = std::move(program);
    EXPECT_FALSE(program.valid());  // NOLINT(bugprone-use-after-move): moved-from is empty
    ASSERT_TRUE(moved.valid());
    const unsigned id = moved.id();
    moved.release();
    EXPECT_FALSE(moved.valid());
    EXPECT_FALSE(gl.glIsProgram(id));
    EXPECT_THROW(Program(gl, ":/vv/shaders/fullscreen.vert", ":/vv/shaders/none.frag", "none"),
                 vv::RenderError);
}

}  // namespace
