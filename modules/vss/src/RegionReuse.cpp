// SPDX-License-Identifier: GPL-3.0-or-later
#include "RegionReuse.h"

#include <cstring>

#include "vv/core/Hash.h"

namespace vv::vss::detail {

namespace {

std::uint64_t keyOf(const VoidRegion& r) {
    Hasher h;
    h.value(r.pixelCount).value(r.x0).value(r.y0).value(r.x1).value(r.y1);
    h.value(r.contour.size());
    // ContourPoint is three 4-byte fields without padding: its bytes are its value
    static_assert(sizeof(ContourPoint) == 12);
    h.bulk(r.contour.data(), r.contour.size() * sizeof(ContourPoint));
    return h.result();
}

bool sameContour(const VoidRegion& a, const VoidRegion& b) {
    return a.contour.size() == b.contour.size() &&
           (a.contour.empty() || std::memcmp(a.contour.data(), b.contour.data(),
                                             a.contour.size() * sizeof(ContourPoint)) == 0);
}

}  // namespace

PreviousRegions::PreviousRegions(const PreviousSolve& previous) : previous_(previous) {
    if (previous.regions == nullptr) {
        return;
    }
    byKey_.reserve(previous.regions->size());
    for (std::size_t i = 0; i < previous.regions->size(); ++i) {
        byKey_.emplace(keyOf((*previous.regions)[i]), i);
    }
}

bool PreviousRegions::copyIfSame(ImageView<const std::int32_t> labels, const VoidRegion& region,
                                 ImageView<float> out) const {
    if (byKey_.empty() || previous_.labels.width() != labels.width() ||
        previous_.labels.height() != labels.height() ||
        previous_.height.width() != labels.width() ||
        previous_.height.height() != labels.height() || region.x0 < 0 || region.y0 < 0 ||
        region.x1 > labels.width() || region.y1 > labels.height()) {
        return false;
    }
    const auto [first, last] = byKey_.equal_range(keyOf(region));
    for (auto it = first; it != last; ++it) {
        const VoidRegion& old = (*previous_.regions)[it->second];
        if (old.pixelCount != region.pixelCount || old.x0 != region.x0 || old.y0 != region.y0 ||
            old.x1 != region.x1 || old.y1 != region.y1 || !sameContour(old, region)) {
            continue;
        }
        // Same box and count: the pixel sets are equal when every pixel of
        // the region was one of the old region's.
        bool same = true;
        for (int y = region.y0; y < region.y1 && same; ++y) {
            const std::int32_t* lab = labels.row(y);
            const std::int32_t* oldLab = previous_.labels.row(y);
            const float* from = previous_.height.row(y);
            float* to = out.row(y);
            for (int x = region.x0; x < region.x1; ++x) {
                if (lab[x] == region.id) {
                    same = same && oldLab[x] == old.id;
                    to[x] = from[x];
                }
            }
        }
        if (same) {
            return true;
        }
    }
    return false;
}

}  // namespace vv::vss::detail
