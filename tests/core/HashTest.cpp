// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <string_view>

#include "vv/core/Hash.h"

namespace {

TEST(HashTest, MatchesThePublishedFnv1aValues) {
    // The FNV-1a 64-bit test vectors of the reference (empty, "a", "foobar").
    EXPECT_EQ(vv::Fnv1a().result(), 0xcbf29ce484222325ULL);
    EXPECT_EQ(vv::Fnv1a().text("a").result(), 0xaf63dc4c8601ec8cULL);
    EXPECT_EQ(vv::Fnv1a().text("foobar").result(), 0x85944171f73967e8ULL);
}

TEST(HashTest, PiecesHashLikeTheirConcatenation) {
    const std::string_view whole = "vessel tree";
    EXPECT_EQ(vv::Fnv1a().text("vessel").text(" tree").result(), vv::Fnv1a().text(whole).result());
}

TEST(HashTest, ValuesHashByTheirBytesAndOrderMatters) {
    const std::array<std::uint32_t, 2> pair = {1U, 2U};
    EXPECT_EQ(vv::Fnv1a().value(pair).result(),
              vv::Fnv1a().bytes(pair.data(), sizeof pair).result());
    EXPECT_NE(vv::Fnv1a().value(1U).value(2U).result(), vv::Fnv1a().value(2U).value(1U).result());
}

}  // namespace
