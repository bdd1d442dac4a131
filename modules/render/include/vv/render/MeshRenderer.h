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

#include "vv/colormaps/ColorMap.h"
#include "vv/colormaps/DepthScale.h"
#include "vv/render/Camera.h"
#include "vv/render/Program.h"
#include "vv/scene/Mesh.h"
#include "vv/scene/MeshTopology.h"

class QOpenGLFunctions_4_1_Core;
class QOpenGLContext;

namespace vv::render {

/// The key light's direction in view space, in degrees: `azimuth` turns it
/// about the view's up axis (0 = from the eye, > 0 = from the right, within
/// [-180, 180]), `elevation` lifts it above the view's horizontal plane
/// (> 0 = from above, within [-90, 90]). The default is the headlight-like
/// key light a little above and left of the eye.
struct LightAngles {
    float azimuth = -14.036243F;
    float elevation = 18.754912F;
    bool operator==(const LightAngles&) const = default;
};

/// The unit vector towards the light: (cos e sin a, sin e, cos e cos a).
/// Throws InvalidArgumentError for angles that are not finite or out of range.
[[nodiscard]] glm::vec3 lightDirection(const LightAngles& angles);

/// What one object (mesh) of a scene looks like, beyond the scene's style.
struct ObjectStyle {
    /// Neutral material colour of this object (sRGB); nullopt = MeshStyle::vesselColor.
    std::optional<glm::vec3> color;
    /// In [0, 1]: 1 = opaque; below 1 the object is drawn in the "translucent"
    /// pass over the composited frame, not into the G-buffer (the VSS and the
    /// AO see through it); 0 = not drawn, like a hidden object.
    float opacity = 1.0F;
    /// nullopt = the scene's array (MeshStyle::array); "" = none (the neutral
    /// material); else the point array of that name (a mesh lacking it shows
    /// no-data). An array other than the scene's spans its own automatic
    /// range over the objects that show it, through the same colour map.
    std::optional<std::string> array;
    bool operator==(const ObjectStyle&) const = default;
};

/// How meshes are shaded. Colours are sRGB in [0, 1]; lighting is applied to
/// them directly (no linearisation), so a surface facing the light shows the
/// colour map's colours unchanged.
struct MeshStyle {
    /// Point array shown through the colour map; empty = the neutral vessel material.
    std::string array;
    colormaps::ColorMap colorMap = colormaps::ColorMap::Viridis;
    /// Discrete bins of the colour map: 0 = continuous, 2..colormaps::kMaxBins
    /// = that many equal bins (colormaps::sample(map, t, bins)).
    int bins = 0;
    /// Values mapped to the first and last colour of the map; nullopt = the
    /// finite range of the array over all meshes. Values outside are clamped.
    std::optional<std::pair<float, float>> range;
    /// The neutral vessel material, used when no array is chosen.
    glm::vec3 vesselColor{0.85F, 0.42F, 0.38F};
    /// Colour of vertices without a value (NaN, or a mesh without the array);
    /// nullopt = the map's colormaps::noDataColor(), which the map never uses.
    std::optional<glm::vec3> noDataColor;
    /// Title of the parameter legend; empty = "name (unit)" of the array.
    std::string legendTitle;
    /// Blinn-Phong with the key light (`light`) and ambient; false draws
    /// flat, unlit colours (exact colour-map colours, for checks and pickers).
    bool lighting = true;
    /// Indices (into Scene::meshes) of meshes not drawn; out-of-range
    /// indices are ignored. Hidden meshes keep their object ids.
    std::vector<std::size_t> hidden;
    /// Per object (index into Scene::meshes) colour, opacity and array;
    /// objects beyond the end use ObjectStyle{}.
    std::vector<ObjectStyle> objects;
    /// The key light of the vessels, the VSS and the translucent objects.
    LightAngles light;

    /// True unless `mesh` is listed in `hidden` or has opacity 0.
    [[nodiscard]] bool visible(std::size_t mesh) const noexcept;
    /// The style of `mesh` (a default one beyond `objects`).
    [[nodiscard]] const ObjectStyle& object(std::size_t mesh) const noexcept;
    /// The array `mesh` shows: its own choice, else `array`; empty = none.
    [[nodiscard]] const std::string& arrayOf(std::size_t mesh) const noexcept;
    /// Visible and with opacity below 1: drawn in the translucent pass.
    [[nodiscard]] bool translucent(std::size_t mesh) const noexcept;
    /// Visible and opaque: drawn into the G-buffer.
    [[nodiscard]] bool opaque(std::size_t mesh) const noexcept;
    /// A hash of what the geometry pass writes: the array of each object and
    /// which objects are drawn opaque (for the render graph's cache).
    [[nodiscard]] std::uint64_t geometryKey() const noexcept;
};

/// Throws InvalidArgumentError unless every object's opacity is within
/// [0, 1] and its colour within [0, 1], and the light angles are valid.
void validateStyle(const MeshStyle& style);

/// The arrays that visible objects of `scene` show and have (a mesh without
/// its array shows no-data), without duplicates: the
/// scene's array (style.array) first when one shows it, then the others in
/// the order of the objects.
[[nodiscard]] std::vector<std::string> shownArrays(const scene::Scene& scene,
                                                   const MeshStyle& style);

/// The automatic range of an array other than the scene's: its finite range
/// over the objects that show it (arrayOf); nullopt when none has a finite value.
[[nodiscard]] std::optional<std::pair<float, float>> objectArrayRange(const scene::Scene& scene,
                                                                      const MeshStyle& style,
                                                                      const std::string& name);

/// A depth cue on the vessel surface itself, the comparison techniques for
/// the VSS (issue 4, pass 5). Depth is normalised to t = (d - dmin) /
/// (dmax - dmin), d the linear view depth, 0 = nearest.
enum class VesselCue : std::uint8_t {
    None,               ///< baseline: no depth cue on the vessels
    Chromadepth,        ///< the vessel coloured by the chromadepth scale (red near -> blue far)
    PseudoChromadepth,  ///< Ropinski et al. 2006: the red (near) -> blue (far) scale
    Fog,                ///< Kersten-Oertel et al. 2014: blend towards the background by t
    /// Behrendt et al. 2017: the pseudo-chromadepth colour at silhouettes,
    /// weighted by the Fresnel term (1 - |n.v|)^k; the interior keeps its
    /// parameter / neutral colour.
    Fresnel,
};

/// Every cue, in UI order.
[[nodiscard]] std::span<const VesselCue> allVesselCues() noexcept;
/// Command-line identifier: "none", "vessel-cd", "vessel-pcd", "fog", "fresnel".
[[nodiscard]] std::string_view name(VesselCue cue) noexcept;
/// Human-readable name ("Vessel pseudo-chromadepth").
[[nodiscard]] std::string_view displayName(VesselCue cue) noexcept;
/// The cue whose name() equals `name`, ignoring ASCII case; nullopt when none does.
[[nodiscard]] std::optional<VesselCue> vesselCueFromName(std::string_view name) noexcept;
/// The depth scale a cue colours with (chromadepth for Chromadepth, pseudo-
/// chromadepth for PseudoChromadepth and Fresnel); nullopt for None and Fog.
[[nodiscard]] std::optional<colormaps::DepthScale> cueDepthScale(VesselCue cue) noexcept;

/// What MeshRenderer::draw() needs to apply a cue.
struct VesselCueParameters {
    VesselCue cue = VesselCue::None;
    float dmin = 0.0F;             ///< linear view depth mapped to t = 0, scene units
    float dmax = 0.0F;             ///< ... to t = 1; dmax - dmin tiny: t = 0 everywhere
    glm::vec3 fogColor{0.0F};      ///< sRGB, the frame's background
    float fogStrength = 0.8F;      ///< Fog: blend weight at t = 1 (0..1)
    float fresnelExponent = 1.0F;  ///< Fresnel: k in (1 - |n.v|)^k
};

/// The light shared by the vessels and the VSS: a key light (by default a
/// little above and left of the eye: a headlight that still shows curvature
/// on surfaces facing the viewer; MeshStyle::light moves it) plus ambient,
/// Blinn-Phong. Directions in view space.
struct Lighting {
    glm::vec3 direction{0.0F, 0.0F, 1.0F};  ///< towards the light, unit length
    float ambient = 0.30F;
    float diffuse = 0.70F;
    float specular = 0.25F;
    float shininess = 48.0F;
};

/// The default Lighting (LightAngles{}).
[[nodiscard]] const Lighting& sceneLighting() noexcept;
/// sceneLighting() with the key light at `angles` (throws like lightDirection()).
[[nodiscard]] Lighting lightingFor(const LightAngles& angles);

/// The array to show by default: "wss" (wall shear stress) when some mesh
/// has a point array of that name (ignoring case; also "wall_shear_stress",
/// "WallShearStress"), else the empty string (neutral material).
[[nodiscard]] std::string defaultArrayName(const scene::Scene& scene);

/// Point array names over all meshes of a scene, without duplicates, in the
/// order they are first met.
[[nodiscard]] std::vector<std::string> pointArrayNames(const scene::Scene& scene);

/// The finite value range of point array `name` over all meshes (magnitude for
/// vectors); nullopt when no mesh has a finite value in it.
[[nodiscard]] std::optional<std::pair<float, float>> arrayRange(const scene::Scene& scene,
                                                                const std::string& name);

/// Pixels per triangle below which a finer preview level gains nothing
/// visible: choosePreviewLevel() keeps about one triangle per this many
/// pixels of the frame.
constexpr long long kPixelsPerPreviewTriangle = 3;

/// The preview level (1-based, as MeshRenderer::drawGBuffer) for a frame of
/// `pixels` pixels among levels of `triangles` (most first): the finest level
/// with at most pixels / kPixelsPerPreviewTriangle triangles, else the
/// coarsest; 0 when there is no level. On software rasterisers the triangle
/// count bounds small frames, so smaller frames draw coarser copies.
[[nodiscard]] std::size_t choosePreviewLevel(std::span<const std::size_t> triangles,
                                             long long pixels) noexcept;

/// Draws a Scene's meshes with OpenGL 4.1 core: position, normal and one
/// scalar per vertex (taken from the chosen point array; vector arrays show
/// their magnitude), Blinn-Phong lighting, the array through a 1-D colour-map
/// texture, and NaN / missing values in the map's noDataColor().
///
/// Every member function that touches GL needs the context that was current
/// at initialize() to be current again. The renderer does not own the
/// context; call release() (context current) before the context goes away.
class MeshRenderer {
  public:
    MeshRenderer();
    ~MeshRenderer();
    MeshRenderer(const MeshRenderer&) = delete;
    MeshRenderer& operator=(const MeshRenderer&) = delete;

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
        return scene_;
    }
    /// How often setScene() uploaded a scene's meshes (also logged at debug
    /// level under "vv.render"), for checks that a scene is not uploaded twice.
    [[nodiscard]] std::uint64_t sceneUploads() const noexcept { return sceneUploads_; }

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
    [[nodiscard]] bool hasPreviewScene() const noexcept { return !previews_.empty(); }
    /// Triangles of each preview level, level 1 first (most triangles).
    [[nodiscard]] const std::vector<std::size_t>& previewTriangles() const noexcept {
        return previewTriangles_;
    }
    /// The preview level for a frame of `pixels` pixels
    /// (choosePreviewLevel over previewTriangles()); 0 without previews.
    [[nodiscard]] std::size_t previewLevelFor(long long pixels) const noexcept;

    /// Sets the style. With the context current, re-uploads the per-vertex
    /// scalars when the array changed and the colour-map texture when the map
    /// or its bins changed (throwing RenderError when GL fails); otherwise
    /// draw() does. Throws InvalidArgumentError for bins out of range.
    void setStyle(const MeshStyle& style);
    [[nodiscard]] const MeshStyle& style() const noexcept { return style_; }
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
        return effectiveRange_;
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
    struct GpuMesh;
    void updateRange();
    void deleteMeshes(std::vector<GpuMesh>& meshes);
    /// Checks and uploads `scene`'s meshes into `target` (scalars left for uploadScalars()).
    void uploadMeshes(const scene::Scene& scene, std::vector<GpuMesh>& target);
    void uploadScalars();
    /// Enables culling for the next draw of `mesh` where cullableFaces() allows it.
    void cullFor(const GpuMesh& mesh, const glm::mat4& view, const glm::mat4& projection);
    /// True when the uploaded per-vertex values are not those of the style's arrays.
    [[nodiscard]] bool scalarsStale() const noexcept;
    /// Uploads the per-object table (colour, array on/off, range, opacity by object id).
    void uploadObjects();
    /// Sets the per-object material uniforms of `program` for mesh `index`.
    void useObject(const Program& program, std::size_t index);
    void uploadLut();
    void uploadCueLut(colormaps::DepthScale scale);
    /// Uploads what the material needs (scalars, LUTs) if stale.
    void prepareMaterial(const VesselCueParameters& cue);
    /// Makes `program` current with the material's uniforms and LUT textures.
    void useMaterial(const Program& program, const VesselCueParameters& cue);
    void unbindMaterial();
    [[nodiscard]] QOpenGLFunctions_4_1_Core& gl() const;

    QOpenGLFunctions_4_1_Core* gl_ = nullptr;
    QOpenGLContext* context_ = nullptr;
    Program program_;
    Program gbufferProgram_;
    Program deferredProgram_;
    unsigned emptyVao_ = 0;
    unsigned lutTexture_ = 0;
    int lutSize_ = 256;
    std::vector<GpuMesh> meshes_;
    std::shared_ptr<const scene::Scene> scene_;
    /// One simplified copy of scene_ and its uploaded meshes.
    struct PreviewLevel {
        std::shared_ptr<const scene::Scene> scene;
        std::vector<GpuMesh> meshes;
    };
    std::vector<PreviewLevel> previews_;         ///< most triangles first
    std::vector<std::size_t> previewTriangles_;  ///< each level's triangles, same order
    /// The meshes `level` draws (drawGBuffer).
    [[nodiscard]] const std::vector<GpuMesh>& meshesOf(std::size_t level) const noexcept;
    void deletePreviews();
    MeshStyle style_;
    std::optional<std::pair<float, float>> effectiveRange_;
    bool scalarsUploadedForArray_ = false;
    /// The array each mesh's uploaded values come from.
    std::vector<std::string> uploadedArrays_;
    /// Ranges of the arrays objects show besides the scene's (objectArrayRange).
    std::vector<std::pair<std::string, std::optional<std::pair<float, float>>>> objectRanges_;
    unsigned objectTexture_ = 0;
    bool objectsStale_ = true;
    std::uint64_t shadingRevision_ = 0;
    std::uint64_t sceneUploads_ = 0;
    bool backFaceCulling_ = true;
    std::size_t lastCulledMeshes_ = 0;
    Lighting lighting_;
    std::optional<colormaps::ColorMap> uploadedMap_;
    int uploadedBins_ = 0;
    unsigned cueLutTexture_ = 0;
    std::optional<colormaps::DepthScale> uploadedCueScale_;
};

}  // namespace vv::render
