// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <cstddef>
#include <cstdint>
#include <glm/glm.hpp>
#include <limits>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "vv/core/Math.h"
#include "vv/render/BackFaceCulling.h"
#include "vv/scene/Mesh.h"
#include "vv/scene/MeshTopology.h"

class QOpenGLFunctions_4_1_Core;

namespace vv::render {

/// Pixels per triangle below which a finer preview level gains nothing
/// visible: choosePreviewLevel() keeps about one triangle per this many
/// pixels of the frame. 4: a moving frame at half of 1280x720 draws the 20k
/// level of the bundled demo (geometry ~1/3 of the 60k level's time on
/// llvmpipe, its SSIM against the settled frame the same: 0.930 / 0.939
/// against 0.936 / 0.930 in the rotating benchmark's two views).
constexpr long long kPixelsPerPreviewTriangle = 4;

/// The level of the refined (subdivided) copy of the scene (GpuMeshes::
/// setRefined), drawn in place of level 0 where its facets are coarse for
/// the view (FrameRenderer::geometryLevel).
inline constexpr std::size_t kRefinedLevel = std::numeric_limits<std::size_t>::max();
/// The median edge on screen, in pixels, from which a scene's facets are
/// coarse for the view: a coarse aorta's lit VSS shows a blob per facet
/// along its silhouettes from about 8 px on (`vesselview-cli artefacts
/// --aorta`, docs/benchmarks/vss.md, "Bumps along coarse silhouettes").
inline constexpr double kCoarseEdgePixels = 8.0;

/// The preview level (1-based, as MeshRenderer::drawGBuffer) for a frame of
/// `pixels` pixels among levels of `triangles` (most first): the finest level
/// with at most pixels / kPixelsPerPreviewTriangle triangles, else the
/// coarsest; 0 when there is no level. On software rasterisers the triangle
/// count bounds small frames, so smaller frames draw coarser copies.
[[nodiscard]] std::size_t choosePreviewLevel(std::span<const std::size_t> triangles,
                                             long long pixels) noexcept;

/// One mesh on the GPU: its vertex array, buffers and what culling and
/// sorting need to know about it.
struct GpuMesh {
    unsigned vao = 0;
    unsigned vertices = 0;  ///< position + normal per vertex
    unsigned scalars = 0;   ///< (value, valid) per vertex; written by MeshMaterial
    unsigned indices = 0;
    int indexCount = 0;
    glm::vec3 center{0.0F};  ///< of the bounding box, for sorting translucent objects
    Aabb bounds;
    /// The mesh it was uploaded from, owned by the attached scene or a
    /// preview level's scene; null while no scene is attached (detach()).
    const scene::Mesh* source = nullptr;
    scene::SurfaceClosure closure = scene::SurfaceClosure::Open;
};

/// The meshes of a scene on the GPU and their levels of detail: level 0 the
/// scene's own, level k >= 1 the k-th simplified copy (most triangles first),
/// each mesh with its surface closure for back-face culling. Owns the GL
/// buffers; every function that takes the GL functions needs the context
/// they belong to current.
class GpuMeshes {
  public:
    /// Uploads `scene`'s meshes (replacing every level). nullptr clears.
    /// Meshes without one normal per position get computed normals; every
    /// mesh starts Open. Throws InvalidArgumentError (naming the mesh's file)
    /// for a triangle index out of range or a mesh too large for one draw
    /// call, RenderError when GL fails (out of memory); what was uploaded
    /// before the failure stays owned.
    void upload(QOpenGLFunctions_4_1_Core& gl, std::shared_ptr<const scene::Scene> scene);
    /// Attaches `scene`, whose content the caller promises to be that of
    /// the uploaded one, without uploading: the buffers, levels and closures
    /// stay, the meshes' sources become `scene`'s. Throws InvalidArgumentError
    /// when its mesh or vertex counts differ from the uploaded ones.
    void attach(std::shared_ptr<const scene::Scene> scene);
    /// Forgets the scene (and its sources) but keeps the buffers, for a later
    /// attach() of the same content. Only the preview levels and the refined
    /// copy keep their scenes.
    void detach() noexcept;
    /// The attached scene; null after detach() or without one.
    [[nodiscard]] const std::shared_ptr<const scene::Scene>& scene() const noexcept {
        return scene_;
    }
    /// True when level 0 has buffers (uploaded, possibly detached).
    [[nodiscard]] bool uploaded() const noexcept { return !meshes_.empty(); }
    /// How often upload() uploaded a scene.
    [[nodiscard]] std::uint64_t uploads() const noexcept { return uploads_; }

    /// Uploads simplified copies of the scene (any order, nulls left out) as
    /// levels 1, 2, ... by falling triangle count, replacing earlier ones; an
    /// empty list clears them. Throws like upload(), and InvalidArgumentError
    /// when a copy's mesh count differs from the scene's (then none is kept).
    void setPreviews(QOpenGLFunctions_4_1_Core& gl,
                     std::vector<std::shared_ptr<const scene::Scene>> previews);
    [[nodiscard]] bool hasPreviews() const noexcept { return !previews_.empty(); }
    [[nodiscard]] std::size_t previewCount() const noexcept { return previews_.size(); }
    /// Triangles of each preview level, level 1 first.
    [[nodiscard]] const std::vector<std::size_t>& previewTriangles() const noexcept {
        return previewTriangles_;
    }
    /// choosePreviewLevel() over previewTriangles(); 0 without previews.
    [[nodiscard]] std::size_t previewLevelFor(long long pixels) const noexcept;

    /// Uploads a refined copy of the scene (one mesh for each of its
    /// meshes, in order) as kRefinedLevel, replacing an earlier one; nullptr
    /// clears it. upload() clears it too. Throws like upload(), and
    /// InvalidArgumentError when its mesh count differs from the scene's
    /// (then none is kept).
    void setRefined(QOpenGLFunctions_4_1_Core& gl, std::shared_ptr<const scene::Scene> refined);
    [[nodiscard]] bool hasRefined() const noexcept { return refined_.scene != nullptr; }

    /// The meshes `level` draws: 0 = the scene's; kRefinedLevel = the
    /// refined copy's (the scene's without one); k = preview level k (the
    /// coarsest when k exceeds the levels, the scene's when there are none).
    [[nodiscard]] const std::vector<GpuMesh>& meshesOf(std::size_t level) const noexcept;
    /// Level 0 or preview level `level` exactly, with its scene (null for
    /// level 0 while detached); for callers that walk every level.
    struct Level {
        const scene::Scene* scene = nullptr;
        const std::vector<GpuMesh>* meshes = nullptr;
    };
    /// Level 0, every preview level in order, then the refined copy.
    [[nodiscard]] std::vector<Level> levels() const;

    /// Sets the closures of `level`'s meshes (one per mesh, in order). Throws
    /// InvalidArgumentError for a level that does not exist or a count that
    /// differs from its meshes.
    void setSurfaceClosures(std::size_t level, const std::vector<scene::SurfaceClosure>& closures);
    /// The closure of mesh `mesh` of `level`; nullopt when there is none.
    [[nodiscard]] std::optional<scene::SurfaceClosure> surfaceClosure(
        std::size_t level, std::size_t mesh) const noexcept;
    /// The faces a draw of `mesh` with these matrices may cull
    /// (cullableFaces of its source and closure); None without a source.
    [[nodiscard]] static CullFace cullableFacesOf(const GpuMesh& mesh, const glm::mat4& view,
                                                  const glm::mat4& projection) noexcept;

    /// Deletes every buffer (preview levels and the refined copy too); the
    /// scene stays attached.
    void clear(QOpenGLFunctions_4_1_Core& gl);
    /// Forgets the buffers without deleting them (their context is gone).
    void forget() noexcept;

  private:
    /// One simplified copy of the scene and its uploaded meshes.
    struct PreviewLevel {
        std::shared_ptr<const scene::Scene> scene;
        std::vector<GpuMesh> meshes;
    };
    static void uploadMeshes(QOpenGLFunctions_4_1_Core& gl, const scene::Scene& scene,
                             std::vector<GpuMesh>& target);
    static void deleteMeshes(QOpenGLFunctions_4_1_Core& gl, std::vector<GpuMesh>& meshes);
    void deletePreviews(QOpenGLFunctions_4_1_Core& gl);
    void deleteRefined(QOpenGLFunctions_4_1_Core& gl);
    /// Throws InvalidArgumentError unless `copy` has one mesh per scene mesh.
    void checkCopy(const scene::Scene& copy, const char* what) const;
    /// Level 0 or preview level `level`; null when there is no such level.
    [[nodiscard]] const std::vector<GpuMesh>* levelMeshes(std::size_t level) const noexcept;
    [[nodiscard]] std::vector<GpuMesh>* levelMeshes(std::size_t level) noexcept;

    std::shared_ptr<const scene::Scene> scene_;
    std::vector<GpuMesh> meshes_;
    std::vector<PreviewLevel> previews_;         ///< most triangles first
    std::vector<std::size_t> previewTriangles_;  ///< each level's triangles, same order
    PreviewLevel refined_;                       ///< kRefinedLevel; no scene when none
    std::uint64_t uploads_ = 0;
};

}  // namespace vv::render
