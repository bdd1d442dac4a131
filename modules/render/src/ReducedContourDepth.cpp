// SPDX-License-Identifier: GPL-3.0-or-later
#include "ReducedContourDepth.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "vv/core/Error.h"

namespace vv::render {

namespace {

/// The outward depth step of vessel pixel (x, y): the largest depth rise
/// toward a background neighbour (see silhouetteDepth), `ridgeStep` where the
/// pixel opposite that neighbour is background too, at most `maxStep`; 0 for
/// a pixel without background neighbours.
float outwardStep(const Image<float>& depth, int x, int y, float ridgeStep, float maxStep) {
    const int w = depth.width();
    const int h = depth.height();
    const auto background = [&](int px, int py) {
        return px >= 0 && py >= 0 && px < w && py < h && !std::isfinite(depth(px, py));
    };
    const auto vessel = [&](int px, int py) {
        return px >= 0 && py >= 0 && px < w && py < h && std::isfinite(depth(px, py));
    };
    float step = 0.0F;
    for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
            if ((dx == 0 && dy == 0) || !background(x + dx, y + dy)) {
                continue;
            }
            if (vessel(x - dx, y - dy)) {
                step = std::max(step, depth(x, y) - depth(x - dx, y - dy));
            } else if (background(x - dx, y - dy)) {
                step = std::max(step, ridgeStep);
            }
        }
    }
    return std::min(step, maxStep);
}

/// Vessels one pixel wide of `depth` get a second pixel, of the depth
/// `extrapolated` gives them (see silhouetteDepth).
Image<float> widenThinVessels(const Image<float>& depth, const Image<float>& extrapolated) {
    Image<float> result = extrapolated;
    const int w = depth.width();
    const int h = depth.height();
    const auto background = [&](int px, int py) {
        return px >= 0 && py >= 0 && px < w && py < h && !std::isfinite(depth(px, py));
    };
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            if (!std::isfinite(depth(x, y))) {
                continue;
            }
            if (background(x - 1, y) && background(x + 1, y)) {
                result(x + 1, y) = extrapolated(x, y);
            }
            if (background(x, y - 1) && background(x, y + 1)) {
                result(x, y + 1) = extrapolated(x, y);
            }
        }
    }
    return result;
}

}  // namespace

Image<float> reduceDepth(const Image<float>& depth, int width, int height) {
    const int w = depth.width();
    const int h = depth.height();
    if (width < 1 || height < 1 || width > w || height > h) {
        throw InvalidArgumentError("reduceDepth: cannot reduce " + std::to_string(w) + "x" +
                                   std::to_string(h) + " to " + std::to_string(width) + "x" +
                                   std::to_string(height));
    }
    // The first render column / row of each reduced pixel: the render pixels
    // whose centres (x + 0.5) fall in it.
    const auto starts = [](int from, int to) {
        std::vector<int> start(static_cast<std::size_t>(to) + 1U);
        for (int i = 0; i <= to; ++i) {
            const double edge = static_cast<double>(i) * from / to - 0.5;
            start[static_cast<std::size_t>(i)] =
                std::clamp(static_cast<int>(std::ceil(edge)), 0, from);
        }
        start.back() = from;
        return start;
    };
    const std::vector<int> columns = starts(w, width);
    const std::vector<int> rows = starts(h, height);
    Image<float> reduced(width, height, std::numeric_limits<float>::infinity());
    for (int y = 0; y < height; ++y) {
        const int y0 = rows[static_cast<std::size_t>(y)];
        const int y1 = rows[static_cast<std::size_t>(y) + 1U];
        for (int x = 0; x < width; ++x) {
            const int x0 = columns[static_cast<std::size_t>(x)];
            const int x1 = columns[static_cast<std::size_t>(x) + 1U];
            float farthest = -std::numeric_limits<float>::infinity();
            for (int sy = y0; sy < y1; ++sy) {
                const float* row = depth.row(sy);
                for (int sx = x0; sx < x1; ++sx) {
                    if (std::isfinite(row[sx])) {
                        farthest = std::max(farthest, row[sx]);
                    }
                }
            }
            if (std::isfinite(farthest)) {
                reduced(x, y) = farthest;
            }
        }
    }
    return reduced;
}

float silhouetteReach(float reduction) noexcept {
    if (!(reduction > 2.0F)) {
        return 0.0F;
    }
    return std::min(1.5F * (1.0F - 2.0F / reduction), 1.0F);
}

Image<float> silhouetteDepth(const Image<float>& depth, float reduction, float pixelScale) {
    const float reach = silhouetteReach(reduction);
    if (!(reach > 0.0F) || !(pixelScale > 0.0F) || !std::isfinite(pixelScale)) {
        return depth;
    }
    Image<float> extrapolated = depth;
    for (int y = 0; y < depth.height(); ++y) {
        for (int x = 0; x < depth.width(); ++x) {
            const float d = depth(x, y);
            if (!std::isfinite(d)) {
                continue;
            }
            const float pixel = pixelScale * std::abs(d);
            extrapolated(x, y) =
                d + reach * outwardStep(depth, x, y, 0.5F * pixel, kMaxSilhouetteSlope * pixel);
        }
    }
    return widenThinVessels(depth, extrapolated);
}

}  // namespace vv::render
