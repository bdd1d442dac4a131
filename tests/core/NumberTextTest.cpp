// SPDX-License-Identifier: GPL-3.0-or-later
// Numbers read from data files as strtod reads them in the C locale, but
// without depending on the process locale.
#include <gtest/gtest.h>

#include <clocale>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <string>

#include "GermanLocale.h"
#include "vv/core/NumberText.h"

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

TEST(NumberText, ParseDecimalNumberReadsWhatStrtodReads) {
    EXPECT_EQ(vv::parseDecimalNumber("0.5"), 0.5);
    EXPECT_EQ(vv::parseDecimalNumber("+1.5e-3"), 1.5e-3);
    EXPECT_EQ(vv::parseDecimalNumber("-2E3"), -2000.0);
    EXPECT_EQ(vv::parseDecimalNumber(".25"), 0.25);
    EXPECT_EQ(vv::parseDecimalNumber("7."), 7.0);
    EXPECT_EQ(vv::parseDecimalNumber("-inf"), -kInf);
    EXPECT_EQ(vv::parseDecimalNumber("Infinity"), kInf);
    const auto nan = vv::parseDecimalNumber("NaN");
    ASSERT_TRUE(nan.has_value());
    EXPECT_TRUE(std::isnan(*nan));
    // Beyond double's range: ±HUGE_VAL above, ±0 below, as strtod.
    EXPECT_EQ(vv::parseDecimalNumber("1e999"), kInf);
    EXPECT_EQ(vv::parseDecimalNumber("-1e+999"), -kInf);
    EXPECT_EQ(vv::parseDecimalNumber("1e-999"), 0.0);
    EXPECT_EQ(vv::parseDecimalNumber("1" + std::string(400, '0')), kInf);
    EXPECT_EQ(vv::parseDecimalNumber("0." + std::string(400, '0') + "1"), 0.0);
    // Not numbers: the whole token must be one.
    for (const char* bad : {"", "+", "-", "+-1", "1,5", "1.5x", " 1", "1 ", "0x1p3", "e5", "--1"}) {
        EXPECT_FALSE(vv::parseDecimalNumber(bad).has_value()) << "'" << bad << "'";
    }
}

TEST(NumberText, ParsingAndFormattingIgnoreTheProcessLocale) {
    // A German LC_NUMERIC makes strtod read "0.5" as 0 and snprintf write
    // "0,5"; ours must not notice it.
    std::string why;
    if (!vv::test::germanLocalePath(why)) {
        GTEST_SKIP() << why;
    }
    const vv::test::GermanNumbers german;
    ASSERT_EQ(std::strtod("0,5", nullptr), 0.5);  // the locale is in force
    EXPECT_EQ(vv::parseDecimalNumber("0.5"), 0.5);
    EXPECT_FALSE(vv::parseDecimalNumber("0,5").has_value());
    EXPECT_EQ(vv::significantText(0.5, 6), "0.5");
    EXPECT_EQ(vv::fixedText(1.25, 2), "1.25");
}

}  // namespace
