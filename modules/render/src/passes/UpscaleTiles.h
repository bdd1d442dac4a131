// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// Which parts of the "upscale" pass's target need its iso-lines and which
// its vessel edges: the pass draws the target in rectangles (scissored
// full-screen triangles), those an iso-line can reach with upscale.frag's
// iso-line program, those with a vessel silhouette among their texels with
// its EDGES variant, and the rest with its colour-only variant (one
// bilinear tap a pixel), which writes the same pixels there. On software
// rasterisers the iso-lines cost about as much as the rest of that pass.

#include <glm/glm.hpp>
#include <vector>

#include "vv/core/Image.h"

namespace vv::render {

/// Rectangles of the target in its pixels (GL window coordinates: x0, y0
/// inclusive, x1, y1 exclusive, y up), runs of tiles along their row.
struct UpscaleTiles {
    std::vector<glm::ivec4> plain;          ///< neither an iso-line nor a vessel edge
    std::vector<glm::ivec4> lines;          ///< iso-lines, no vessel edge
    std::vector<glm::ivec4> edges;          ///< a vessel edge, no iso-line
    std::vector<glm::ivec4> linesAndEdges;  ///< both
};

/// What splitUpscaleTiles() reads. Null maps make every tile need what
/// they would tell (when it is asked for at all).
struct UpscaleTileMaps {
    /// The iso-lines: how many (<= 0: none, `height` not read), their
    /// width in target pixels, and the VSS height texture's texels they are
    /// drawn from (non-finite values: the texture's "no VSS" mark).
    int isoLines = 0;
    float isoLineWidth = 1.5F;
    const Image<float>* height = nullptr;
    /// The vessel edges (`edges` false: none, `depth` not read) and the
    /// render size's linear depth (finite on vessel pixels, non-finite off
    /// them), of the size the colour is upscaled from.
    bool edges = false;
    const Image<float>* depth = nullptr;
};

/// Splits a `target`-sized frame into `tile` x `tile` pixel tiles (`tile`
/// even, >= 2; the last row and column as large as the target leaves; the
/// neighbours of a kind along a row merged into one rectangle) by two
/// questions. Lines: can upscale.frag, drawing the iso-lines from the
/// bilinear height, give a pixel of the tile any iso-line coverage?
/// Conservative: no only when the tile's heights (with the bilinear taps'
/// neighbours) stay farther from every level than the line reaches at the
/// steepest slope among them. Edges: do the texels the tile's bilinear taps
/// read (with a texel more each side) hold both vessel and non-vessel
/// depths, so that upscale.frag's EDGES variant can draw a silhouette in
/// it? Throws vv::InvalidArgumentError for an empty map that is read or an
/// empty `target`, or an odd or too small `tile`.
[[nodiscard]] UpscaleTiles splitUpscaleTiles(const UpscaleTileMaps& maps, glm::ivec2 target,
                                             int tile);

}  // namespace vv::render
