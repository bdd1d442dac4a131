// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/render/MeshRenderer.h"

#include <QByteArray>
#include <QFile>
#include <QOpenGLContext>
#include <QOpenGLFunctions_4_1_Core>
#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <string_view>

#include "vv/core/Error.h"
#include "vv/core/Hash.h"
#include "vv/core/Log.h"
#include "vv/render/BackFaceCulling.h"
#include "vv/render/GlResources.h"
#include "vv/scene/MeshTopology.h"

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

std::string lower(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return s;
}

constexpr std::string_view kMaterial = ":/vv/shaders/vessel_shading.glsl";
constexpr std::string_view kMeshVertex = ":/vv/shaders/mesh.vert";

/// The per-vertex (value, valid) pairs of `name` on `mesh`; (0, 0) where the
/// value is NaN / infinite or the mesh lacks the array.
std::vector<glm::vec2> scalarsFor(const scene::Mesh& mesh, const std::string& name) {
    std::vector<glm::vec2> out(mesh.vertexCount(), glm::vec2(0.0F));
    if (name.empty()) {
        return out;
    }
    const scene::DataArray* array = mesh.pointArray(name);
    if (array == nullptr || array->components < 1 || array->tupleCount() != mesh.vertexCount()) {
        return out;
    }
    const auto components = static_cast<std::size_t>(array->components);
    for (std::size_t i = 0; i < out.size(); ++i) {
        float value = 0.0F;
        if (components == 1) {
            value = array->values[i];
        } else {
            double sum = 0.0;
            for (std::size_t c = 0; c < components; ++c) {
                const double v = array->values[i * components + c];
                sum += v * v;
            }
            value = static_cast<float>(std::sqrt(sum));
        }
        if (std::isfinite(value)) {
            out[i] = glm::vec2(value, 1.0F);
        }
    }
    return out;
}

/// Ends a texture upload to `target` on the active unit: `filter` for
/// minification and magnification, clamped s, unbound, unit 0 active again;
/// throws RenderError naming `what` when GL reports an error.
void finishUpload(QOpenGLFunctions_4_1_Core& f, GLenum target, GLint filter, const char* what) {
    f.glTexParameteri(target, GL_TEXTURE_MIN_FILTER, filter);
    f.glTexParameteri(target, GL_TEXTURE_MAG_FILTER, filter);
    f.glTexParameteri(target, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    f.glBindTexture(target, 0);
    f.glActiveTexture(GL_TEXTURE0);
    checkGlError(f, what);
}

}  // namespace

namespace {

constexpr std::array kAllCues{VesselCue::None, VesselCue::Chromadepth, VesselCue::PseudoChromadepth,
                              VesselCue::Fog, VesselCue::Fresnel};
constexpr int kCueLutSize = 256;
/// Texture unit of the cue's depth-scale table (unit 0 holds the colour map).
constexpr GLint kCueLutUnit = 1;
/// shadeGBuffer() binds the G-buffer's four textures from this unit on.
constexpr GLint kGBufferFirstUnit = 2;
/// ... and the per-object table to this one.
constexpr GLint kObjectTableUnit = kGBufferFirstUnit + 4;

/// Widens `range` by the finite range of `mesh`'s point array `name`, if any.
void widenRange(std::optional<std::pair<float, float>>& range, const scene::Mesh& mesh,
                const std::string& name) {
    const scene::DataArray* array = mesh.pointArray(name);
    const auto r = array != nullptr ? array->finiteRange() : std::nullopt;
    if (!r) {
        return;
    }
    if (!range) {
        range = r;
    } else {
        range->first = std::min(range->first, r->first);
        range->second = std::max(range->second, r->second);
    }
}

bool inUnitRange(float v) noexcept {
    return std::isfinite(v) && v >= 0.0F && v <= 1.0F;
}

}  // namespace

std::span<const VesselCue> allVesselCues() noexcept {
    return kAllCues;
}

std::string_view name(VesselCue cue) noexcept {
    switch (cue) {
        case VesselCue::None:
            return "none";
        case VesselCue::Chromadepth:
            return "vessel-cd";
        case VesselCue::PseudoChromadepth:
            return "vessel-pcd";
        case VesselCue::Fog:
            return "fog";
        case VesselCue::Fresnel:
            return "fresnel";
    }
    return "none";
}

std::string_view displayName(VesselCue cue) noexcept {
    switch (cue) {
        case VesselCue::None:
            return "None";
        case VesselCue::Chromadepth:
            return "Vessel chromadepth";
        case VesselCue::PseudoChromadepth:
            return "Vessel pseudo-chromadepth";
        case VesselCue::Fog:
            return "Depth fog";
        case VesselCue::Fresnel:
            return "Fresnel-edge pseudo-chromadepth";
    }
    return "None";
}

std::optional<VesselCue> vesselCueFromName(std::string_view text) noexcept {
    for (const VesselCue cue : kAllCues) {
        const std::string_view n = name(cue);
        if (n.size() == text.size() &&
            std::equal(n.begin(), n.end(), text.begin(), [](char a, char b) {
                return std::tolower(static_cast<unsigned char>(a)) ==
                       std::tolower(static_cast<unsigned char>(b));
            })) {
            return cue;
        }
    }
    return std::nullopt;
}

std::optional<colormaps::DepthScale> cueDepthScale(VesselCue cue) noexcept {
    switch (cue) {
        case VesselCue::Chromadepth:
            return colormaps::DepthScale::Chromadepth;
        case VesselCue::PseudoChromadepth:
        case VesselCue::Fresnel:
            return colormaps::DepthScale::PseudoChromadepth;
        case VesselCue::None:
        case VesselCue::Fog:
            return std::nullopt;
    }
    return std::nullopt;
}

glm::vec3 lightDirection(const LightAngles& angles) {
    if (!std::isfinite(angles.azimuth) || !std::isfinite(angles.elevation) ||
        std::abs(angles.azimuth) > 180.0F || std::abs(angles.elevation) > 90.0F) {
        throw InvalidArgumentError(
            "the light direction must have an azimuth within -180..180 and "
            "an elevation within -90..90 degrees, got " +
            std::to_string(angles.azimuth) + ", " + std::to_string(angles.elevation));
    }
    const float a = glm::radians(angles.azimuth);
    const float e = glm::radians(angles.elevation);
    return glm::normalize(
        glm::vec3(std::cos(e) * std::sin(a), std::sin(e), std::cos(e) * std::cos(a)));
}

const Lighting& sceneLighting() noexcept {
    static const Lighting lighting = [] {
        Lighting l;
        l.direction = glm::normalize(glm::vec3(-0.25F, 0.35F, 1.0F));
        return l;
    }();
    return lighting;
}

Lighting lightingFor(const LightAngles& angles) {
    Lighting l = sceneLighting();
    if (!(angles == LightAngles{})) {
        l.direction = lightDirection(angles);
    }
    return l;
}

void validateStyle(const MeshStyle& style) {
    static_cast<void>(lightDirection(style.light));
    for (std::size_t i = 0; i < style.objects.size(); ++i) {
        const ObjectStyle& o = style.objects[i];
        const bool colorOk = !o.color || (inUnitRange(o.color->r) && inUnitRange(o.color->g) &&
                                          inUnitRange(o.color->b));
        if (!inUnitRange(o.opacity) || !colorOk) {
            throw InvalidArgumentError("object " + std::to_string(i) +
                                       ": opacity and colour components must be within 0..1");
        }
    }
}

std::vector<std::string> shownArrays(const scene::Scene& scene, const MeshStyle& style) {
    std::vector<std::string> arrays;
    for (std::size_t i = 0; i < scene.meshes.size(); ++i) {
        const std::string& a = style.arrayOf(i);
        if (!style.visible(i) || a.empty() || scene.meshes[i].pointArray(a) == nullptr ||
            std::find(arrays.begin(), arrays.end(), a) != arrays.end()) {
            continue;
        }
        if (a == style.array) {
            arrays.insert(arrays.begin(), a);
        } else {
            arrays.push_back(a);
        }
    }
    return arrays;
}

std::optional<std::pair<float, float>> objectArrayRange(const scene::Scene& scene,
                                                        const MeshStyle& style,
                                                        const std::string& name) {
    std::optional<std::pair<float, float>> range;
    for (std::size_t i = 0; i < scene.meshes.size(); ++i) {
        if (style.arrayOf(i) == name) {
            widenRange(range, scene.meshes[i], name);
        }
    }
    return range;
}

std::string defaultArrayName(const scene::Scene& scene) {
    for (const auto& wanted : {"wss", "wall_shear_stress", "wallshearstress"}) {
        for (const auto& mesh : scene.meshes) {
            for (const auto& array : mesh.pointArrays) {
                if (lower(array.name) == wanted) {
                    return array.name;
                }
            }
        }
    }
    return {};
}

std::vector<std::string> pointArrayNames(const scene::Scene& scene) {
    std::vector<std::string> names;
    for (const auto& mesh : scene.meshes) {
        for (const auto& array : mesh.pointArrays) {
            if (std::find(names.begin(), names.end(), array.name) == names.end()) {
                names.push_back(array.name);
            }
        }
    }
    return names;
}

std::optional<std::pair<float, float>> arrayRange(const scene::Scene& scene,
                                                  const std::string& name) {
    std::optional<std::pair<float, float>> range;
    for (const auto& mesh : scene.meshes) {
        widenRange(range, mesh, name);
    }
    return range;
}

struct MeshRenderer::GpuMesh {
    GLuint vao = 0;
    GLuint vertices = 0;
    GLuint scalars = 0;
    GLuint indices = 0;
    GLsizei indexCount = 0;
    glm::vec3 center{0.0F};  ///< of the bounding box, for sorting translucent objects
    Aabb bounds;
    /// The mesh it was uploaded from, owned by scene_ or a preview level's scene.
    const scene::Mesh* source = nullptr;
    scene::SurfaceClosure closure = scene::SurfaceClosure::Open;
};

MeshRenderer::MeshRenderer() : lighting_(sceneLighting()) {}

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
    meshes_.clear();
    previews_.clear();
    previewTriangles_.clear();
    program_ = Program();
    gbufferProgram_ = Program();
    deferredProgram_ = Program();
    emptyVao_ = 0;
    lutTexture_ = 0;
    cueLutTexture_ = 0;
    objectTexture_ = 0;
    objectsStale_ = true;
    ++shadingRevision_;
    uploadedMap_.reset();
    uploadedCueScale_.reset();
    scalarsUploadedForArray_ = false;
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

    f.glGenTextures(1, &lutTexture_);
    f.glGenTextures(1, &cueLutTexture_);
    f.glGenTextures(1, &objectTexture_);
    uploadedMap_.reset();
    uploadLut();
    checkGlError(f, "MeshRenderer::initialize");
}

void MeshRenderer::release() noexcept {
    if (gl_ == nullptr || QOpenGLContext::currentContext() != context_) {
        meshes_.clear();
        previews_.clear();
        previewTriangles_.clear();
        return;
    }
    auto& f = *gl_;
    deleteMeshes(meshes_);
    deletePreviews();
    if (lutTexture_ != 0) {
        f.glDeleteTextures(1, &lutTexture_);
        lutTexture_ = 0;
    }
    if (cueLutTexture_ != 0) {
        f.glDeleteTextures(1, &cueLutTexture_);
        cueLutTexture_ = 0;
    }
    if (objectTexture_ != 0) {
        f.glDeleteTextures(1, &objectTexture_);
        objectTexture_ = 0;
    }
    objectsStale_ = true;
    uploadedCueScale_.reset();
    program_.release();
    gbufferProgram_.release();
    deferredProgram_.release();
    if (emptyVao_ != 0) {
        f.glDeleteVertexArrays(1, &emptyVao_);
        emptyVao_ = 0;
    }
    uploadedMap_.reset();
    scalarsUploadedForArray_ = false;
}

void MeshRenderer::deleteMeshes(std::vector<GpuMesh>& meshes) {
    auto& f = gl();
    for (auto& m : meshes) {
        f.glDeleteVertexArrays(1, &m.vao);
        f.glDeleteBuffers(1, &m.vertices);
        f.glDeleteBuffers(1, &m.scalars);
        f.glDeleteBuffers(1, &m.indices);
    }
    meshes.clear();
}

void MeshRenderer::uploadMeshes(const scene::Scene& scene, std::vector<GpuMesh>& target) {
    auto& f = gl();
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
        f.glGenVertexArrays(1, &gpu.vao);
        f.glGenBuffers(1, &gpu.vertices);
        f.glGenBuffers(1, &gpu.scalars);
        f.glGenBuffers(1, &gpu.indices);
        target.push_back(gpu);  // owned from here on, so errors below do not leak

        f.glBindVertexArray(gpu.vao);
        f.glBindBuffer(GL_ARRAY_BUFFER, gpu.vertices);
        f.glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(vertices.size() * sizeof(Vertex)),
                       vertices.data(), GL_STATIC_DRAW);
        f.glEnableVertexAttribArray(kPositionLocation);
        f.glVertexAttribPointer(kPositionLocation, 3, GL_FLOAT, GL_FALSE, sizeof(Vertex),
                                reinterpret_cast<const void*>(offsetof(Vertex, position)));
        f.glEnableVertexAttribArray(kNormalLocation);
        f.glVertexAttribPointer(kNormalLocation, 3, GL_FLOAT, GL_FALSE, sizeof(Vertex),
                                reinterpret_cast<const void*>(offsetof(Vertex, normal)));

        f.glBindBuffer(GL_ARRAY_BUFFER, gpu.scalars);
        f.glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(n * sizeof(glm::vec2)), nullptr,
                       GL_DYNAMIC_DRAW);
        f.glEnableVertexAttribArray(kScalarLocation);
        f.glVertexAttribPointer(kScalarLocation, 2, GL_FLOAT, GL_FALSE, sizeof(glm::vec2), nullptr);

        f.glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, gpu.indices);
        f.glBufferData(GL_ELEMENT_ARRAY_BUFFER,
                       static_cast<GLsizeiptr>(mesh.indices.size() * sizeof(std::uint32_t)),
                       mesh.indices.data(), GL_STATIC_DRAW);
        target.back().indexCount = static_cast<GLsizei>(mesh.indices.size());
        target.back().bounds = mesh.bounds();
        if (!target.back().bounds.empty()) {
            target.back().center = 0.5F * (target.back().bounds.min + target.back().bounds.max);
        }
        target.back().source = &mesh;  // Open until setSurfaceClosures()
        f.glBindVertexArray(0);
        f.glBindBuffer(GL_ARRAY_BUFFER, 0);
        checkGlError(f, "uploading a mesh");
    }
}

void MeshRenderer::setScene(std::shared_ptr<const scene::Scene> scene) {
    deleteMeshes(meshes_);
    deletePreviews();
    ++shadingRevision_;
    scene_ = std::move(scene);
    scalarsUploadedForArray_ = false;
    objectsStale_ = true;
    updateRange();
    if (!scene_) {
        return;
    }
    uploadMeshes(*scene_, meshes_);
    uploadScalars();
    ++sceneUploads_;
    static const log::Category category{"vv.render"};
    log::debug(category, "uploaded a scene: " + std::to_string(scene_->meshes.size()) +
                             " meshes, " + std::to_string(scene_->triangleCount()) + " triangles");
}

void MeshRenderer::deletePreviews() {
    for (PreviewLevel& level : previews_) {
        deleteMeshes(level.meshes);
    }
    previews_.clear();
    previewTriangles_.clear();
}

void MeshRenderer::setPreviewScene(std::shared_ptr<const scene::Scene> preview) {
    std::vector<std::shared_ptr<const scene::Scene>> previews;
    if (preview) {
        previews.push_back(std::move(preview));
    }
    setPreviewScenes(std::move(previews));
}

void MeshRenderer::setPreviewScenes(std::vector<std::shared_ptr<const scene::Scene>> previews) {
    deletePreviews();
    ++shadingRevision_;
    std::erase(previews, nullptr);
    if (previews.empty()) {
        return;
    }
    for (const auto& preview : previews) {
        if (!scene_ || preview->meshes.size() != scene_->meshes.size()) {
            throw InvalidArgumentError(
                "the preview scene must have one mesh for each mesh of the scene (" +
                std::to_string(preview->meshes.size()) + " for " +
                std::to_string(scene_ ? scene_->meshes.size() : 0) + ")");
        }
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
            uploadMeshes(*level.scene, level.meshes);
        }
    } catch (...) {
        deletePreviews();
        throw;
    }
    scalarsUploadedForArray_ = false;
    uploadScalars();
}

std::size_t MeshRenderer::previewLevelFor(long long pixels) const noexcept {
    return choosePreviewLevel(previewTriangles_, pixels);
}

const std::vector<MeshRenderer::GpuMesh>& MeshRenderer::meshesOf(std::size_t level) const noexcept {
    if (level == 0 || previews_.empty()) {
        return meshes_;
    }
    return previews_[std::min(level, previews_.size()) - 1].meshes;
}

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

void MeshRenderer::setStyle(const MeshStyle& style) {
    colormaps::validateBins(style.bins);
    validateStyle(style);
    style_ = style;
    lighting_ = lightingFor(style_.light);
    objectsStale_ = true;
    ++shadingRevision_;
    updateRange();
    // With the context current, upload now; otherwise draw() catches up.
    if (gl_ != nullptr && QOpenGLContext::currentContext() == context_) {
        if (scalarsStale()) {
            uploadScalars();
        }
        uploadLut();
    }
}

void MeshRenderer::updateRange() {
    effectiveRange_.reset();
    objectRanges_.clear();
    if (!scene_) {
        return;
    }
    if (!style_.array.empty()) {
        effectiveRange_ = style_.range ? style_.range : arrayRange(*scene_, style_.array);
    }
    for (std::size_t i = 0; i < scene_->meshes.size(); ++i) {
        const std::string& name = style_.arrayOf(i);
        if (name.empty() || name == style_.array ||
            std::any_of(objectRanges_.begin(), objectRanges_.end(),
                        [&](const auto& entry) { return entry.first == name; })) {
            continue;
        }
        objectRanges_.emplace_back(name, objectArrayRange(*scene_, style_, name));
    }
}

std::optional<std::pair<float, float>> MeshRenderer::objectRange(std::size_t mesh) const {
    const std::string& name = style_.arrayOf(mesh);
    if (name.empty()) {
        return std::nullopt;
    }
    if (name == style_.array) {
        return effectiveRange_;
    }
    for (const auto& [array, range] : objectRanges_) {
        if (array == name) {
            return range;
        }
    }
    return std::nullopt;
}

bool MeshRenderer::scalarsStale() const noexcept {
    if (!scalarsUploadedForArray_ || !scene_) {
        return true;
    }
    for (std::size_t i = 0; i < scene_->meshes.size(); ++i) {
        if (i >= uploadedArrays_.size() || uploadedArrays_[i] != style_.arrayOf(i)) {
            return true;
        }
    }
    return false;
}

void MeshRenderer::uploadObjects() {
    if (!objectsStale_) {
        return;
    }
    auto& f = gl();
    GLint maxSize = 0;
    f.glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxSize);
    const std::size_t count = scene_ ? scene_->meshes.size() : 0U;
    // Row = object id (row 0 unused). Objects beyond the largest texture keep
    // the scene's material (vessel.frag falls back to the uniforms).
    const std::size_t rows = std::min(count + 1, static_cast<std::size_t>(std::max(maxSize, 1)));
    std::vector<glm::vec4> table(rows * 2, glm::vec4(0.0F));
    for (std::size_t id = 1; id < rows; ++id) {
        const std::size_t mesh = id - 1;
        const ObjectStyle& o = style_.object(mesh);
        const glm::vec3 color = o.color.value_or(style_.vesselColor);
        const bool useArray = !style_.arrayOf(mesh).empty();
        const auto range = objectRange(mesh).value_or(std::make_pair(0.0F, 1.0F));
        table[id * 2] = glm::vec4(color, useArray ? 1.0F : 0.0F);
        table[id * 2 + 1] = glm::vec4(range.first, range.second, o.opacity, 0.0F);
    }
    f.glActiveTexture(GL_TEXTURE0 + kObjectTableUnit);
    f.glBindTexture(GL_TEXTURE_2D, objectTexture_);
    f.glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    f.glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, 2, static_cast<GLsizei>(rows), 0, GL_RGBA,
                   GL_FLOAT, table.data());
    finishUpload(f, GL_TEXTURE_2D, GL_NEAREST, "uploading the per-object styles");
    objectsStale_ = false;
}

void MeshRenderer::useObject(const Program& program, std::size_t index) {
    auto& f = gl();
    const auto loc = [&](std::string_view name) { return program.location(name); };
    const ObjectStyle& o = style_.object(index);
    const glm::vec3 color = o.color.value_or(style_.vesselColor);
    const auto range = objectRange(index).value_or(std::make_pair(0.0F, 1.0F));
    f.glUniform1i(loc("uUseArray"), style_.arrayOf(index).empty() ? 0 : 1);
    f.glUniform3f(loc("uBaseColor"), color.r, color.g, color.b);
    f.glUniform2f(loc("uRange"), range.first, range.second);
}

void MeshRenderer::uploadScalars() {
    auto& f = gl();
    if (!scene_) {
        return;
    }
    const auto upload = [&](const scene::Scene& scene, const std::vector<GpuMesh>& meshes) {
        for (std::size_t m = 0; m < meshes.size(); ++m) {
            const auto scalars = scalarsFor(scene.meshes[m], style_.arrayOf(m));
            f.glBindBuffer(GL_ARRAY_BUFFER, meshes[m].scalars);
            f.glBufferSubData(GL_ARRAY_BUFFER, 0,
                              static_cast<GLsizeiptr>(scalars.size() * sizeof(glm::vec2)),
                              scalars.data());
        }
    };
    upload(*scene_, meshes_);
    for (const PreviewLevel& level : previews_) {
        upload(*level.scene, level.meshes);
    }
    f.glBindBuffer(GL_ARRAY_BUFFER, 0);
    checkGlError(f, "uploading array values");
    uploadedArrays_.clear();
    for (std::size_t m = 0; m < scene_->meshes.size(); ++m) {
        uploadedArrays_.push_back(style_.arrayOf(m));
    }
    scalarsUploadedForArray_ = true;
}

void MeshRenderer::uploadLut() {
    const int bins = style_.bins >= 2 ? style_.bins : 0;
    if (uploadedMap_ == style_.colorMap && uploadedBins_ == bins) {
        return;
    }
    auto& f = gl();
    // Binned: exactly the bins' colours (colormaps::lut(map, bins)), nearest
    // filtering, the shader picks the bin's texel centre.
    const int size = bins >= 2 ? bins : lutSize_;
    const auto table = colormaps::lut(style_.colorMap, size);
    const GLint filter = bins >= 2 ? GL_NEAREST : GL_LINEAR;
    f.glActiveTexture(GL_TEXTURE0);
    f.glBindTexture(GL_TEXTURE_1D, lutTexture_);
    f.glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    f.glTexImage1D(GL_TEXTURE_1D, 0, GL_RGBA8, size, 0, GL_RGBA, GL_UNSIGNED_BYTE, table.data());
    finishUpload(f, GL_TEXTURE_1D, filter, "uploading the colour map");
    uploadedMap_ = style_.colorMap;
    uploadedBins_ = bins;
}

void MeshRenderer::uploadCueLut(colormaps::DepthScale scale) {
    if (uploadedCueScale_ == scale) {
        return;
    }
    auto& f = gl();
    const auto table = colormaps::lut(scale, kCueLutSize);
    f.glActiveTexture(GL_TEXTURE0 + kCueLutUnit);
    f.glBindTexture(GL_TEXTURE_1D, cueLutTexture_);
    f.glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    f.glTexImage1D(GL_TEXTURE_1D, 0, GL_RGBA8, kCueLutSize, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                   table.data());
    finishUpload(f, GL_TEXTURE_1D, GL_LINEAR, "uploading the vessel cue's depth scale");
    uploadedCueScale_ = scale;
}

void MeshRenderer::prepareMaterial(const VesselCueParameters& cue) {
    if (scalarsStale()) {
        uploadScalars();
    }
    uploadObjects();
    uploadLut();
    if (const auto cueScale = cueDepthScale(cue.cue)) {
        uploadCueLut(*cueScale);
    }
}

void MeshRenderer::useMaterial(const Program& program, const VesselCueParameters& cue) {
    auto& f = gl();
    const bool useArray = !style_.array.empty();
    // An array without any finite value shows no-data everywhere.
    const std::pair<float, float> range = effectiveRange_.value_or(std::make_pair(0.0F, 1.0F));
    const glm::vec3 noData = style_.noDataColor.value_or(colormaps::noDataColor(style_.colorMap));
    const Lighting& light = lighting_;
    program.use();
    const auto loc = [&](std::string_view name) { return program.location(name); };
    f.glUniform1i(loc("uUseArray"), useArray ? 1 : 0);
    f.glUniform3f(loc("uBaseColor"), style_.vesselColor.r, style_.vesselColor.g,
                  style_.vesselColor.b);
    f.glUniform3f(loc("uNoDataColor"), noData.r, noData.g, noData.b);
    f.glUniform1i(loc("uLut"), 0);
    f.glUniform1f(loc("uLutSize"), static_cast<float>(lutSize_));
    f.glUniform1i(loc("uBins"), uploadedBins_);
    f.glUniform1i(loc("uCue"), static_cast<GLint>(cue.cue));
    f.glUniform1i(loc("uCueLut"), kCueLutUnit);
    f.glUniform1f(loc("uCueLutSize"), static_cast<float>(kCueLutSize));
    f.glUniform2f(loc("uCueDepthRange"), cue.dmin, cue.dmax);
    f.glUniform3f(loc("uFogColor"), cue.fogColor.r, cue.fogColor.g, cue.fogColor.b);
    f.glUniform1f(loc("uFogStrength"), std::clamp(cue.fogStrength, 0.0F, 1.0F));
    f.glUniform1f(loc("uFresnelExponent"), std::max(cue.fresnelExponent, 0.0F));
    f.glUniform2f(loc("uRange"), range.first, range.second);
    f.glUniform1i(loc("uLighting"), style_.lighting ? 1 : 0);
    f.glUniform3f(loc("uLightDirection"), light.direction.x, light.direction.y, light.direction.z);
    f.glUniform1f(loc("uAmbient"), light.ambient);
    f.glUniform1f(loc("uDiffuse"), light.diffuse);
    f.glUniform1f(loc("uSpecular"), light.specular);
    f.glUniform1f(loc("uShininess"), light.shininess);
    f.glUniform1f(loc("uOpacity"), 1.0F);
    f.glUniform1i(loc("uObjects"), kObjectTableUnit);
    GLint rows = 0;
    f.glActiveTexture(GL_TEXTURE0 + kObjectTableUnit);
    f.glBindTexture(GL_TEXTURE_2D, objectTexture_);
    f.glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_HEIGHT, &rows);
    f.glUniform1i(loc("uObjectCount"), std::max(rows - 1, 0));
    f.glActiveTexture(GL_TEXTURE0 + kCueLutUnit);
    f.glBindTexture(GL_TEXTURE_1D, cueDepthScale(cue.cue) ? cueLutTexture_ : 0U);
    f.glActiveTexture(GL_TEXTURE0);
    f.glBindTexture(GL_TEXTURE_1D, lutTexture_);
}

void MeshRenderer::unbindMaterial() {
    auto& f = gl();
    f.glActiveTexture(GL_TEXTURE0 + kObjectTableUnit);
    f.glBindTexture(GL_TEXTURE_2D, 0);
    f.glActiveTexture(GL_TEXTURE0 + kCueLutUnit);
    f.glBindTexture(GL_TEXTURE_1D, 0);
    f.glActiveTexture(GL_TEXTURE0);
    f.glBindTexture(GL_TEXTURE_1D, 0);
    f.glUseProgram(0);
}

bool MeshStyle::visible(std::size_t mesh) const noexcept {
    return std::find(hidden.begin(), hidden.end(), mesh) == hidden.end() &&
           object(mesh).opacity > 0.0F;
}

const ObjectStyle& MeshStyle::object(std::size_t mesh) const noexcept {
    static const ObjectStyle defaults;
    return mesh < objects.size() ? objects[mesh] : defaults;
}

const std::string& MeshStyle::arrayOf(std::size_t mesh) const noexcept {
    const ObjectStyle& o = object(mesh);
    return o.array ? *o.array : array;
}

bool MeshStyle::translucent(std::size_t mesh) const noexcept {
    return visible(mesh) && object(mesh).opacity < 1.0F;
}

bool MeshStyle::opaque(std::size_t mesh) const noexcept {
    return visible(mesh) && object(mesh).opacity >= 1.0F;
}

std::uint64_t MeshStyle::geometryKey() const noexcept {
    Fnv1a hash;
    hash.text(array);
    for (const std::size_t index : hidden) {
        hash.value(index);
    }
    for (std::size_t i = 0; i < objects.size(); ++i) {
        if (!objects[i].array && objects[i].opacity >= 1.0F) {
            continue;  // as if it were not listed (its colour is not in the G-buffer)
        }
        const std::string& shown = arrayOf(i);
        const std::uint64_t size = shown.size();
        const bool drawn = opaque(i);
        hash.value(i).value(size).text(shown).value(drawn);
    }
    return hash.result();
}

void MeshRenderer::draw(const Camera& camera, DepthMode mode, const VesselCueParameters& cue) {
    auto& f = gl();
    if (!program_.valid()) {
        throw RenderError("MeshRenderer::draw without a shader program");
    }
    if (meshes_.empty()) {
        return;
    }
    prepareMaterial(cue);
    const glm::mat4 view = camera.viewMatrix();
    const glm::mat4 projection = camera.projectionMatrix();
    const glm::mat3 normalMatrix = glm::transpose(glm::inverse(glm::mat3(view)));

    f.glEnable(GL_DEPTH_TEST);
    f.glDepthFunc(mode == DepthMode::Write ? GL_LESS : GL_LEQUAL);
    f.glDepthMask(mode == DepthMode::Write ? GL_TRUE : GL_FALSE);
    f.glDisable(GL_BLEND);
    useMaterial(program_, cue);
    lastCulledMeshes_ = 0;
    const auto loc = [&](std::string_view name) { return program_.location(name); };
    f.glUniformMatrix4fv(loc("uView"), 1, GL_FALSE, &view[0][0]);
    f.glUniformMatrix4fv(loc("uProjection"), 1, GL_FALSE, &projection[0][0]);
    f.glUniformMatrix3fv(loc("uNormalMatrix"), 1, GL_FALSE, &normalMatrix[0][0]);
    for (std::size_t i = 0; i < meshes_.size(); ++i) {
        if (!style_.visible(i)) {
            continue;
        }
        useObject(program_, i);
        cullFor(meshes_[i], view, projection);
        f.glBindVertexArray(meshes_[i].vao);
        f.glDrawElements(GL_TRIANGLES, meshes_[i].indexCount, GL_UNSIGNED_INT, nullptr);
    }
    f.glDisable(GL_CULL_FACE);
    f.glBindVertexArray(0);
    unbindMaterial();
    f.glDepthMask(GL_TRUE);
    checkGlError(f, "drawing meshes");
}

void MeshRenderer::shadeGBuffer(const Camera& camera, const GBufferTextures& gbuffer,
                                const VesselCueParameters& cue) {
    auto& f = gl();
    if (!deferredProgram_.valid()) {
        throw RenderError("MeshRenderer::shadeGBuffer without a shader program");
    }
    prepareMaterial(cue);
    f.glDisable(GL_DEPTH_TEST);
    f.glDepthMask(GL_FALSE);
    f.glDisable(GL_BLEND);
    useMaterial(deferredProgram_, cue);
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
        const auto unit = static_cast<GLint>(kGBufferFirstUnit + i);
        f.glUniform1i(loc(inputs[i].first), unit);
        f.glActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(unit));
        f.glBindTexture(GL_TEXTURE_2D, inputs[i].second);
    }
    f.glBindVertexArray(emptyVao_);
    f.glDrawArrays(GL_TRIANGLES, 0, 3);
    f.glBindVertexArray(0);
    for (std::size_t i = 0; i < inputs.size(); ++i) {
        f.glActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(kGBufferFirstUnit + i));
        f.glBindTexture(GL_TEXTURE_2D, 0);
    }
    unbindMaterial();
    f.glDepthMask(GL_TRUE);
    checkGlError(f, "shading the vessels from the G-buffer");
}

bool MeshRenderer::hasTranslucent() const noexcept {
    for (std::size_t i = 0; i < meshes_.size(); ++i) {
        if (style_.translucent(i)) {
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
    const std::vector<GpuMesh>& drawn = meshesOf(level);
    const glm::mat4 view = camera.viewMatrix();
    // Back to front: the farthest bounding-box centre (most negative view z) first.
    std::vector<std::pair<float, std::size_t>> order;
    for (std::size_t i = 0; i < drawn.size(); ++i) {
        if (style_.translucent(i)) {
            order.emplace_back((view * glm::vec4(drawn[i].center, 1.0F)).z, i);
        }
    }
    if (order.empty()) {
        return;
    }
    std::sort(order.begin(), order.end());
    prepareMaterial(cue);
    const glm::mat4 projection = camera.projectionMatrix();
    const glm::mat3 normalMatrix = glm::transpose(glm::inverse(glm::mat3(view)));
    useMaterial(program_, cue);
    const auto loc = [&](std::string_view name) { return program_.location(name); };
    f.glUniformMatrix4fv(loc("uView"), 1, GL_FALSE, &view[0][0]);
    f.glUniformMatrix4fv(loc("uProjection"), 1, GL_FALSE, &projection[0][0]);
    f.glUniformMatrix3fv(loc("uNormalMatrix"), 1, GL_FALSE, &normalMatrix[0][0]);
    f.glEnable(GL_DEPTH_TEST);
    f.glDisable(GL_CULL_FACE);
    // Premultiplied "over": colour * opacity + destination * (1 - opacity).
    f.glBlendFuncSeparate(GL_ONE, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    for (const auto& [z, i] : order) {
        useObject(program_, i);
        f.glUniform1f(loc("uOpacity"), style_.object(i).opacity);
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
    unbindMaterial();
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
    if (meshes_.empty()) {
        return;
    }
    if (scalarsStale()) {
        uploadScalars();
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
    const GLint objectId = loc("uObjectId");
    GLuint id = 1;
    const std::vector<GpuMesh>& drawn = meshesOf(level);
    lastCulledMeshes_ = 0;
    for (std::size_t i = 0; i < drawn.size(); ++i) {
        f.glUniform1ui(objectId, id++);
        if (!style_.opaque(i)) {
            continue;  // hidden or translucent: its id stays reserved
        }
        f.glUniform1i(useArray, style_.arrayOf(i).empty() ? 0 : 1);
        cullFor(drawn[i], view, projection);
        f.glBindVertexArray(drawn[i].vao);
        f.glDrawElements(GL_TRIANGLES, drawn[i].indexCount, GL_UNSIGNED_INT, nullptr);
    }
    f.glDisable(GL_CULL_FACE);
    f.glBindVertexArray(0);
    f.glUseProgram(0);
    checkGlError(f, "drawing the G-buffer");
}

void MeshRenderer::setSurfaceClosures(std::size_t level,
                                      const std::vector<scene::SurfaceClosure>& closures) {
    if (level > previews_.size()) {
        throw InvalidArgumentError("no geometry level " + std::to_string(level) + " (" +
                                   std::to_string(previews_.size()) + " preview levels)");
    }
    std::vector<GpuMesh>& meshes = level == 0 ? meshes_ : previews_[level - 1].meshes;
    if (closures.size() != meshes.size()) {
        throw InvalidArgumentError("level " + std::to_string(level) + " has " +
                                   std::to_string(meshes.size()) + " meshes, not " +
                                   std::to_string(closures.size()));
    }
    for (std::size_t i = 0; i < meshes.size(); ++i) {
        meshes[i].closure = closures[i];
    }
}

std::optional<scene::SurfaceClosure> MeshRenderer::surfaceClosure(std::size_t level,
                                                                  std::size_t mesh) const noexcept {
    if (level > previews_.size()) {
        return std::nullopt;
    }
    const std::vector<GpuMesh>& meshes = level == 0 ? meshes_ : previews_[level - 1].meshes;
    if (mesh >= meshes.size()) {
        return std::nullopt;
    }
    return meshes[mesh].closure;
}

void MeshRenderer::cullFor(const GpuMesh& mesh, const glm::mat4& view,
                           const glm::mat4& projection) {
    auto& f = gl();
    const CullFace faces =
        backFaceCulling_ && mesh.source != nullptr
            ? cullableFaces(*mesh.source, mesh.closure, mesh.bounds, view, projection)
            : CullFace::None;
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
