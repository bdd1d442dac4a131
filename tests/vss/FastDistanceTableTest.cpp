// SPDX-License-Identifier: GPL-3.0-or-later
// The fast VSS solver's distance table (FastTables.h, distanceTable): every
// entry is the weight of its lattice offset rounded once; the leaf tiles that
// read it (and compute the points beyond it in the same scale) keep the
// tolerance on every pixel, and the switch really changes the path taken.
#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>

#include "FastKernel.h"
#include "FastSolverTestUtil.h"
#include "FastStats.h"
#include "FastTables.h"
#include "vv/core/Image.h"

namespace vv::vss::fast_distance_table_test {
namespace {

using namespace fasttest;  // NOLINT(google-build-using-namespace): the shared test scenes
using detail::kDistTableHalf;
using detail::kDistTableStride;

TEST(FastDistanceTableTest, HoldsTheWeightOfEveryOffsetRoundedOnce) {
    for (const double p : {1.0, 2.0, 3.3, 8.0, 12.0}) {
        const detail::fast::PowerTables tab(p);
        const auto table = detail::fast::distanceTable(tab);
        ASSERT_NE(table, nullptr) << p;
        ASSERT_EQ(table->size(), static_cast<std::size_t>(kDistTableStride) * kDistTableStride);
        const float* w = table->data();
        EXPECT_EQ(detail::fast::distanceTable(tab), table) << "kept for the next solver";
        double worst = 0.0;
        for (int dy = -kDistTableHalf; dy < kDistTableHalf + detail::kLeafTile; ++dy) {
            for (int dx = -kDistTableHalf; dx < kDistTableHalf + detail::kLeafTile; ++dx) {
                const float v = w[static_cast<std::size_t>(dy + kDistTableHalf) * kDistTableStride +
                                  static_cast<std::size_t>(dx + kDistTableHalf)];
                const double d2 = static_cast<double>(dx) * dx + static_cast<double>(dy) * dy;
                if (d2 == 0.0) {
                    EXPECT_EQ(v, std::numeric_limits<float>::infinity());
                    continue;
                }
                const double exact = std::pow(d2, -p / 2.0);
                ASSERT_GE(std::abs(exact), static_cast<double>(std::numeric_limits<float>::min()));
                worst = std::max(worst, std::abs(static_cast<double>(v) / exact - 1.0));
            }
        }
        // one rounding to float, plus pw's own error (< 1e-13)
        EXPECT_LE(worst, 0x1p-24 + 1e-12) << p;
    }
    // Beyond p ~ 12 the far entries would leave float's normal range: no table.
    for (const double p : {16.0, 64.0}) {
        const detail::fast::PowerTables tab(p);
        EXPECT_EQ(detail::fast::distanceTable(tab), nullptr) << p;
    }
}

// Solves the scene with the table on or off; returns the counters.
detail::FastSolverStats solveCounting(const Scene& s, double p, double tol, bool table,
                                      Image<float>& out) {
    detail::setFastSolverDistanceTableForTesting(table);
    detail::resetFastSolverStats();
    out = solveAll(s, p, tol);
    const detail::FastSolverStats st = detail::fastSolverStats();
    detail::setFastSolverDistanceTableForTesting(true);  // the default
    return st;
}

TEST(FastDistanceTableTest, OnAndOffKeepTheToleranceOnEveryPixel) {
    // Large enough that some leaf tiles have near points beyond the table's
    // 128 pixels (computed in the table's scale), and no band boxes, so that
    // the leaf tiles do the near sums at p <= 4 too.
    detail::setFastSolverBandBoxesForTesting(false);
    const Scene s = randomScene(560, 360, MaskKind::Tree, 4242);
    bool mixed = false;
    for (const double p : {1.0, 3.3, 4.0, 8.0}) {
        const Image<double> ref = referenceImage(s, p);
        for (const double tol : {0.5 / 255.0, 1e-4}) {
            Image<float> on;
            Image<float> off;
            const detail::FastSolverStats a = solveCounting(s, p, tol, true, on);
            const detail::FastSolverStats b = solveCounting(s, p, tol, false, off);
            const Check ca = compare(s, on, ref);
            const Check cb = compare(s, off, ref);
            EXPECT_EQ(ca.bad, 0) << "p " << p << " tol " << tol;
            EXPECT_LE(ca.maxErr, tol) << "p " << p << " tol " << tol;
            EXPECT_EQ(cb.bad, 0) << "p " << p << " tol " << tol;
            EXPECT_LE(cb.maxErr, tol) << "p " << p << " tol " << tol;
            // the table is what the leaves used, and only when on
            EXPECT_GT(a.tableLeaves, 0) << "p " << p << " tol " << tol;
            EXPECT_GT(a.tablePairs, tol > 1e-3 ? a.nearPairs / 2 : 0)
                << "p " << p << " tol " << tol;
            EXPECT_LE(a.tablePairs, a.nearPairs);
            EXPECT_EQ(b.tableLeaves, 0);
            EXPECT_EQ(b.tablePairs, 0);
            mixed = mixed || a.tablePairs < a.nearPairs;
            // the same choices: the table changes how a weight is found, not which
            EXPECT_EQ(a.nearPairs, b.nearPairs);
            EXPECT_EQ(a.m2l, b.m2l);
        }
    }
    detail::setFastSolverBandBoxesForTesting(true);  // the default
    EXPECT_TRUE(mixed) << "no leaf computed some near points beside the table's";
}

TEST(FastDistanceTableTest, TheCheckInTheTablesScaleCatchesALooseBudget) {
    // With an a-priori budget far too loose, truncation errors beyond the
    // tolerance reach the leaves that read the table: their check (the
    // polynomial and E in absolute scale) must send those pixels to the exact
    // fall-backs.
    const Scene s = randomScene(240, 180, MaskKind::Tree, 8);
    for (const double p : {3.3, 8.0}) {
        const Image<double> ref = referenceImage(s, p);
        for (const double loose : {1e2, 1e3}) {
            detail::setFastSolverBudgetScaleForTesting(loose);
            Image<float> out;
            const detail::FastSolverStats st = solveCounting(s, p, 0.5 / 255.0, true, out);
            detail::setFastSolverBudgetScaleForTesting(1.0);
            const Check c = compare(s, out, ref);
            EXPECT_EQ(c.bad, 0) << "p " << p << " budget x" << loose;
            EXPECT_LE(c.maxErr, 0.5 / 255.0) << "p " << p << " budget x" << loose;
            EXPECT_GT(st.tablePairs, 0) << "p " << p << " budget x" << loose;
            EXPECT_GT(st.fallbackPixels, 0) << "p " << p << " budget x" << loose;
        }
    }
}

TEST(FastDistanceTableTest, LargePowersComputeEveryWeight) {
    const Scene s = randomScene(200, 150, MaskKind::Lines, 99);
    const double p = 16.0;
    Image<float> out;
    const detail::FastSolverStats st = solveCounting(s, p, 0.5 / 255.0, true, out);
    const Check c = compare(s, out, referenceImage(s, p));
    EXPECT_EQ(c.bad, 0);
    EXPECT_LE(c.maxErr, 0.5 / 255.0);
    EXPECT_GT(st.nearPairs, 0);
    EXPECT_EQ(st.tablePairs, 0);
}

}  // namespace
}  // namespace vv::vss::fast_distance_table_test
