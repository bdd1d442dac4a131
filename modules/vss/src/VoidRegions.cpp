// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/vss/VoidRegions.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "BackgroundLabels.h"
#include "vv/core/Error.h"
#include "vv/core/Parallel.h"

namespace vv::vss {

namespace {

/// Marks with 1 in cand[x] (w bytes) the vessel pixels of row y of the mask
/// that have a background pixel among their 8 neighbours (the only ones that
/// are contour points), 0 elsewhere; near (w + 2 bytes) is scratch. One pass
/// over bytes, which the compiler vectorises.
void contourCandidates(ImageView<const std::uint8_t> mask, int y, std::vector<std::uint8_t>& near,
                       std::vector<std::uint8_t>& cand) {
    const int w = mask.width();
    const std::uint8_t* here = mask.row(y);
    const std::uint8_t* above = y > 0 ? mask.row(y - 1) : here;  // here: no background added
    const std::uint8_t* below = y + 1 < mask.height() ? mask.row(y + 1) : here;
    std::uint8_t* nb = near.data() + 1;  // nb[x]: background in column x of rows y - 1 .. y + 1
    near[0] = 0;
    near[static_cast<std::size_t>(w) + 1] = 0;
    for (int x = 0; x < w; ++x) {
        nb[x] = static_cast<std::uint8_t>(static_cast<unsigned>(above[x] == 0) |
                                          static_cast<unsigned>(here[x] == 0) |
                                          static_cast<unsigned>(below[x] == 0));
    }
    std::uint8_t* c = cand.data();
    for (int x = 0; x < w; ++x) {
        c[x] = static_cast<std::uint8_t>(static_cast<unsigned>(here[x] != 0) &
                                         static_cast<unsigned>(nb[x - 1] | nb[x] | nb[x + 1]));
    }
}

/// The contour points of the vessel pixels of rows [y0, y1), row-major: each
/// once for every distinct region among its 8 neighbours, as (region, point).
void contourBand(ImageView<const std::uint8_t> mask, ImageView<const std::int32_t> labels,
                 ImageView<const float> z, bool haveZ, int y0, int y1,
                 std::vector<std::pair<std::int32_t, ContourPoint>>& out) {
    const int w = labels.width();
    const int h = labels.height();
    std::vector<std::uint8_t> near(static_cast<std::size_t>(w) + 2);
    std::vector<std::uint8_t> cand(static_cast<std::size_t>(w) + 8, 0);  // zero padding
    for (int y = y0; y < y1; ++y) {
        contourCandidates(mask, y, near, cand);
        const std::int32_t* rowAbove = y > 0 ? labels.row(y - 1) : nullptr;
        const std::int32_t* rowHere = labels.row(y);
        const std::int32_t* rowBelow = y + 1 < h ? labels.row(y + 1) : nullptr;
        for (int x = 0; x < w; ++x) {
            if (cand[static_cast<std::size_t>(x)] == 0) {
                std::uint64_t v = 0;  // skip eight non-candidates at a time
                std::memcpy(&v, cand.data() + x, sizeof v);
                if (v == 0) {
                    x += 7;
                }
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
    // labelBackground writes every pixel (kVesselLabel on vessels), in parallel
    result.labels = Image<std::int32_t>(w, h, UninitialisedPixels{});
    if (w == 0 || h == 0) {
        return result;
    }

    const std::vector<detail::ComponentBox> boxes =
        detail::labelBackground(vesselMask, result.labels.view());
    const int regionCount = static_cast<int>(boxes.size());
    result.regions.resize(boxes.size());
    for (std::size_t i = 0; i < boxes.size(); ++i) {
        VoidRegion& r = result.regions[i];
        r.id = static_cast<std::int32_t>(i);
        r.x0 = boxes[i].x0;
        r.y0 = boxes[i].y0;
        r.x1 = boxes[i].x1;
        r.y1 = boxes[i].y1;
        r.pixelCount = boxes[i].pixels;
    }

    // Contours: one row-major pass over vessel pixels; each appends itself once
    // to the contour of every distinct region among its 8 neighbours, so each
    // contour comes out in row-major order without duplicates. In bands of
    // rows in parallel, each band's points then appended band after band: the
    // same lists as one serial pass.
    if (regionCount == 0) {
        return result;
    }
    const int bands = (h + detail::kBandRows - 1) / detail::kBandRows;
    std::vector<std::vector<std::pair<std::int32_t, ContourPoint>>> found(
        static_cast<std::size_t>(bands));
    parallelFor(0, bands, 1, [&](long b0, long b1) {
        for (long b = b0; b < b1; ++b) {
            const int y0 = static_cast<int>(b) * detail::kBandRows;
            contourBand(vesselMask, result.labels.view(), z, haveZ, y0,
                        std::min(h, y0 + detail::kBandRows), found[static_cast<std::size_t>(b)]);
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
