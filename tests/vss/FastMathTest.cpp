// SPDX-License-Identifier: GPL-3.0-or-later
// Accuracy of the brute solver's vectorisable log2 / exp2 (src/FastMath.h).
#include <gtest/gtest.h>

#include <cmath>

#include "FastMath.h"

namespace vv::vss::detail {
namespace {

TEST(FastMathTest, Log2Accuracy) {
    // t from 2^-10 to 2^30, dense near 1 where the weights matter most.
    double worstAbsNear1 = 0.0;
    double worstRel = 0.0;
    for (double t = 0x1p-10; t < 0x1p30; t *= 1.0001) {
        const auto f = static_cast<float>(t);
        const double exact = std::log2(static_cast<double>(f));
        const double got = fastLog2(f);
        if (f >= 0.5F && f <= 2.0F) {
            worstAbsNear1 = std::max(worstAbsNear1, std::abs(got - exact));
        } else {
            worstRel = std::max(worstRel, std::abs(got - exact) / std::abs(exact));
        }
    }
    EXPECT_LT(worstAbsNear1, 2e-7);
    EXPECT_LT(worstRel, 2e-7);
    EXPECT_EQ(fastLog2(1.0F), 0.0F);
    EXPECT_NEAR(fastLog2(1024.0F), 10.0F, 1e-6);
}

TEST(FastMathTest, Exp2Accuracy) {
    double worstRel = 0.0;
    for (double a = 0.5; a > -125.0; a -= 0.000917) {
        const auto f = static_cast<float>(a);
        const double exact = std::exp2(static_cast<double>(f));
        const double got = fastExp2(f);
        worstRel = std::max(worstRel, std::abs(got - exact) / exact);
    }
    EXPECT_LT(worstRel, 2e-7);
    EXPECT_NEAR(fastExp2(0.0F), 1.0F, 1.2e-7);
    EXPECT_EQ(fastExp2(-126.0F), 0.0F);
    EXPECT_EQ(fastExp2(-5000.0F), 0.0F);
    EXPECT_GT(fastExp2(-124.9F), 0.0F);
    EXPECT_TRUE(std::isnormal(fastExp2(-124.99F)));
}

}  // namespace
}  // namespace vv::vss::detail
