// SPDX-License-Identifier: GPL-3.0-or-later
// Artefacts of the lit VSS along silhouettes (issue 19, part 1): the
// artefact score (ArtefactScore.h) of several meshes in one view, as a
// Markdown table. Used by `vesselview-cli artefacts` and the tests.
#pragma once

#include <cstddef>
#include <cstdint>
#include <stop_token>
#include <string>
#include <vector>

#include "ArtefactScore.h"
#include "vv/core/Image.h"
#include "vv/render/Camera.h"
#include "vv/render/ViewPresets.h"
#include "vv/scene/Mesh.h"

namespace vv::bench {

/// The lit VSS of a scene, computed on the CPU as an exact viewer frame is.
struct LitVss {
    Image<float> luminance;       ///< vssLuminance(); NaN off the VSS
    Image<std::uint8_t> vessels;  ///< 1 = vessel pixel
};

/// render::rasterizeDepth of `scene` through `camera`, vss::solve with the
/// fast solver at power `p` (default tolerance), vss::fittedSlopes,
/// vss::addNormalCoherence and vssLuminance under render::sceneLighting()
/// (the headlight). Throws as those do.
[[nodiscard]] LitVss litVss(const scene::Scene& scene, const render::Camera& camera, double p,
                            const std::stop_token& stop = {});

struct ArtefactCase {
    std::string label;  ///< row name
    scene::Scene scene;
};

struct ArtefactBenchmarkOptions {
    int width = 1280;  ///< 1..8192 each
    int height = 720;
    render::ViewPreset view = render::ViewPreset::Close;
    double p = 2.0;  ///< finite, > 0
    ArtefactScoreOptions score;
    std::stop_token stop;
};

struct ArtefactRow {
    std::string label;
    std::size_t triangles = 0;
    ArtefactScore score;
};

/// The score of every case, all seen through the preset camera of the FIRST
/// case (so that a decimated copy is seen exactly as its original). Throws
/// InvalidArgumentError without cases or for options out of range, and as
/// litVss / artefactScore do.
[[nodiscard]] std::vector<ArtefactRow> runArtefactBenchmark(
    const std::vector<ArtefactCase>& cases, const ArtefactBenchmarkOptions& options);

/// The rows as a GitHub Markdown table: label, triangles, band pixels, score
/// in 1/1000 of the luminance range, and the score relative to the first row
/// (C-locale numbers: a machine format for the docs).
[[nodiscard]] std::string artefactTable(const std::vector<ArtefactRow>& rows);

}  // namespace vv::bench
