// SPDX-License-Identifier: GPL-3.0-or-later
// Tiled rendering: the off-axis sub-frustum of one tile of an image, and the
// split of an image into tiles with guard bands.
#pragma once

#include <glm/glm.hpp>
#include <vector>

namespace vv::render {

/// A rectangle of pixels [x, x + width) x [y, y + height) of an image, origin
/// at the top-left corner, +y down (like QImage and Camera pixels).
struct PixelRect {
    int x = 0;
    int y = 0;
    int width = 0;
    int height = 0;
    friend bool operator==(const PixelRect&, const PixelRect&) = default;
};

/// The projection that draws only `tile` of a fullWidth x fullHeight image
/// drawn with `projection`: clip x and y are scaled and shifted so that the
/// tile's rectangle fills NDC [-1, 1]^2 (an off-axis sub-frustum; depth is
/// unchanged). Rendered at a tile.width x tile.height viewport, pixel (i, j)
/// of the tile is pixel (tile.x + i, tile.y + j) of the full image, so tiles
/// put side by side give the full image's rasterisation. The tile may reach
/// beyond the image. Throws InvalidArgumentError when a size is below 1.
[[nodiscard]] glm::mat4 tileProjection(const glm::mat4& projection, int fullWidth, int fullHeight,
                                       const PixelRect& tile);

/// One tile of a tiled render: `core` is the part of the image it delivers,
/// `render` the rectangle it is rendered at: the core grown by a guard band
/// on every side that does not touch the image border (cropped away again),
/// so that screen-space filters see the same neighbourhood as in one piece.
struct RenderTile {
    PixelRect core;
    PixelRect render;
};

/// Splits a width x height image into tiles whose rendered rectangles are at
/// most maxSide pixels per side: cores of at most maxSide - 2 guard pixels,
/// in rows from the top-left, as even in size as possible. Throws
/// InvalidArgumentError when a size is below 1, guard < 0, or maxSide leaves
/// no core (maxSide <= 2 guard).
[[nodiscard]] std::vector<RenderTile> splitIntoTiles(int width, int height, int maxSide, int guard);

}  // namespace vv::render
