// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/render/GpuMeshes.h"

#include <QOpenGLFunctions_4_1_Core>
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <utility>

#include "vv/core/Error.h"
#include "vv/core/Log.h"
#include "vv/render/GlResources.h"

namespace vv::render {

namespace {

constexpr GLuint kPositionLocation = 0;
constexpr GLuint kNormalLocation = 1;
constexpr GLuint kScalarLocation = 2;

struct Vertex {
    glm::vec3 position;
    glm::vec3 normal;
};
static_assert(sizeof(Vertex) == 6 * sizeof(float), "Vertex must be tightly packed");

}  // namespace

std::size_t choosePreviewLevel(std::span<const std::size_t> triangles, long long pixels) noexcept {
    if (triangles.empty()) {
        return 0;
    }
    const long long budget = std::max(pixels, 0LL) / kPixelsPerPreviewTriangle;
    for (std::size_t i = 0; i < triangles.size(); ++i) {
        if (static_cast<long long>(triangles[i]) <= budget) {
            return i + 1;
        }
    }
    return triangles.size();
}

void GpuMeshes::deleteMeshes(QOpenGLFunctions_4_1_Core& gl, std::vector<GpuMesh>& meshes) {
    for (auto& m : meshes) {
        gl.glDeleteVertexArrays(1, &m.vao);
        gl.glDeleteBuffers(1, &m.vertices);
        gl.glDeleteBuffers(1, &m.scalars);
        gl.glDeleteBuffers(1, &m.indices);
    }
    meshes.clear();
}

void GpuMeshes::uploadMeshes(QOpenGLFunctions_4_1_Core& gl, const scene::Scene& scene,
                             std::vector<GpuMesh>& target) {
    for (const auto& mesh : scene.meshes) {
        const std::size_t n = mesh.vertexCount();
        if (mesh.indices.size() > static_cast<std::size_t>(std::numeric_limits<GLsizei>::max()) ||
            n > std::numeric_limits<std::uint32_t>::max()) {
            throw InvalidArgumentError(mesh.source,
                                       "mesh '" + mesh.name + "' is too large to draw at once");
        }
        for (const auto index : mesh.indices) {
            if (index >= n) {
                throw InvalidArgumentError(
                    mesh.source, "mesh '" + mesh.name + "' has a triangle index out of range");
            }
        }
        scene::Mesh withNormals;
        const std::vector<glm::vec3>* normals = &mesh.normals;
        if (mesh.normals.size() != n) {
            withNormals.positions = mesh.positions;
            withNormals.indices = mesh.indices;
            scene::computeNormals(withNormals);
            normals = &withNormals.normals;
        }
        std::vector<Vertex> vertices(n);
        for (std::size_t i = 0; i < n; ++i) {
            vertices[i] = Vertex{mesh.positions[i], (*normals)[i]};
        }

        GpuMesh gpu;
        gl.glGenVertexArrays(1, &gpu.vao);
        gl.glGenBuffers(1, &gpu.vertices);
        gl.glGenBuffers(1, &gpu.scalars);
        gl.glGenBuffers(1, &gpu.indices);
        target.push_back(gpu);  // owned from here on, so errors below do not leak

        gl.glBindVertexArray(gpu.vao);
        gl.glBindBuffer(GL_ARRAY_BUFFER, gpu.vertices);
        gl.glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(vertices.size() * sizeof(Vertex)),
                        vertices.data(), GL_STATIC_DRAW);
        gl.glEnableVertexAttribArray(kPositionLocation);
        gl.glVertexAttribPointer(kPositionLocation, 3, GL_FLOAT, GL_FALSE, sizeof(Vertex),
                                 reinterpret_cast<const void*>(offsetof(Vertex, position)));
        gl.glEnableVertexAttribArray(kNormalLocation);
        gl.glVertexAttribPointer(kNormalLocation, 3, GL_FLOAT, GL_FALSE, sizeof(Vertex),
                                 reinterpret_cast<const void*>(offsetof(Vertex, normal)));

        gl.glBindBuffer(GL_ARRAY_BUFFER, gpu.scalars);
        gl.glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(n * sizeof(glm::vec2)), nullptr,
                        GL_DYNAMIC_DRAW);
        gl.glEnableVertexAttribArray(kScalarLocation);
        gl.glVertexAttribPointer(kScalarLocation, 2, GL_FLOAT, GL_FALSE, sizeof(glm::vec2),
                                 nullptr);

        gl.glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, gpu.indices);
        gl.glBufferData(GL_ELEMENT_ARRAY_BUFFER,
                        static_cast<GLsizeiptr>(mesh.indices.size() * sizeof(std::uint32_t)),
                        mesh.indices.data(), GL_STATIC_DRAW);
        target.back().indexCount = static_cast<GLsizei>(mesh.indices.size());
        target.back().bounds = mesh.bounds();
        if (!target.back().bounds.empty()) {
            target.back().center = 0.5F * (target.back().bounds.min + target.back().bounds.max);
        }
        target.back().source = &mesh;  // Open until setSurfaceClosures()
        gl.glBindVertexArray(0);
        gl.glBindBuffer(GL_ARRAY_BUFFER, 0);
        checkGlError(gl, "uploading a mesh");
    }
}

void GpuMeshes::upload(QOpenGLFunctions_4_1_Core& gl, std::shared_ptr<const scene::Scene> scene) {
    deleteMeshes(gl, meshes_);
    deletePreviews(gl);
    deleteRefined(gl);
    scene_ = std::move(scene);
    if (!scene_) {
        return;
    }
    uploadMeshes(gl, *scene_, meshes_);
    ++uploads_;
    static const log::Category category{"vv.render"};
    log::debug(category, "uploaded a scene: " + std::to_string(scene_->meshes.size()) +
                             " meshes, " + std::to_string(scene_->triangleCount()) + " triangles");
}

void GpuMeshes::attach(std::shared_ptr<const scene::Scene> scene) {
    const std::size_t count = scene ? scene->meshes.size() : 0U;
    bool same = count == meshes_.size();
    for (std::size_t i = 0; same && i < count; ++i) {
        same = static_cast<std::size_t>(meshes_[i].indexCount) == scene->meshes[i].indices.size();
    }
    if (!same) {
        throw InvalidArgumentError("the scene to attach is not the uploaded one (" +
                                   std::to_string(count) + " meshes for " +
                                   std::to_string(meshes_.size()) + ")");
    }
    scene_ = std::move(scene);
    for (std::size_t i = 0; i < count; ++i) {
        meshes_[i].source = &scene_->meshes[i];
    }
}

void GpuMeshes::detach() noexcept {
    for (GpuMesh& mesh : meshes_) {
        mesh.source = nullptr;
    }
    scene_.reset();
}

void GpuMeshes::deletePreviews(QOpenGLFunctions_4_1_Core& gl) {
    for (PreviewLevel& level : previews_) {
        deleteMeshes(gl, level.meshes);
    }
    previews_.clear();
    previewTriangles_.clear();
}

void GpuMeshes::checkCopy(const scene::Scene& copy, const char* what) const {
    if (!scene_ || copy.meshes.size() != scene_->meshes.size()) {
        throw InvalidArgumentError(std::string("the ") + what +
                                   " scene must have one mesh for each mesh of the scene (" +
                                   std::to_string(copy.meshes.size()) + " for " +
                                   std::to_string(scene_ ? scene_->meshes.size() : 0) + ")");
    }
}

void GpuMeshes::deleteRefined(QOpenGLFunctions_4_1_Core& gl) {
    deleteMeshes(gl, refined_.meshes);
    refined_.scene.reset();
}

void GpuMeshes::setRefined(QOpenGLFunctions_4_1_Core& gl,
                           std::shared_ptr<const scene::Scene> refined) {
    deleteRefined(gl);
    if (!refined) {
        return;
    }
    checkCopy(*refined, "refined");
    try {
        uploadMeshes(gl, *refined, refined_.meshes);
    } catch (...) {
        deleteRefined(gl);
        throw;
    }
    refined_.scene = std::move(refined);
}

void GpuMeshes::setPreviews(QOpenGLFunctions_4_1_Core& gl,
                            std::vector<std::shared_ptr<const scene::Scene>> previews) {
    deletePreviews(gl);
    std::erase(previews, nullptr);
    if (previews.empty()) {
        return;
    }
    for (const auto& preview : previews) {
        checkCopy(*preview, "preview");
    }
    std::stable_sort(previews.begin(), previews.end(), [](const auto& a, const auto& b) {
        return a->triangleCount() > b->triangleCount();
    });
    for (auto& preview : previews) {
        previewTriangles_.push_back(preview->triangleCount());
        previews_.push_back(PreviewLevel{std::move(preview), {}});
    }
    try {
        for (PreviewLevel& level : previews_) {
            uploadMeshes(gl, *level.scene, level.meshes);
        }
    } catch (...) {
        deletePreviews(gl);
        throw;
    }
}

std::size_t GpuMeshes::previewLevelFor(long long pixels) const noexcept {
    return choosePreviewLevel(previewTriangles_, pixels);
}

const std::vector<GpuMesh>& GpuMeshes::meshesOf(std::size_t level) const noexcept {
    if (level == kRefinedLevel) {
        return hasRefined() ? refined_.meshes : meshes_;
    }
    if (level == 0 || previews_.empty()) {
        return meshes_;
    }
    return previews_[std::min(level, previews_.size()) - 1].meshes;
}

std::vector<GpuMeshes::Level> GpuMeshes::levels() const {
    std::vector<Level> all{Level{scene_.get(), &meshes_}};
    for (const PreviewLevel& level : previews_) {
        all.push_back(Level{level.scene.get(), &level.meshes});
    }
    if (hasRefined()) {
        all.push_back(Level{refined_.scene.get(), &refined_.meshes});
    }
    return all;
}

const std::vector<GpuMesh>* GpuMeshes::levelMeshes(std::size_t level) const noexcept {
    if (level == kRefinedLevel) {
        return hasRefined() ? &refined_.meshes : nullptr;
    }
    if (level > previews_.size()) {
        return nullptr;
    }
    return level == 0 ? &meshes_ : &previews_[level - 1].meshes;
}

std::vector<GpuMesh>* GpuMeshes::levelMeshes(std::size_t level) noexcept {
    if (level == kRefinedLevel) {
        return hasRefined() ? &refined_.meshes : nullptr;
    }
    if (level > previews_.size()) {
        return nullptr;
    }
    return level == 0 ? &meshes_ : &previews_[level - 1].meshes;
}

void GpuMeshes::setSurfaceClosures(std::size_t level,
                                   const std::vector<scene::SurfaceClosure>& closures) {
    std::vector<GpuMesh>* meshes = levelMeshes(level);
    if (meshes == nullptr) {
        throw InvalidArgumentError(
            "no geometry level " +
            (level == kRefinedLevel ? std::string("refined") : std::to_string(level)) + " (" +
            std::to_string(previews_.size()) + " preview levels)");
    }
    if (closures.size() != meshes->size()) {
        throw InvalidArgumentError("level " + std::to_string(level) + " has " +
                                   std::to_string(meshes->size()) + " meshes, not " +
                                   std::to_string(closures.size()));
    }
    for (std::size_t i = 0; i < meshes->size(); ++i) {
        (*meshes)[i].closure = closures[i];
    }
}

std::optional<scene::SurfaceClosure> GpuMeshes::surfaceClosure(std::size_t level,
                                                               std::size_t mesh) const noexcept {
    const std::vector<GpuMesh>* meshes = levelMeshes(level);
    if (meshes == nullptr || mesh >= meshes->size()) {
        return std::nullopt;
    }
    return (*meshes)[mesh].closure;
}

CullFace GpuMeshes::cullableFacesOf(const GpuMesh& mesh, const glm::mat4& view,
                                    const glm::mat4& projection) noexcept {
    return mesh.source != nullptr
               ? cullableFaces(*mesh.source, mesh.closure, mesh.bounds, view, projection)
               : CullFace::None;
}

void GpuMeshes::clear(QOpenGLFunctions_4_1_Core& gl) {
    deleteMeshes(gl, meshes_);
    deletePreviews(gl);
    deleteRefined(gl);
}

void GpuMeshes::forget() noexcept {
    meshes_.clear();
    previews_.clear();
    previewTriangles_.clear();
    refined_ = {};
}

}  // namespace vv::render
