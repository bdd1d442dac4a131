// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/vss/VoidRegions.h"

#include <algorithm>
#include <array>
#include <limits>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>
#include <string>

#include "vv/core/Error.h"

namespace vv::vss {

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
    for (int y = 0; y < h; ++y) {
        const std::uint8_t* m = vesselMask.row(y);
        auto* b = background.ptr<std::uint8_t>(y);
        for (int x = 0; x < w; ++x) {
            b[x] = m[x] != 0 ? 0 : 1;
        }
    }
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
    // algorithm choice): OpenCV label l -> our id order[l], vessel 0 -> -1.
    std::vector<std::int32_t> order(static_cast<std::size_t>(count), -2);
    order[0] = kVesselLabel;
    std::int32_t next = 0;
    for (int y = 0; y < h; ++y) {
        std::int32_t* l = result.labels.row(y);
        for (int x = 0; x < w; ++x) {
            std::int32_t& id = order[static_cast<std::size_t>(l[x])];
            if (id == -2) {
                id = next++;
            }
            l[x] = id;
        }
    }

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
    // contour comes out in row-major order without duplicates.
    if (regionCount == 0) {
        return result;
    }
    for (int y = 0; y < h; ++y) {
        const std::int32_t* rowAbove = y > 0 ? result.labels.row(y - 1) : nullptr;
        const std::int32_t* rowHere = result.labels.row(y);
        const std::int32_t* rowBelow = y + 1 < h ? result.labels.row(y + 1) : nullptr;
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
            if (n == 0) {
                continue;
            }
            const float depth = haveZ ? z(x, y) : 0.0F;
            for (int i = 0; i < n; ++i) {
                result.regions[static_cast<std::size_t>(found[static_cast<std::size_t>(i)])]
                    .contour.push_back(ContourPoint{x, y, depth});
            }
        }
    }
    return result;
}

}  // namespace vv::vss
