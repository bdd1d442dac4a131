// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <cstdint>
#include <glm/glm.hpp>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "vv/render/Camera.h"
#include "vv/render/GpuMeshes.h"
#include "vv/render/MeshMaterial.h"
#include "vv/render/MeshStyle.h"
#include "vv/render/Program.h"
#include "vv/scene/Mesh.h"
#include "vv/scene/MeshTopology.h"

class QOpenGLFunctions_4_1_Core;
class QOpenGLContext;

namespace vv::render {

/// Draws a Scene's meshes with OpenGL 4.1 core: position, normal and one
/// scalar per vertex (taken from the chosen point array; vector arrays show
/// their magnitude), Blinn-Phong lighting, the array through a 1-D colour-map
/// texture, and NaN / missing values in the map's noDataColor().
///
/// Its pieces: GpuMeshes (the meshes and their levels of detail on the GPU,
/// closures, the culling decision), MeshMaterial (per-vertex values, colour
/// maps, the per-object table, uniforms); this class holds the programs and
/// draws. Every member function that touches GL needs the context that was
/// current at initialize() to be current again. The renderer does not own the
/// context; call release() (context current) before the context goes away.
class MeshRenderer {
  public:
    MeshRenderer();
    ~MeshRenderer();
    MeshRenderer(const MeshRenderer&) = delete;
    MeshRenderer& operator=(const MeshRenderer&) = delete;
    MeshRenderer(MeshRenderer&&) = delete;
    MeshRenderer& operator=(MeshRenderer&&) = delete;

    /// Resolves GL 4.1 core functions and builds the shaders from the
    /// resources :/vv/shaders/mesh.vert and mesh.frag. Throws RenderError when
    /// no context is current, the context is not OpenGL >= 4.1 core, or a
    /// shader does not compile or link (the message has the GL log).
    void initialize();
    [[nodiscard]] bool initialized() const noexcept;

    /// Uploads the scene's meshes (replacing any previous ones). The scene is
    /// kept (shared) to re-upload scalars when the array changes. nullptr clears.
    /// Meshes without one normal per position get computed normals.
    /// Throws RenderError when not initialized, the context is not current or
    /// GL fails (out of memory); InvalidArgumentError (naming the mesh's file)
    /// for a triangle index out of range or a mesh too large for one draw call.
    void setScene(std::shared_ptr<const scene::Scene> scene);
    [[nodiscard]] const std::shared_ptr<const scene::Scene>& scene() const noexcept {
        return geometry_.scene();
    }
    /// How often setScene() uploaded a scene's meshes (also logged at debug
    /// level under "vv.render"), for checks that a scene is not uploaded twice.
    [[nodiscard]] std::uint64_t sceneUploads() const noexcept { return geometry_.uploads(); }
    /// Shows `scene`, whose content (positions, normals, indices, point
    /// arrays) the caller promises to be that of the scene uploaded last,
    /// without uploading it again: only the meshes' sources follow the new
    /// object (values, ranges and closures are those of the same content). Needs no GL context.
    /// Throws InvalidArgumentError when its mesh or index counts differ from the uploaded ones.
    void attachScene(std::shared_ptr<const scene::Scene> scene);
    /// Lets go of the scene but keeps its meshes on the GPU for a later
    /// attachScene() of the same content; nothing is drawn until then.
    void detachScene() noexcept;

    /// Uploads simplified copies of the current scene (meshio::simplifiedScene),
    /// in any order, replacing earlier ones; drawGBuffer(camera, level) draws
    /// level 1 = the copy with the most triangles, 2 = the next, ... instead
    /// of the scene, e.g. while the camera moves. Null entries are left out;
    /// an empty list clears them, and setScene() clears them too. Same throws
    /// as setScene(), and InvalidArgumentError when a copy's mesh count
    /// differs from the scene's (then no copy is kept).
    void setPreviewScenes(std::vector<std::shared_ptr<const scene::Scene>> previews);
    /// setPreviewScenes() with one copy (nullptr: none).
    void setPreviewScene(std::shared_ptr<const scene::Scene> preview);
    [[nodiscard]] bool hasPreviewScene() const noexcept { return geometry_.hasPreviews(); }
    /// Triangles of each preview level, level 1 first (most triangles).
    [[nodiscard]] const std::vector<std::size_t>& previewTriangles() const noexcept {
        return geometry_.previewTriangles();
    }
    /// The preview level for a frame of `pixels` pixels
    /// (choosePreviewLevel over previewTriangles()); 0 without previews.
    [[nodiscard]] std::size_t previewLevelFor(long long pixels) const noexcept;

    /// Uploads a refined (subdivided) copy of the current scene, one mesh
    /// per scene mesh with its arrays (meshio::subdividedScene), replacing an
    /// earlier one; drawGBuffer(camera, kRefinedLevel) draws it instead of
    /// the scene. `sourceEdgeMm` is the median edge length of the scene's
    /// own meshes (refinedWanted). nullptr clears it, and setScene() clears
    /// it too. Same throws as setScene(), and InvalidArgumentError when its
    /// mesh count differs from the scene's (then none is kept).
    void setRefinedScene(std::shared_ptr<const scene::Scene> refined, double sourceEdgeMm);
    [[nodiscard]] bool hasRefinedScene() const noexcept { return geometry_.hasRefined(); }
    /// Whether a frame of `camera` should draw the refined copy: there is
    /// one, and the scene's median edge, as seen from the camera at the
    /// middle of the scene's box (foreshortened by pi / 4 on average),
    /// spans at least kCoarseEdgePixels of the camera's viewport (the whole
    /// image's, for every tile of it and at every render scale alike).
    [[nodiscard]] bool refinedWanted(const Camera& camera) const noexcept;

    /// Sets the style. With the context current, re-uploads the per-vertex
    /// scalars when the array changed and the colour-map texture when the map
    /// or its bins changed (throwing RenderError when GL fails); otherwise
    /// draw() does. Throws InvalidArgumentError for bins out of range.
    void setStyle(const MeshStyle& style);
    [[nodiscard]] const MeshStyle& style() const noexcept { return material_.style(); }
    /// Changes with everything shadeGBuffer() reads besides its G-buffer and
    /// cue: each setStyle(), setScene(), setPreviewScenes() and initialize(),
    /// so a graph pass that keeps its shaded colours can depend on it.
    [[nodiscard]] std::uint64_t shadingRevision() const noexcept { return shadingRevision_; }

    /// Back-face culling where it changes no pixel (render::cullableFaces:
    /// closed surfaces seen from outside); on by default. On llvmpipe it
    /// halves the geometry pass of a closed vessel tree. Off draws both sides
    /// of every triangle (for comparisons and benchmarks).
    void setBackFaceCulling(bool enabled) noexcept { backFaceCulling_ = enabled; }
    [[nodiscard]] bool backFaceCulling() const noexcept { return backFaceCulling_; }
    /// The closures of geometry level `level` (0 = the scene, k = preview
    /// level k), one per mesh in order (scene::surfaceClosures of the same
    /// scene, e.g. computed on another thread: O(triangles), ~25 ms for 300k
    /// here). setScene() and setPreviewScenes() leave their meshes Open
    /// (drawn two-sided, no culling) until then. Throws InvalidArgumentError
    /// for a level that does not exist or a count that differs from the
    /// level's meshes.
    void setSurfaceClosures(std::size_t level, const std::vector<scene::SurfaceClosure>& closures);
    /// The closure culling uses for mesh `mesh` of level `level`; nullopt when
    /// there is no such mesh.
    [[nodiscard]] std::optional<scene::SurfaceClosure> surfaceClosure(
        std::size_t level, std::size_t mesh) const noexcept;
    /// How many meshes the last drawGBuffer() or draw() drew with culling.
    [[nodiscard]] std::size_t lastCulledMeshes() const noexcept { return lastCulledMeshes_; }

    /// The value range the colour map spans now (the style's range or the
    /// array's finite range); nullopt when no array is shown or it has no finite value.
    [[nodiscard]] std::optional<std::pair<float, float>> effectiveRange() const noexcept {
        return material_.effectiveRange();
    }
    /// The range the colour map spans on object `mesh`: effectiveRange() for
    /// the scene's array, objectArrayRange() for another; nullopt for none.
    [[nodiscard]] std::optional<std::pair<float, float>> objectRange(std::size_t mesh) const;

    /// How draw() uses the depth buffer.
    enum class DepthMode {
        Write,     ///< depth test GL_LESS and depth writes (a plain forward pass)
        TestOnly,  ///< GL_LEQUAL against a depth buffer drawGBuffer() filled, no writes
    };

    /// Draws into the currently bound framebuffer with the camera's matrices:
    /// the shaded colour to draw buffer 0 (alpha 1) and the parameter value
    /// (NaN = no data) to draw buffer 1 when the framebuffer has one.
    /// Depth test on; does not clear. The caller sets the viewport. A chosen
    /// array that a mesh lacks, or that has no finite value, shows the map's
    /// noDataColor(). Throws RenderError when not initialized, the context is
    /// not current or GL reports an error.
    /// `cue` adds a depth cue on the vessels (default: none).
    void draw(const Camera& camera, DepthMode mode = DepthMode::Write,
              const VesselCueParameters& cue = {});

    /// The geometry pass: draws the meshes into the currently bound G-buffer,
    /// draw buffer 0 = linear view depth (R32F, distance along the viewing
    /// axis in scene units), 1 = view-space normal facing the viewer
    /// (RGBA16F, w = 1 where the parameter is valid, else 0), 2 = object id
    /// (R32UI, 1 + mesh index), 3 = parameter value (R32F, NaN = no data or
    /// no array chosen; ignored without a fourth attachment). Depth test GL_LESS
    /// with writes; does not clear. Same vertex shader as draw(), so a later
    /// draw(camera, DepthMode::TestOnly) hits exactly the same depths.
    /// `level` 0 draws the scene; k >= 1 draws preview level k
    /// (setPreviewScenes; the coarsest when k exceeds the levels, the scene
    /// when there are none). Throws like draw().
    void drawGBuffer(const Camera& camera, std::size_t level = 0);

    /// The G-buffer drawGBuffer() filled, as GL texture names.
    struct GBufferTextures {
        unsigned linearDepth = 0;  ///< R32F
        unsigned normal = 0;       ///< RGBA16F, w = 1 where the parameter is valid
        unsigned parameter = 0;    ///< R32F
        unsigned objectId = 0;     ///< R32UI
    };

    /// Deferred shading: one full-screen triangle into the currently bound
    /// framebuffer (draw buffer 0), every covered G-buffer pixel shaded with
    /// the same material as draw() (colour, alpha 1), uncovered pixels
    /// (object id 0) cleared to transparent black. No depth test; the caller
    /// sets the viewport to the G-buffer's size. `camera` must be the one
    /// the G-buffer was drawn with. Throws like draw().
    void shadeGBuffer(const Camera& camera, const GBufferTextures& gbuffer,
                      const VesselCueParameters& cue = {});

    /// The translucent pass: draws the visible objects with opacity below 1
    /// into the currently bound framebuffer, premultiplied (colour * opacity,
    /// opacity) over what it holds, back to front by the view depth of each
    /// object's bounding-box centre. Each object first writes its depth
    /// (colour masked), then draws its nearest surface with GL_LEQUAL, so an
    /// object shows one layer of itself; the bound depth buffer must hold the
    /// opaque depth (a copy: it is written). Same material, light and
    /// parameter colours as draw(). Does not clear. Throws like draw().
    /// `level` chooses the meshes as in drawGBuffer().
    void drawTranslucent(const Camera& camera, const VesselCueParameters& cue = {},
                         std::size_t level = 0);
    /// True when some visible object has opacity below 1.
    [[nodiscard]] bool hasTranslucent() const noexcept;

    /// Deletes all GL objects; the context of initialize() must be current.
    /// Safe to call more than once.
    void release() noexcept;

    /// The GL strings of the context ("renderer / version"), for logs and About boxes.
    [[nodiscard]] std::string glDescription() const;

  private:
    /// True when a scene is attached and uploaded (detachScene() draws nothing).
    [[nodiscard]] bool drawable() const noexcept {
        return geometry_.scene() != nullptr && geometry_.uploaded();
    }
    /// Enables culling for the next draw of `mesh` where cullableFaces() allows it.
    void cullFor(const GpuMesh& mesh, const glm::mat4& view, const glm::mat4& projection);
    [[nodiscard]] QOpenGLFunctions_4_1_Core& gl() const;

    QOpenGLFunctions_4_1_Core* gl_ = nullptr;
    QOpenGLContext* context_ = nullptr;
    Program program_;
    Program gbufferProgram_;
    Program deferredProgram_;
    unsigned emptyVao_ = 0;
    GpuMeshes geometry_;
    double refinedSourceEdgeMm_ = 0.0;  ///< setRefinedScene()
    glm::vec3 refinedCentre_{0.0F};     ///< of the scene's box, at setRefinedScene()
    MeshMaterial material_;
    std::uint64_t shadingRevision_ = 0;
    bool backFaceCulling_ = true;
    std::size_t lastCulledMeshes_ = 0;
};

}  // namespace vv::render
