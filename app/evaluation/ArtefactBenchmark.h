// SPDX-License-Identifier: GPL-3.0-or-later
// Artefacts of the lit VSS along silhouettes (issue 19, part 1): the
// artefact score (ArtefactScore.h) of several meshes in one view, as a
// Markdown table. Used by `vesselview-cli artefacts` and the tests.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <stop_token>
#include <string>
#include <vector>

#include "evaluation/ArtefactScore.h"
#include "vv/core/Image.h"
#include "vv/render/Camera.h"
#include "vv/render/MeshStyle.h"
#include "vv/render/ViewPresets.h"
#include "vv/scene/Mesh.h"

namespace vv::evaluation {

/// The lit VSS of a scene, computed on the CPU as an exact viewer frame is.
struct LitVss {
    Image<float> luminance;       ///< vssLuminance(); NaN off the VSS
    Image<std::uint8_t> vessels;  ///< 1 = vessel pixel
};

/// render::rasterizeDepth of `scene` through `camera`, vss::solve with the
/// fast solver at power `p` (default tolerance), vss::fittedSlopes,
/// vss::addNormalCoherence and vssLuminance under `lighting` (by default
/// render::sceneLighting(), the viewer's default key light). Throws as those do.
[[nodiscard]] LitVss litVss(const scene::Scene& scene, const render::Camera& camera, double p,
                            const std::stop_token& stop = {},
                            const render::Lighting& lighting = render::sceneLighting());

/// The reference of the artefact score, a frame without the pixel
/// staircase: litVss with z' on each void pixel taken from the same view
/// solved at `scale` times the width and height (over the frame's depth
/// range) at that pixel's centre, i.e. the VSS of a silhouette `scale` times
/// finer, sampled at the frame's pixels; slopes, coherence and lighting as
/// in litVss at the frame's size (their windows cover the same scene). A
/// void pixel whose centre the fine raster finds covered keeps its own z'.
/// Throws InvalidArgumentError unless scale is odd and >= 1, and as litVss.
[[nodiscard]] LitVss referenceLitVss(const scene::Scene& scene, const render::Camera& camera,
                                     double p, int scale, const std::stop_token& stop = {},
                                     const render::Lighting& lighting = render::sceneLighting());

struct ArtefactCase {
    std::string label;  ///< row name
    scene::Scene scene;
};

struct ArtefactBenchmarkOptions {
    int width = 1280;  ///< 1..8192 each
    int height = 720;
    render::ViewPreset view = render::ViewPreset::Close;
    double p = 2.0;  ///< finite, > 0
    /// The key light (the viewer's default unless set).
    render::LightAngles light;
    /// The clean reference of each case (referenceLitVss at this scale): 0 =
    /// none; else 3, 5 or 7.
    int referenceScale = 3;
    ArtefactScoreOptions score;
    std::stop_token stop;
};

struct ArtefactRow {
    std::string label;
    std::size_t triangles = 0;
    ArtefactScore score;
    ArtefactScore reference;  ///< of the supersampled reference (rms 0 without one)
    /// The score next to the silhouettes and away from them (bands
    /// kNearBand and kFarBand, second differences kBumpSpacing apart): a
    /// faceted silhouette's bumps raise the first and not the second,
    /// whatever the view's own smoothness.
    ArtefactScore near;
    ArtefactScore far;
    /// The median length of the meshes' triangle edges on screen (px), over
    /// the edges in front of the camera: how coarse the facets are for this
    /// view (0 without one).
    double medianEdgePx = 0.0;
};

/// medianEdgePx of ArtefactRow: every triangle edge of `scene` with both
/// ends in front of `camera`, projected into its viewport.
[[nodiscard]] double medianEdgePixels(const scene::Scene& scene, const render::Camera& camera);

/// The bands of ArtefactRow::near and ::far, in px from the nearest vessel
/// pixel (issue 36's measure of bumps along silhouettes: the roughness 2-6
/// px from the vessels over that 12-30 px away).
inline constexpr std::array<double, 2> kNearBand{2.0, 6.0};
inline constexpr std::array<double, 2> kFarBand{12.0, 30.0};
/// px between the samples of those bands' second differences: a coarse
/// facet's light or dark blob along a silhouette spans some 20-40 px in the
/// demo's views at 1280x720, which the score's own 3 px (made for the pixel
/// staircase) barely sees.
inline constexpr double kBumpSpacing = 10.0;

/// The score of every case, all seen through the preset camera of the FIRST
/// case (so that a decimated copy is seen exactly as its original). Throws
/// InvalidArgumentError without cases or for options out of range, and as
/// litVss / artefactScore do.
[[nodiscard]] std::vector<ArtefactRow> runArtefactBenchmark(
    const std::vector<ArtefactCase>& cases, const ArtefactBenchmarkOptions& options);

/// The rows as a GitHub Markdown table: label, triangles, band pixels, score
/// in 1/1000 of the luminance range, the reference's score and the score
/// over it (1 = as clean as the supersampled frame; "-" without a
/// reference), the score relative to the first row, the near and far
/// scores and their ratio, and the median edge on screen (C-locale numbers:
/// a machine format for the docs).
[[nodiscard]] std::string artefactTable(const std::vector<ArtefactRow>& rows);

}  // namespace vv::evaluation
