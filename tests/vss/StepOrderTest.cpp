// SPDX-License-Identifier: GPL-3.0-or-later
// The step solver's contour order (ContourOrder.h): a permutation that walks
// along the borders, and what it buys against the list's row-major order.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <map>
#include <stop_token>
#include <utility>
#include <vector>

#include "ContourOrder.h"
#include "VssTestUtil.h"
#include "vv/core/Image.h"
#include "vv/vss/Solver.h"
#include "vv/vss/VoidRegions.h"

namespace vv::vss {
namespace {

using detail::ContourOrder;
using detail::orderAlongBorders;

bool adjacent8(const ContourPoint& a, const ContourPoint& b) {
    return std::abs(a.x - b.x) <= 1 && std::abs(a.y - b.y) <= 1;
}

/// The number of consecutive pairs of the order that are not 8-neighbours.
int countBreaks(const std::vector<ContourPoint>& points, const ContourOrder& order) {
    int breaks = 0;
    for (std::size_t j = 1; j < order.index.size(); ++j) {
        breaks += static_cast<int>(!adjacent8(points[order.index[j - 1]], points[order.index[j]]));
    }
    return breaks;
}

/// Checks that the order is a permutation of 0 .. n-1 and that its chains are
/// what ContourOrder promises: 8-connected inside, broken between.
void expectValidOrder(const std::vector<ContourPoint>& points, const ContourOrder& order) {
    ASSERT_EQ(order.index.size(), points.size());
    std::vector<std::uint32_t> sorted = order.index;
    std::sort(sorted.begin(), sorted.end());
    for (std::size_t i = 0; i < sorted.size(); ++i) {
        ASSERT_EQ(sorted[i], i) << "not a permutation";
    }
    if (points.empty()) {
        EXPECT_TRUE(order.chainStart.empty());
        return;
    }
    ASSERT_FALSE(order.chainStart.empty());
    EXPECT_EQ(order.chainStart.front(), 0U);
    std::vector<bool> starts(points.size(), false);
    for (std::size_t c = 0; c < order.chainStart.size(); ++c) {
        ASSERT_LT(order.chainStart[c], points.size());
        if (c > 0) {
            EXPECT_LT(order.chainStart[c - 1], order.chainStart[c]);
        }
        starts[order.chainStart[c]] = true;
    }
    for (std::size_t j = 1; j < order.index.size(); ++j) {
        const bool adj = adjacent8(points[order.index[j - 1]], points[order.index[j]]);
        EXPECT_EQ(adj, !starts[j]) << "at position " << j;
    }
}

/// The boundary of a digital disc: its pixels with a 4-neighbour outside (a
/// closed 8-connected curve), listed row-major, with depth `z`.
std::vector<ContourPoint> discBoundary(int cx, int cy, int r, float z = 0.0F) {
    const auto inside = [&](int x, int y) {
        return (x - cx) * (x - cx) + (y - cy) * (y - cy) <= r * r;
    };
    std::vector<ContourPoint> out;
    for (int y = cy - r; y <= cy + r; ++y) {
        for (int x = cx - r; x <= cx + r; ++x) {
            if (inside(x, y) && (!inside(x + 1, y) || !inside(x - 1, y) || !inside(x, y + 1) ||
                                 !inside(x, y - 1))) {
                out.push_back(ContourPoint{x, y, z});
            }
        }
    }
    return out;
}

std::vector<ContourPoint> rowMajor(std::vector<ContourPoint> points) {
    std::stable_sort(points.begin(), points.end(),
                     [](const ContourPoint& a, const ContourPoint& b) {
                         return a.y != b.y ? a.y < b.y : a.x < b.x;
                     });
    return points;
}

TEST(ContourOrderTest, EmptyAndSinglePoint) {
    const std::vector<ContourPoint> none;
    const ContourOrder o0 = orderAlongBorders(none);
    EXPECT_TRUE(o0.index.empty());
    EXPECT_TRUE(o0.chainStart.empty());
    const std::vector<ContourPoint> one{{7, -3, 0.5F}};
    const ContourOrder o1 = orderAlongBorders(one);
    EXPECT_EQ(o1.index, std::vector<std::uint32_t>{0});
    EXPECT_EQ(o1.chainStart, std::vector<std::uint32_t>{0});
}

TEST(ContourOrderTest, OneRingIsOneUnbrokenChain) {
    for (int r = 1; r <= 40; ++r) {
        const std::vector<ContourPoint> ring = discBoundary(50, 60, r);
        const ContourOrder order = orderAlongBorders(ring);
        expectValidOrder(ring, order);
        EXPECT_EQ(order.chainStart.size(), 1U) << "radius " << r;
        EXPECT_EQ(countBreaks(ring, order), 0) << "radius " << r;
        // Closed: the walk ends next to where it started (r >= 2: a real ring).
        if (r >= 2) {
            EXPECT_TRUE(adjacent8(ring[order.index.front()], ring[order.index.back()]))
                << "radius " << r;
        }
    }
}

TEST(ContourOrderTest, RectangleRingIsOneChainAlongTheSides) {
    // A 10 x 6 rectangle's outline, row-major.
    std::vector<ContourPoint> ring;
    for (int y = 0; y < 6; ++y) {
        for (int x = 0; x < 10; ++x) {
            if (y == 0 || y == 5 || x == 0 || x == 9) {
                ring.push_back(ContourPoint{x, y, 0.0F});
            }
        }
    }
    const ContourOrder order = orderAlongBorders(ring);
    expectValidOrder(ring, order);
    EXPECT_EQ(countBreaks(ring, order), 0);
    // Every step is a 4-step: the walk never cuts a corner.
    for (std::size_t j = 1; j < order.index.size(); ++j) {
        const ContourPoint& a = ring[order.index[j - 1]];
        const ContourPoint& b = ring[order.index[j]];
        EXPECT_EQ(std::abs(a.x - b.x) + std::abs(a.y - b.y), 1) << j;
    }
}

TEST(ContourOrderTest, SeparateRingsGiveOneChainEach) {
    for (int k = 1; k <= 6; ++k) {
        std::vector<ContourPoint> points;
        for (int i = 0; i < k; ++i) {
            // Side by side and overlapping in rows, so row-major interleaves them.
            const std::vector<ContourPoint> ring = discBoundary(10 + 25 * i, 20 + 3 * i, 8 + i);
            points.insert(points.end(), ring.begin(), ring.end());
        }
        points = rowMajor(points);
        const ContourOrder order = orderAlongBorders(points);
        expectValidOrder(points, order);
        EXPECT_EQ(order.chainStart.size(), static_cast<std::size_t>(k));
        EXPECT_EQ(countBreaks(points, order), k - 1) << k << " rings";
        // The row-major list itself jumps between the rings on every row.
        if (k >= 2) {
            ContourOrder identity;
            for (std::uint32_t i = 0; i < points.size(); ++i) {
                identity.index.push_back(i);
            }
            EXPECT_GT(countBreaks(points, identity), 10 * (k - 1));
        }
    }
}

TEST(ContourOrderTest, OpenArcEnteredInTheMiddleIsOneChain) {
    // The upper half of a ring (a "∩"): row-major starts at its top, in the
    // middle of the curve; the backward extension must still make one chain.
    std::vector<ContourPoint> arc;
    for (const ContourPoint& q : discBoundary(30, 30, 12)) {
        if (q.y <= 30) {
            arc.push_back(q);
        }
    }
    const ContourOrder order = orderAlongBorders(arc);
    expectValidOrder(arc, order);
    EXPECT_EQ(order.chainStart.size(), 1U);
    EXPECT_EQ(countBreaks(arc, order), 0);
    // It runs from one foot of the arc to the other.
    const ContourPoint& a = arc[order.index.front()];
    const ContourPoint& b = arc[order.index.back()];
    EXPECT_EQ(a.y, 30);
    EXPECT_EQ(b.y, 30);
    EXPECT_NE(a.x, b.x);
}

TEST(ContourOrderTest, DuplicatesAreKeptAndInputOrderDoesNotMatter) {
    std::vector<ContourPoint> ring = discBoundary(0, 0, 9);
    // Depth tags the input position; list three pixels twice more.
    for (std::size_t i = 0; i < ring.size(); ++i) {
        ring[i].z = static_cast<float>(i);
    }
    const std::vector<ContourPoint> base = ring;
    ring.push_back(ContourPoint{base[3].x, base[3].y, 1000.0F});
    ring.push_back(ContourPoint{base[3].x, base[3].y, 1001.0F});
    ring.push_back(ContourPoint{base[10].x, base[10].y, 1002.0F});
    const ContourOrder order = orderAlongBorders(ring);
    expectValidOrder(ring, order);
    EXPECT_EQ(countBreaks(ring, order), 0);
    // The same multiset of (x, y, z).
    std::multimap<std::pair<int, int>, float> in;
    std::multimap<std::pair<int, int>, float> out;
    for (const ContourPoint& q : ring) {
        in.emplace(std::pair{q.x, q.y}, q.z);
    }
    for (const std::uint32_t i : order.index) {
        out.emplace(std::pair{ring[i].x, ring[i].y}, ring[i].z);
    }
    EXPECT_EQ(in, out);

    // A shuffled input gives the same walk over the pixels.
    std::vector<ContourPoint> shuffled = base;
    test::Rng rng(7);
    for (std::size_t i = shuffled.size() - 1; i > 0; --i) {
        std::swap(shuffled[i], shuffled[rng.next() % (i + 1)]);
    }
    const ContourOrder a = orderAlongBorders(base);
    const ContourOrder b = orderAlongBorders(shuffled);
    ASSERT_EQ(a.index.size(), b.index.size());
    for (std::size_t j = 0; j < a.index.size(); ++j) {
        EXPECT_EQ(base[a.index[j]].x, shuffled[b.index[j]].x) << j;
        EXPECT_EQ(base[a.index[j]].y, shuffled[b.index[j]].y) << j;
    }
}

TEST(ContourOrderTest, RealContoursOfRandomMasks) {
    // The contours findVoidRegions makes: always a valid order, and far fewer
    // jumps than the row-major list.
    std::size_t breaks = 0;
    std::size_t rowMajorBreaks = 0;
    for (std::uint64_t seed = 1; seed <= 40; ++seed) {
        const Image<std::uint8_t> mask = test::randomMask(90, 70, seed);
        const VoidRegionSet set = findVoidRegions(mask.view());
        for (const VoidRegion& r : set.regions) {
            const ContourOrder order = orderAlongBorders(r.contour);
            expectValidOrder(r.contour, order);
            breaks += static_cast<std::size_t>(countBreaks(r.contour, order));
            ContourOrder identity;
            for (std::uint32_t i = 0; i < r.contour.size(); ++i) {
                identity.index.push_back(i);
            }
            rowMajorBreaks += static_cast<std::size_t>(countBreaks(r.contour, identity));
        }
    }
    EXPECT_GT(rowMajorBreaks, 0U);
    EXPECT_LT(breaks * 4, rowMajorBreaks) << breaks << " against " << rowMajorBreaks;
}

TEST(ContourOrderTest, AnnulusInnerContourIsOneChain) {
    // A thick vessel ring: the enclosed void's contour is the ring's inner
    // boundary (8-adjacent vessel pixels, 4-connected at the corners).
    for (int r = 4; r <= 30; r += 2) {
        const int size = 2 * r + 12;
        const int c = size / 2;
        Image<std::uint8_t> mask(size, size, 0);
        for (int y = 0; y < size; ++y) {
            for (int x = 0; x < size; ++x) {
                const int d2 = (x - c) * (x - c) + (y - c) * (y - c);
                mask(x, y) = static_cast<std::uint8_t>(d2 >= r * r && d2 <= (r + 3) * (r + 3));
            }
        }
        const VoidRegionSet set = findVoidRegions(mask.view());
        const std::int32_t inner = set.labels(c, c);
        ASSERT_GE(inner, 0);
        const auto& contour = set.regions[static_cast<std::size_t>(inner)].contour;
        const ContourOrder order = orderAlongBorders(contour);
        expectValidOrder(contour, order);
        EXPECT_EQ(order.chainStart.size(), 1U) << "radius " << r;
    }
}

// ---------------------------------------------------------------------------
// The step solver on two parallel vertical vessels: left a 1 px line at z = 0,
// right a 3 px wide bar at z = 1, one void region around and between them.
// Its row-major contour lists per row (10, y), (30, y), (32, y): every 3rd
// entry is then always the same wall.

struct TwoVessels {
    Image<std::uint8_t> mask{64, 64, 0};
    Image<float> z{64, 64, 0.0F};
    VoidRegionSet set;

    TwoVessels() {
        for (int y = 5; y <= 58; ++y) {
            mask(10, y) = 1;
            for (int x = 30; x <= 32; ++x) {
                mask(x, y) = 1;
                z(x, y) = 1.0F;
            }
        }
        set = findVoidRegions(mask.view(), z.view());
    }
};

Image<float> solveWith(const TwoVessels& s, SolverKind kind, int step) {
    SolverOptions options;
    options.kind = kind;
    options.p = 2.0;
    options.step = step;
    const auto solver = makeSolver(options);
    Image<float> out(64, 64, std::numeric_limits<float>::quiet_NaN());
    for (const VoidRegion& r : s.set.regions) {
        solver->solveRegion(s.set.labels.view(), r, out.view(), std::stop_token{});
    }
    return out;
}

/// Plain double IDW (p = 2) over every k-th point of the list as given.
Image<float> idwEveryKth(const TwoVessels& s, int k) {
    Image<float> out(64, 64, std::numeric_limits<float>::quiet_NaN());
    for (const VoidRegion& r : s.set.regions) {
        for (int y = 0; y < 64; ++y) {
            for (int x = 0; x < 64; ++x) {
                if (s.set.labels(x, y) != r.id) {
                    continue;
                }
                double sw = 0.0;
                double swz = 0.0;
                for (std::size_t i = 0; i < r.contour.size(); i += static_cast<std::size_t>(k)) {
                    const double dx = r.contour[i].x - x;
                    const double dy = r.contour[i].y - y;
                    const double w = 1.0 / (dx * dx + dy * dy);
                    sw += w;
                    swz += w * r.contour[i].z;
                }
                out(x, y) = static_cast<float>(swz / sw);
            }
        }
    }
    return out;
}

/// The max abs difference over the void pixels of rows [y0, y1).
double maxError(const TwoVessels& s, const Image<float>& a, const Image<float>& b, int y0 = 0,
                int y1 = 64) {
    double m = 0.0;
    for (int y = y0; y < y1; ++y) {
        for (int x = 0; x < 64; ++x) {
            if (s.set.labels(x, y) >= 0) {
                EXPECT_TRUE(std::isfinite(a(x, y)) && std::isfinite(b(x, y))) << x << ", " << y;
                m = std::max(m, std::abs(static_cast<double>(a(x, y)) - b(x, y)));
            }
        }
    }
    return m;
}

TEST(StepSolverOrderTest, BorderOrderSamplesEveryWallOfTwoParallelVessels) {
    const TwoVessels s;
    ASSERT_EQ(s.set.regions.size(), 1U);
    const auto& contour = s.set.regions[0].contour;
    // The precondition of the scenario: the raw list is row-major.
    EXPECT_EQ(rowMajor(contour).size(), contour.size());
    for (std::size_t i = 1; i < contour.size(); ++i) {
        ASSERT_TRUE(contour[i - 1].y < contour[i].y ||
                    (contour[i - 1].y == contour[i].y && contour[i - 1].x < contour[i].x));
    }

    const Image<float> reference = solveWith(s, SolverKind::Reference, 1);
    // The test's own IDW agrees with the reference on the full list.
    EXPECT_LT(maxError(s, idwEveryKth(s, 1), reference), 1e-5);

    const Image<float> rowMajorStep3 = idwEveryKth(s, 3);
    const Image<float> step3 = solveWith(s, SolverKind::Step, 3);
    const double rowMajorError = maxError(s, rowMajorStep3, reference);
    const double stepError = maxError(s, step3, reference);
    // Along the vessels, away from their ends (rows 5 and 58): an evenly
    // sampled wall is nearly as good as the whole wall.
    const double rowMajorAlong = maxError(s, rowMajorStep3, reference, 12, 52);
    const double stepAlong = maxError(s, step3, reference, 12, 52);
    const double step1Error = maxError(s, solveWith(s, SolverKind::Step, 1), reference);
    RecordProperty("row_major_step3_max_error", std::to_string(rowMajorError));
    RecordProperty("border_step3_max_error", std::to_string(stepError));
    RecordProperty("row_major_step3_max_error_along", std::to_string(rowMajorAlong));
    RecordProperty("border_step3_max_error_along", std::to_string(stepAlong));
    EXPECT_LT(step1Error, 1e-5);
    // Row-major, every 3rd contour pixel is always on the bar's right wall: the
    // line (z = 0) is dropped entirely, and z' next to it is about 1.
    EXPECT_GT(rowMajorError, 0.5) << "border order: " << stepError;
    EXPECT_GT(rowMajorAlong, 0.5) << "border order: " << stepAlong;
    // Border order: a small error along the vessels; the largest one is beyond
    // the line's lower end, whose last pixels are skipped (measured: 0.11).
    EXPECT_LT(stepAlong, 0.03) << "row-major: " << rowMajorAlong;
    EXPECT_LT(stepError, 0.15) << "row-major: " << rowMajorError;
}

TEST(StepSolverOrderTest, KeepsAtLeastOnePointPerRegion) {
    // One vessel pixel: a contour of 1 point, step 5 still uses it.
    Image<std::uint8_t> mask(9, 7, 0);
    Image<float> z(9, 7, 0.0F);
    mask(4, 3) = 1;
    z(4, 3) = 0.25F;
    const VoidRegionSet set = findVoidRegions(mask.view(), z.view());
    ASSERT_EQ(set.regions.size(), 1U);
    SolverOptions options;
    options.kind = SolverKind::Step;
    options.step = 5;
    Image<float> out(9, 7, -1.0F);
    makeSolver(options)->solveRegion(set.labels.view(), set.regions[0], out.view(),
                                     std::stop_token{});
    for (int y = 0; y < 7; ++y) {
        for (int x = 0; x < 9; ++x) {
            EXPECT_EQ(out(x, y), mask(x, y) != 0 ? -1.0F : 0.25F) << x << ", " << y;
        }
    }
}

}  // namespace
}  // namespace vv::vss
