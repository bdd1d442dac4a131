// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/study/MarkerPairs.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <set>

#include "vv/core/Error.h"
#include "vv/vss/VoidRegions.h"

namespace vv::study {
namespace {

constexpr int kStrata = 8;
/// How far a site looks for the void regions it borders, px (wider vessels
/// border none: their markers count as in no common region).
constexpr int kRegionReach = 120;
/// Random pair draws per pair asked for (the strata fill from them).
constexpr std::size_t kDrawsPerPair = 4000;

void checkCriteria(const PairCriteria& c) {
    const auto fraction = [](double v) { return v >= 0.0 && v <= 1.0; };
    if (!fraction(c.minDepthDifference) || !fraction(c.largeDepthDifference) ||
        !fraction(c.minHorizontalSeparation) || !fraction(c.farScreenDistance) ||
        !fraction(c.flatness) || !(c.maxSlope > 0.0) || c.markerRadius < 1 ||
        c.markerRadius > 200 || c.surfaceRadius < 0 || c.surfaceRadius > c.markerRadius ||
        c.siteStep < 1 || c.siteStep > 200) {
        throw InvalidArgumentError(
            "marker pair criteria out of range (fractions in [0, 1], a positive slope, a "
            "marker radius and a site step of 1 to 200 px, a surface radius up to the "
            "marker's)");
    }
}

bool isVessel(float d) {
    return std::isfinite(d);
}

/// Whether the marked point's neighbourhood around (x, y) lies on one
/// visible surface.
bool flatFootprint(ImageView<const float> depth, int x, int y, int radius, double tolerance) {
    const float centre = depth(x, y);
    for (int dy = -radius; dy <= radius; ++dy) {
        for (int dx = -radius; dx <= radius; ++dx) {
            if (dx * dx + dy * dy > radius * radius) {
                continue;
            }
            const float d = depth(x + dx, y + dy);
            if (!isVessel(d) || std::abs(d - centre) > tolerance) {
                return false;
            }
        }
    }
    return true;
}

/// The void regions on either side of the vessel at (x, y): along each of
/// 8 axes through it the first void pixel both ways (up to kRegionReach);
/// the axis across which the vessel is narrowest (the shortest such chord)
/// gives the regions. Empty when no axis finds void both ways.
std::vector<int> borderingRegions(const Image<std::int32_t>& labels, int x, int y) {
    constexpr int kAxes = 8;
    const auto firstVoid = [&](double dx, double dy) -> std::pair<int, std::int32_t> {
        for (int step = 1; step <= kRegionReach; ++step) {
            const int xx = x + static_cast<int>(std::lround(dx * step));
            const int yy = y + static_cast<int>(std::lround(dy * step));
            if (xx < 0 || yy < 0 || xx >= labels.width() || yy >= labels.height()) {
                return {-1, vss::kVesselLabel};  // the image's border: no region that way
            }
            const std::int32_t label = labels.view()(xx, yy);
            if (label != vss::kVesselLabel) {
                return {step, label};
            }
        }
        return {-1, vss::kVesselLabel};
    };
    int best = std::numeric_limits<int>::max();
    std::vector<int> regions;
    for (int a = 0; a < kAxes; ++a) {
        const double angle = std::numbers::pi * a / kAxes;
        const auto [forward, ahead] = firstVoid(std::cos(angle), std::sin(angle));
        const auto [backward, behind] = firstVoid(-std::cos(angle), -std::sin(angle));
        if (forward > 0 && backward > 0 && forward + backward < best) {
            best = forward + backward;
            regions = {ahead, behind};
        }
    }
    std::ranges::sort(regions);
    regions.erase(std::unique(regions.begin(), regions.end()), regions.end());
    return regions;
}

bool share(const std::vector<int>& a, const std::vector<int>& b) {
    return std::ranges::any_of(a, [&](int r) { return std::ranges::binary_search(b, r); });
}

const char* stratumName(int s) {
    static constexpr std::array<const char*, kStrata> kNames{
        "near, small depth difference, different regions",
        "near, small depth difference, same region",
        "near, large depth difference, different regions",
        "near, large depth difference, same region",
        "far, small depth difference, different regions",
        "far, small depth difference, same region",
        "far, large depth difference, different regions",
        "far, large depth difference, same region"};
    return kNames[static_cast<std::size_t>(s)];
}

}  // namespace

PairSet pickMarkerPairs(ImageView<const float> depth, std::size_t count, std::uint64_t seed,
                        const PairCriteria& c) {
    checkCriteria(c);
    PairSet set;
    const int w = depth.width();
    const int h = depth.height();
    Image<std::uint8_t> mask(w, h, 0);
    double lo = std::numeric_limits<double>::infinity();
    double hi = -std::numeric_limits<double>::infinity();
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            if (isVessel(depth(x, y))) {
                mask.view()(x, y) = 1;
                lo = std::min(lo, static_cast<double>(depth(x, y)));
                hi = std::max(hi, static_cast<double>(depth(x, y)));
            }
        }
    }
    if (!(hi > lo)) {
        set.notes.emplace_back("the image shows no vessel with a depth range: no pairs");
        return set;
    }
    set.depthMin = lo;
    set.depthMax = hi;
    const double range = hi - lo;
    const vss::VoidRegionSet regions = vss::findVoidRegions(mask.view());

    std::vector<MarkerSite> sites;
    const int r = c.markerRadius;
    for (int y = r; y < h - r; y += c.siteStep) {
        for (int x = r; x < w - r; x += c.siteStep) {
            if (isVessel(depth(x, y)) &&
                flatFootprint(depth, x, y, c.surfaceRadius, c.flatness * range)) {
                sites.push_back({x, y, depth(x, y), borderingRegions(regions.labels, x, y)});
            }
        }
    }
    set.sites = sites.size();

    // Random draws sorted into the strata; the first of each stratum are its
    // share, the rest its reserve.
    std::array<std::vector<MarkerPair>, kStrata> strata;
    std::set<std::pair<std::size_t, std::size_t>> drawn;
    std::mt19937_64 random(seed);
    const double diagonal = std::hypot(static_cast<double>(w), static_cast<double>(h));
    const std::size_t draws =
        sites.size() < 2 ? 0 : kDrawsPerPair * std::max<std::size_t>(count, 1);
    for (std::size_t d = 0; d < draws; ++d) {
        std::size_t i = random() % sites.size();
        std::size_t j = random() % sites.size();
        if (i == j) {
            continue;
        }
        if (sites[i].x > sites[j].x) {
            std::swap(i, j);
        }
        const MarkerSite& a = sites[i];
        const MarkerSite& b = sites[j];
        const double dx = b.x - a.x;
        const double dy = std::abs(b.y - a.y);
        const double difference = std::abs(a.depth - b.depth) / range;
        if (dx < c.minHorizontalSeparation * w || dy > c.maxSlope * dx ||
            difference < c.minDepthDifference || !drawn.emplace(i, j).second) {
            continue;
        }
        MarkerPair pair{a,
                        b,
                        difference,
                        std::hypot(dx, dy) / diagonal,
                        share(a.regions, b.regions),
                        a.depth < b.depth,
                        0};
        pair.stratum = (pair.screenDistance > c.farScreenDistance ? 4 : 0) +
                       (difference > c.largeDepthDifference ? 2 : 0) + (pair.sameRegion ? 1 : 0);
        auto& bucket = strata[static_cast<std::size_t>(pair.stratum)];
        if (bucket.size() < count) {
            bucket.push_back(pair);
        }
    }

    // Round-robin over the strata; a site serves one pair only.
    std::set<std::pair<int, int>> used;
    const auto take = [&](std::vector<MarkerPair>& bucket, std::size_t& at) {
        while (at < bucket.size()) {
            const MarkerPair& p = bucket[at++];
            if (!used.contains({p.left.x, p.left.y}) && !used.contains({p.right.x, p.right.y})) {
                used.insert({p.left.x, p.left.y});
                used.insert({p.right.x, p.right.y});
                set.pairs.push_back(p);
                return true;
            }
        }
        return false;
    };
    std::array<std::size_t, kStrata> at{};
    std::array<std::size_t, kStrata> taken{};
    const std::size_t share = (count + kStrata - 1) / kStrata;
    for (std::size_t round = 0; round < share && set.pairs.size() < count; ++round) {
        for (int s = 0; s < kStrata && set.pairs.size() < count; ++s) {
            if (take(strata[static_cast<std::size_t>(s)], at[static_cast<std::size_t>(s)])) {
                ++taken[static_cast<std::size_t>(s)];
            }
        }
    }
    // Short strata's shares from the others' reserves, still in turn.
    for (bool progress = true; progress && set.pairs.size() < count;) {
        progress = false;
        for (int s = 0; s < kStrata && set.pairs.size() < count; ++s) {
            if (take(strata[static_cast<std::size_t>(s)], at[static_cast<std::size_t>(s)])) {
                ++taken[static_cast<std::size_t>(s)];
                progress = true;
            }
        }
    }
    const std::size_t fair = count / kStrata;
    for (int s = 0; s < kStrata; ++s) {
        if (taken[static_cast<std::size_t>(s)] < fair) {
            set.notes.push_back(std::string(stratumName(s)) + ": " +
                                std::to_string(taken[static_cast<std::size_t>(s)]) + " of " +
                                std::to_string(fair) + " pairs (the image has too few)");
        }
    }
    if (set.pairs.size() < count) {
        set.notes.push_back(std::to_string(set.pairs.size()) + " of " + std::to_string(count) +
                            " pairs: the image has no more that meet the criteria");
    }
    return set;
}

}  // namespace vv::study
