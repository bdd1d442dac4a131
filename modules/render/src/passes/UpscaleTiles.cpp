// SPDX-License-Identifier: GPL-3.0-or-later
#include "passes/UpscaleTiles.h"

#include <algorithm>
#include <cmath>

#include "vv/core/Error.h"

namespace vv::render {

namespace {

/// A texel as upscale.frag reads it: clamp(z, 0, 1); the "no VSS" mark
/// (non-finite on the CPU, -1 in the texture) as 0.
float texelValue(float v) {
    return std::isfinite(v) ? std::clamp(v, 0.0F, 1.0F) : 0.0F;
}

/// The texels [first, last] that the bilinear taps of the target pixels
/// [from, to) read along one axis (with their derivative partners and a
/// texel more each side for rounding), clamped to the edge like the texture.
glm::ivec2 texelSpan(int from, int to, double texelsPerPixel, int texels) {
    const auto texel = [&](int pixel) {
        return static_cast<int>(std::floor((pixel + 0.5) * texelsPerPixel - 0.5));
    };
    return {std::clamp(texel(from) - 1, 0, texels - 1),
            std::clamp(texel(to - 1) + 2, 0, texels - 1)};
}

/// Whether any pixel whose heights come from the texel block can get
/// iso-line coverage (see upscale.frag: coverage is 0 where the distance
/// to the nearest level over the per-pixel change of z * N is at least
/// half the width + 0.5).
bool reachesALine(const Image<float>& height, glm::ivec2 xs, glm::ivec2 ys,
                  glm::dvec2 texelsPerPixel, int isoLines, float isoLineWidth) {
    float zmin = 1.0F;
    float zmax = 0.0F;
    float stepX = 0.0F;  // the largest change between neighbouring texels
    float stepY = 0.0F;
    for (int y = ys.x; y <= ys.y; ++y) {
        const float* row = height.row(y);
        const float* below = y < ys.y ? height.row(y + 1) : nullptr;
        for (int x = xs.x; x <= xs.y; ++x) {
            const float z = texelValue(row[x]);
            zmin = std::min(zmin, z);
            zmax = std::max(zmax, z);
            if (x < xs.y) {
                stepX = std::max(stepX, std::abs(texelValue(row[x + 1]) - z));
            }
            if (below != nullptr) {
                stepY = std::max(stepY, std::abs(texelValue(below[x]) - z));
            }
        }
    }
    const double n = isoLines;
    const double qmin = zmin * n;
    const double qmax = zmax * n;
    const double level = std::floor(qmin);
    if (qmax >= level + 1.0 || qmin - level < 1e-4) {
        return true;  // a level lies among them
    }
    const double bands = std::min(qmin - level, level + 1.0 - qmax) - 1e-4;
    const double perPixel =
        n * std::hypot(stepX * texelsPerPixel.x, stepY * texelsPerPixel.y) * 1.001 + 1e-6;
    const double reach = 0.5 * std::max(static_cast<double>(isoLineWidth), 0.0) + 0.5;
    return bands < reach * perPixel;
}

/// Appends [x0, x1) x [y0, y1) to `out`, merged with its last rectangle
/// when that one ends at x0 in the same row.
void addTile(std::vector<glm::ivec4>& out, int x0, int y0, int x1, int y1) {
    if (!out.empty() && out.back().z == x0 && out.back().y == y0 && out.back().w == y1) {
        out.back().z = x1;
        return;
    }
    out.emplace_back(x0, y0, x1, y1);
}

}  // namespace

UpscaleTiles splitUpscaleTiles(const Image<float>& height, glm::ivec2 target, int isoLines,
                               float isoLineWidth, int tile) {
    if (height.width() <= 0 || height.height() <= 0 || target.x <= 0 || target.y <= 0) {
        throw InvalidArgumentError("splitUpscaleTiles: empty height or target");
    }
    if (tile < 2 || tile % 2 != 0) {
        throw InvalidArgumentError("splitUpscaleTiles: the tile size must be even and >= 2");
    }
    const glm::dvec2 texelsPerPixel(static_cast<double>(height.width()) / target.x,
                                    static_cast<double>(height.height()) / target.y);
    UpscaleTiles tiles;
    for (int y0 = 0; y0 < target.y; y0 += tile) {
        const int y1 = std::min(y0 + tile, target.y);
        const glm::ivec2 ys = texelSpan(y0, y1, texelsPerPixel.y, height.height());
        for (int x0 = 0; x0 < target.x; x0 += tile) {
            const int x1 = std::min(x0 + tile, target.x);
            const glm::ivec2 xs = texelSpan(x0, x1, texelsPerPixel.x, height.width());
            const bool lines = isoLines > 0 &&
                               reachesALine(height, xs, ys, texelsPerPixel, isoLines, isoLineWidth);
            addTile(lines ? tiles.lines : tiles.plain, x0, y0, x1, y1);
        }
    }
    return tiles;
}

}  // namespace vv::render
