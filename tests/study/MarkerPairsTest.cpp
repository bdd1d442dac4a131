// SPDX-License-Identifier: GPL-3.0-or-later
// Marker pairs on depth images whose vessels, void regions and depths are
// known: every pair meets the paper's criteria, the "same void region"
// flag is the truth of the drawing, no marker sits on an edge between two
// vessels, the strata are balanced as far as the image allows, and the same
// seed gives the same pairs.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <set>

#include "vv/core/Error.h"
#include "vv/study/MarkerPairs.h"

namespace vv::study {
namespace {

constexpr float kBackground = std::numeric_limits<float>::infinity();
constexpr int kWidth = 480;
constexpr int kHeight = 240;

/// Three vertical vessels (A, B, C, 40 px wide) across the image, each
/// tilted in depth from top to bottom: A 10 -> 13, B 13 -> 17, C 16 -> 20.
/// The void between A and B is one region, between B and C another.
struct Bars {
    Image<float> depth{kWidth, kHeight, kBackground};
    static constexpr std::array<int, 3> kLeft{60, 200, 360};
    static constexpr std::array<std::array<float, 2>, 3> kDepth{{{10, 13}, {13, 17}, {16, 20}}};

    Bars() {
        for (int b = 0; b < 3; ++b) {
            for (int y = 0; y < kHeight; ++y) {
                const float t = static_cast<float>(y) / (kHeight - 1);
                for (int x = kLeft[b]; x < kLeft[b] + 40; ++x) {
                    depth.view()(x, y) = kDepth[b][0] + t * (kDepth[b][1] - kDepth[b][0]);
                }
            }
        }
    }
    static int barOf(int x) {
        for (int b = 0; b < 3; ++b) {
            if (x >= kLeft[b] && x < kLeft[b] + 40) {
                return b;
            }
        }
        return -1;
    }
};

TEST(MarkerPairs, EveryPairMeetsTheCriteriaAndItsRegionFlagIsTrue) {
    const Bars bars;
    const PairCriteria criteria;
    const PairSet set = pickMarkerPairs(bars.depth.view(), 24, 7, criteria);
    ASSERT_EQ(set.pairs.size(), 24U);
    EXPECT_FLOAT_EQ(set.depthMin, 10.0F);
    EXPECT_FLOAT_EQ(set.depthMax, 20.0F);
    std::set<std::pair<int, int>> sites;
    for (const MarkerPair& p : set.pairs) {
        const int a = Bars::barOf(p.left.x);
        const int b = Bars::barOf(p.right.x);
        ASSERT_GE(a, 0);
        ASSERT_GE(b, 0);
        // The marked point's neighbourhood lies inside one bar.
        for (const MarkerSite* s : {&p.left, &p.right}) {
            const int bar = Bars::barOf(s->x);
            EXPECT_GE(s->x - criteria.surfaceRadius, Bars::kLeft[bar]);
            EXPECT_LT(s->x + criteria.surfaceRadius, Bars::kLeft[bar] + 40);
            EXPECT_FLOAT_EQ(static_cast<float>(s->depth), bars.depth.view()(s->x, s->y));
            EXPECT_TRUE(sites.insert({s->x, s->y}).second) << "a site used twice";
        }
        EXPECT_LT(p.left.x, p.right.x);
        EXPECT_GE(p.right.x - p.left.x, criteria.minHorizontalSeparation * kWidth);
        EXPECT_LE(std::abs(p.right.y - p.left.y), p.right.x - p.left.x);
        EXPECT_NEAR(p.depthDifference, std::abs(p.left.depth - p.right.depth) / 10.0, 1e-9);
        EXPECT_GE(p.depthDifference, 0.1);
        EXPECT_EQ(p.leftIsCloser, p.left.depth < p.right.depth);
        // Neighbouring bars share the void between them; A and C share none.
        EXPECT_EQ(p.sameRegion, std::abs(a - b) == 1) << a << " " << b;
    }
}

TEST(MarkerPairs, TheStrataAreBalancedAsFarAsTheImageAllows) {
    const Bars bars;
    const PairSet set = pickMarkerPairs(bars.depth.view(), 32, 11);
    std::map<int, int> perStratum;
    for (const MarkerPair& p : set.pairs) {
        ++perStratum[p.stratum];
        EXPECT_EQ(p.stratum, (p.screenDistance > 0.35 ? 4 : 0) +
                                 (p.depthDifference > 0.25 ? 2 : 0) + (p.sameRegion ? 1 : 0));
    }
    // The bars cannot fill three strata: A and C (the only pair bordering no
    // common region) are always far apart and differ by a quarter of the
    // range or more. Each is noted; the other five have their share of 4 (and
    // more, from the empty ones' shares).
    ASSERT_EQ(set.pairs.size(), 32U);
    for (const int empty : {0, 2, 4}) {
        EXPECT_EQ(perStratum[empty], 0) << empty;
    }
    for (const int filled : {1, 3, 5, 6, 7}) {
        EXPECT_GE(perStratum[filled], 4) << filled;
    }
    ASSERT_EQ(set.notes.size(), 3U);
    for (const std::string& note : set.notes) {
        EXPECT_NE(note.find("different regions: 0 of 4"), std::string::npos) << note;
    }
}

TEST(MarkerPairs, TheSameSeedGivesTheSamePairs) {
    const Bars bars;
    const PairSet first = pickMarkerPairs(bars.depth.view(), 16, 3);
    const PairSet again = pickMarkerPairs(bars.depth.view(), 16, 3);
    const PairSet other = pickMarkerPairs(bars.depth.view(), 16, 4);
    ASSERT_EQ(first.pairs.size(), again.pairs.size());
    ASSERT_EQ(first.pairs.size(), other.pairs.size());
    bool allSame = true;
    for (std::size_t i = 0; i < first.pairs.size(); ++i) {
        EXPECT_EQ(first.pairs[i].left.x, again.pairs[i].left.x);
        EXPECT_EQ(first.pairs[i].right.y, again.pairs[i].right.y);
        allSame = allSame && first.pairs[i].left.x == other.pairs[i].left.x &&
                  first.pairs[i].left.y == other.pairs[i].left.y;
    }
    EXPECT_FALSE(allSame);
}

// A near vessel crossing in front of a far one: no marker on the edge where
// the far one disappears behind the near one.
TEST(MarkerPairs, NoMarkerSitsOnAnEdgeBetweenTwoVessels) {
    Image<float> depth(kWidth, kHeight, kBackground);
    for (int y = 0; y < kHeight; ++y) {
        for (int x = 40; x < 440; ++x) {
            if (y >= 100 && y < 150) {
                depth.view()(x, y) = 20.0F;  // the far vessel, horizontal
            }
            if (x >= 220 && x < 270) {
                depth.view()(x, y) = 10.0F;  // the near one, vertical, in front
            }
        }
    }
    const PairCriteria criteria;
    const PairSet set = pickMarkerPairs(depth.view(), 8, 5, criteria);
    ASSERT_FALSE(set.pairs.empty());
    for (const MarkerPair& p : set.pairs) {
        for (const MarkerSite* s : {&p.left, &p.right}) {
            if (s->depth > 15.0) {  // on the far vessel: clear of the near one's edges
                EXPECT_TRUE(s->x + criteria.surfaceRadius < 220 ||
                            s->x - criteria.surfaceRadius >= 270)
                    << s->x;
            }
        }
    }
}

TEST(MarkerPairs, AnImageWithoutVesselsGivesNoPairsAndSaysSo) {
    const Image<float> empty(64, 64, kBackground);
    const PairSet set = pickMarkerPairs(empty.view(), 5, 1);
    EXPECT_TRUE(set.pairs.empty());
    ASSERT_FALSE(set.notes.empty());
    PairCriteria bad;
    bad.minDepthDifference = 1.5;
    EXPECT_THROW(static_cast<void>(pickMarkerPairs(empty.view(), 5, 1, bad)), InvalidArgumentError);
}

}  // namespace
}  // namespace vv::study
