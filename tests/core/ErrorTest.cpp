// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>

#include "vv/core/Error.h"

namespace {

TEST(Error, WhatNamesFileAndProblem) {
    const vv::FormatError e(std::filesystem::path("/data/tree.stl"),
                            "truncated after 12 triangles");
    EXPECT_STREQ(e.what(), "/data/tree.stl: truncated after 12 triangles");
    EXPECT_EQ(e.file(), std::filesystem::path("/data/tree.stl"));
    EXPECT_EQ(e.problem(), "truncated after 12 triangles");
}

TEST(Error, WithoutFileIsJustTheProblem) {
    const vv::InvalidArgumentError e("p must be positive");
    EXPECT_STREQ(e.what(), "p must be positive");
    EXPECT_TRUE(e.file().empty());
}

TEST(Error, HierarchyCatchesAtRoot) {
    auto thrower = [](int kind) {
        switch (kind) {
            case 0:
                throw vv::IoError(std::filesystem::path("a"), "x");
            case 1:
                throw vv::FormatError(std::filesystem::path("b"), "y");
            case 2:
                throw vv::CancelledError();
            default:
                throw vv::RenderError("z");
        }
    };
    for (int k = 0; k < 4; ++k) {
        EXPECT_THROW(thrower(k), vv::Error);
    }
    EXPECT_THROW(thrower(2), vv::CancelledError);
}

}  // namespace
