// SPDX-License-Identifier: GPL-3.0-or-later
// The centrelines `render` and `report` draw with --centerlines on, and the
// surface that they and `centerline` analyse.
#pragma once

#include <filesystem>
#include <ostream>

#include "vv/render/CenterlineOverlay.h"
#include "vv/scene/Mesh.h"

namespace vv::cli {

/// The surface of `scene` (read from `input`) that the centreline analysis
/// takes: its first mesh, with a note on `err` when there are more (naming
/// the one analysed) and a warning when its size says it is not in mm.
/// Throws FormatError naming `input` when the scene has no mesh.
[[nodiscard]] const scene::Mesh& analysedSurface(const scene::Scene& scene,
                                                 const std::filesystem::path& input,
                                                 std::ostream& err);

/// The centrelines of analysedSurface() (vv::analysis::computeCenterlines
/// with its defaults, its notes on `err`) as an overlay coloured by
/// `colouring`, over the range of their inscribed diameters, in a map other
/// than `vesselMap` (the one the vessels' array is shown in) so that the two
/// legends cannot be read for each other. Throws analysis::AnalysisError
/// (exit code 3) when the surface cannot be analysed, as `centerline` does.
[[nodiscard]] render::CenterlineOverlay centerlineOverlay(const scene::Scene& scene,
                                                          const std::filesystem::path& input,
                                                          render::CenterlineColouring colouring,
                                                          colormaps::ColorMap vesselMap,
                                                          std::ostream& err);

}  // namespace vv::cli
