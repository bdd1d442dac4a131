// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/render/MeshRenderer.h"

#include <QOpenGLContext>
#include <QOpenGLFunctions_4_1_Core>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <numbers>
#include <string>
#include <string_view>
#include <utility>

#include "vv/core/Error.h"
#include "vv/render/BackFaceCulling.h"
#include "vv/render/GlResources.h"

namespace vv::render {

namespace {

constexpr std::string_view kMaterial = ":/vv/shaders/vessel_shading.glsl";
constexpr std::string_view kMeshVertex = ":/vv/shaders/mesh.vert";

}  // namespace

MeshRenderer::MeshRenderer() = default;

MeshRenderer::~MeshRenderer() {
    if (context_ != nullptr && QOpenGLContext::currentContext() == context_) {
        release();
    }
    // Otherwise the GL objects go with their context.
}

QOpenGLFunctions_4_1_Core& MeshRenderer::gl() const {
    if (gl_ == nullptr) {
        throw RenderError("MeshRenderer used before initialize()");
    }
    if (QOpenGLContext::currentContext() != context_) {
        throw RenderError("MeshRenderer used without its OpenGL context current");
    }
    return *gl_;
}

bool MeshRenderer::initialized() const noexcept {
    return gl_ != nullptr && program_.valid();
}

void MeshRenderer::initialize() {
    // Throws RenderError without a current OpenGL 4.1 core context.
    QOpenGLFunctions_4_1_Core* functions = &currentGl41();
    QOpenGLContext* context = QOpenGLContext::currentContext();
    if (gl_ != nullptr && context_ == context) {
        release();
    }
    gl_ = functions;
    context_ = context;
    // Objects of an earlier context are gone with it: upload everything anew.
    geometry_.forget();
    material_.forget();
    program_ = Program();
    gbufferProgram_ = Program();
    deferredProgram_ = Program();
    emptyVao_ = 0;
    ++shadingRevision_;
    auto& f = *gl_;

    // mesh.vert binds its attributes with layout qualifiers.
    const std::string_view forward[] = {kMaterial, ":/vv/shaders/mesh.frag"};
    const std::string_view deferred[] = {kMaterial, ":/vv/shaders/vessel.frag"};
    try {
        program_ = Program(f, kMeshVertex, forward, "mesh");
        gbufferProgram_ = Program(f, kMeshVertex, ":/vv/shaders/gbuffer.frag", "G-buffer");
        deferredProgram_ =
            Program(f, ":/vv/shaders/fullscreen.vert", deferred, "deferred vessel shading");
    } catch (...) {
        program_.release();
        gbufferProgram_.release();
        throw;
    }
    f.glGenVertexArrays(1, &emptyVao_);
    material_.initialize(f);
    checkGlError(f, "MeshRenderer::initialize");
}

void MeshRenderer::release() noexcept {
    if (gl_ == nullptr || QOpenGLContext::currentContext() != context_) {
        geometry_.forget();
        return;
    }
    auto& f = *gl_;
    geometry_.clear(f);
    material_.release(f);
    program_.release();
    gbufferProgram_.release();
    deferredProgram_.release();
    if (emptyVao_ != 0) {
        f.glDeleteVertexArrays(1, &emptyVao_);
        emptyVao_ = 0;
    }
}

void MeshRenderer::setScene(std::shared_ptr<const scene::Scene> scene) {
    auto& f = gl();
    ++shadingRevision_;
    material_.setScene(scene.get());
    geometry_.upload(f, std::move(scene));
    if (geometry_.scene()) {
        material_.uploadScalars(f, geometry_);
    }
}

void MeshRenderer::attachScene(std::shared_ptr<const scene::Scene> scene) {
    // The same content: the values on the GPU and the ranges stay right.
    geometry_.attach(std::move(scene));
}

void MeshRenderer::detachScene() noexcept {
    geometry_.detach();
}

void MeshRenderer::setPreviewScene(std::shared_ptr<const scene::Scene> preview) {
    std::vector<std::shared_ptr<const scene::Scene>> previews;
    if (preview) {
        previews.push_back(std::move(preview));
    }
    setPreviewScenes(std::move(previews));
}

void MeshRenderer::setPreviewScenes(std::vector<std::shared_ptr<const scene::Scene>> previews) {
    auto& f = gl();
    ++shadingRevision_;
    geometry_.setPreviews(f, std::move(previews));
    if (geometry_.hasPreviews()) {
        material_.uploadScalars(f, geometry_);
    }
}

void MeshRenderer::setRefinedScene(std::shared_ptr<const scene::Scene> refined,
                                   double sourceEdgeMm) {
    auto& f = gl();
    ++shadingRevision_;
    geometry_.setRefined(f, std::move(refined));
    refinedSourceEdgeMm_ = geometry_.hasRefined() ? sourceEdgeMm : 0.0;
    if (geometry_.hasRefined()) {
        const Aabb box = geometry_.scene()->bounds();
        refinedCentre_ = box.empty() ? glm::vec3(0.0F) : 0.5F * (box.min + box.max);
        material_.uploadScalars(f, geometry_);
    }
}

bool MeshRenderer::refinedWanted(const Camera& camera) const noexcept {
    const int height = camera.viewportHeight();
    if (!geometry_.hasRefined() || !(refinedSourceEdgeMm_ > 0.0) || height <= 0) {
        return false;
    }
    const double distance = glm::length(camera.eye() - refinedCentre_);
    const double halfHeight =
        distance * std::tan(0.5 * glm::radians(static_cast<double>(camera.fieldOfView())));
    if (!(halfHeight > 0.0)) {
        return true;  // at the scene's middle: every facet is huge
    }
    const double pixelsPerMm = 0.5 * static_cast<double>(height) / halfHeight;
    return 0.25 * std::numbers::pi * refinedSourceEdgeMm_ * pixelsPerMm >= kCoarseEdgePixels;
}

std::size_t MeshRenderer::previewLevelFor(long long pixels) const noexcept {
    return geometry_.previewLevelFor(pixels);
}

void MeshRenderer::setStyle(const MeshStyle& style) {
    material_.setStyle(style, geometry_.scene().get());
    ++shadingRevision_;
    // With the context current, upload now; otherwise draw() catches up.
    if (gl_ != nullptr && QOpenGLContext::currentContext() == context_) {
        if (material_.scalarsStale(geometry_)) {
            material_.uploadScalars(*gl_, geometry_);
        }
        material_.uploadLut(*gl_);
    }
}

std::optional<std::pair<float, float>> MeshRenderer::objectRange(std::size_t mesh) const {
    return material_.objectRange(mesh);
}

void MeshRenderer::setSurfaceClosures(std::size_t level,
                                      const std::vector<scene::SurfaceClosure>& closures) {
    geometry_.setSurfaceClosures(level, closures);
}

std::optional<scene::SurfaceClosure> MeshRenderer::surfaceClosure(std::size_t level,
                                                                  std::size_t mesh) const noexcept {
    return geometry_.surfaceClosure(level, mesh);
}

void MeshRenderer::draw(const Camera& camera, DepthMode mode, const VesselCueParameters& cue) {
    auto& f = gl();
    if (!program_.valid()) {
        throw RenderError("MeshRenderer::draw without a shader program");
    }
    if (!drawable()) {
        return;
    }
    material_.prepare(f, geometry_, cue);
    const glm::mat4 view = camera.viewMatrix();
    const glm::mat4 projection = camera.projectionMatrix();
    const glm::mat3 normalMatrix = glm::transpose(glm::inverse(glm::mat3(view)));

    f.glEnable(GL_DEPTH_TEST);
    f.glDepthFunc(mode == DepthMode::Write ? GL_LESS : GL_LEQUAL);
    f.glDepthMask(mode == DepthMode::Write ? GL_TRUE : GL_FALSE);
    f.glDisable(GL_BLEND);
    material_.use(f, program_, cue);
    lastCulledMeshes_ = 0;
    const auto loc = [&](std::string_view name) { return program_.location(name); };
    f.glUniformMatrix4fv(loc("uView"), 1, GL_FALSE, &view[0][0]);
    f.glUniformMatrix4fv(loc("uProjection"), 1, GL_FALSE, &projection[0][0]);
    f.glUniformMatrix3fv(loc("uNormalMatrix"), 1, GL_FALSE, &normalMatrix[0][0]);
    const std::vector<GpuMesh>& meshes = geometry_.meshesOf(0);
    for (std::size_t i = 0; i < meshes.size(); ++i) {
        if (!style().visible(i)) {
            continue;
        }
        material_.useObject(f, program_, i);
        cullFor(meshes[i], view, projection);
        f.glBindVertexArray(meshes[i].vao);
        f.glDrawElements(GL_TRIANGLES, meshes[i].indexCount, GL_UNSIGNED_INT, nullptr);
    }
    f.glDisable(GL_CULL_FACE);
    f.glBindVertexArray(0);
    material_.unbind(f);
    f.glDepthMask(GL_TRUE);
    checkGlError(f, "drawing meshes");
}

void MeshRenderer::shadeGBuffer(const Camera& camera, const GBufferTextures& gbuffer,
                                const VesselCueParameters& cue) {
    auto& f = gl();
    if (!deferredProgram_.valid()) {
        throw RenderError("MeshRenderer::shadeGBuffer without a shader program");
    }
    material_.prepare(f, geometry_, cue);
    f.glDisable(GL_DEPTH_TEST);
    f.glDepthMask(GL_FALSE);
    f.glDisable(GL_BLEND);
    material_.use(f, deferredProgram_, cue);
    const auto loc = [&](std::string_view name) { return deferredProgram_.location(name); };
    // A perspective projection maps view x / -z to ndc x * P[0][0] (y likewise).
    const glm::mat4 projection = camera.projectionMatrix();
    f.glUniform2f(loc("uViewScale"), 1.0F / projection[0][0], 1.0F / projection[1][1]);
    // Off-axis frusta (tiles, Camera::setWindow) shift NDC by P[2][0], P[2][1].
    f.glUniform2f(loc("uViewOffset"), projection[2][0], projection[2][1]);
    const std::array<std::pair<const char*, unsigned>, 4> inputs = {{
        {"uLinearDepth", gbuffer.linearDepth},
        {"uNormal", gbuffer.normal},
        {"uParameter", gbuffer.parameter},
        {"uObjectId", gbuffer.objectId},
    }};
    for (std::size_t i = 0; i < inputs.size(); ++i) {
        const auto unit = static_cast<GLint>(MeshMaterial::kGBufferFirstUnit + i);
        f.glUniform1i(loc(inputs[i].first), unit);
        f.glActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(unit));
        f.glBindTexture(GL_TEXTURE_2D, inputs[i].second);
    }
    f.glBindVertexArray(emptyVao_);
    f.glDrawArrays(GL_TRIANGLES, 0, 3);
    f.glBindVertexArray(0);
    for (std::size_t i = 0; i < inputs.size(); ++i) {
        f.glActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(MeshMaterial::kGBufferFirstUnit + i));
        f.glBindTexture(GL_TEXTURE_2D, 0);
    }
    material_.unbind(f);
    f.glDepthMask(GL_TRUE);
    checkGlError(f, "shading the vessels from the G-buffer");
}

bool MeshRenderer::hasTranslucent() const noexcept {
    if (!drawable()) {
        return false;
    }
    for (std::size_t i = 0; i < geometry_.meshesOf(0).size(); ++i) {
        if (style().translucent(i)) {
            return true;
        }
    }
    return false;
}

void MeshRenderer::drawTranslucent(const Camera& camera, const VesselCueParameters& cue,
                                   std::size_t level) {
    auto& f = gl();
    if (!program_.valid()) {
        throw RenderError("MeshRenderer::drawTranslucent without a shader program");
    }
    if (!drawable()) {
        return;
    }
    const std::vector<GpuMesh>& drawn = geometry_.meshesOf(level);
    const glm::mat4 view = camera.viewMatrix();
    // Back to front: the farthest bounding-box centre (most negative view z) first.
    std::vector<std::pair<float, std::size_t>> order;
    for (std::size_t i = 0; i < drawn.size(); ++i) {
        if (style().translucent(i)) {
            order.emplace_back((view * glm::vec4(drawn[i].center, 1.0F)).z, i);
        }
    }
    if (order.empty()) {
        return;
    }
    std::sort(order.begin(), order.end());
    material_.prepare(f, geometry_, cue);
    const glm::mat4 projection = camera.projectionMatrix();
    const glm::mat3 normalMatrix = glm::transpose(glm::inverse(glm::mat3(view)));
    material_.use(f, program_, cue);
    const auto loc = [&](std::string_view name) { return program_.location(name); };
    f.glUniformMatrix4fv(loc("uView"), 1, GL_FALSE, &view[0][0]);
    f.glUniformMatrix4fv(loc("uProjection"), 1, GL_FALSE, &projection[0][0]);
    f.glUniformMatrix3fv(loc("uNormalMatrix"), 1, GL_FALSE, &normalMatrix[0][0]);
    f.glEnable(GL_DEPTH_TEST);
    f.glDisable(GL_CULL_FACE);
    // Premultiplied "over": colour * opacity + destination * (1 - opacity).
    f.glBlendFuncSeparate(GL_ONE, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    for (const auto& [z, i] : order) {
        material_.useObject(f, program_, i);
        f.glUniform1f(loc("uOpacity"), style().object(i).opacity);
        f.glBindVertexArray(drawn[i].vao);
        // Its nearest surface into the depth buffer, then only that surface blended.
        f.glDisable(GL_BLEND);
        f.glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
        f.glDepthMask(GL_TRUE);
        f.glDepthFunc(GL_LESS);
        f.glDrawElements(GL_TRIANGLES, drawn[i].indexCount, GL_UNSIGNED_INT, nullptr);
        f.glEnable(GL_BLEND);
        f.glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
        f.glDepthMask(GL_FALSE);
        f.glDepthFunc(GL_LEQUAL);
        f.glDrawElements(GL_TRIANGLES, drawn[i].indexCount, GL_UNSIGNED_INT, nullptr);
    }
    f.glBindVertexArray(0);
    material_.unbind(f);
    f.glDisable(GL_BLEND);
    f.glDepthMask(GL_TRUE);
    f.glDepthFunc(GL_LESS);
    checkGlError(f, "drawing translucent objects");
}

void MeshRenderer::drawGBuffer(const Camera& camera, std::size_t level) {
    auto& f = gl();
    if (!gbufferProgram_.valid()) {
        throw RenderError("MeshRenderer::drawGBuffer without a shader program");
    }
    if (!drawable()) {
        return;
    }
    if (material_.scalarsStale(geometry_)) {
        material_.uploadScalars(f, geometry_);
    }
    const glm::mat4 view = camera.viewMatrix();
    const glm::mat4 projection = camera.projectionMatrix();
    const glm::mat3 normalMatrix = glm::transpose(glm::inverse(glm::mat3(view)));
    f.glEnable(GL_DEPTH_TEST);
    f.glDepthFunc(GL_LESS);
    f.glDepthMask(GL_TRUE);
    f.glDisable(GL_BLEND);
    gbufferProgram_.use();
    const auto loc = [&](std::string_view name) { return gbufferProgram_.location(name); };
    f.glUniformMatrix4fv(loc("uView"), 1, GL_FALSE, &view[0][0]);
    f.glUniformMatrix4fv(loc("uProjection"), 1, GL_FALSE, &projection[0][0]);
    f.glUniformMatrix3fv(loc("uNormalMatrix"), 1, GL_FALSE, &normalMatrix[0][0]);
    const GLint useArray = loc("uUseArray");
    const GLint labels = loc("uLabels");
    const GLint objectId = loc("uObjectId");
    GLuint id = 1;
    const std::vector<GpuMesh>& drawn = geometry_.meshesOf(level);
    lastCulledMeshes_ = 0;
    for (std::size_t i = 0; i < drawn.size(); ++i) {
        f.glUniform1ui(objectId, id++);
        if (!style().opaque(i)) {
            continue;  // hidden or translucent: its id stays reserved
        }
        f.glUniform1i(useArray, style().arrayOf(i).empty() ? 0 : 1);
        f.glUniform1i(labels, material_.objectLabels(i) != nullptr ? 1 : 0);
        cullFor(drawn[i], view, projection);
        f.glBindVertexArray(drawn[i].vao);
        f.glDrawElements(GL_TRIANGLES, drawn[i].indexCount, GL_UNSIGNED_INT, nullptr);
    }
    f.glDisable(GL_CULL_FACE);
    f.glBindVertexArray(0);
    f.glUseProgram(0);
    checkGlError(f, "drawing the G-buffer");
}

void MeshRenderer::cullFor(const GpuMesh& mesh, const glm::mat4& view,
                           const glm::mat4& projection) {
    auto& f = gl();
    const CullFace faces =
        backFaceCulling_ ? GpuMeshes::cullableFacesOf(mesh, view, projection) : CullFace::None;
    if (faces == CullFace::None) {
        f.glDisable(GL_CULL_FACE);
        return;
    }
    f.glEnable(GL_CULL_FACE);
    f.glCullFace(faces == CullFace::Back ? GL_BACK : GL_FRONT);
    ++lastCulledMeshes_;
}

std::string MeshRenderer::glDescription() const {
    auto& f = gl();
    const auto text = [&](GLenum name) {
        const auto* s = reinterpret_cast<const char*>(f.glGetString(name));
        return s != nullptr ? std::string(s) : std::string("?");
    };
    return text(GL_RENDERER) + " / OpenGL " + text(GL_VERSION);
}

}  // namespace vv::render
