// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <glm/glm.hpp>
#include <memory>

#include "vv/render/Camera.h"
#include "vv/render/Program.h"
#include "vv/scene/Volume.h"

class QOpenGLContext;
class QOpenGLFunctions_4_1_Core;

namespace vv::render {

/// A volume as a depth source of the geometry pass (docs/design-notes.md,
/// "Volume depth source"): first-hit iso-surface ray casting into the same
/// G-buffer outputs MeshRenderer::drawGBuffer writes (linear depth, view-space
/// normal with w = 0, object id, parameter NaN) and gl_FragDepth, so meshes
/// and the volume depth-test together and the VSS, shading and cues work on
/// a volume without a mesh.
///
/// The volume lives on the GPU as a 3-D texture (R16F for Int16 volumes, R32F
/// for Float32; linear filtering; the values as stored, e.g. HU). Rays march
/// in voxel index space (step 0.5 voxel) inside the box of the voxel centres
/// and stop at the first sample at or above the iso value; the crossing is
/// refined by bisection. The normal is the central-difference gradient taken
/// to view space through the inverse transpose of index-to-view, so
/// anisotropic spacing and gantry-tilt shear shade correctly.
///
/// Every call that touches GL needs the context current at initialize().
class VolumeRenderer {
  public:
    VolumeRenderer() = default;
    ~VolumeRenderer();
    VolumeRenderer(const VolumeRenderer&) = delete;
    VolumeRenderer& operator=(const VolumeRenderer&) = delete;
    VolumeRenderer(VolumeRenderer&&) = delete;
    VolumeRenderer& operator=(VolumeRenderer&&) = delete;

    /// Builds the shader in the current context. Throws RenderError when no
    /// OpenGL 4.1 core context is current or the shader fails.
    void initialize();
    [[nodiscard]] bool initialized() const noexcept { return program_.valid(); }
    /// Deletes the GL objects (context current). Safe to call more than once.
    void release() noexcept;

    /// The volume to draw (nullptr = none). Treated as immutable: setting the
    /// same object again keeps the uploaded texture; a changed volume needs a
    /// new object. Uploads lazily, at the next drawGBuffer().
    void setVolume(std::shared_ptr<const scene::Volume> volume) noexcept;
    [[nodiscard]] const std::shared_ptr<const scene::Volume>& volume() const noexcept {
        return volume_;
    }

    /// Draws the first hit of every pixel's ray with the iso-surface at
    /// `isoValue` into the bound G-buffer framebuffer (four colour
    /// attachments and a depth attachment, as in the geometry pass), with the
    /// depth test on. Does nothing without a volume. Throws RenderError when
    /// the volume exceeds GL_MAX_3D_TEXTURE_SIZE or GL fails.
    void drawGBuffer(const Camera& camera, float isoValue, unsigned objectId);

  private:
    void upload();

    QOpenGLFunctions_4_1_Core* gl_ = nullptr;
    QOpenGLContext* context_ = nullptr;
    Program program_;
    unsigned vao_ = 0;
    unsigned texture_ = 0;
    std::shared_ptr<const scene::Volume> volume_;
    bool uploaded_ = false;
    float valueScale_ = 1.0F;  ///< texel value -> volume value (Int16 is normalised)
};

}  // namespace vv::render
