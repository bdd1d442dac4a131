// SPDX-License-Identifier: GPL-3.0-or-later
// The fast VSS solver's per-p tables (FastTables.h).
#include "FastTables.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <memory>
#include <mutex>
#include <utility>

namespace vv::vss::detail::fast {

PowerTables::PowerTables(double pIn) : p(pIn), halfP(pIn / 2.0) {
    for (int e = 0; e <= 5; ++e) {
        if (halfP == static_cast<double>(1 << e)) {
            squarings = e;
        }
    }
    // measured on the micro-benchmark: 10 is fastest for p <= 16 (fewer,
    // larger clusters outweigh the O(degree^3) translations), 8 above
    degree = p <= 16.0 ? 10 : 8;
    c.resize(kMaxTerms + 1);
    c[0] = 1.0;
    for (int n = 1; n <= kMaxTerms; ++n) {
        c[n] = c[n - 1] * (p + n - 1) / n;
    }
    ratio.resize(kMaxTerms + 1);
    for (int n = 0; n <= kMaxTerms; ++n) {
        ratio[static_cast<std::size_t>(n)] = std::max(1.0, (p + n) / (n + 1.0));
    }
    std::array<double, 2 * kS> poch{};
    poch[0] = 1.0;
    for (int k = 1; k < 2 * kS; ++k) {
        poch[k] = poch[k - 1] * (halfP + k - 1);
    }
    std::array<double, kS> fact{};
    fact[0] = 1.0;
    for (int k = 1; k < kS; ++k) {
        fact[k] = fact[k - 1] * k;
    }
    for (int l = 0; l < kS; ++l) {
        for (int r = 0; l + r < kS; ++r) {
            h[l][r] = ((l % 2 == 0) ? 1.0 : -1.0) * poch[l + r] / (fact[l] * fact[r]);
        }
    }
    for (int n = 0; n < kS; ++n) {
        binom[n][0] = 1.0;
        for (int k = 1; k <= n; ++k) {
            binom[n][k] = binom[n - 1][k - 1] + (k <= n - 1 ? binom[n - 1][k] : 0.0);
        }
    }
    poly.assign(static_cast<std::size_t>(kS * kS * kS), Cx{0.0, 0.0});
    const Cx ipow[4] = {{1.0, 0.0}, {0.0, 1.0}, {-1.0, 0.0}, {0.0, -1.0}};
    for (int l = 0; l < kS; ++l) {
        for (int lp = 0; l + lp < kS; ++lp) {
            for (int ea = 0; ea <= l; ++ea) {
                for (int eb = 0; eb <= lp; ++eb) {
                    // C(l,a) C(l',b) u^{l+l'-a-b} v^{a+b} i^{a+b} (-1)^b
                    const double coef = binom[l][ea] * binom[lp][eb] * ((eb % 2 == 0) ? 1.0 : -1.0);
                    poly[static_cast<std::size_t>((l * kS + lp) * kS + ea + eb)] +=
                        coef * ipow[(ea + eb) % 4];
                }
            }
        }
    }
}

bool distanceTableFits(double p, double d) {
    return p * std::log2(std::max(d, 1.0)) <= 96.0;
}

namespace {

// The table for tab.p (distanceTable): the quadrant dx, dy >= 0, then its
// mirror images.
std::shared_ptr<const std::vector<float>> buildDistanceTable(const PowerTables& tab) {
    constexpr int kH = kDistTableHalf;
    constexpr auto kStride = static_cast<std::size_t>(kDistTableStride);
    auto w = std::make_shared<std::vector<float>>(kStride * kStride, 0.0F);
    for (int dy = 0; dy < kH + kLeafTile; ++dy) {
        float* row = &(*w)[static_cast<std::size_t>(kH + dy) * kStride];
        for (int dx = 0; dx < kH + kLeafTile; ++dx) {
            const double d2 = static_cast<double>(dx) * dx + static_cast<double>(dy) * dy;
            // d = 0 is a contour pixel, never a region pixel: its lane is not used
            row[kH + dx] = d2 > 0.0 ? static_cast<float>(tab.pw(1.0 / d2))
                                    : std::numeric_limits<float>::infinity();
        }
        for (int dx = 1; dx <= kH; ++dx) {
            row[kH - dx] = row[kH + dx];
        }
    }
    for (int dy = 1; dy <= kH; ++dy) {
        std::copy_n(&(*w)[static_cast<std::size_t>(kH + dy) * kStride], kStride,
                    &(*w)[static_cast<std::size_t>(kH - dy) * kStride]);
    }
    return w;
}

}  // namespace

std::shared_ptr<const std::vector<float>> distanceTable(const PowerTables& tab) {
    // the farthest entry: dx = dy = kDistTableHalf + 15
    if (!distanceTableFits(tab.p, std::hypot(kDistTableHalf + kLeafTile - 1.0,
                                             kDistTableHalf + kLeafTile - 1.0))) {
        return nullptr;
    }
    // the tables of the last kKept powers, most recent first
    constexpr std::size_t kKept = 4;
    static std::mutex mutex;
    static std::vector<std::pair<double, std::shared_ptr<const std::vector<float>>>> kept;
    const std::scoped_lock lock(mutex);
    const auto it =
        std::find_if(kept.begin(), kept.end(), [&tab](const auto& e) { return e.first == tab.p; });
    if (it != kept.end()) {
        std::rotate(kept.begin(), it, it + 1);
        return kept.front().second;
    }
    kept.insert(kept.begin(), {tab.p, buildDistanceTable(tab)});
    if (kept.size() > kKept) {
        kept.pop_back();
    }
    return kept.front().second;
}

}  // namespace vv::vss::detail::fast
