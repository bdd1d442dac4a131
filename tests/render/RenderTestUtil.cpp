// SPDX-License-Identifier: GPL-3.0-or-later
#include "RenderTestUtil.h"

#include <QGuiApplication>
#include <QString>
#include <QSurfaceFormat>
#include <cmath>
#include <cstdint>
#include <numbers>

#include "TestMeshes.h"
#include "vv/core/Error.h"

namespace vv::render::test {

FrameHarness::FrameHarness(int width, int height) : width_(width), height_(height) {
    if (!makeGl41Current(surface_, context_)) {
        throw vv::RenderError("no OpenGL 4.1 context for the test");
    }
    fbo_ = std::make_unique<QOpenGLFramebufferObject>(width, height);
    renderer_.initialize();
}

FrameHarness::~FrameHarness() {
    context_.makeCurrent(&surface_);
    renderer_.release();
    fbo_.reset();
    context_.doneCurrent();
}

void FrameHarness::setScene(const vv::scene::Scene& scene) {
    renderer_.meshRenderer().setScene(std::make_shared<const vv::scene::Scene>(scene));
    camera_.setViewport(width_, height_);
    camera_.fit(scene.bounds());
}

QImage FrameHarness::render(const MeshStyle& style, const FrameSettings& settings) {
    renderer_.meshRenderer().setStyle(style);
    renderer_.render(camera_, settings, FrameTarget{fbo_->handle(), width_, height_});
    return fbo_->toImage().convertToFormat(QImage::Format_RGB32);
}

std::vector<std::uint32_t> FrameHarness::objectIds() {
    std::vector<std::uint32_t> ids(static_cast<std::size_t>(width_ * height_), 0U);
    for (int y = 0; y < height_; ++y) {
        for (int x = 0; x < width_; ++x) {
            const auto sample = renderer_.probe(camera_, x, height_ - 1 - y);
            ids[static_cast<std::size_t>(y * width_ + x)] = sample ? sample->objectId : 0U;
        }
    }
    return ids;
}

PassState passState(const OffscreenRenderer& renderer, const std::string& pass) {
    for (const auto& info : renderer.lastPasses()) {
        if (info.name == pass) {
            return info.state;
        }
    }
    ADD_FAILURE() << "no pass " << pass;
    return PassState::Pending;
}

void saveImage(const QImage& image, const std::string& prefix, const std::string& name) {
    image.save(QString(VV_TEST_TMP) + "/" + QString::fromStdString(prefix) +
                   QString::fromStdString(name) + ".png",
               "PNG");
}

vv::scene::Mesh makeTube(float radius, float x0, float length, float y, float z, int segments,
                         int rings) {
    return vv::test::tube({.radius = radius,
                           .start = glm::vec3(x0, y, z),
                           .length = length,
                           .segments = segments,
                           .rings = rings});
}

vv::scene::Scene twoTubes(float radius, float z, int segments, int rings) {
    vv::scene::Scene scene;
    scene.meshes.push_back(makeTube(radius, -10.0F, 20.0F, 3.0F, z, segments, rings));
    scene.meshes.push_back(makeTube(radius, -10.0F, 20.0F, -3.0F, -z, segments, rings));
    return scene;
}

OffscreenOptions exactOptions(int width, int height) {
    OffscreenOptions o;
    o.width = width;
    o.height = height;
    o.display.background = {26.0F / 255.0F, 51.0F / 255.0F, 77.0F / 255.0F};
    o.display.ao.enabled = false;
    o.display.antialiasing = false;
    return o;
}

glm::vec3 toVec(QRgb p) {
    return {static_cast<float>(qRed(p)) / 255.0F, static_cast<float>(qGreen(p)) / 255.0F,
            static_cast<float>(qBlue(p)) / 255.0F};
}

}  // namespace vv::render::test
