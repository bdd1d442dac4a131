// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <set>
#include <string_view>
#include <vector>

#include "vv/core/Hash.h"

namespace {

TEST(HashTest, MatchesThePublishedHasherValues) {
    // The FNV-1a 64-bit test vectors of the reference (empty, "a", "foobar").
    EXPECT_EQ(vv::Hasher().result(), 0xcbf29ce484222325ULL);
    EXPECT_EQ(vv::Hasher().text("a").result(), 0xaf63dc4c8601ec8cULL);
    EXPECT_EQ(vv::Hasher().text("foobar").result(), 0x85944171f73967e8ULL);
}

TEST(HashTest, PiecesHashLikeTheirConcatenation) {
    const std::string_view whole = "vessel tree";
    EXPECT_EQ(vv::Hasher().text("vessel").text(" tree").result(),
              vv::Hasher().text(whole).result());
}

TEST(HashTest, ValuesHashByTheirBytesAndOrderMatters) {
    const std::array<std::uint32_t, 2> pair = {1U, 2U};
    EXPECT_EQ(vv::Hasher().value(pair).result(),
              vv::Hasher().bytes(pair.data(), sizeof pair).result());
    EXPECT_NE(vv::Hasher().value(1U).value(2U).result(), vv::Hasher().value(2U).value(1U).result());
}

/// bulk() of `buffer` from a fresh hasher.
std::uint64_t bulkHash(const std::vector<unsigned char>& buffer) {
    return vv::Hasher().bulk(buffer.data(), buffer.size()).result();
}

TEST(HashTest, BulkSeesEveryBitOfEveryByteAndTheSize) {
    // 101 bytes: three 32-byte strides and a 5-byte tail.
    std::vector<unsigned char> buffer(101);
    for (std::size_t i = 0; i < buffer.size(); ++i) {
        buffer[i] = static_cast<unsigned char>(i * 37U + 11U);
    }
    const std::uint64_t base = bulkHash(buffer);
    EXPECT_EQ(bulkHash(buffer), base);
    std::set<std::uint64_t> seen{base};
    for (std::size_t i = 0; i < buffer.size(); ++i) {
        for (const unsigned bit : {0U, 7U}) {
            std::vector<unsigned char> changed = buffer;
            changed[i] = static_cast<unsigned char>(changed[i] ^ (1U << bit));
            EXPECT_TRUE(seen.insert(bulkHash(changed)).second) << "byte " << i << " bit " << bit;
        }
    }
    std::vector<unsigned char> longer = buffer;
    longer.push_back(0);
    EXPECT_NE(bulkHash(longer), base);
    // A word's high bits reach the result as its low bits do.
    std::vector<unsigned char> zeros(64, 0);
    std::vector<unsigned char> high = zeros;
    high[7] = 0x80;
    std::vector<unsigned char> low = zeros;
    low[0] = 0x80;
    EXPECT_NE(bulkHash(high), bulkHash(low));
    EXPECT_NE(bulkHash(high), bulkHash(zeros));
}

}  // namespace
