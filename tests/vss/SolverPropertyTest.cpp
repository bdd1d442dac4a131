// SPDX-License-Identifier: GPL-3.0-or-later
// The properties of VSS.md, asserted for every solver: reference, brute,
// step with k = 1 (equal to brute) and fast (skipped while it is not built).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <ostream>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "VssTestUtil.h"
#include "vv/core/Error.h"
#include "vv/vss/Solver.h"
#include "vv/vss/Vss.h"

namespace vv::vss {
namespace {

using test::Rng;

struct SolverCase {
    const char* name;
    SolverKind kind;
    int step;
};

// Readable parameter values in test listings (and so in ctest's test names).
void PrintTo(const SolverCase& solverCase, std::ostream* os) {
    *os << solverCase.name;
}

const SolverCase kSolvers[] = {
    {"reference", SolverKind::Reference, 1},
    {"brute", SolverKind::Brute, 1},
    {"step1", SolverKind::Step, 1},
    {"fast", SolverKind::Fast, 3},
};

const double kPowers[] = {0.25, 0.5, 1.0, 2.0, 4.0, 8.0, 16.0, 32.0, 64.0};

/// The solver of case `c` for the power `p`.
std::unique_ptr<Solver> solverFor(const SolverCase& c, double p) {
    SolverOptions options;
    options.kind = c.kind;
    options.p = p;
    options.step = c.step;
    return makeSolver(options);
}

/// Allowed difference from the exact answer.
double tolerance(const SolverCase& c, const Solver& solver) {
    switch (c.kind) {
        case SolverKind::Reference:
            return 2e-6;  // double, rounded to float
        case SolverKind::Brute:
        case SolverKind::Step:
            return 5e-6;  // measured: below 1e-6 on random masks for p = 0.25 ... 100
        case SolverKind::Fast:
            return solver.errorBound() + 1e-5;
    }
    return 0.0;
}

VssResult run(const Solver& solver, const Image<float>& depth, const Image<std::uint8_t>& mask,
              const DepthRange& range = {}) {
    return solve(depth.view(), mask.view(), solver, range);
}

/// Asserts no NaN / Inf on void pixels with a contour and the maximum principle
/// per region; NaN on void pixels of a region without contour.
void expectBoundedAndFinite(const VssResult& r, const std::string& what) {
    std::vector<float> lo(r.regions.size(), std::numeric_limits<float>::infinity());
    std::vector<float> hi(r.regions.size(), -std::numeric_limits<float>::infinity());
    for (const auto& region : r.regions) {
        for (const auto& c : region.contour) {
            lo[static_cast<std::size_t>(region.id)] =
                std::min(lo[static_cast<std::size_t>(region.id)], c.z);
            hi[static_cast<std::size_t>(region.id)] =
                std::max(hi[static_cast<std::size_t>(region.id)], c.z);
        }
    }
    int failures = 0;
    for (int y = 0; y < r.labels.height(); ++y) {
        for (int x = 0; x < r.labels.width(); ++x) {
            const std::int32_t id = r.labels(x, y);
            const float v = r.height(x, y);
            if (id == kVesselLabel) {
                if (!(v >= 0.0F && v <= 1.0F) && failures++ < 5) {
                    ADD_FAILURE() << what << ": vessel pixel (" << x << ", " << y << ") z = " << v;
                }
                continue;
            }
            const auto i = static_cast<std::size_t>(id);
            if (r.regions[i].contour.empty()) {
                if (!std::isnan(v) && failures++ < 5) {
                    ADD_FAILURE() << what << ": (" << x << ", " << y << ") has no VSS but " << v;
                }
                continue;
            }
            if (!(std::isfinite(v) && v >= lo[i] && v <= hi[i]) && failures++ < 5) {
                ADD_FAILURE() << what << ": z'(" << x << ", " << y << ") = " << v
                              << " outside the contour range [" << lo[i] << ", " << hi[i]
                              << "] of region " << id;
            }
        }
    }
}

void expectNear(const Image<float>& a, const Image<float>& b, double tol, const std::string& what) {
    ASSERT_EQ(a.width(), b.width());
    ASSERT_EQ(a.height(), b.height());
    double worst = 0.0;
    int wx = -1;
    int wy = -1;
    for (int y = 0; y < a.height(); ++y) {
        for (int x = 0; x < a.width(); ++x) {
            if (std::isnan(a(x, y)) != std::isnan(b(x, y))) {
                ADD_FAILURE() << what << ": NaN at (" << x << ", " << y << ") in one only";
                return;
            }
            if (std::isnan(a(x, y))) {
                continue;
            }
            const double d = std::abs(static_cast<double>(a(x, y)) - b(x, y));
            if (d > worst) {
                worst = d;
                wx = x;
                wy = y;
            }
        }
    }
    EXPECT_LE(worst, tol) << what << ": worst at (" << wx << ", " << wy << ")";
}

/// The reference result of random mask `seed` at power p, computed once.
const VssResult& referenceFor(std::uint64_t seed, double p, const Image<float>& depth,
                              const Image<std::uint8_t>& mask) {
    static std::map<std::pair<std::uint64_t, double>, VssResult> cache;
    const auto key = std::make_pair(seed, p);
    auto it = cache.find(key);
    if (it == cache.end()) {
        SolverOptions options;
        options.kind = SolverKind::Reference;
        options.p = p;
        it = cache.emplace(key, run(*makeSolver(options), depth, mask)).first;
    }
    return it->second;
}

std::string caseName(const SolverCase& c) {
    return c.name;
}

// ---------------------------------------------------------------------------
// Per solver and per p.

class SolverPowerTest : public ::testing::TestWithParam<std::tuple<SolverCase, double>> {
  protected:
    [[nodiscard]] const SolverCase& solverCase() const { return std::get<0>(GetParam()); }
    [[nodiscard]] double p() const { return std::get<1>(GetParam()); }
};

TEST_P(SolverPowerTest, RandomMasksBoundedAndNearReference) {
    const auto solver = solverFor(solverCase(), p());
    // Four of the twenty random masks per p (all twenty: SolverTest.TwentyRandomMasks).
    const auto pIndex = static_cast<std::uint64_t>(std::log2(p()) + 2.0);
    for (std::uint64_t k = 0; k < 4; ++k) {
        const std::uint64_t seed = 1000 + (pIndex * 4 + k) % 20;
        const auto mask = test::randomMask(64, 48, seed);
        const auto depth = test::randomDepth(64, 48, seed);
        const VssResult r = run(*solver, depth, mask);
        const std::string what = std::string(solverCase().name) + " seed " + std::to_string(seed);
        expectBoundedAndFinite(r, what);
        if (solverCase().kind == SolverKind::Reference) {
            // Against the definition, evaluated independently in long double.
            for (int y = 0; y < 48; y += 3) {
                for (int x = (y / 3) % 5; x < 64; x += 5) {
                    const std::int32_t id = r.labels(x, y);
                    if (id == kVesselLabel) {
                        continue;
                    }
                    const auto& contour = r.regions[static_cast<std::size_t>(id)].contour;
                    ASSERT_FALSE(contour.empty());
                    EXPECT_NEAR(r.height(x, y), test::idw(contour, x, y, p()), 2e-6)
                        << what << " at (" << x << ", " << y << ")";
                }
            }
        } else {
            expectNear(r.height, referenceFor(seed, p(), depth, mask).height,
                       tolerance(solverCase(), *solver), what);
        }
    }
}

TEST_P(SolverPowerTest, RegionOfOnePixel) {
    const auto solver = solverFor(solverCase(), p());
    // A void pixel in a ring of 8 vessel pixels with different depths.
    Image<std::uint8_t> mask(3, 3, 1);
    mask(1, 1) = 0;
    Image<float> depth(3, 3);
    for (int y = 0; y < 3; ++y) {
        for (int x = 0; x < 3; ++x) {
            depth(x, y) = static_cast<float>(10 + 3 * y + x);
        }
    }
    depth(1, 1) = 0.0F;  // ignored: background
    const VssResult r = run(*solver, depth, mask, {RangeMode::Fixed, 0.0, 20.0});
    ASSERT_EQ(r.regions.size(), 1U);
    ASSERT_EQ(r.regions[0].contour.size(), 8U);
    // Edge neighbours at distance 1 (weight 1), corners at sqrt 2 (weight 2^-p/2).
    const double wc = std::pow(2.0, -p() / 2);
    double sw = 0.0;
    double swz = 0.0;
    for (int y = 0; y < 3; ++y) {
        for (int x = 0; x < 3; ++x) {
            if (x == 1 && y == 1) {
                continue;
            }
            const double w = (x == 1 || y == 1) ? 1.0 : wc;
            sw += w;
            swz += w * (10 + 3 * y + x) / 20.0;
        }
    }
    EXPECT_NEAR(r.height(1, 1), swz / sw, tolerance(solverCase(), *solver));
}

TEST_P(SolverPowerTest, OneByNAndNByOne) {
    const auto solver = solverFor(solverCase(), p());
    for (const bool transposed : {false, true}) {
        const int n = 41;
        Image<std::uint8_t> mask(transposed ? 1 : n, transposed ? n : 1, 0);
        Image<float> depth(mask.width(), mask.height(), 0.0F);
        const auto set = [&](int i, float d) {
            (transposed ? mask(0, i) : mask(i, 0)) = 1;
            (transposed ? depth(0, i) : depth(i, 0)) = d;
        };
        set(5, 1.0F);
        set(30, 3.0F);
        const VssResult r = run(*solver, depth, mask);
        // Three regions: [0, 5), (5, 30), (30, n). The outer ones see one pixel.
        ASSERT_EQ(r.regions.size(), 3U);
        expectBoundedAndFinite(r, "1xN");
        const auto at = [&](int i) { return transposed ? r.height(0, i) : r.height(i, 0); };
        EXPECT_FLOAT_EQ(at(0), 0.0F);
        EXPECT_FLOAT_EQ(at(40), 1.0F);
        for (int i = 6; i < 30; ++i) {
            const double a = 1.0 / std::pow(i - 5, p());
            const double b = 1.0 / std::pow(30 - i, p());
            EXPECT_NEAR(at(i), b / (a + b), tolerance(solverCase(), *solver)) << i;
        }
    }
}

TEST_P(SolverPowerTest, SingleVesselPixelAndConstantDepth) {
    const auto solver = solverFor(solverCase(), p());
    {
        Image<std::uint8_t> mask(23, 17, 0);
        mask(4, 9) = 1;
        const Image<float> depth(23, 17, 7.0F);
        const VssResult r = run(*solver, depth, mask, {RangeMode::Fixed, 5.0, 9.0});
        ASSERT_EQ(r.regions.size(), 1U);
        ASSERT_EQ(r.regions[0].contour.size(), 1U);
        for (int y = 0; y < 17; ++y) {
            for (int x = 0; x < 23; ++x) {
                ASSERT_NEAR(r.height(x, y), 0.5F, 1e-6) << x << ", " << y;
            }
        }
    }
    {
        // Constant depth, visible range: flat scene, z = 0 and z' = 0.
        const auto mask = test::randomMask(40, 30, 77);
        const Image<float> depth(40, 30, 123.0F);
        const VssResult r = run(*solver, depth, mask);
        EXPECT_TRUE(r.flat);
        for (int y = 0; y < 30; ++y) {
            for (int x = 0; x < 40; ++x) {
                ASSERT_EQ(r.height(x, y), 0.0F) << x << ", " << y;
            }
        }
    }
}

TEST_P(SolverPowerTest, FarNearRatio1e7) {
    const auto solver = solverFor(solverCase(), p());
    const auto mask = test::randomMask(48, 40, 4242);
    Image<float> depth(48, 40);
    for (int y = 0; y < 40; ++y) {
        for (int x = 0; x < 48; ++x) {
            depth(x, y) = (x + y) % 3 == 0 ? 1e-3F : ((x * y) % 5 == 0 ? 1e4F : 1.0F);
        }
    }
    const VssResult r = run(*solver, depth, mask);
    EXPECT_FLOAT_EQ(static_cast<float>(r.dmax / r.dmin), 1e7F);
    expectBoundedAndFinite(r, "far/near 1e7");
    if (solverCase().kind != SolverKind::Reference) {
        SolverOptions options;
        options.kind = SolverKind::Reference;
        options.p = p();
        expectNear(r.height, run(*makeSolver(options), depth, mask).height,
                   tolerance(solverCase(), *solver), "far/near 1e7");
    }
}

TEST_P(SolverPowerTest, CheckerboardIsTheMeanOfTheEdgeNeighbours) {
    const auto solver = solverFor(solverCase(), p());
    const int w = 16;
    const int h = 12;
    Image<std::uint8_t> mask(w, h, 0);
    Image<float> depth(w, h, 0.0F);
    Rng rng(99);
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            mask(x, y) = (x + y) % 2;
            depth(x, y) = static_cast<float>(rng.uniform());
        }
    }
    const VssResult r = run(*solver, depth, mask, {RangeMode::Fixed, 0.0, 1.0});
    EXPECT_EQ(r.regions.size(), static_cast<std::size_t>(w * h / 2));
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            if (mask(x, y) != 0) {
                continue;
            }
            // Every vessel neighbour of a void pixel is an edge neighbour at distance 1.
            double sum = 0.0;
            int n = 0;
            const int dx[4] = {-1, 1, 0, 0};
            const int dy[4] = {0, 0, -1, 1};
            for (int k = 0; k < 4; ++k) {
                const int qx = x + dx[k];
                const int qy = y + dy[k];
                if (qx >= 0 && qy >= 0 && qx < w && qy < h) {
                    sum += depth(qx, qy);
                    ++n;
                }
            }
            ASSERT_NEAR(r.height(x, y), sum / n, tolerance(solverCase(), *solver))
                << x << ", " << y;
        }
    }
}

TEST_P(SolverPowerTest, ContourTouchingTheBorder) {
    const auto solver = solverFor(solverCase(), p());
    // A vessel crossing the image top to bottom and one entering from the left.
    const int w = 50;
    const int h = 30;
    Image<std::uint8_t> mask(w, h, 0);
    Image<float> depth(w, h, 0.0F);
    for (int y = 0; y < h; ++y) {
        for (int x = 20 + y / 6; x < 23 + y / 6; ++x) {
            mask(x, y) = 1;
            depth(x, y) = static_cast<float>(5 + y);
        }
    }
    for (int x = 0; x < 23; ++x) {  // reaches the first vessel: splits its left side
        mask(x, 14) = 1;
        depth(x, 14) = static_cast<float>(60 - x);
    }
    const VssResult r = run(*solver, depth, mask);
    ASSERT_EQ(r.regions.size(), 3U);
    expectBoundedAndFinite(r, "border");
    SolverOptions options;
    options.kind = SolverKind::Reference;
    options.p = p();
    if (solverCase().kind != SolverKind::Reference) {
        expectNear(r.height, run(*makeSolver(options), depth, mask).height,
                   tolerance(solverCase(), *solver), "border");
    }
}

TEST_P(SolverPowerTest, FullAndEmptyMaskAndOneByOne) {
    const auto solver = solverFor(solverCase(), p());
    {
        const Image<std::uint8_t> mask(9, 5, 1);
        const auto depth = test::randomDepth(9, 5, 3);
        const VssResult r = run(*solver, depth, mask);
        EXPECT_TRUE(r.regions.empty());
        expectBoundedAndFinite(r, "full mask");
    }
    {
        const Image<std::uint8_t> mask(9, 5, 0);
        const auto depth = test::randomDepth(9, 5, 3);
        const VssResult r = run(*solver, depth, mask);
        ASSERT_EQ(r.regions.size(), 1U);
        EXPECT_TRUE(r.regions[0].contour.empty());
        for (int y = 0; y < 5; ++y) {
            for (int x = 0; x < 9; ++x) {
                EXPECT_TRUE(std::isnan(r.height(x, y)));
            }
        }
    }
    for (const std::uint8_t m : {0, 1}) {
        const Image<std::uint8_t> mask(1, 1, m);
        const Image<float> depth(1, 1, 3.5F);
        const VssResult r = run(*solver, depth, mask);
        EXPECT_EQ(r.regions.size(), m != 0 ? 0U : 1U);
        if (m != 0) {
            EXPECT_EQ(r.height(0, 0), 0.0F);
        } else {
            EXPECT_TRUE(std::isnan(r.height(0, 0)));
        }
    }
}

INSTANTIATE_TEST_SUITE_P(AllSolversAllPowers, SolverPowerTest,
                         ::testing::Combine(::testing::ValuesIn(kSolvers),
                                            ::testing::ValuesIn(kPowers)),
                         [](const ::testing::TestParamInfo<std::tuple<SolverCase, double>>& param) {
                             std::string p = std::to_string(std::get<1>(param.param));
                             p.erase(p.find_last_not_of('0') + 1);
                             std::replace(p.begin(), p.end(), '.', '_');
                             if (!p.empty() && p.back() == '_') {
                                 p.pop_back();
                             }
                             return caseName(std::get<0>(param.param)) + "_p" + p;
                         });

// ---------------------------------------------------------------------------
// Per solver.

class SolverTest : public ::testing::TestWithParam<SolverCase> {};

TEST_P(SolverTest, TwentyRandomMasks) {
    const auto solver = solverFor(GetParam(), 2.0);
    for (std::uint64_t seed = 1000; seed < 1020; ++seed) {
        const auto mask = test::randomMask(64, 48, seed);
        const auto depth = test::randomDepth(64, 48, seed);
        const VssResult r = run(*solver, depth, mask);
        const std::string what = std::string(GetParam().name) + " seed " + std::to_string(seed);
        expectBoundedAndFinite(r, what);
        expectNear(r.height, referenceFor(seed, 2.0, depth, mask).height,
                   tolerance(GetParam(), *solver), what);
    }
}

/// A random mask inside a vessel frame, so that padding the image does not
/// change its regions.
Image<std::uint8_t> framedMask(int w, int h, std::uint64_t seed) {
    auto mask = test::randomMask(w, h, seed);
    for (int x = 0; x < w; ++x) {
        mask(x, 0) = 1;
        mask(x, h - 1) = 1;
    }
    for (int y = 0; y < h; ++y) {
        mask(0, y) = 1;
        mask(w - 1, y) = 1;
    }
    return mask;
}

TEST_P(SolverTest, TranslationMirrorTransposeInvariance) {
    for (const double p : {1.0, 4.0, 16.0}) {
        const auto solver = solverFor(GetParam(), p);
        const double tol = 2.0 * tolerance(GetParam(), *solver);
        for (std::uint64_t seed = 7; seed < 10; ++seed) {
            const int w = 45;
            const int h = 33;
            const auto mask = framedMask(w, h, seed);
            const auto depth = test::randomDepth(w, h, seed);
            const VssResult base = run(*solver, depth, mask);
            // Transformed copies: (x, y) -> map(x, y) in an image of size W' x H'.
            struct Transform {
                const char* name;
                int w;
                int h;
                int (*mx)(int, int, int, int);
                int (*my)(int, int, int, int);
            };
            const Transform transforms[] = {
                {"translate", w + 11, h + 6, [](int x, int, int, int) { return x + 7; },
                 [](int, int y, int, int) { return y + 4; }},
                {"mirror x", w, h, [](int x, int, int ww, int) { return ww - 1 - x; },
                 [](int, int y, int, int) { return y; }},
                {"mirror y", w, h, [](int x, int, int, int) { return x; },
                 [](int, int y, int, int hh) { return hh - 1 - y; }},
                {"transpose", h, w, [](int, int y, int, int) { return y; },
                 [](int x, int, int, int) { return x; }},
            };
            for (const auto& t : transforms) {
                Image<std::uint8_t> m2(t.w, t.h, 0);
                Image<float> d2(t.w, t.h, 1.0F);
                for (int y = 0; y < h; ++y) {
                    for (int x = 0; x < w; ++x) {
                        m2(t.mx(x, y, w, h), t.my(x, y, w, h)) = mask(x, y);
                        d2(t.mx(x, y, w, h), t.my(x, y, w, h)) = depth(x, y);
                    }
                }
                const VssResult moved = run(*solver, d2, m2);
                double worst = 0.0;
                for (int y = 0; y < h; ++y) {
                    for (int x = 0; x < w; ++x) {
                        const float a = base.height(x, y);
                        const float b = moved.height(t.mx(x, y, w, h), t.my(x, y, w, h));
                        ASSERT_TRUE(std::isfinite(a) && std::isfinite(b));
                        worst = std::max(worst, std::abs(static_cast<double>(a) - b));
                    }
                }
                EXPECT_LE(worst, tol)
                    << GetParam().name << " " << t.name << " p " << p << " seed " << seed;
            }
        }
    }
}

TEST_P(SolverTest, PowerLimits) {
    // p -> 0: the mean of the contour depths. p -> inf: the nearest one.
    const auto mask = test::randomMask(40, 30, 31);
    const auto depth = test::randomDepth(40, 30, 31);
    {
        const auto solver = solverFor(GetParam(), 1e-3);
        const VssResult r = run(*solver, depth, mask);
        for (int y = 0; y < 30; ++y) {
            for (int x = 0; x < 40; ++x) {
                const std::int32_t id = r.labels(x, y);
                if (id == kVesselLabel) {
                    continue;
                }
                const auto& contour = r.regions[static_cast<std::size_t>(id)].contour;
                double mean = 0.0;
                for (const auto& c : contour) {
                    mean += c.z;
                }
                mean /= static_cast<double>(contour.size());
                // w_i = d_i^-0.001 = 1 - 0.001 ln d_i + ...: within 0.001 * ln(50) * 2.
                ASSERT_NEAR(r.height(x, y), mean, 0.008) << x << ", " << y;
            }
        }
    }
    {
        const auto solver = solverFor(GetParam(), 64.0);
        const VssResult r = run(*solver, depth, mask);
        int checked = 0;
        for (int y = 0; y < 30; ++y) {
            for (int x = 0; x < 40; ++x) {
                const std::int32_t id = r.labels(x, y);
                if (id == kVesselLabel) {
                    continue;
                }
                const auto& contour = r.regions[static_cast<std::size_t>(id)].contour;
                // |z' - z_nearest| <= sum over the others of (d_nearest / d_i)^64.
                std::size_t nearest = 0;
                double d2min = std::numeric_limits<double>::infinity();
                for (std::size_t i = 0; i < contour.size(); ++i) {
                    const double dx = contour[i].x - x;
                    const double dy = contour[i].y - y;
                    if (dx * dx + dy * dy < d2min) {
                        d2min = dx * dx + dy * dy;
                        nearest = i;
                    }
                }
                double bound = 0.0;
                for (std::size_t i = 0; i < contour.size(); ++i) {
                    const double dx = contour[i].x - x;
                    const double dy = contour[i].y - y;
                    if (i != nearest) {
                        bound += std::pow(d2min / (dx * dx + dy * dy), 32.0);
                    }
                }
                if (bound < 1e-3) {
                    ++checked;
                    ASSERT_NEAR(r.height(x, y), contour[nearest].z,
                                bound + tolerance(GetParam(), *solver))
                        << x << ", " << y;
                }
            }
        }
        EXPECT_GT(checked, 50);
    }
}

TEST_P(SolverTest, Huge7680x4320SparseMask) {
    const auto solver = solverFor(GetParam(), 64.0);
    const int w = 7680;
    const int h = 4320;
    Image<std::uint8_t> mask(w, h, 0);
    Image<float> depth(w, h, std::numeric_limits<float>::infinity());
    // Two vessel dots far apart: p = 64 over distances up to 8800 px.
    mask(100, 200) = 1;
    depth(100, 200) = 2.0F;
    mask(7000, 4000) = 1;
    depth(7000, 4000) = 4.0F;
    const VssResult r = run(*solver, depth, mask);
    ASSERT_EQ(r.regions.size(), 1U);
    ASSERT_EQ(r.regions[0].contour.size(), 2U);
    // Exact: z' = w2 / (w1 + w2) with w = d^-64 (z = 0 and 1).
    const auto expected = [](int x, int y) {
        const double d1 = std::hypot(x - 100.0, y - 200.0);
        const double d2 = std::hypot(x - 7000.0, y - 4000.0);
        return 1.0 / (1.0 + std::pow(d2 / d1, 64.0));
    };
    std::int64_t bad = 0;
    for (int y = 0; y < h; y += 7) {
        for (int x = 0; x < w; x += 7) {
            const float v = r.height(x, y);
            if (r.labels(x, y) == kVesselLabel) {
                continue;
            }
            if (!std::isfinite(v) ||
                std::abs(v - expected(x, y)) > tolerance(GetParam(), *solver)) {
                if (bad++ < 5) {
                    ADD_FAILURE() << "(" << x << ", " << y << "): " << v << " vs "
                                  << expected(x, y);
                }
            }
        }
    }
    EXPECT_EQ(bad, 0);
}

TEST_P(SolverTest, AMillionContourPixels) {
    // A 4x4 void block in a 1002 x 1000 vessel image whose region lists every
    // vessel pixel as contour: about 10^6 contour pixels for 16 void pixels.
    const int w = 1002;
    const int h = 1000;
    Image<std::int32_t> labels(w, h, kVesselLabel);
    VoidRegion region;
    region.id = 0;
    region.x0 = 500;
    region.y0 = 500;
    region.x1 = 504;
    region.y1 = 504;
    region.pixelCount = 16;
    Rng rng(5);
    region.contour.reserve(static_cast<std::size_t>(w) * h);
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            if (x >= 500 && x < 504 && y >= 500 && y < 504) {
                labels(x, y) = 0;
            } else {
                const double s = 0.5 + 0.3 * std::sin(x * 0.01) * std::cos(y * 0.013);
                region.contour.push_back(
                    {x, y, static_cast<float>(s + 0.2 * (rng.uniform() - 0.5))});
            }
        }
    }
    ASSERT_GE(region.contour.size(), 1000000U);
    for (const double p : {0.5, 2.0, 8.0}) {
        const auto solver = solverFor(GetParam(), p);
        Image<float> out(w, h, -7.0F);
        solver->solveRegion(labels.view(), region, out.view(), {});
        for (int y = 500; y < 504; ++y) {
            for (int x = 500; x < 504; ++x) {
                EXPECT_FALSE(std::isnan(out(x, y)));
            }
        }
        for (const int y : {500, 503}) {
            for (const int x : {500, 502}) {
                EXPECT_NEAR(out(x, y), test::idw<double>(region.contour, x, y, p),
                            tolerance(GetParam(), *solver))
                    << "p " << p << " at " << x << ", " << y;
            }
        }
        EXPECT_EQ(out(499, 500), -7.0F) << "a pixel outside the region was written";
        EXPECT_EQ(out(0, 0), -7.0F);
    }
}

TEST_P(SolverTest, SolveRegionContract) {
    const auto solver = solverFor(GetParam(), 2.0);
    // Two regions side by side: solving one leaves the other untouched.
    Image<std::int32_t> labels(6, 1, 0);
    labels(3, 0) = kVesselLabel;
    labels(4, 0) = 1;
    labels(5, 0) = 1;
    VoidRegion a{0, {{3, 0, 0.25F}}, 3, 0, 0, 3, 1};
    VoidRegion b{1, {}, 2, 4, 0, 6, 1};
    Image<float> out(6, 1, 9.0F);
    solver->solveRegion(labels.view(), a, out.view(), {});
    EXPECT_FLOAT_EQ(out(0, 0), 0.25F);
    EXPECT_FLOAT_EQ(out(2, 0), 0.25F);
    EXPECT_EQ(out(3, 0), 9.0F);
    EXPECT_EQ(out(4, 0), 9.0F);
    solver->solveRegion(labels.view(), b, out.view(), {});
    EXPECT_TRUE(std::isnan(out(4, 0)));
    EXPECT_TRUE(std::isnan(out(5, 0)));
    EXPECT_EQ(out(3, 0), 9.0F);
    // Cancellation.
    std::stop_source stop;
    stop.request_stop();
    EXPECT_THROW(solver->solveRegion(labels.view(), a, out.view(), stop.get_token()),
                 CancelledError);
}

INSTANTIATE_TEST_SUITE_P(AllSolvers, SolverTest, ::testing::ValuesIn(kSolvers),
                         [](const ::testing::TestParamInfo<SolverCase>& param) {
                             return caseName(param.param);
                         });

// ---------------------------------------------------------------------------
// The factory.

TEST(SolverFactoryTest, ParsesNamesAndValidates) {
    for (const auto kind :
         {SolverKind::Reference, SolverKind::Brute, SolverKind::Step, SolverKind::Fast}) {
        EXPECT_EQ(parseSolverKind(toString(kind)), kind);
    }
    EXPECT_THROW(static_cast<void>(parseSolverKind("Brute")), InvalidArgumentError);
    EXPECT_THROW(static_cast<void>(parseSolverKind("")), InvalidArgumentError);
    const auto bad = [](auto change) {
        SolverOptions o;
        o.kind = SolverKind::Brute;
        change(o);
        return o;
    };
    for (const double p : {0.0, -1.0, std::numeric_limits<double>::quiet_NaN(),
                           std::numeric_limits<double>::infinity()}) {
        EXPECT_THROW(static_cast<void>(makeSolver(bad([&](SolverOptions& o) { o.p = p; }))),
                     InvalidArgumentError)
            << p;
        EXPECT_THROW(static_cast<void>(makeSolver(bad([&](SolverOptions& o) { o.tolerance = p; }))),
                     InvalidArgumentError)
            << p;
    }
    EXPECT_THROW(static_cast<void>(makeSolver(bad([](SolverOptions& o) { o.step = 0; }))),
                 InvalidArgumentError);
    SolverOptions ok;
    ok.kind = SolverKind::Reference;
    EXPECT_EQ(makeSolver(ok)->errorBound(), 0.0);
    ok.kind = SolverKind::Brute;
    EXPECT_EQ(makeSolver(ok)->errorBound(), 0.0);
    ok.kind = SolverKind::Step;
    ok.step = 3;
    EXPECT_TRUE(std::isnan(makeSolver(ok)->errorBound()));
}

TEST(StepSolverTest, UsesEveryKthContourPixelAlongAStraightBorder) {
    // A row of void pixels under a row of vessel pixels with depths 0, 1, 0, 1, ...
    // Along the border (here one straight run) step 2 keeps contour pixels
    // 0, 2, 4, ...: all depth 0.
    const int w = 20;
    Image<std::uint8_t> mask(w, 2, 0);
    Image<float> depth(w, 2, 0.0F);
    for (int x = 0; x < w; ++x) {
        mask(x, 0) = 1;
        depth(x, 0) = static_cast<float>(x % 2);
    }
    SolverOptions options;
    options.kind = SolverKind::Step;
    options.step = 2;
    const VssResult r = solve(depth.view(), mask.view(), VssOptions{options, {}, {}});
    for (int x = 0; x < w; ++x) {
        EXPECT_EQ(r.height(x, 1), 0.0F) << x;
    }
    options.step = 1;
    const VssResult all = solve(depth.view(), mask.view(), VssOptions{options, {}, {}});
    EXPECT_GT(all.height(5, 1), 0.3F);
}

}  // namespace
}  // namespace vv::vss
