// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// The vessels' silhouettes of a frame drawn at a reduced size, rebuilt
// from the render size's staircase for the "upscale" pass (upscale.frag's
// EDGES variant draws them at the target's resolution). A silhouette
// crosses the render pixels in steps: runs of texel pairs, one a vessel
// pixel and the other not, along the edge, each run a pixel off the next.
// The straight edge they sample passes the middle of a run on the pairs'
// midline and its ends half a texel off it, towards the neighbouring runs
// (as MLAA rebuilds aliased edges): a step one way at one end and the
// other way at the other end makes one straight line through the run, a
// step at one end only a ramp over that half. Found on the CPU from the
// depth the frame read back, where a shader would search every target
// pixel's run again (several render pixels' worth of target pixels share
// one run).

#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

#include "vv/core/Image.h"

namespace vv::render {

/// How far silhouetteRuns() follows a run each way (render pixels): edges
/// down to about 3.5 degrees off an axis get their whole runs.
inline constexpr int kSilhouetteSearch = 16;

/// The vessel pixels of the render size's linear depth `depth` (finite on
/// vessel pixels, non-finite off them; any row order): 1, else 0.
[[nodiscard]] Image<std::uint8_t> vesselMask(const Image<float>& depth);

/// For every texel t of `vessels` (vesselMask()), where the
/// silhouette through the pair (t, t + (0, 1)) crosses the pair's columns'
/// sides x - 0.5 (.x) and x + 0.5 (.y), and where the one through the pair
/// (t, t + (1, 0)) crosses its rows' sides y - 0.5 (.z) and y + 0.5 (.w):
/// as offsets from the pair's midline in texels towards the second texel,
/// in [-0.5, 0.5], stored as round((offset + 0.5) * 255) (a unorm texture
/// reads offset + 0.5). Pairs that are both or neither vessel pixels hold
/// offset 0. `search` (>= 0) bounds the run each way; the image's border
/// ends a run without a step. Throws vv::InvalidArgumentError for a
/// negative `search`.
[[nodiscard]] Image<glm::u8vec4> silhouetteRuns(const Image<std::uint8_t>& vessels,
                                                int search = kSilhouetteSearch);

/// The rectangles of a `target`-sized frame upscaled from `vessels`' size
/// (GL window coordinates, pixels: x0, y0 inclusive, x1, y1 exclusive)
/// that hold every target pixel whose bilinear footprint (the 2x2 texels
/// around its centre, clamped to the edge) has vessel and other texels
/// (`vessels`: vesselMask()): where upscale.frag's EDGES variant draws a
/// silhouette. One per run of such footprints along a row of texels, a
/// pixel wider each side than its pixels (against rounding). Throws
/// vv::InvalidArgumentError for an empty `vessels` or `target`.
[[nodiscard]] std::vector<glm::ivec4> silhouetteRects(const Image<std::uint8_t>& vessels,
                                                      glm::ivec2 target);

}  // namespace vv::render
