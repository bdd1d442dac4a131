// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>

#include <chrono>
#include <cstdlib>
#include <set>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "VssTestUtil.h"
#include "vv/core/Error.h"
#include "vv/vss/VoidRegions.h"

namespace vv::vss {
namespace {

/// Checks `found` against the independent BFS labelling of `mask`.
void expectMatchesNaive(const Image<std::uint8_t>& mask, const VoidRegionSet& found,
                        const std::string& what) {
    const auto naive = test::naiveRegions(mask.view());
    ASSERT_EQ(found.regions.size(), naive.contours.size()) << what;
    for (int y = 0; y < mask.height(); ++y) {
        for (int x = 0; x < mask.width(); ++x) {
            ASSERT_EQ(found.labels(x, y), naive.labels(x, y)) << what << " at " << x << ", " << y;
        }
    }
    for (std::size_t i = 0; i < found.regions.size(); ++i) {
        const VoidRegion& r = found.regions[i];
        EXPECT_EQ(r.id, static_cast<std::int32_t>(i));
        EXPECT_EQ(r.pixelCount, naive.counts[i]) << what << " region " << i;
        // Contour: same set, row-major, no duplicates.
        std::set<std::pair<int, int>> got;
        std::pair<int, int> previous{-1, -1};
        for (const auto& c : r.contour) {
            const std::pair<int, int> key{c.y, c.x};
            EXPECT_LT(previous, key) << what << ": region " << i << " contour not row-major";
            previous = key;
            got.insert(key);
        }
        EXPECT_EQ(got, naive.contours[i]) << what << " region " << i;
        // Bounding box: tight around the region's pixels.
        int x0 = mask.width();
        int y0 = mask.height();
        int x1 = 0;
        int y1 = 0;
        for (int y = 0; y < mask.height(); ++y) {
            for (int x = 0; x < mask.width(); ++x) {
                if (naive.labels(x, y) == static_cast<std::int32_t>(i)) {
                    x0 = std::min(x0, x);
                    y0 = std::min(y0, y);
                    x1 = std::max(x1, x + 1);
                    y1 = std::max(y1, y + 1);
                }
            }
        }
        EXPECT_EQ(r.x0, x0);
        EXPECT_EQ(r.y0, y0);
        EXPECT_EQ(r.x1, x1);
        EXPECT_EQ(r.y1, y1);
    }
}

TEST(VoidRegionsTest, RandomMasksMatchAnIndependentLabelling) {
    for (std::uint64_t seed = 1; seed <= 20; ++seed) {
        const auto mask = test::randomMask(64, 48, seed);
        expectMatchesNaive(mask, findVoidRegions(mask.view()), "seed " + std::to_string(seed));
    }
}

TEST(VoidRegionsTest, RandomNoiseMasks) {
    // Salt-and-pepper masks: many small regions, diagonal touches everywhere.
    for (std::uint64_t seed = 1; seed <= 10; ++seed) {
        test::Rng rng(seed);
        Image<std::uint8_t> mask(37, 29);
        for (int y = 0; y < 29; ++y) {
            for (int x = 0; x < 37; ++x) {
                mask(x, y) = rng.uniform() < 0.45 ? 1 : 0;
            }
        }
        expectMatchesNaive(mask, findVoidRegions(mask.view()), "noise " + std::to_string(seed));
    }
}

TEST(VoidRegionsTest, TallMasksAcrossManyRowBandsMatchTheNaiveLabelling) {
    // Labelling (a union-find per band, joined along the band borders),
    // renumbering and contours run in bands of 32 rows in parallel:
    // regions and contours that cross many band borders (noise and the
    // random shapes, 200+ rows) must still match the independent labelling.
    for (std::uint64_t seed = 1; seed <= 4; ++seed) {
        test::Rng rng(seed);
        Image<std::uint8_t> mask(53, 211);
        for (int y = 0; y < mask.height(); ++y) {
            for (int x = 0; x < mask.width(); ++x) {
                mask(x, y) = rng.uniform() < 0.4 ? 1 : 0;
            }
        }
        expectMatchesNaive(mask, findVoidRegions(mask.view()), "noise " + std::to_string(seed));
        const auto shapes = test::randomMask(97, 260, seed);
        expectMatchesNaive(shapes, findVoidRegions(shapes.view()),
                           "shapes " + std::to_string(seed));
        const auto exact = test::randomMask(64, 256, seed + 10);  // bands end at the last row
        expectMatchesNaive(exact, findVoidRegions(exact.view()),
                           "256 rows " + std::to_string(seed));
    }
}

TEST(VoidRegionsTest, LongRunsAndAnyNonzeroMaskByteMatchTheNaiveLabelling) {
    // Labelling and contours skip runs of background and of vessel pixels
    // eight mask bytes at a time: runs of every length across those words,
    // rows of widths around multiples of eight, and vessel bytes other than
    // 1 (any nonzero byte is a vessel, 0x80 and 0xff included) must give the
    // independent labelling, boxes and contours.
    for (const int w : {1, 7, 8, 9, 15, 16, 17, 64, 131}) {
        for (std::uint64_t seed = 1; seed <= 3; ++seed) {
            test::Rng rng(seed * 977 + static_cast<std::uint64_t>(w));
            Image<std::uint8_t> mask(w, 70);
            for (int y = 0; y < mask.height(); ++y) {
                int x = 0;
                bool vessel = rng.uniform() < 0.5;
                while (x < w) {
                    // runs of 1 to 24 pixels; vessels of random nonzero bytes
                    const int len = 1 + static_cast<int>(rng.uniform() * 24.0);
                    for (int k = 0; k < len && x < w; ++k, ++x) {
                        const auto b = static_cast<std::uint8_t>(
                            rng.uniform() < 0.5 ? 1 : 1 + static_cast<int>(rng.uniform() * 255.0));
                        mask(x, y) = vessel ? b : 0;
                    }
                    vessel = !vessel;
                }
            }
            expectMatchesNaive(mask, findVoidRegions(mask.view()),
                               "width " + std::to_string(w) + " seed " + std::to_string(seed));
        }
    }
}

TEST(VoidRegionsTest, SameResultWithOneOrThreeThreads) {
    // The parallel passes must give exactly what one thread gives: labels,
    // boxes, counts, and every contour in the same order with the same depths.
    const int w = 640;
    const int h = 480;
    // sparse noise: large and small regions, many of them across band borders
    test::Rng rng(17);
    Image<std::uint8_t> mask(w, h);
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            mask(x, y) = rng.uniform() < 0.3 ? 1 : 0;
        }
    }
    const auto z = test::randomDepth(w, h, 18);
    const char* old = std::getenv("VV_THREADS");
    const std::string saved = old != nullptr ? old : "";
    std::vector<VoidRegionSet> results;
    for (const char* threads : {"1", "3"}) {
        ::setenv("VV_THREADS", threads, 1);
        results.push_back(findVoidRegions(mask.view(), z.view()));
    }
    if (old != nullptr) {
        ::setenv("VV_THREADS", saved.c_str(), 1);
    } else {
        ::unsetenv("VV_THREADS");
    }
    const VoidRegionSet& a = results[0];
    const VoidRegionSet& b = results[1];
    ASSERT_GT(a.regions.size(), 3U);
    ASSERT_EQ(a.regions.size(), b.regions.size());
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            ASSERT_EQ(a.labels(x, y), b.labels(x, y)) << x << ", " << y;
        }
    }
    for (std::size_t i = 0; i < a.regions.size(); ++i) {
        const VoidRegion& ra = a.regions[i];
        const VoidRegion& rb = b.regions[i];
        EXPECT_EQ(ra.id, rb.id);
        EXPECT_EQ(ra.pixelCount, rb.pixelCount);
        EXPECT_EQ(std::tie(ra.x0, ra.y0, ra.x1, ra.y1), std::tie(rb.x0, rb.y0, rb.x1, rb.y1));
        ASSERT_EQ(ra.contour.size(), rb.contour.size()) << i;
        for (std::size_t k = 0; k < ra.contour.size(); ++k) {
            EXPECT_EQ(ra.contour[k].x, rb.contour[k].x);
            EXPECT_EQ(ra.contour[k].y, rb.contour[k].y);
            EXPECT_EQ(ra.contour[k].z, rb.contour[k].z);
        }
    }
}

TEST(VoidRegionsTest, DiagonalBackgroundPixelsAreSeparateRegions) {
    // 4-connectivity of the background: two void pixels touching at a corner
    // are two regions, and the vessel pixels between them are in both contours.
    Image<std::uint8_t> mask(2, 2, 1);
    mask(0, 0) = 0;
    mask(1, 1) = 0;
    const auto found = findVoidRegions(mask.view());
    ASSERT_EQ(found.regions.size(), 2U);
    EXPECT_EQ(found.labels(0, 0), 0);
    EXPECT_EQ(found.labels(1, 1), 1);
    EXPECT_EQ(found.labels(1, 0), kVesselLabel);
    EXPECT_EQ(found.regions[0].contour.size(), 2U);
    EXPECT_EQ(found.regions[1].contour.size(), 2U);
}

TEST(VoidRegionsTest, SmallAndDegenerateImages) {
    {
        const Image<std::uint8_t> mask(1, 1, 0);
        const auto found = findVoidRegions(mask.view());
        ASSERT_EQ(found.regions.size(), 1U);
        EXPECT_TRUE(found.regions[0].contour.empty());
        EXPECT_EQ(found.regions[0].pixelCount, 1);
    }
    {
        const Image<std::uint8_t> mask(1, 1, 1);
        const auto found = findVoidRegions(mask.view());
        EXPECT_TRUE(found.regions.empty());
        EXPECT_EQ(found.labels(0, 0), kVesselLabel);
    }
    {
        const Image<std::uint8_t> mask(0, 0);
        const auto found = findVoidRegions(mask.view());
        EXPECT_TRUE(found.regions.empty());
    }
    {
        // All vessel, all background.
        const Image<std::uint8_t> full(31, 7, 255);
        EXPECT_TRUE(findVoidRegions(full.view()).regions.empty());
        const Image<std::uint8_t> empty(31, 7, 0);
        const auto found = findVoidRegions(empty.view());
        ASSERT_EQ(found.regions.size(), 1U);
        EXPECT_TRUE(found.regions[0].contour.empty());
        EXPECT_EQ(found.regions[0].pixelCount, 31 * 7);
        EXPECT_EQ(found.regions[0].x1, 31);
        EXPECT_EQ(found.regions[0].y1, 7);
    }
    for (const bool column : {false, true}) {
        // 1xN: every vessel pixel splits the line.
        Image<std::uint8_t> mask(column ? 1 : 50, column ? 50 : 1, 0);
        for (const int i : {0, 10, 11, 30}) {
            (column ? mask(0, i) : mask(i, 0)) = 1;
        }
        expectMatchesNaive(mask, findVoidRegions(mask.view()), column ? "Nx1" : "1xN");
        EXPECT_EQ(findVoidRegions(mask.view()).regions.size(), 3U);
    }
}

TEST(VoidRegionsTest, ContourDepthsComeFromZAndSizesAreChecked) {
    auto mask = test::randomMask(20, 15, 3);
    Image<float> z(20, 15);
    for (int y = 0; y < 15; ++y) {
        for (int x = 0; x < 20; ++x) {
            z(x, y) = static_cast<float>(x * 100 + y);
        }
    }
    const auto found = findVoidRegions(mask.view(), z.view());
    for (const auto& r : found.regions) {
        for (const auto& c : r.contour) {
            EXPECT_EQ(c.z, static_cast<float>(c.x * 100 + c.y));
        }
    }
    const Image<float> wrong(19, 15);
    EXPECT_THROW(static_cast<void>(findVoidRegions(mask.view(), wrong.view())),
                 InvalidArgumentError);
}

TEST(VoidRegionsTest, StridedMaskView) {
    // A sub-view of a larger mask (stride > width).
    const auto big = test::randomMask(80, 60, 11);
    const auto sub = big.view().sub(7, 5, 50, 40);
    Image<std::uint8_t> copy(50, 40);
    for (int y = 0; y < 40; ++y) {
        for (int x = 0; x < 50; ++x) {
            copy(x, y) = sub(x, y);
        }
    }
    const auto a = findVoidRegions(sub);
    const auto b = findVoidRegions(copy.view());
    ASSERT_EQ(a.regions.size(), b.regions.size());
    for (std::size_t i = 0; i < a.regions.size(); ++i) {
        EXPECT_EQ(a.regions[i].contour.size(), b.regions[i].contour.size());
    }
}

TEST(VoidRegionsTest, Huge7680x4320) {
    const int w = 7680;
    const int h = 4320;
    Image<std::uint8_t> mask(w, h, 0);
    // A vertical vessel across the image and a small ring: three regions.
    for (int y = 0; y < h; ++y) {
        mask(3000, y) = 1;
    }
    for (int y = 99; y <= 101; ++y) {
        for (int x = 99; x <= 101; ++x) {
            mask(x, y) = 1;
        }
    }
    mask(100, 100) = 0;
    const auto start = std::chrono::steady_clock::now();
    const auto found = findVoidRegions(mask.view());
    const double s =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    ASSERT_EQ(found.regions.size(), 3U);
    EXPECT_EQ(found.regions[0].pixelCount, 3000LL * h - 9);  // left of the line, minus the ring
    EXPECT_EQ(found.regions[0].contour.size(), static_cast<std::size_t>(h + 8));
    // Ids in raster order of the first pixel: right of the line (row 0), then the ring.
    EXPECT_EQ(found.regions[1].pixelCount, static_cast<std::int64_t>(w - 3001) * h);
    EXPECT_EQ(found.regions[1].contour.size(), static_cast<std::size_t>(h));
    EXPECT_EQ(found.regions[1].x0, 3001);
    EXPECT_EQ(found.regions[2].pixelCount, 1);
    EXPECT_EQ(found.regions[2].contour.size(), 8U);
    EXPECT_EQ(found.labels(100, 100), 2);
    // Recorded, not judged (load on CI would judge it); bench/vss_solve_pfm
    // times the labelling with the solve.
    RecordProperty("seconds", std::to_string(s));
}

}  // namespace
}  // namespace vv::vss
