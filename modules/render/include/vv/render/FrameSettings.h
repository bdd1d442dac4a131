// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// What a frame is drawn with besides camera, scene and mesh style (the
// display settings), where it goes, and what its VSS was. Plain C++: no GL.

#include <glm/glm.hpp>
#include <limits>

#include "vv/colormaps/DepthScale.h"
#include "vv/render/MeshStyle.h"
#include "vv/vss/DepthNormalization.h"
#include "vv/vss/Solver.h"

namespace vv::render {

/// The default background: a dark grey (sRGB), of frames, offscreen renders,
/// exports and the display settings alike.
inline constexpr glm::vec3 kDefaultBackground{0.13F, 0.14F, 0.16F};

/// How the Void Space Surface is computed and shaded.
struct VssSettings {
    bool enabled = true;
    colormaps::DepthScale scale = colormaps::DepthScale::Chromadepth;
    /// Solver, p, tolerance (fast solver by default).
    vss::SolverOptions solver;
    int isoLines = 8;               ///< N iso-lines at z' = k / N; 0 = none
    float isoLineWidth = 1.5F;      ///< pixels
    float isoLineStrength = 0.55F;  ///< 0..1
    float lighting = 1.0F;          ///< 0 = flat scale colours, 1 = full Blinn-Phong
    float opacity = 1.0F;           ///< 0..1, the VSS over the background
    /// Progressive refinement: a preview solve (while the camera moves) uses
    /// the fast solver with at least `previewTolerance`, so it finishes sooner;
    /// the exact solve (preview = false) uses `solver` as given. 2/255: at
    /// 8/255 the fast solver's interpolation bent z' enough between samples
    /// for the lit VSS to show seams across the void while moving; 2/255
    /// costs ~1 ms CPU more per moving frame at 0.42 of 1280x720
    /// (docs/benchmarks/render.md, "Moving frames, round 7").
    bool preview = false;
    double previewTolerance = 2.0 / 255.0;
    /// The depth range z is normalised over (VSS.md): the visible vessels'
    /// min / max (default: the scale adapts to each view), or a fixed range
    /// in scene units (the colours keep their depth across views; depths
    /// outside clamp). Bad fixed ranges throw InvalidArgumentError at render().
    vss::DepthRange range;
};

/// The solver options a VSS solve with `settings` uses (preview or exact).
[[nodiscard]] vss::SolverOptions effectiveSolverOptions(const VssSettings& settings) noexcept;

/// What the depth a person reads (depth legend, probe) is measured from.
enum class DepthReference {
    /// The frontmost visible vessel point: "depth behind the frontmost
    /// vessel", 0 there (the visible range, and a view's pinned one).
    FrontmostVessel,
    /// The camera: the viewing distance, as the user's fixed near / far are
    /// given (the legend runs from near to far).
    Camera,
};

/// The reference of a frame's depth scale: Camera while the VSS is on with a
/// fixed range the user chose (not vss::DepthRange::pinnedVisible), else
/// FrontmostVessel (the visible range; with the VSS off the vessel cue
/// always spans the visible vessels).
[[nodiscard]] constexpr DepthReference depthReference(const VssSettings& settings) noexcept {
    return settings.enabled && settings.range.mode == vss::RangeMode::Fixed &&
                   !settings.range.pinnedVisible
               ? DepthReference::Camera
               : DepthReference::FrontmostVessel;
}

/// A depth cue on the vessels themselves (pass 5, for comparison with the
/// VSS). Its depth range is the VSS's dmin / dmax when a VSS is shown, else
/// the visible vessels' linear depth range.
struct VesselCueSettings {
    VesselCue cue = VesselCue::None;
    float fogStrength = 0.8F;      ///< Fog: blend towards the background at the far end
    float fresnelExponent = 1.0F;  ///< Fresnel: k in (1 - |n.v|)^k
};

/// Screen-space ambient occlusion over the vessels and the VSS ("ssao" and
/// "ao-blur" passes): darkens the VSS next to the vessels (and the vessels
/// half as much), so they look anchored on the surface.
struct AoSettings {
    bool enabled = true;
    float radius = 3.0F;    ///< scene units (mm for the demo)
    float strength = 0.8F;  ///< 0..1: how much full occlusion darkens
    /// Frames with more pixels than this compute the occlusion (and its
    /// blur) at half the resolution per axis, a quarter of the work, and the
    /// composite reads it bilinearly: the AO is a low-frequency shade and
    /// its disc is 3x wider in pixels at 4K than at 720p. Default: up to
    /// 2560x1440 at full resolution, so 4K UHD at half.
    long long fullResolutionPixels = 2560LL * 1440LL;
};

/// 1, or 2 when a frame of `size` computes its AO at half resolution.
[[nodiscard]] inline int aoStepFor(const AoSettings& ao, long long pixels) noexcept {
    return pixels > ao.fullResolutionPixels ? 2 : 1;
}

/// Everything a frame needs besides the camera, the scene and the mesh style
/// (which lives in FrameRenderer::meshRenderer()). A still frame's are
/// frameSettings() of the display settings (DisplaySettings.h); the
/// refinement policy lowers them for moving frames.
struct FrameSettings {
    glm::vec3 background{kDefaultBackground};  ///< sRGB
    VssSettings vss;
    VesselCueSettings cue;
    AoSettings ao;
    /// FXAA on the composited frame ("fxaa" pass, last).
    bool antialiasing = true;
    /// Render size relative to the target, in [0.1, 1]: below 1 every pass
    /// (G-buffer, solve, shading) runs at the reduced size, and the "fxaa"
    /// pass (anti-aliasing on) or "upscale" (off: the VSS iso-lines are then
    /// drawn at the target's size) brings it into the target with bilinear
    /// taps. For interactive frames on slow rasterisers; 1 = full resolution.
    float resolutionScale = 1.0F;
    /// The VSS's size relative to the render size, in [0.25, 1]: below 1 the
    /// VSS is solved and shaded at that smaller size, from the render size's
    /// depth reduced to it (every vessel pixel of the render size kept), and
    /// composited under the vessels edge-aware: for moving frames, which
    /// draw the vessels sharper than a VSS solve at their size would allow
    /// (RefinementPolicy). Taken as 1 with the ambient occlusion on (it
    /// reads the VSS at the render size) and for an external VSS
    /// (FrameRenderer::setExternalVss).
    float vssResolutionScale = 1.0F;
    /// Draw the G-buffer from one of the mesh renderer's preview scenes
    /// (simplified copies, MeshRenderer::setPreviewScenes) when it has any,
    /// the level chosen for the render size (MeshRenderer::previewLevelFor:
    /// about one triangle per kPixelsPerPreviewTriangle pixels): for frames
    /// while the camera moves, where triangle count, not pixels, bounds the
    /// frame time of software rasterisers. The VSS of such a frame is solved on that
    /// geometry's depth (a preview, never cached as the exact one).
    bool simplifiedGeometry = false;
    /// Draw the G-buffer from the mesh renderer's refined copy of the scene
    /// (MeshRenderer::setRefinedScene, Loop-subdivided) when it has one and
    /// the scene's facets are coarse for the view: its median edge at least
    /// kCoarseEdgePixels on screen (MeshRenderer::refinedWanted). A coarse
    /// mesh's silhouette zig-zags in depth from vertex to vertex, and the
    /// lit VSS shows every facet as a blob along it (issue 36).
    bool smoothCoarseMeshes = true;
};

/// The framebuffer a frame is drawn into: `framebuffer` (0 = the default one)
/// of width x height device pixels.
struct FrameTarget {
    unsigned framebuffer = 0;
    int width = 1;
    int height = 1;
};

/// What the VSS of the last frame was.
struct VssFrameStatus {
    bool shown = false;    ///< a VSS was drawn
    bool current = false;  ///< it belongs to this frame's view (not a previous one)
    bool pending = false;  ///< a solve for this frame's view is still running
    double dmin = 0.0;     ///< its depth range in scene units
    double dmax = 0.0;
    double solveMilliseconds = 0.0;  ///< wall time of the solve that made it
    bool preview = false;            ///< the shown VSS is a preview solve (VssSettings::preview)
    /// The shown solve's guaranteed bound on |z' - z'_exact| (its solver's
    /// errorBound(): 0 for exact solvers, the tolerance for fast ones); NaN
    /// when the solver gives none (the paper's step, k > 1) or no VSS is shown.
    double errorBound = std::numeric_limits<double>::quiet_NaN();
};

}  // namespace vv::render
