// SPDX-License-Identifier: GPL-3.0-or-later
#include "passes/SilhouetteRuns.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "vv/core/Error.h"

namespace vv::render {

namespace {

/// A run's reach along one direction: how many more pairs continue it,
/// and where the edge goes after them (+1 towards the pairs' second texel,
/// -1 away from it, 0 no step: a swapped pair, the border, or the search's
/// end).
struct RunEnd {
    int length = 0;
    int step = 0;
};

/// The silhouette's offsets from the midline of the pair run (see the
/// header) at the sides -0.5 and +0.5 of the pair `before` + `after` + 1
/// pairs long whose ends step as `before` and `after` say. A run stepping
/// the same way at both ends (a bump: a vessel's tip, a lone vessel pixel)
/// peaks at its centre; the pair holding the peak gets its mean height on
/// both sides, as the shader draws a line between the sides (a lone pixel
/// keeps a bar of half its area instead of vanishing at the peak's foot).
glm::vec2 runOffsets(const RunEnd& before, const RunEnd& after) {
    const double n = before.length + after.length + 1;
    const auto at = [&](double x) {
        const double t = (x + before.length + 0.5) / n;  // 0 .. 1 over the run
        if (before.step != 0 && before.step == -after.step) {
            return before.step * 0.5 * (1.0 - 2.0 * t);
        }
        return before.step * 0.5 * std::max(1.0 - 2.0 * t, 0.0) +
               after.step * 0.5 * std::max(2.0 * t - 1.0, 0.0);
    };
    const double peak = 0.5 * n - before.length - 0.5;  // where t = 0.5
    if (before.step != 0 && before.step == after.step && std::abs(peak) < 0.5) {
        const double mean =
            0.5 * (at(-0.5) + at(peak)) * (peak + 0.5) + 0.5 * (at(peak) + at(0.5)) * (0.5 - peak);
        return glm::vec2(static_cast<float>(mean));
    }
    return {static_cast<float>(at(-0.5)), static_cast<float>(at(0.5))};
}

std::uint8_t encode(float offset) {
    return static_cast<std::uint8_t>(std::lround(std::clamp(offset + 0.5F, 0.0F, 1.0F) * 255.0F));
}

}  // namespace

Image<std::uint8_t> vesselMask(const Image<float>& depth) {
    Image<std::uint8_t> mask(depth.width(), depth.height(), UninitialisedPixels{});
    for (int y = 0; y < depth.height(); ++y) {
        const float* in = depth.row(y);
        std::uint8_t* out = mask.row(y);
        for (int x = 0; x < depth.width(); ++x) {
            out[x] = std::isfinite(in[x]) ? 1 : 0;
        }
    }
    return mask;
}

Image<glm::u8vec4> silhouetteRuns(const Image<std::uint8_t>& vessels, int search) {
    if (search < 0) {
        throw InvalidArgumentError("silhouetteRuns: the search must not be negative");
    }
    const int w = vessels.width();
    const int h = vessels.height();
    Image<glm::u8vec4> runs(w, h, glm::u8vec4(encode(0.0F)));
    const auto vessel = [&](glm::ivec2 t) { return vessels(t.x, t.y) != 0; };
    const auto inside = [&](glm::ivec2 t) { return t.x >= 0 && t.y >= 0 && t.x < w && t.y < h; };
    // The run of pairs (c, c + across) with c's class `low` from c along `step`.
    const auto follow = [&](glm::ivec2 c, glm::ivec2 step, glm::ivec2 across, bool low) {
        RunEnd end;
        for (int k = 1; k <= search; ++k) {
            const glm::ivec2 t = c + k * step;
            if (!inside(t) || !inside(t + across)) {
                return end;
            }
            const bool a = vessel(t);
            const bool b = vessel(t + across);
            if (a == low && b != low) {
                end.length = k;
                continue;
            }
            end.step = a == b ? (a == low ? 1 : -1) : 0;
            return end;
        }
        return end;
    };
    // The pair (c, c + across) straddles a silhouette: its run's offsets.
    const auto rebuild = [&](glm::ivec2 c, glm::ivec2 across, glm::u8vec4& out, int first) {
        const glm::ivec2 along(across.y, across.x);
        const bool low = vessel(c);
        const glm::vec2 offsets =
            runOffsets(follow(c, -along, across, low), follow(c, along, across, low));
        out[first] = encode(offsets.x);
        out[first + 1] = encode(offsets.y);
    };
    for (int y = 0; y < h; ++y) {
        const std::uint8_t* row = vessels.row(y);
        const std::uint8_t* above = y + 1 < h ? vessels.row(y + 1) : nullptr;
        for (int x = 0; x < w; ++x) {
            if (above != nullptr && above[x] != row[x]) {
                rebuild({x, y}, {0, 1}, runs(x, y), 0);  // a flatter edge: its run along x
            }
            if (x + 1 < w && row[x + 1] != row[x]) {
                rebuild({x, y}, {1, 0}, runs(x, y), 2);  // a steeper one: along y
            }
        }
    }
    return runs;
}

std::vector<glm::ivec4> silhouetteRects(const Image<std::uint8_t>& vessels, glm::ivec2 target) {
    const int w = vessels.width();
    const int h = vessels.height();
    if (w <= 0 || h <= 0 || target.x <= 0 || target.y <= 0) {
        throw InvalidArgumentError("silhouetteRects: empty mask or target");
    }
    const glm::dvec2 texelsPerPixel(static_cast<double>(w) / target.x,
                                    static_cast<double>(h) / target.y);
    // The target pixels whose footprint starts at texel i (-1 .. n - 1)
    // along an axis: centre (p + 0.5) * texelsPerPixel - 0.5 in [i, i + 1).
    const auto pixels = [&](int i, int axis) {
        const double scale = texelsPerPixel[axis];
        const auto first = [&](int texel) {
            return static_cast<int>(std::ceil((texel + 0.5) / scale - 0.5));
        };
        return glm::ivec2(first(i), first(i + 1));
    };
    std::vector<glm::ivec4> rects;
    for (int j = -1; j < h; ++j) {
        const std::uint8_t* lower = vessels.row(std::clamp(j, 0, h - 1));
        const std::uint8_t* upper = vessels.row(std::clamp(j + 1, 0, h - 1));
        // Vessel texels in column i of the footprint's two rows, clamped.
        const auto column = [&](int i) {
            const int c = std::clamp(i, 0, w - 1);
            return lower[c] + upper[c];
        };
        const glm::ivec2 ys = pixels(j, 1);
        const int y0 = std::max(ys.x - 1, 0);
        const int y1 = std::min(ys.y + 1, target.y);
        int runStart = 0;
        bool inRun = false;
        for (int i = -1; i <= w; ++i) {
            const int n = i < w ? column(i) + column(i + 1) : 0;
            const bool mixed = n > 0 && n < 4;
            if (mixed && !inRun) {
                runStart = i;
                inRun = true;
            } else if (!mixed && inRun) {
                inRun = false;
                const int x0 = std::max(pixels(runStart, 0).x - 1, 0);
                const int x1 = std::min(pixels(i - 1, 0).y + 1, target.x);
                if (x0 < x1 && y0 < y1) {
                    rects.emplace_back(x0, y0, x1, y1);
                }
            }
        }
    }
    return rects;
}

}  // namespace vv::render
