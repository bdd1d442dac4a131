// SPDX-License-Identifier: GPL-3.0-or-later
// Two-pass union-find labelling per band of rows (BackgroundLabels.h).
#include "BackgroundLabels.h"

#include <algorithm>
#include <cstddef>
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

/// One band: provisional labels (band-local, in raster order of their first
/// pixel), their union-find parents and boxes.
struct Band {
    int y0 = 0;
    int y1 = 0;
    std::vector<std::int32_t> parent;
    std::vector<ComponentBox> boxes;
    std::int32_t offset = 0;  // first global provisional id
};

/// Labels the band run by run (a run: consecutive background pixels of a
/// row): a run takes the first label above it and unites every other label
/// above it; a run with none above gets a new label. Same sets, and new labels
/// in the raster order of each set's first pixel, as pixel by pixel.
void labelBand(ImageView<const std::uint8_t> mask, ImageView<std::int32_t> labels, Band& band) {
    const int w = mask.width();
    for (int y = band.y0; y < band.y1; ++y) {
        const std::uint8_t* m = mask.row(y);
        const std::uint8_t* mUp = y > band.y0 ? mask.row(y - 1) : nullptr;
        std::int32_t* l = labels.row(y);
        const std::int32_t* lUp = y > band.y0 ? labels.row(y - 1) : nullptr;
        int x = 0;
        while (x < w) {
            if (m[x] != 0) {
                l[x] = -1;
                ++x;
                continue;
            }
            const int x0 = x;
            while (x < w && m[x] == 0) {
                ++x;
            }
            std::int32_t id = -1;
            if (mUp != nullptr) {
                std::int32_t last = -1;
                for (int xx = x0; xx < x; ++xx) {
                    if (mUp[xx] != 0 || lUp[xx] == last) {
                        continue;
                    }
                    last = lUp[xx];
                    if (id < 0) {
                        id = last;
                    } else {
                        unite(band.parent, id, last);
                    }
                }
            }
            if (id < 0) {
                id = static_cast<std::int32_t>(band.parent.size());
                band.parent.push_back(id);
                band.boxes.push_back(ComponentBox{x0, y, x, y + 1, 0});
            }
            std::fill(l + x0, l + x, id);
            ComponentBox& b = band.boxes[static_cast<std::size_t>(id)];
            b.x0 = std::min(b.x0, x0);
            b.x1 = std::max(b.x1, x);
            b.y1 = y + 1;
            b.pixels += x - x0;
        }
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
            labelBand(mask, labels, bands[static_cast<std::size_t>(b)]);
        }
    });
    // 2. One union-find over every provisional label (global id = offset +
    // local id: raster order of the first pixels), joined along band borders.
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
        const std::uint8_t* mA = mask.row(below.y0 - 1);
        const std::uint8_t* mB = mask.row(below.y0);
        const std::int32_t* lA = labels.row(below.y0 - 1);
        const std::int32_t* lB = labels.row(below.y0);
        for (int x = 0; x < w; ++x) {
            if (mA[x] == 0 && mB[x] == 0) {
                unite(parent, lA[x] + above.offset, lB[x] + below.offset);
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
    // 4. Renumber the pixels.
    parallelFor(0, bandCount, 1, [&](long b0, long b1) {
        for (long b = b0; b < b1; ++b) {
            const Band& band = bands[static_cast<std::size_t>(b)];
            for (int y = band.y0; y < band.y1; ++y) {
                std::int32_t* l = labels.row(y);
                for (int x = 0; x < w; ++x) {
                    if (l[x] >= 0) {
                        l[x] = finalId[static_cast<std::size_t>(l[x]) +
                                       static_cast<std::size_t>(band.offset)];
                    }
                }
            }
        }
    });
    return result;
}

}  // namespace vv::vss::detail
