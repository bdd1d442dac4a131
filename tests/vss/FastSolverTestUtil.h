// SPDX-License-Identifier: GPL-3.0-or-later
// Shared by the fast VSS solver's tests (FastSolverTest.cpp, FastNearBoxTest.cpp):
// seeded scenes with their own labelling and contours, the exact
// double-precision reference, the solve of every region and the comparison.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stop_token>
#include <vector>

#include "FastSolver.h"
#include "VssTestUtil.h"
#include "vv/core/Image.h"
#include "vv/vss/Solver.h"

namespace vv::vss::fasttest {

using test::Rng;  // SplitMix64 (VssTestUtil.h)

/// Labels (4-connected void components), regions with contours (8-adjacent
/// vessel pixels) and the normalised depth of vessel pixels.
struct Scene {
    Image<std::int32_t> labels;
    Image<float> z;
    std::vector<VoidRegion> regions;
};

inline Scene makeScene(const Image<std::uint8_t>& mask, const Image<float>& z) {
    const int w = mask.width();
    const int h = mask.height();
    Scene s;
    s.z = z;
    s.labels = Image<std::int32_t>(w, h, kVesselLabel);
    std::vector<std::pair<int, int>> stack;
    std::int32_t next = 0;
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            if (mask(x, y) != 0 || s.labels(x, y) != kVesselLabel) {
                continue;
            }
            VoidRegion r;
            r.id = next++;
            r.x0 = x;
            r.y0 = y;
            r.x1 = x + 1;
            r.y1 = y + 1;
            s.labels(x, y) = r.id;
            stack.emplace_back(x, y);
            while (!stack.empty()) {
                const auto [cx, cy] = stack.back();
                stack.pop_back();
                ++r.pixelCount;
                r.x0 = std::min(r.x0, cx);
                r.y0 = std::min(r.y0, cy);
                r.x1 = std::max(r.x1, cx + 1);
                r.y1 = std::max(r.y1, cy + 1);
                const int nx[4] = {cx - 1, cx + 1, cx, cx};
                const int ny[4] = {cy, cy, cy - 1, cy + 1};
                for (int k = 0; k < 4; ++k) {
                    if (nx[k] >= 0 && ny[k] >= 0 && nx[k] < w && ny[k] < h &&
                        mask(nx[k], ny[k]) == 0 && s.labels(nx[k], ny[k]) == kVesselLabel) {
                        s.labels(nx[k], ny[k]) = r.id;
                        stack.emplace_back(nx[k], ny[k]);
                    }
                }
            }
            s.regions.push_back(r);
        }
    }
    // contours: vessel pixels 8-adjacent to a region pixel
    Image<std::int32_t> stamp(w, h, -1);
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            const std::int32_t id = s.labels(x, y);
            if (id < 0) {
                continue;
            }
            for (int dy = -1; dy <= 1; ++dy) {
                for (int dx = -1; dx <= 1; ++dx) {
                    const int vx = x + dx;
                    const int vy = y + dy;
                    if (vx < 0 || vy < 0 || vx >= w || vy >= h || mask(vx, vy) == 0) {
                        continue;
                    }
                    // a vessel pixel may border the same region many times: stamp per region
                    if (stamp(vx, vy) == id) {
                        continue;
                    }
                    bool seen = false;
                    for (const ContourPoint& c : s.regions[static_cast<std::size_t>(id)].contour) {
                        if (c.x == vx && c.y == vy) {
                            seen = true;
                            break;
                        }
                    }
                    stamp(vx, vy) = id;
                    if (!seen) {
                        s.regions[static_cast<std::size_t>(id)].contour.push_back(
                            {vx, vy, z(vx, vy)});
                    }
                }
            }
        }
    }
    return s;
}

/// Exact z' in double precision, weights scaled by the nearest distance:
/// `power(q)` is q^(p/2) of the squared ratio q = dmin^2 / d^2.
template <class Power>
double referencePixelWith(const VoidRegion& r, int x, int y, const Power& power) {
    double dmin2 = std::numeric_limits<double>::infinity();
    for (const ContourPoint& c : r.contour) {
        const double dx = x - c.x;
        const double dy = y - c.y;
        dmin2 = std::min(dmin2, dx * dx + dy * dy);
    }
    double D = 0.0;
    double N = 0.0;
    for (const ContourPoint& c : r.contour) {
        const double dx = x - c.x;
        const double dy = y - c.y;
        const double w = power(dmin2 / (dx * dx + dy * dy));
        D += w;
        N += w * c.z;
    }
    return N / D;
}

/// q^n by squaring.
inline double integerPower(double q, unsigned n) {
    double result = 1.0;
    for (; n != 0; n >>= 1U, q *= q) {
        if ((n & 1U) != 0) {
            result *= q;
        }
    }
    return result;
}

/// referencePixelWith for the power p: p = 0.5 and whole p up to 256 (the
/// powers the tests use) by square roots and products, within a few ulps of
/// std::pow and many times faster; any other p by std::pow.
inline double referencePixel(const VoidRegion& r, int x, int y, double p) {
    if (p == 0.5) {
        return referencePixelWith(r, x, y, [](double q) { return std::sqrt(std::sqrt(q)); });
    }
    if (p >= 1.0 && p <= 256.0 && p == std::floor(p)) {
        const auto whole = static_cast<unsigned>(p);
        const unsigned half = whole / 2U;
        if (whole % 2U == 0U) {
            return referencePixelWith(r, x, y, [half](double q) { return integerPower(q, half); });
        }
        return referencePixelWith(
            r, x, y, [half](double q) { return integerPower(q, half) * std::sqrt(q); });
    }
    return referencePixelWith(r, x, y, [p](double q) { return std::pow(q, p / 2.0); });
}

inline Image<double> referenceImage(const Scene& s, double p) {
    Image<double> ref(s.labels.width(), s.labels.height(),
                      std::numeric_limits<double>::quiet_NaN());
    for (const VoidRegion& r : s.regions) {
        if (r.contour.empty()) {
            continue;
        }
        for (int y = r.y0; y < r.y1; ++y) {
            for (int x = r.x0; x < r.x1; ++x) {
                if (s.labels(x, y) == r.id) {
                    ref(x, y) = referencePixel(r, x, y, p);
                }
            }
        }
    }
    return ref;
}

inline Image<float> solveAll(const Scene& s, double p, double tol,
                             const std::stop_token& stop = {}) {
    SolverOptions o;
    o.kind = SolverKind::Fast;
    o.p = p;
    o.tolerance = tol;
    const auto solver = detail::makeFastSolver(o);
    EXPECT_EQ(solver->errorBound(), tol);
    Image<float> out(s.labels.width(), s.labels.height(), -7.0F);
    for (const VoidRegion& r : s.regions) {
        solver->solveRegion(s.labels.view(), r, out.view(), stop);
    }
    return out;
}

struct Check {
    double maxErr = 0.0;
    long bad = 0;  // non-finite or outside the region's contour depth range
    long pixels = 0;
};

inline Check compare(const Scene& s, const Image<float>& out, const Image<double>& ref) {
    Check c;
    for (const VoidRegion& r : s.regions) {
        float lo = std::numeric_limits<float>::infinity();
        float hi = -lo;
        for (const ContourPoint& p : r.contour) {
            lo = std::min(lo, p.z);
            hi = std::max(hi, p.z);
        }
        for (int y = r.y0; y < r.y1; ++y) {
            for (int x = r.x0; x < r.x1; ++x) {
                if (s.labels(x, y) != r.id) {
                    continue;
                }
                ++c.pixels;
                const float v = out(x, y);
                if (r.contour.empty()) {
                    c.bad += std::isnan(v) ? 0 : 1;
                    continue;
                }
                if (!std::isfinite(v) || v < lo || v > hi) {
                    ++c.bad;
                    continue;
                }
                c.maxErr = std::max(c.maxErr, std::abs(static_cast<double>(v) - ref(x, y)));
            }
        }
    }
    return c;
}

inline void paintLine(Image<std::uint8_t>& m, double x0, double y0, double x1, double y1,
                      double rad) {
    const int bx0 = std::max(0, static_cast<int>(std::floor(std::min(x0, x1) - rad)));
    const int bx1 = std::min(m.width() - 1, static_cast<int>(std::ceil(std::max(x0, x1) + rad)));
    const int by0 = std::max(0, static_cast<int>(std::floor(std::min(y0, y1) - rad)));
    const int by1 = std::min(m.height() - 1, static_cast<int>(std::ceil(std::max(y0, y1) + rad)));
    const double vx = x1 - x0;
    const double vy = y1 - y0;
    const double len2 = vx * vx + vy * vy;
    for (int y = by0; y <= by1; ++y) {
        for (int x = bx0; x <= bx1; ++x) {
            double t = len2 > 0 ? ((x - x0) * vx + (y - y0) * vy) / len2 : 0.0;
            t = std::clamp(t, 0.0, 1.0);
            const double dx = x - (x0 + t * vx);
            const double dy = y - (y0 + t * vy);
            if (dx * dx + dy * dy <= rad * rad) {
                m(x, y) = 1;
            }
        }
    }
}

enum class MaskKind { Blobs, Lines, Checker, Tree };

/// Seeded masks and depths: blobs, thick lines, a checkerboard patch, a branching tree.
inline Scene randomScene(int w, int h, MaskKind kind, std::uint64_t seed) {
    Rng rng(seed);
    Image<std::uint8_t> m(w, h, 0);
    switch (kind) {
        case MaskKind::Blobs:
            for (int k = rng.range(3, 8); k > 0; --k) {
                paintLine(m, rng.uniform() * w, rng.uniform() * h, rng.uniform() * w,
                          rng.uniform() * h, 0.0);
                const double cx = rng.uniform() * w;
                const double cy = rng.uniform() * h;
                paintLine(m, cx, cy, cx, cy, 1.0 + rng.uniform() * 6.0);
            }
            break;
        case MaskKind::Lines:
            for (int k = rng.range(2, 6); k > 0; --k) {
                paintLine(m, rng.uniform() * w, rng.uniform() * h, rng.uniform() * w,
                          rng.uniform() * h, 0.5 + rng.uniform() * 2.5);
            }
            break;
        case MaskKind::Checker: {
            const int x0 = rng.range(0, w / 2);
            const int y0 = rng.range(0, h / 2);
            for (int y = y0; y < std::min(h, y0 + h / 2); ++y) {
                for (int x = x0; x < std::min(w, x0 + w / 2); ++x) {
                    m(x, y) = static_cast<std::uint8_t>((x + y) % 2);
                }
            }
            paintLine(m, 0, rng.uniform() * h, w, rng.uniform() * h, 1.0);
            break;
        }
        case MaskKind::Tree: {
            struct Br {
                double x, y, a, r;
                int depth;
            };
            std::vector<Br> todo{{w * 0.5, h * 0.95, -1.5707963, 2.0 + 0.006 * w, 0}};
            while (!todo.empty()) {
                Br b = todo.back();
                todo.pop_back();
                const double len = (0.15 + 0.2 * rng.uniform()) * std::min(w, h);
                const double x1 = b.x + len * std::cos(b.a);
                const double y1 = b.y + len * std::sin(b.a);
                paintLine(m, b.x, b.y, x1, y1, b.r);
                if (b.depth < 5) {
                    todo.push_back(
                        {x1, y1, b.a - 0.3 - 0.5 * rng.uniform(), b.r * 0.75, b.depth + 1});
                    todo.push_back(
                        {x1, y1, b.a + 0.3 + 0.5 * rng.uniform(), b.r * 0.75, b.depth + 1});
                }
            }
            break;
        }
    }
    Image<float> z(w, h, 0.0F);
    const double gx = rng.uniform();
    const double gy = rng.uniform();
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            const double v = 0.5 + 0.35 * std::sin(gx * 12.0 * x / w + gy * 9.0 * y / h) +
                             0.15 * (rng.uniform() - 0.5);
            z(x, y) = static_cast<float>(std::clamp(v, 0.0, 1.0));
        }
    }
    return makeScene(m, z);
}

/// A large void with a few vessel strokes near one corner: most of it is far
/// from every contour point (the coarse boxes of FastCoarse.h). depthRange
/// scales the contour depths (around 0.5): tiny ranges are a stiff case.
inline Scene farFieldScene(int w, int h, double depthRange, bool singleSpeck) {
    Image<std::uint8_t> mask(w, h, 0);
    if (singleSpeck) {
        mask(20, 24) = 1;
        mask(21, 24) = 1;
    } else {
        paintLine(mask, 12.0, 18.0, 70.0, 40.0, 2.5);
        paintLine(mask, 70.0, 40.0, 40.0, 90.0, 1.5);
        paintLine(mask, 70.0, 40.0, 110.0, 30.0, 1.0);
    }
    Image<float> z(w, h, 0.0F);
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            // depth varies fast along the strokes: a rough contour
            const double t = std::sin(0.37 * x) * std::cos(0.23 * y) + 0.002 * (x - y);
            z(x, y) = static_cast<float>(0.5 + 0.5 * depthRange * std::clamp(t, -1.0, 1.0));
        }
    }
    return makeScene(mask, z);
}

}  // namespace vv::vss::fasttest
