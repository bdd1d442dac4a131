// SPDX-License-Identifier: GPL-3.0-or-later
// Helpers for the vss tests: a seeded PRNG, mask makers, independent
// implementations of the definitions (VSS.md) to check the library against.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <queue>
#include <set>
#include <utility>
#include <vector>

#include "vv/core/Image.h"
#include "vv/vss/Solver.h"

namespace vv::vss::test {

/// SplitMix64: small, seeded, the same on every platform.
class Rng {
  public:
    explicit Rng(std::uint64_t seed) : state_(seed) {}
    std::uint64_t next() {
        std::uint64_t z = (state_ += 0x9e3779b97f4a7c15ULL);
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
        return z ^ (z >> 31);
    }
    /// Uniform in [0, 1).
    double uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }
    /// Uniform integer in [lo, hi].
    int range(int lo, int hi) {
        return lo + static_cast<int>(next() % static_cast<std::uint64_t>(hi - lo + 1));
    }

  private:
    std::uint64_t state_;
};

/// A random vessel-like mask: a few thick random line segments and discs.
inline Image<std::uint8_t> randomMask(int w, int h, std::uint64_t seed) {
    Rng rng(seed);
    Image<std::uint8_t> mask(w, h, 0);
    const int lines = rng.range(2, 6);
    for (int k = 0; k < lines; ++k) {
        const double x0 = rng.uniform() * w;
        const double y0 = rng.uniform() * h;
        const double x1 = rng.uniform() * w;
        const double y1 = rng.uniform() * h;
        const double r = 0.5 + rng.uniform() * 2.0;
        for (int y = 0; y < h; ++y) {
            for (int x = 0; x < w; ++x) {
                const double vx = x1 - x0;
                const double vy = y1 - y0;
                const double len2 = vx * vx + vy * vy;
                double t = len2 > 0 ? ((x - x0) * vx + (y - y0) * vy) / len2 : 0.0;
                t = std::clamp(t, 0.0, 1.0);
                const double dx = x - (x0 + t * vx);
                const double dy = y - (y0 + t * vy);
                if (dx * dx + dy * dy <= r * r) {
                    mask(x, y) = 1;
                }
            }
        }
    }
    const int discs = rng.range(0, 4);
    for (int k = 0; k < discs; ++k) {
        const int cx = rng.range(0, w - 1);
        const int cy = rng.range(0, h - 1);
        const int r = rng.range(1, 5);
        for (int y = std::max(0, cy - r); y <= std::min(h - 1, cy + r); ++y) {
            for (int x = std::max(0, cx - r); x <= std::min(w - 1, cx + r); ++x) {
                if ((x - cx) * (x - cx) + (y - cy) * (y - cy) <= r * r) {
                    mask(x, y) = 1;
                }
            }
        }
    }
    return mask;
}

/// Random depth in [near, far] (smooth plus noise), for every pixel.
inline Image<float> randomDepth(int w, int h, std::uint64_t seed, double near = 10.0,
                                double far = 50.0) {
    Rng rng(seed ^ 0x5eedULL);
    const double a = rng.uniform() * 0.3;
    const double b = rng.uniform() * 0.3;
    Image<float> depth(w, h);
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            const double s = 0.5 + 0.35 * std::sin(a * x + 1.3) * std::cos(b * y + 0.4) +
                             0.15 * (rng.uniform() - 0.5);
            depth(x, y) = static_cast<float>(near + (far - near) * std::clamp(s, 0.0, 1.0));
        }
    }
    return depth;
}

/// Independent labelling: BFS over 4-connected background, ids in raster order
/// of the first pixel; contour sets by brute force.
struct NaiveRegions {
    Image<std::int32_t> labels;
    std::vector<std::set<std::pair<int, int>>> contours;  // (y, x)
    std::vector<std::int64_t> counts;
};

inline NaiveRegions naiveRegions(ImageView<const std::uint8_t> mask) {
    const int w = mask.width();
    const int h = mask.height();
    NaiveRegions r;
    r.labels = Image<std::int32_t>(w, h, -2);
    std::int32_t next = 0;
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            if (mask(x, y) != 0) {
                r.labels(x, y) = kVesselLabel;
                continue;
            }
            if (r.labels(x, y) != -2) {
                continue;
            }
            const std::int32_t id = next++;
            r.contours.emplace_back();
            r.counts.push_back(0);
            std::queue<std::pair<int, int>> queue;
            queue.emplace(x, y);
            r.labels(x, y) = id;
            while (!queue.empty()) {
                const auto [px, py] = queue.front();
                queue.pop();
                ++r.counts.back();
                const int nx[4] = {px - 1, px + 1, px, px};
                const int ny[4] = {py, py, py - 1, py + 1};
                for (int k = 0; k < 4; ++k) {
                    if (nx[k] < 0 || ny[k] < 0 || nx[k] >= w || ny[k] >= h) {
                        continue;
                    }
                    if (mask(nx[k], ny[k]) == 0 && r.labels(nx[k], ny[k]) == -2) {
                        r.labels(nx[k], ny[k]) = id;
                        queue.emplace(nx[k], ny[k]);
                    }
                }
                for (int dy = -1; dy <= 1; ++dy) {
                    for (int dx = -1; dx <= 1; ++dx) {
                        const int qx = px + dx;
                        const int qy = py + dy;
                        if (qx >= 0 && qy >= 0 && qx < w && qy < h && mask(qx, qy) != 0) {
                            r.contours.back().emplace(qy, qx);
                        }
                    }
                }
            }
        }
    }
    return r;
}

/// z'(x, y) straight from the definition, w_i = (dmin/d_i)^p in type Real.
template <typename Real = long double>
double idw(const std::vector<ContourPoint>& contour, int x, int y, double p) {
    Real dmin2 = std::numeric_limits<Real>::infinity();
    for (const auto& c : contour) {
        const Real dx = c.x - x;
        const Real dy = c.y - y;
        dmin2 = std::min(dmin2, dx * dx + dy * dy);
    }
    Real sw = 0;
    Real swz = 0;
    for (const auto& c : contour) {
        const Real dx = c.x - x;
        const Real dy = c.y - y;
        const Real w = std::pow(dmin2 / (dx * dx + dy * dy), static_cast<Real>(p) / 2);
        sw += w;
        swz += w * c.z;
    }
    return static_cast<double>(swz / sw);
}

}  // namespace vv::vss::test
