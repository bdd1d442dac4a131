// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// Which parts of the "upscale" pass's target need its iso-lines: the pass
// draws the target in rectangles (scissored full-screen triangles), those an
// iso-line can reach with upscale.frag's full program and the rest with its
// colour-only variant (one bilinear tap a pixel), which writes the same
// pixels there. On software rasterisers the iso-lines cost about as much as
// the rest of that pass.

#include <glm/glm.hpp>
#include <vector>

#include "vv/core/Image.h"

namespace vv::render {

/// Rectangles of the target in its pixels (GL window coordinates: x0, y0
/// inclusive, x1, y1 exclusive, y up), runs of tiles along their row.
struct UpscaleTiles {
    std::vector<glm::ivec4> plain;  ///< where no iso-line pixel can show
    std::vector<glm::ivec4> lines;  ///< the others
};

/// Splits a `target`-sized frame into `tile` x `tile` pixel tiles (`tile`
/// even, >= 2; the last row and column as large as the target leaves; the
/// neighbours of a kind along a row merged into one rectangle) by
/// whether upscale.frag, drawing `isoLines` iso-lines `isoLineWidth` target
/// pixels wide from the bilinear `height` (the VSS height texture's texels:
/// non-finite values as the texture's "no VSS" mark), can give a pixel of
/// the tile any iso-line coverage. Conservative: a tile is plain only when
/// its heights (with the bilinear taps' neighbours) stay farther from every
/// level than the line reaches at the steepest slope among them. With
/// `isoLines` <= 0 every tile is plain. Throws vv::InvalidArgumentError for an
/// empty `height` or `target`, or an odd or too small `tile`.
[[nodiscard]] UpscaleTiles splitUpscaleTiles(const Image<float>& height, glm::ivec2 target,
                                             int isoLines, float isoLineWidth, int tile);

}  // namespace vv::render
