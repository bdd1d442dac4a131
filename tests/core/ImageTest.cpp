// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>

#include <limits>

#include "vv/core/Image.h"
#include "vv/core/ImageRange.h"

namespace {

TEST(Image, SizeStrideAndFill) {
    vv::Image<float> img(5, 3, 1.5F, 8);
    EXPECT_EQ(img.width(), 5);
    EXPECT_EQ(img.height(), 3);
    EXPECT_EQ(img.stride(), 8);
    EXPECT_EQ(img.pixelCount(), 15U);
    EXPECT_FLOAT_EQ(img(4, 2), 1.5F);
    img(4, 2) = 7.0F;
    // Row y starts stride elements after row y-1.
    EXPECT_EQ(img.row(2) - img.row(1), 8);
    EXPECT_FLOAT_EQ(img.data()[2 * 8 + 4], 7.0F);
}

TEST(Image, DefaultIsEmptyAndBadSizesThrow) {
    const vv::Image<int> empty;
    EXPECT_TRUE(empty.empty());
    EXPECT_TRUE(vv::Image<int>(0, 4).empty());
    EXPECT_THROW(vv::Image<int>(-1, 4), vv::InvalidArgumentError);
    EXPECT_THROW(vv::Image<int>(4, 4, 0, 3), vv::InvalidArgumentError);
}

TEST(Image, UninitialisedPixelsHaveTheSizeAndKeepWhatIsWritten) {
    // Pixels are unspecified until written (a large image's pages are first
    // touched by the parallel loop that writes them); size and stride are set.
    vv::Image<float> img(7, 4, vv::UninitialisedPixels{});
    EXPECT_EQ(img.width(), 7);
    EXPECT_EQ(img.height(), 4);
    EXPECT_EQ(img.stride(), 7);
    img.fill(2.0F);
    img(6, 3) = 5.0F;
    EXPECT_FLOAT_EQ(img(0, 0), 2.0F);
    EXPECT_FLOAT_EQ(img(6, 3), 5.0F);
    // A copy is a copy; the filling constructor still fills.
    const vv::Image<float> copy = img;
    EXPECT_FLOAT_EQ(copy(6, 3), 5.0F);
    EXPECT_FLOAT_EQ(vv::Image<float>(3, 2, 1.5F)(2, 1), 1.5F);
    EXPECT_TRUE(vv::Image<int>(0, 3, vv::UninitialisedPixels{}).empty());
    EXPECT_THROW(vv::Image<int>(-1, 3, vv::UninitialisedPixels{}), vv::InvalidArgumentError);
}

TEST(Image, SubViewAliasesStorage) {
    vv::Image<int> img(6, 4, 0);
    auto sub = img.view().sub(2, 1, 3, 2);
    EXPECT_EQ(sub.width(), 3);
    EXPECT_EQ(sub.height(), 2);
    EXPECT_EQ(sub.stride(), 6);
    sub(0, 0) = 5;
    sub(2, 1) = 9;
    EXPECT_EQ(img(2, 1), 5);
    EXPECT_EQ(img(4, 2), 9);
    EXPECT_THROW((void)img.view().sub(4, 0, 3, 1), vv::InvalidArgumentError);
    EXPECT_THROW((void)img.view().sub(0, -1, 1, 1), vv::InvalidArgumentError);
}

TEST(Image, ConstViewConversion) {
    vv::Image<int> img(2, 2, 3);
    const vv::ImageView<const int> view = img.view();
    EXPECT_EQ(view(1, 1), 3);
    EXPECT_EQ(view.data(), img.data());
}

TEST(Image, FiniteRangeSkipsNonFiniteValuesAndRespectsTheView) {
    constexpr float kInf = std::numeric_limits<float>::infinity();
    constexpr float kNan = std::numeric_limits<float>::quiet_NaN();
    vv::Image<float> depth(4, 3, kInf);
    EXPECT_FALSE(vv::finiteRange(depth.view()).has_value());  // all background
    depth(1, 1) = 7.5F;
    depth(2, 1) = kNan;
    depth(3, 2) = -kInf;
    depth(0, 2) = 2.25F;
    depth(3, 0) = 1.0F;  // outside the sub-view below
    const auto all = vv::finiteRange(depth.view());
    ASSERT_TRUE(all.has_value());
    EXPECT_EQ(all->first, 1.0F);
    EXPECT_EQ(all->second, 7.5F);
    const auto part = vv::finiteRange(depth.view().sub(0, 1, 3, 2));
    ASSERT_TRUE(part.has_value());
    EXPECT_EQ(part->first, 2.25F);
    EXPECT_EQ(part->second, 7.5F);
}

}  // namespace
