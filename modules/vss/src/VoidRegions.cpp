// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/vss/VoidRegions.h"

#include <algorithm>
#include <array>
#include <functional>
#include <limits>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>
#include <string>
#include <utility>
#include <vector>

#include "vv/core/Error.h"
#include "vv/core/Parallel.h"

namespace vv::vss {

namespace {

/// Rows per band of the parallel passes (a fixed size: the bands, and so the
/// order of everything they produce, do not depend on the thread count).
constexpr int kBandRows = 32;

/// body(y0, y1) over bands of kBandRows rows of an image of h rows, in parallel.
void forRowBands(int h, const std::function<void(int, int)>& body) {
    const long bands = (h + kBandRows - 1) / kBandRows;
    parallelFor(0, bands, 1, [&](long b0, long b1) {
        body(static_cast<int>(b0) * kBandRows, std::min(h, static_cast<int>(b1) * kBandRows));
    });
}

/// The contour points of the vessel pixels of rows [y0, y1), row-major: each
/// once for every distinct region among its 8 neighbours, as (region, point).
void contourBand(ImageView<const std::int32_t> labels, ImageView<const float> z, bool haveZ, int y0,
                 int y1, std::vector<std::pair<std::int32_t, ContourPoint>>& out) {
    const int w = labels.width();
    const int h = labels.height();
    for (int y = y0; y < y1; ++y) {
        const std::int32_t* rowAbove = y > 0 ? labels.row(y - 1) : nullptr;
        const std::int32_t* rowHere = labels.row(y);
        const std::int32_t* rowBelow = y + 1 < h ? labels.row(y + 1) : nullptr;
        for (int x = 0; x < w; ++x) {
            if (rowHere[x] != kVesselLabel) {
                continue;
            }
            std::array<std::int32_t, 8> found{};
            int n = 0;
            const auto look = [&](const std::int32_t* row) {
                if (row == nullptr) {
                    return;
                }
                for (int xx = std::max(0, x - 1); xx <= std::min(w - 1, x + 1); ++xx) {
                    const std::int32_t id = row[xx];
                    if (id != kVesselLabel &&
                        std::find(found.begin(), found.begin() + n, id) == found.begin() + n) {
                        found[static_cast<std::size_t>(n++)] = id;
                    }
                }
            };
            look(rowAbove);
            look(rowHere);
            look(rowBelow);
            const float depth = haveZ && n > 0 ? z(x, y) : 0.0F;
            for (int i = 0; i < n; ++i) {
                out.emplace_back(found[static_cast<std::size_t>(i)], ContourPoint{x, y, depth});
            }
        }
    }
}

}  // namespace

VoidRegionSet findVoidRegions(ImageView<const std::uint8_t> vesselMask, ImageView<const float> z) {
    const int w = vesselMask.width();
    const int h = vesselMask.height();
    const bool haveZ = !z.empty() || z.data() != nullptr;
    if (haveZ && (z.width() != w || z.height() != h)) {
        throw InvalidArgumentError("findVoidRegions: the mask is " + std::to_string(w) + "x" +
                                   std::to_string(h) + " but z is " + std::to_string(z.width()) +
                                   "x" + std::to_string(z.height()));
    }
    VoidRegionSet result;
    result.labels = Image<std::int32_t>(w, h, kVesselLabel);
    if (w == 0 || h == 0) {
        return result;
    }

    // OpenCV labels the nonzero pixels of its input: give it the background.
    cv::Mat background(h, w, CV_8U);
    forRowBands(h, [&](int y0, int y1) {
        for (int y = y0; y < y1; ++y) {
            const std::uint8_t* m = vesselMask.row(y);
            auto* b = background.ptr<std::uint8_t>(y);
            for (int x = 0; x < w; ++x) {
                b[x] = m[x] != 0 ? 0 : 1;
            }
        }
    });
    // Labels are written straight into our label image (0 = vessel, 1..n = regions).
    cv::Mat cvLabels(h, w, CV_32S, result.labels.data(),
                     static_cast<std::size_t>(result.labels.stride()) * sizeof(std::int32_t));
    cv::Mat stats;
    cv::Mat centroids;
    const int count =
        cv::connectedComponentsWithStats(background, cvLabels, stats, centroids, 4, CV_32S);
    if (cvLabels.data != static_cast<void*>(result.labels.data())) {
        throw Error("findVoidRegions: OpenCV did not label in place");  // cannot happen
    }
    background.release();
    const int regionCount = std::max(0, count - 1);

    // Renumber in raster order of first appearance (independent of OpenCV's
    // algorithm choice): a region's first pixel is the leftmost of its top
    // row, found from its bounding box; OpenCV label l -> our id order[l],
    // vessel 0 -> -1.
    std::vector<std::array<int, 3>> firsts;  // (top row, first x, OpenCV label)
    firsts.reserve(static_cast<std::size_t>(regionCount));
    for (int label = 1; label < count; ++label) {
        const int top = stats.at<int>(label, cv::CC_STAT_TOP);
        const std::int32_t* row = result.labels.row(top);
        int x = stats.at<int>(label, cv::CC_STAT_LEFT);
        while (row[x] != label) {
            ++x;
        }
        firsts.push_back({top, x, label});
    }
    std::sort(firsts.begin(), firsts.end());
    std::vector<std::int32_t> order(static_cast<std::size_t>(count), kVesselLabel);
    for (std::size_t i = 0; i < firsts.size(); ++i) {
        order[static_cast<std::size_t>(firsts[i][2])] = static_cast<std::int32_t>(i);
    }
    forRowBands(h, [&](int y0, int y1) {
        for (int y = y0; y < y1; ++y) {
            std::int32_t* l = result.labels.row(y);
            for (int x = 0; x < w; ++x) {
                l[x] = order[static_cast<std::size_t>(l[x])];
            }
        }
    });

    result.regions.resize(static_cast<std::size_t>(regionCount));
    for (int label = 1; label < count; ++label) {
        VoidRegion& r =
            result.regions[static_cast<std::size_t>(order[static_cast<std::size_t>(label)])];
        r.id = order[static_cast<std::size_t>(label)];
        r.x0 = stats.at<int>(label, cv::CC_STAT_LEFT);
        r.y0 = stats.at<int>(label, cv::CC_STAT_TOP);
        r.x1 = r.x0 + stats.at<int>(label, cv::CC_STAT_WIDTH);
        r.y1 = r.y0 + stats.at<int>(label, cv::CC_STAT_HEIGHT);
        r.pixelCount = stats.at<int>(label, cv::CC_STAT_AREA);
    }

    // Contours: one row-major pass over vessel pixels; each appends itself once
    // to the contour of every distinct region among its 8 neighbours, so each
    // contour comes out in row-major order without duplicates. In bands of
    // rows in parallel, each band's points then appended band after band: the
    // same lists as one serial pass.
    if (regionCount == 0) {
        return result;
    }
    const int bands = (h + kBandRows - 1) / kBandRows;
    std::vector<std::vector<std::pair<std::int32_t, ContourPoint>>> found(
        static_cast<std::size_t>(bands));
    parallelFor(0, bands, 1, [&](long b0, long b1) {
        for (long b = b0; b < b1; ++b) {
            const int y0 = static_cast<int>(b) * kBandRows;
            contourBand(result.labels.view(), z, haveZ, y0, std::min(h, y0 + kBandRows),
                        found[static_cast<std::size_t>(b)]);
        }
    });
    std::vector<std::size_t> sizes(result.regions.size(), 0);
    for (const auto& band : found) {
        for (const auto& [id, c] : band) {
            ++sizes[static_cast<std::size_t>(id)];
        }
    }
    for (std::size_t i = 0; i < sizes.size(); ++i) {
        result.regions[i].contour.reserve(sizes[i]);
    }
    for (const auto& band : found) {
        for (const auto& [id, c] : band) {
            result.regions[static_cast<std::size_t>(id)].contour.push_back(c);
        }
    }
    return result;
}

}  // namespace vv::vss
