// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// How meshes look: the style of the scene and of each object, the light,
// the depth cues on the vessels and the array helpers the panels, sessions
// and reports share with the renderer. Plain C++: no OpenGL.

#include <cstddef>
#include <cstdint>
#include <glm/glm.hpp>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "vv/colormaps/ColorMap.h"
#include "vv/colormaps/DepthScale.h"
#include "vv/scene/ArrayLabels.h"
#include "vv/scene/Mesh.h"

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

/// How the values of the scene's array are read: as a measurement through
/// the colour map, or as labels (segment ids) with one colour each.
enum class ArrayValues : std::uint8_t {
    Auto,        ///< labels when scene::looksCategorical(), else continuous
    Continuous,  ///< always through the colour map
    Categories,  ///< always labels (up to scene::kMaxLabels distinct whole numbers)
};

/// Every mode, in UI order.
[[nodiscard]] std::span<const ArrayValues> allArrayValues() noexcept;
/// Command-line identifier: "auto", "continuous", "categories".
[[nodiscard]] std::string_view name(ArrayValues values) noexcept;
/// The mode whose name() equals `text`, ignoring ASCII case (also "labels"
/// for Categories); nullopt when none does.
[[nodiscard]] std::optional<ArrayValues> arrayValuesFromName(std::string_view text) noexcept;

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
    /// Labels or a measurement: applies to `array`; arrays that objects show
    /// besides it are always read as ArrayValues::Auto.
    ArrayValues values = ArrayValues::Auto;
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
    /// A hash of which objects write the depth (the set of objects that are
    /// not opaque: hidden or translucent), the same for styles that differ
    /// only in arrays or colours: the depth, and so the VSS, of one view
    /// changes with it (the solve's key). Allocates: throws std::bad_alloc.
    [[nodiscard]] std::uint64_t depthKey() const;
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

/// The labels array `name` is shown with (sorted by value, each shown in
/// colormaps::labelColor(its index)); nullopt when it is shown through the
/// colour map: by style.values for the scene's array, by
/// scene::looksCategorical() for others; Categories on an array that is not
/// whole-numbered or has more than scene::kMaxLabels distinct values stays
/// continuous.
[[nodiscard]] std::optional<std::vector<scene::Label>> shownLabels(const scene::Scene& scene,
                                                                   const MeshStyle& style,
                                                                   const std::string& name);

/// shownLabels() of every array the style shows (shownArrays()), by name.
using ShownLabels = std::vector<std::pair<std::string, std::optional<std::vector<scene::Label>>>>;

/// The labels of `name` in `labels`; null when it is not shown as labels.
[[nodiscard]] const std::vector<scene::Label>* labelsOf(const ShownLabels& labels,
                                                        const std::string& name);

/// ShownLabels of one scene, computed again only when what decides them
/// changes (the shown arrays, the scene's array or its Values mode), not
/// per frame or per style edit: finding labels reads every value of an
/// array. The owner calls invalidate() when the scene changes.
class ShownLabelsCache {
  public:
    /// The labels `style` shows of `scene`. Throws std::bad_alloc only.
    [[nodiscard]] const ShownLabels& get(const scene::Scene& scene, const MeshStyle& style);
    /// The scene changed: the next get() computes again.
    void invalidate() noexcept { valid_ = false; }
    /// How often get() computed the labels (each reads the arrays' values).
    [[nodiscard]] std::size_t computations() const noexcept { return computations_; }

  private:
    bool valid_ = false;
    std::size_t computations_ = 0;
    std::vector<std::string> arrays_;
    std::string array_;
    ArrayValues values_ = ArrayValues::Auto;
    ShownLabels labels_;
};

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
/// The cue whose name() equals `text`, ignoring ASCII case; nullopt when none does.
[[nodiscard]] std::optional<VesselCue> vesselCueFromName(std::string_view text) noexcept;
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

}  // namespace vv::render
