// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/render/MeshMaterial.h"

#include <QOpenGLFunctions_4_1_Core>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <initializer_list>
#include <string>
#include <string_view>

#include "vv/colormaps/LabelPalette.h"
#include "vv/render/GlResources.h"

namespace vv::render {

namespace {

constexpr int kCueLutSize = 256;

/// The per-vertex (value, valid) pairs of `name` on `mesh`; (0, 0) where the
/// value is NaN / infinite or the mesh lacks the array. With `labels`,
/// valid is 1 + the value's index among them (the shaders read it flat, per
/// triangle, as the label's colour index), 0 for a value not among them.
std::vector<glm::vec2> scalarsFor(const scene::Mesh& mesh, const std::string& name,
                                  const std::vector<scene::Label>* labels) {
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
        if (!std::isfinite(value)) {
            continue;
        }
        if (labels == nullptr) {
            out[i] = glm::vec2(value, 1.0F);
            continue;
        }
        const auto it = std::lower_bound(
            labels->begin(), labels->end(), value,
            [](const scene::Label& l, float v) { return static_cast<float>(l.value) < v; });
        if (it != labels->end() && static_cast<float>(it->value) == value) {
            out[i] = glm::vec2(value, 1.0F + static_cast<float>(it - labels->begin()));
        }
    }
    return out;
}

/// Ends a texture upload to `target` on the active unit: `filter` for
/// minification and magnification, clamped s, unbound, unit 0 active again;
/// throws RenderError naming `what` when GL reports an error.
void finishUpload(QOpenGLFunctions_4_1_Core& gl, GLenum target, GLint filter, const char* what) {
    gl.glTexParameteri(target, GL_TEXTURE_MIN_FILTER, filter);
    gl.glTexParameteri(target, GL_TEXTURE_MAG_FILTER, filter);
    gl.glTexParameteri(target, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    gl.glBindTexture(target, 0);
    gl.glActiveTexture(GL_TEXTURE0);
    checkGlError(gl, what);
}

}  // namespace

MeshMaterial::MeshMaterial() : lighting_(sceneLighting()) {}

void MeshMaterial::forget() noexcept {
    lutTexture_ = 0;
    cueLutTexture_ = 0;
    objectTexture_ = 0;
    labelTexture_ = 0;
    objectsStale_ = true;
    uploadedMap_.reset();
    uploadedCueScale_.reset();
    scalarsUploaded_ = false;
}

void MeshMaterial::initialize(QOpenGLFunctions_4_1_Core& gl) {
    forget();
    gl.glGenTextures(1, &lutTexture_);
    gl.glGenTextures(1, &cueLutTexture_);
    gl.glGenTextures(1, &objectTexture_);
    gl.glGenTextures(1, &labelTexture_);
    uploadLut(gl);
    uploadLabelPalette(gl);
}

void MeshMaterial::release(QOpenGLFunctions_4_1_Core& gl) noexcept {
    for (unsigned* texture : {&lutTexture_, &cueLutTexture_, &objectTexture_, &labelTexture_}) {
        if (*texture != 0) {
            gl.glDeleteTextures(1, texture);
        }
    }
    forget();
}

void MeshMaterial::setStyle(const MeshStyle& style, const scene::Scene* scene) {
    colormaps::validateBins(style.bins);
    validateStyle(style);
    style_ = style;
    lighting_ = lightingFor(style_.light);
    objectsStale_ = true;
    updateRange(scene);
}

void MeshMaterial::setScene(const scene::Scene* scene) {
    labelCache_.invalidate();
    scalarsUploaded_ = false;
    objectsStale_ = true;
    updateRange(scene);
}

void MeshMaterial::updateRange(const scene::Scene* scene) {
    effectiveRange_.reset();
    objectRanges_.clear();
    labels_.clear();
    if (scene == nullptr) {
        return;
    }
    labels_ = labelCache_.get(*scene, style_);
    if (!style_.array.empty()) {
        effectiveRange_ = style_.range ? style_.range : arrayRange(*scene, style_.array);
    }
    for (std::size_t i = 0; i < scene->meshes.size(); ++i) {
        const std::string& name = style_.arrayOf(i);
        if (name.empty() || name == style_.array ||
            std::any_of(objectRanges_.begin(), objectRanges_.end(),
                        [&](const auto& entry) { return entry.first == name; })) {
            continue;
        }
        objectRanges_.emplace_back(name, objectArrayRange(*scene, style_, name));
    }
}

std::optional<std::pair<float, float>> MeshMaterial::objectRange(std::size_t mesh) const {
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

const std::vector<scene::Label>* MeshMaterial::objectLabels(std::size_t mesh) const {
    return labelsOf(labels_, style_.arrayOf(mesh));
}

bool MeshMaterial::scalarsStale(const GpuMeshes& meshes) const noexcept {
    const scene::Scene* scene = meshes.scene().get();
    if (!scalarsUploaded_ || scene == nullptr) {
        return true;
    }
    for (std::size_t i = 0; i < scene->meshes.size(); ++i) {
        if (i >= uploadedArrays_.size() ||
            uploadedArrays_[i] != std::make_pair(style_.arrayOf(i), objectLabels(i) != nullptr)) {
            return true;
        }
    }
    return false;
}

void MeshMaterial::uploadObjects(QOpenGLFunctions_4_1_Core& gl, const scene::Scene* scene) {
    if (!objectsStale_) {
        return;
    }
    GLint maxSize = 0;
    gl.glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxSize);
    const std::size_t count = scene != nullptr ? scene->meshes.size() : 0U;
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
        const float labels = objectLabels(mesh) != nullptr ? 1.0F : 0.0F;
        table[id * 2 + 1] = glm::vec4(range.first, range.second, o.opacity, labels);
    }
    gl.glActiveTexture(GL_TEXTURE0 + kObjectTableUnit);
    gl.glBindTexture(GL_TEXTURE_2D, objectTexture_);
    gl.glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    gl.glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, 2, static_cast<GLsizei>(rows), 0, GL_RGBA,
                    GL_FLOAT, table.data());
    finishUpload(gl, GL_TEXTURE_2D, GL_NEAREST, "uploading the per-object styles");
    objectsStale_ = false;
}

void MeshMaterial::useObject(QOpenGLFunctions_4_1_Core& gl, const Program& program,
                             std::size_t mesh) const {
    const auto loc = [&](std::string_view name) { return program.location(name); };
    const ObjectStyle& o = style_.object(mesh);
    const glm::vec3 color = o.color.value_or(style_.vesselColor);
    const auto range = objectRange(mesh).value_or(std::make_pair(0.0F, 1.0F));
    gl.glUniform1i(loc("uUseArray"), style_.arrayOf(mesh).empty() ? 0 : 1);
    gl.glUniform3f(loc("uBaseColor"), color.r, color.g, color.b);
    gl.glUniform2f(loc("uRange"), range.first, range.second);
    gl.glUniform1i(loc("uLabels"), objectLabels(mesh) != nullptr ? 1 : 0);
}

void MeshMaterial::uploadScalars(QOpenGLFunctions_4_1_Core& gl, const GpuMeshes& meshes) {
    const scene::Scene* scene = meshes.scene().get();
    if (scene == nullptr) {
        return;
    }
    for (const GpuMeshes::Level& level : meshes.levels()) {
        const std::vector<GpuMesh>& gpu = *level.meshes;
        for (std::size_t m = 0; m < gpu.size(); ++m) {
            const auto scalars =
                scalarsFor(level.scene->meshes[m], style_.arrayOf(m), objectLabels(m));
            gl.glBindBuffer(GL_ARRAY_BUFFER, gpu[m].scalars);
            gl.glBufferSubData(GL_ARRAY_BUFFER, 0,
                               static_cast<GLsizeiptr>(scalars.size() * sizeof(glm::vec2)),
                               scalars.data());
        }
    }
    gl.glBindBuffer(GL_ARRAY_BUFFER, 0);
    checkGlError(gl, "uploading array values");
    uploadedArrays_.clear();
    for (std::size_t m = 0; m < scene->meshes.size(); ++m) {
        uploadedArrays_.emplace_back(style_.arrayOf(m), objectLabels(m) != nullptr);
    }
    scalarsUploaded_ = true;
}

void MeshMaterial::uploadLut(QOpenGLFunctions_4_1_Core& gl) {
    const int bins = style_.bins >= 2 ? style_.bins : 0;
    if (uploadedMap_ == style_.colorMap && uploadedBins_ == bins) {
        return;
    }
    // Binned: exactly the bins' colours (colormaps::lut(map, bins)), nearest
    // filtering, the shader picks the bin's texel centre.
    const int size = bins >= 2 ? bins : lutSize_;
    const auto table = colormaps::lut(style_.colorMap, size);
    const GLint filter = bins >= 2 ? GL_NEAREST : GL_LINEAR;
    gl.glActiveTexture(GL_TEXTURE0);
    gl.glBindTexture(GL_TEXTURE_1D, lutTexture_);
    gl.glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    gl.glTexImage1D(GL_TEXTURE_1D, 0, GL_RGBA8, size, 0, GL_RGBA, GL_UNSIGNED_BYTE, table.data());
    finishUpload(gl, GL_TEXTURE_1D, filter, "uploading the colour map");
    uploadedMap_ = style_.colorMap;
    uploadedBins_ = bins;
}

void MeshMaterial::uploadCueLut(QOpenGLFunctions_4_1_Core& gl, colormaps::DepthScale scale) {
    if (uploadedCueScale_ == scale) {
        return;
    }
    const auto table = colormaps::lut(scale, kCueLutSize);
    gl.glActiveTexture(GL_TEXTURE0 + kCueLutUnit);
    gl.glBindTexture(GL_TEXTURE_1D, cueLutTexture_);
    gl.glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    gl.glTexImage1D(GL_TEXTURE_1D, 0, GL_RGBA8, kCueLutSize, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                    table.data());
    finishUpload(gl, GL_TEXTURE_1D, GL_LINEAR, "uploading the vessel cue's depth scale");
    uploadedCueScale_ = scale;
}

void MeshMaterial::uploadLabelPalette(QOpenGLFunctions_4_1_Core& gl) {
    std::vector<glm::u8vec4> table;
    for (const glm::vec3& color : colormaps::labelPalette()) {
        table.push_back(colormaps::toRgba8(color));
    }
    gl.glActiveTexture(GL_TEXTURE0 + kLabelPaletteUnit);
    gl.glBindTexture(GL_TEXTURE_1D, labelTexture_);
    gl.glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    gl.glTexImage1D(GL_TEXTURE_1D, 0, GL_RGBA8, static_cast<GLsizei>(table.size()), 0, GL_RGBA,
                    GL_UNSIGNED_BYTE, table.data());
    finishUpload(gl, GL_TEXTURE_1D, GL_NEAREST, "uploading the label palette");
}

void MeshMaterial::prepare(QOpenGLFunctions_4_1_Core& gl, const GpuMeshes& meshes,
                           const VesselCueParameters& cue) {
    if (scalarsStale(meshes)) {
        uploadScalars(gl, meshes);
    }
    uploadObjects(gl, meshes.scene().get());
    uploadLut(gl);
    if (const auto cueScale = cueDepthScale(cue.cue)) {
        uploadCueLut(gl, *cueScale);
    }
}

void MeshMaterial::use(QOpenGLFunctions_4_1_Core& gl, const Program& program,
                       const VesselCueParameters& cue) const {
    const bool useArray = !style_.array.empty();
    // An array without any finite value shows no-data everywhere.
    const std::pair<float, float> range = effectiveRange_.value_or(std::make_pair(0.0F, 1.0F));
    const glm::vec3 noData = style_.noDataColor.value_or(colormaps::noDataColor(style_.colorMap));
    const Lighting& light = lighting_;
    program.use();
    const auto loc = [&](std::string_view name) { return program.location(name); };
    gl.glUniform1i(loc("uUseArray"), useArray ? 1 : 0);
    const bool labels = std::any_of(labels_.begin(), labels_.end(), [&](const auto& entry) {
        return entry.first == style_.array && entry.second.has_value();
    });
    gl.glUniform1i(loc("uLabels"), labels ? 1 : 0);
    gl.glUniform1i(loc("uLabelPalette"), kLabelPaletteUnit);
    gl.glUniform1i(loc("uLabelPaletteSize"), static_cast<GLint>(colormaps::labelPalette().size()));
    gl.glUniform3f(loc("uBaseColor"), style_.vesselColor.r, style_.vesselColor.g,
                   style_.vesselColor.b);
    gl.glUniform3f(loc("uNoDataColor"), noData.r, noData.g, noData.b);
    gl.glUniform1i(loc("uLut"), 0);
    gl.glUniform1f(loc("uLutSize"), static_cast<float>(lutSize_));
    gl.glUniform1i(loc("uBins"), uploadedBins_);
    gl.glUniform1i(loc("uCue"), static_cast<GLint>(cue.cue));
    gl.glUniform1i(loc("uCueLut"), kCueLutUnit);
    gl.glUniform1f(loc("uCueLutSize"), static_cast<float>(kCueLutSize));
    gl.glUniform2f(loc("uCueDepthRange"), cue.dmin, cue.dmax);
    gl.glUniform3f(loc("uFogColor"), cue.fogColor.r, cue.fogColor.g, cue.fogColor.b);
    gl.glUniform1f(loc("uFogStrength"), std::clamp(cue.fogStrength, 0.0F, 1.0F));
    gl.glUniform1f(loc("uFresnelExponent"), std::max(cue.fresnelExponent, 0.0F));
    gl.glUniform2f(loc("uRange"), range.first, range.second);
    gl.glUniform1i(loc("uLighting"), style_.lighting ? 1 : 0);
    gl.glUniform3f(loc("uLightDirection"), light.direction.x, light.direction.y, light.direction.z);
    gl.glUniform1f(loc("uAmbient"), light.ambient);
    gl.glUniform1f(loc("uDiffuse"), light.diffuse);
    gl.glUniform1f(loc("uSpecular"), light.specular);
    gl.glUniform1f(loc("uShininess"), light.shininess);
    gl.glUniform1f(loc("uOpacity"), 1.0F);
    gl.glUniform1i(loc("uObjects"), kObjectTableUnit);
    GLint rows = 0;
    gl.glActiveTexture(GL_TEXTURE0 + kObjectTableUnit);
    gl.glBindTexture(GL_TEXTURE_2D, objectTexture_);
    gl.glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_HEIGHT, &rows);
    gl.glUniform1i(loc("uObjectCount"), std::max(rows - 1, 0));
    gl.glActiveTexture(GL_TEXTURE0 + kCueLutUnit);
    gl.glBindTexture(GL_TEXTURE_1D, cueDepthScale(cue.cue) ? cueLutTexture_ : 0U);
    gl.glActiveTexture(GL_TEXTURE0 + kLabelPaletteUnit);
    gl.glBindTexture(GL_TEXTURE_1D, labelTexture_);
    gl.glActiveTexture(GL_TEXTURE0);
    gl.glBindTexture(GL_TEXTURE_1D, lutTexture_);
}

void MeshMaterial::unbind(QOpenGLFunctions_4_1_Core& gl) {
    gl.glActiveTexture(GL_TEXTURE0 + kLabelPaletteUnit);
    gl.glBindTexture(GL_TEXTURE_1D, 0);
    gl.glActiveTexture(GL_TEXTURE0 + kObjectTableUnit);
    gl.glBindTexture(GL_TEXTURE_2D, 0);
    gl.glActiveTexture(GL_TEXTURE0 + kCueLutUnit);
    gl.glBindTexture(GL_TEXTURE_1D, 0);
    gl.glActiveTexture(GL_TEXTURE0);
    gl.glBindTexture(GL_TEXTURE_1D, 0);
    gl.glUseProgram(0);
}

}  // namespace vv::render
