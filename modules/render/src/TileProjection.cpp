// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/render/TileProjection.h"

#include <algorithm>
#include <string>

#include "vv/core/Error.h"

namespace vv::render {

namespace {

/// `length` split into `count` parts as even as possible: the start of part `i`.
int partStart(int length, int count, int i) noexcept {
    return static_cast<int>(static_cast<long long>(length) * i / count);
}

/// Ceiling of a / b for positive values.
int ceilDiv(int a, int b) noexcept {
    return (a + b - 1) / b;
}

}  // namespace

glm::mat4 tileProjection(const glm::mat4& projection, int fullWidth, int fullHeight,
                         const PixelRect& tile) {
    if (fullWidth < 1 || fullHeight < 1 || tile.width < 1 || tile.height < 1) {
        throw InvalidArgumentError("a tile projection needs sizes of at least 1 pixel, got image " +
                                   std::to_string(fullWidth) + "x" + std::to_string(fullHeight) +
                                   ", tile " + std::to_string(tile.width) + "x" +
                                   std::to_string(tile.height));
    }
    const double w = fullWidth;
    const double h = fullHeight;
    // The tile's NDC extent in the full image (NDC y points up, pixel rows down).
    const double left = 2.0 * tile.x / w - 1.0;
    const double right = 2.0 * (tile.x + tile.width) / w - 1.0;
    const double top = 1.0 - 2.0 * tile.y / h;
    const double bottom = 1.0 - 2.0 * (tile.y + tile.height) / h;
    // ndc' = (ndc - centre) / halfExtent, applied in clip space (times w).
    const double sx = 0.5 * (right - left);
    const double sy = 0.5 * (top - bottom);
    const double cx = 0.5 * (right + left);
    const double cy = 0.5 * (top + bottom);
    glm::dmat4 crop(1.0);  // glm: crop[column][row]
    crop[0][0] = 1.0 / sx;
    crop[3][0] = -cx / sx;
    crop[1][1] = 1.0 / sy;
    crop[3][1] = -cy / sy;
    return {crop * glm::dmat4(projection)};
}

std::vector<RenderTile> splitIntoTiles(int width, int height, int maxSide, int guard) {
    if (width < 1 || height < 1 || guard < 0 || maxSide - 2 * guard < 1) {
        throw InvalidArgumentError("cannot split " + std::to_string(width) + "x" +
                                   std::to_string(height) + " into tiles of at most " +
                                   std::to_string(maxSide) + " pixels with a guard band of " +
                                   std::to_string(guard));
    }
    const int core = maxSide - 2 * guard;
    // Images that fit one tile need no guard at all.
    const int columns = width <= maxSide ? 1 : ceilDiv(width, core);
    const int rows = height <= maxSide ? 1 : ceilDiv(height, core);
    std::vector<RenderTile> tiles;
    tiles.reserve(static_cast<std::size_t>(columns) * static_cast<std::size_t>(rows));
    for (int row = 0; row < rows; ++row) {
        const int y0 = partStart(height, rows, row);
        const int y1 = partStart(height, rows, row + 1);
        for (int column = 0; column < columns; ++column) {
            const int x0 = partStart(width, columns, column);
            const int x1 = partStart(width, columns, column + 1);
            RenderTile tile;
            tile.core = {x0, y0, x1 - x0, y1 - y0};
            const int rx0 = std::max(0, x0 - guard);
            const int ry0 = std::max(0, y0 - guard);
            const int rx1 = std::min(width, x1 + guard);
            const int ry1 = std::min(height, y1 + guard);
            tile.render = {rx0, ry0, rx1 - rx0, ry1 - ry0};
            tiles.push_back(tile);
        }
    }
    return tiles;
}

}  // namespace vv::render
