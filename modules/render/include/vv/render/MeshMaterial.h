// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "vv/colormaps/ColorMap.h"
#include "vv/colormaps/DepthScale.h"
#include "vv/render/GpuMeshes.h"
#include "vv/render/MeshStyle.h"
#include "vv/render/Program.h"

class QOpenGLFunctions_4_1_Core;

namespace vv::render {

/// The material of the meshes, as MeshStyle describes it: the per-vertex
/// values of the shown arrays (written into each GpuMesh's scalar buffer),
/// the colour map and the cue's depth scale as 1-D tables, the per-object
/// table (colour, array on/off, range, opacity, labels by object id), the
/// label palette and the
/// uniforms that tie them to a program. Uploads lazily: what the style did
/// not change stays on the GPU. Functions that take the GL functions need
/// their context current; they throw RenderError when GL fails.
class MeshMaterial {
  public:
    /// Texture units: the colour map on 0, the cue's depth scale on
    /// kCueLutUnit, the per-object table on kObjectTableUnit; the four units
    /// from kGBufferFirstUnit on are left to the G-buffer of deferred shading.
    static constexpr int kCueLutUnit = 1;
    static constexpr int kGBufferFirstUnit = 2;
    static constexpr int kObjectTableUnit = kGBufferFirstUnit + 4;
    /// The label palette (colormaps::labelPalette()) for label arrays.
    static constexpr int kLabelPaletteUnit = kObjectTableUnit + 1;

    MeshMaterial();

    /// Makes the textures (forgetting any of an earlier context) and uploads
    /// the colour map.
    void initialize(QOpenGLFunctions_4_1_Core& gl);
    /// Deletes the textures. Safe to call more than once.
    void release(QOpenGLFunctions_4_1_Core& gl) noexcept;
    /// Forgets the textures without deleting them (their context is gone):
    /// everything is uploaded anew after initialize().
    void forget() noexcept;

    /// Sets the style; `scene` (may be null) gives the automatic ranges.
    /// Throws InvalidArgumentError for bins out of range or an invalid style
    /// (validateStyle), changing nothing then.
    void setStyle(const MeshStyle& style, const scene::Scene* scene);
    [[nodiscard]] const MeshStyle& style() const noexcept { return style_; }
    /// A scene of new content (or none): its ranges; values and table stale.
    void setScene(const scene::Scene* scene);

    /// The range the colour map spans (the style's, else the array's finite
    /// range); nullopt when no array is shown or it has no finite value.
    [[nodiscard]] const std::optional<std::pair<float, float>>& effectiveRange() const noexcept {
        return effectiveRange_;
    }
    /// The range on object `mesh`: effectiveRange() for the scene's array,
    /// objectArrayRange() for another; nullopt for none.
    [[nodiscard]] std::optional<std::pair<float, float>> objectRange(std::size_t mesh) const;

    /// The labels object `mesh` shows (shownLabels()); null when its array
    /// is shown through the colour map or it shows none.
    [[nodiscard]] const std::vector<scene::Label>* objectLabels(std::size_t mesh) const;

    /// True when the uploaded per-vertex values are not those of the style's
    /// arrays on `meshes`' attached scene.
    [[nodiscard]] bool scalarsStale(const GpuMeshes& meshes) const noexcept;
    /// Uploads the values of the style's arrays into every level's scalar
    /// buffers (nothing without an attached scene).
    void uploadScalars(QOpenGLFunctions_4_1_Core& gl, const GpuMeshes& meshes);
    /// Uploads the colour map when its map or bins changed.
    void uploadLut(QOpenGLFunctions_4_1_Core& gl);
    /// Uploads what a draw with `cue` needs and is stale: values, table, maps.
    void prepare(QOpenGLFunctions_4_1_Core& gl, const GpuMeshes& meshes,
                 const VesselCueParameters& cue);

    /// Makes `program` current with the material's uniforms and textures.
    void use(QOpenGLFunctions_4_1_Core& gl, const Program& program,
             const VesselCueParameters& cue) const;
    /// Sets `program`'s per-object uniforms (colour, array on/off, range) for `mesh`.
    void useObject(QOpenGLFunctions_4_1_Core& gl, const Program& program, std::size_t mesh) const;
    /// Unbinds the material's textures and the program.
    static void unbind(QOpenGLFunctions_4_1_Core& gl);

  private:
    void updateRange(const scene::Scene* scene);
    void uploadObjects(QOpenGLFunctions_4_1_Core& gl, const scene::Scene* scene);
    void uploadCueLut(QOpenGLFunctions_4_1_Core& gl, colormaps::DepthScale scale);
    void uploadLabelPalette(QOpenGLFunctions_4_1_Core& gl);

    MeshStyle style_;
    Lighting lighting_;
    std::optional<std::pair<float, float>> effectiveRange_;
    /// Ranges of the arrays objects show besides the scene's (objectArrayRange).
    std::vector<std::pair<std::string, std::optional<std::pair<float, float>>>> objectRanges_;
    /// The labels of every shown array (shownLabels()), by array name.
    ShownLabelsCache labelCache_;
    ShownLabels labels_;
    bool scalarsUploaded_ = false;
    /// The array each mesh's uploaded values come from, and whether as labels.
    std::vector<std::pair<std::string, bool>> uploadedArrays_;
    unsigned lutTexture_ = 0;
    int lutSize_ = 256;
    std::optional<colormaps::ColorMap> uploadedMap_;
    int uploadedBins_ = 0;
    unsigned cueLutTexture_ = 0;
    std::optional<colormaps::DepthScale> uploadedCueScale_;
    unsigned objectTexture_ = 0;
    unsigned labelTexture_ = 0;
    bool objectsStale_ = true;
};

}  // namespace vv::render
