// SPDX-License-Identifier: GPL-3.0-or-later
// Two-pass union-find labelling of runs per band of rows (BackgroundLabels.h).
#include "BackgroundLabels.h"

#include <algorithm>
#include <cstddef>
#include <cstring>
#include <limits>

#include "vv/core/Error.h"
#include "vv/core/Parallel.h"

namespace vv::vss::detail {
namespace {

/// Root of i; halves the paths on the way (every parent is <= its child).
std::int32_t findRoot(std::vector<std::int32_t>& parent, std::int32_t i) {
    while (parent[static_cast<std::size_t>(i)] != i) {
        const std::int32_t up = parent[static_cast<std::size_t>(i)];
        parent[static_cast<std::size_t>(i)] = parent[static_cast<std::size_t>(up)];
        i = up;
    }
    return i;
}

/// Joins the sets of a and b under the smaller root (the first in raster order).
void unite(std::vector<std::int32_t>& parent, std::int32_t a, std::int32_t b) {
    a = findRoot(parent, a);
    b = findRoot(parent, b);
    if (a < b) {
        parent[static_cast<std::size_t>(b)] = a;
    } else if (b < a) {
        parent[static_cast<std::size_t>(a)] = b;
    }
}

/// A run: the background pixels [x0, x1) of one row, with their provisional label.
struct Run {
    int x0 = 0;
    int x1 = 0;
    std::int32_t id = 0;
};

/// One band: its runs row by row (those of row y0 + r are
/// runs[rowStart[r]] .. runs[rowStart[r + 1] - 1], left to right), their
/// provisional labels (band-local, in raster order of their first pixel),
/// the labels' union-find parents and boxes.
struct Band {
    int y0 = 0;
    int y1 = 0;
    std::vector<Run> runs;
    std::vector<std::size_t> rowStart;
    std::vector<std::int32_t> parent;
    std::vector<ComponentBox> boxes;
    std::int32_t offset = 0;  // first global provisional id
};

constexpr std::uint64_t kOnes = 0x0101010101010101ULL;
constexpr std::uint64_t kHighs = 0x8080808080808080ULL;

/// First x in [x, w) with m[x] != 0 (or w): eight bytes at a time.
int skipBackground(const std::uint8_t* m, int x, int w) {
    while (x + 8 <= w) {
        std::uint64_t v = 0;
        std::memcpy(&v, m + x, sizeof v);
        if (v != 0) {
            break;
        }
        x += 8;
    }
    while (x < w && m[x] == 0) {
        ++x;
    }
    return x;
}

/// First x in [x, w) with m[x] == 0 (or w): eight bytes at a time.
int skipVessel(const std::uint8_t* m, int x, int w) {
    while (x + 8 <= w) {
        std::uint64_t v = 0;
        std::memcpy(&v, m + x, sizeof v);
        if (((v - kOnes) & ~v & kHighs) != 0) {  // some byte is zero
            break;
        }
        x += 8;
    }
    while (x < w && m[x] != 0) {
        ++x;
    }
    return x;
}

/// Labels the band run by run: a run takes the label of the first run above
/// that shares a column with it and unites every other such label; a run
/// with none above gets a new label. Same sets, and new labels in the raster
/// order of each set's first pixel, as pixel by pixel. Writes no pixel.
void labelBand(ImageView<const std::uint8_t> mask, Band& band) {
    const int w = mask.width();
    band.rowStart.assign(1, 0);
    std::size_t upBegin = 0;  // runs of the row above: [upBegin, upEnd)
    std::size_t upEnd = 0;
    for (int y = band.y0; y < band.y1; ++y) {
        const std::uint8_t* m = mask.row(y);
        std::size_t k = upBegin;  // first run above that may overlap the current one
        int x = skipVessel(m, 0, w);
        while (x < w) {
            const int x0 = x;
            x = skipBackground(m, x, w);
            while (k < upEnd && band.runs[k].x1 <= x0) {
                ++k;
            }
            std::int32_t id = -1;
            for (std::size_t j = k; j < upEnd && band.runs[j].x0 < x; ++j) {
                if (id < 0) {
                    id = band.runs[j].id;
                } else {
                    unite(band.parent, id, band.runs[j].id);
                }
            }
            if (id < 0) {
                id = static_cast<std::int32_t>(band.parent.size());
                band.parent.push_back(id);
                band.boxes.push_back(ComponentBox{x0, y, x, y + 1, 0});
            }
            band.runs.push_back(Run{x0, x, id});
            ComponentBox& b = band.boxes[static_cast<std::size_t>(id)];
            b.x0 = std::min(b.x0, x0);
            b.x1 = std::max(b.x1, x);
            b.y1 = y + 1;
            b.pixels += x - x0;
            x = skipVessel(m, x, w);
        }
        upBegin = upEnd;
        upEnd = band.runs.size();
        band.rowStart.push_back(upEnd);
    }
}

}  // namespace

std::vector<ComponentBox> labelBackground(ImageView<const std::uint8_t> mask,
                                          ImageView<std::int32_t> labels) {
    const int w = mask.width();
    const int h = mask.height();
    if (labels.width() != w || labels.height() != h) {
        throw InvalidArgumentError("labelBackground: the mask and the labels differ in size");
    }
    if (w == 0 || h == 0) {
        return {};
    }
    const int bandCount = (h + kBandRows - 1) / kBandRows;
    std::vector<Band> bands(static_cast<std::size_t>(bandCount));
    for (int b = 0; b < bandCount; ++b) {
        bands[static_cast<std::size_t>(b)].y0 = b * kBandRows;
        bands[static_cast<std::size_t>(b)].y1 = std::min(h, (b + 1) * kBandRows);
    }
    // 1. Each band on its own.
    parallelFor(0, bandCount, 1, [&](long b0, long b1) {
        for (long b = b0; b < b1; ++b) {
            labelBand(mask, bands[static_cast<std::size_t>(b)]);
        }
    });
    // 2. One union-find over every provisional label (global id = offset +
    // local id: raster order of the first pixels), joined along band borders
    // (the runs of a band's last row and the next band's first row that
    // share a column).
    std::int64_t total = 0;
    for (Band& band : bands) {
        band.offset = static_cast<std::int32_t>(total);
        total += static_cast<std::int64_t>(band.parent.size());
    }
    if (total > std::numeric_limits<std::int32_t>::max()) {
        throw InvalidArgumentError("labelBackground: too many components");  // > 8192 x 8192
    }
    std::vector<std::int32_t> parent(static_cast<std::size_t>(total));
    std::vector<ComponentBox> boxes(static_cast<std::size_t>(total));
    for (const Band& band : bands) {
        for (std::size_t i = 0; i < band.parent.size(); ++i) {
            parent[static_cast<std::size_t>(band.offset) + i] = band.parent[i] + band.offset;
            boxes[static_cast<std::size_t>(band.offset) + i] = band.boxes[i];
        }
    }
    for (int b = 1; b < bandCount; ++b) {
        const Band& above = bands[static_cast<std::size_t>(b - 1)];
        const Band& below = bands[static_cast<std::size_t>(b)];
        const std::size_t aEnd = above.rowStart.back();
        std::size_t i = above.rowStart[above.rowStart.size() - 2];
        for (std::size_t j = 0; j < below.rowStart[1]; ++j) {
            const Run& r = below.runs[j];
            while (i < aEnd && above.runs[i].x1 <= r.x0) {
                ++i;
            }
            for (std::size_t k = i; k < aEnd && above.runs[k].x0 < r.x1; ++k) {
                unite(parent, above.runs[k].id + above.offset, r.id + below.offset);
            }
        }
    }
    // 3. Final ids: the roots (each set's first label in raster order) in
    // increasing order; every other label after its root.
    std::vector<std::int32_t> finalId(static_cast<std::size_t>(total));
    std::vector<ComponentBox> result;
    for (std::int32_t i = 0; i < static_cast<std::int32_t>(total); ++i) {
        const std::int32_t root = findRoot(parent, i);
        const ComponentBox& bi = boxes[static_cast<std::size_t>(i)];
        if (root == i) {
            finalId[static_cast<std::size_t>(i)] = static_cast<std::int32_t>(result.size());
            result.push_back(bi);
            continue;
        }
        const std::int32_t id = finalId[static_cast<std::size_t>(root)];
        finalId[static_cast<std::size_t>(i)] = id;
        ComponentBox& r = result[static_cast<std::size_t>(id)];
        r.x0 = std::min(r.x0, bi.x0);
        r.y0 = std::min(r.y0, bi.y0);
        r.x1 = std::max(r.x1, bi.x1);
        r.y1 = std::max(r.y1, bi.y1);
        r.pixels += bi.pixels;
    }
    // 4. Every pixel written once, run by run: the final id on the runs,
    // kVesselLabel (-1) between them.
    parallelFor(0, bandCount, 1, [&](long b0, long b1) {
        for (long b = b0; b < b1; ++b) {
            const Band& band = bands[static_cast<std::size_t>(b)];
            for (int y = band.y0; y < band.y1; ++y) {
                const auto r = static_cast<std::size_t>(y - band.y0);
                std::int32_t* l = labels.row(y);
                int x = 0;
                for (std::size_t k = band.rowStart[r]; k < band.rowStart[r + 1]; ++k) {
                    const Run& run = band.runs[k];
                    std::fill(l + x, l + run.x0, -1);
                    std::fill(l + run.x0, l + run.x1,
                              finalId[static_cast<std::size_t>(run.id) +
                                      static_cast<std::size_t>(band.offset)]);
                    x = run.x1;
                }
                std::fill(l + x, l + w, -1);
            }
        }
    });
    return result;
}

}  // namespace vv::vss::detail
