// SPDX-License-Identifier: GPL-3.0-or-later
// Where a stimulus' two markers go (the paper's "Stimuli"): on visible vessel
// surface, their depths at least a tenth of the image's depth range apart,
// clearly left and right of each other, and the pairs balanced over the
// screen distance, the depth difference and whether the two markers border
// the same void region. From the G-buffer's depth alone (no GL here), and
// reproducible from a seed.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "vv/core/Image.h"

namespace vv::study {

/// A place for a marker: a pixel of a vessel's visible surface.
struct MarkerSite {
    int x = 0;
    int y = 0;
    double depth = 0.0;        ///< the G-buffer's linear depth there
    std::vector<int> regions;  ///< void regions it borders (ids of vss::findVoidRegions)
};

/// One stimulus' two markers, `left` left of `right` on screen.
struct MarkerPair {
    MarkerSite left;
    MarkerSite right;
    /// |depth difference| / the image's vessel depth range, in [0, 1].
    double depthDifference = 0.0;
    /// Screen distance / the image's diagonal.
    double screenDistance = 0.0;
    /// Both markers border a common void region (the VSS joins them there).
    bool sameRegion = false;
    /// Which marker is closer to the viewer (the smaller depth).
    bool leftIsCloser = false;
    /// The stratum it was drawn from: 0..7 = far (4) + large difference (2) +
    /// same region (1); the strata are what the set is balanced over.
    int stratum = 0;
};

struct PairCriteria {
    /// Least depth difference, of the image's vessel depth range (the paper: 10 %).
    double minDepthDifference = 0.10;
    /// Above this depth difference a pair is in the "large difference" strata.
    double largeDepthDifference = 0.25;
    /// Least horizontal distance between the markers, of the image's width.
    double minHorizontalSeparation = 0.12;
    /// |dy| at most this times |dx|: clearly left and right, not above each other.
    double maxSlope = 1.0;
    /// Above this screen distance (of the diagonal) a pair is in the "far" strata.
    double farScreenDistance = 0.35;
    /// The marker's reach, px (its arms; they may lie over anything):
    /// markers keep this far from the image's border.
    int markerRadius = 10;
    /// The marked point's neighbourhood, px: every pixel within it is vessel
    /// and within `flatness` of the centre's depth (one visible surface: not
    /// an edge where a vessel passes behind another, nor a grazing rim).
    int surfaceRadius = 3;
    /// Of the depth range: how far the neighbourhood's depths may stray.
    double flatness = 0.02;
    /// Sites are looked for every this many pixels.
    int siteStep = 4;
};

struct PairSet {
    std::vector<MarkerPair> pairs;
    double depthMin = 0.0;  ///< the image's vessel depth range
    double depthMax = 0.0;
    std::size_t sites = 0;  ///< candidate sites found
    /// Strata that had fewer pairs than their share (their share filled from
    /// the others), in words.
    std::vector<std::string> notes;
};

/// Picks `count` pairs in `depth` (linear depth, +Inf or NaN on background,
/// row 0 at the top), balanced over the 8 strata (as evenly as they allow),
/// each pair at most once, no marker site used twice; the same seed gives the
/// same pairs. Fewer pairs when the image does not hold that many (a note
/// says so). Throws InvalidArgumentError for criteria out of range.
[[nodiscard]] PairSet pickMarkerPairs(ImageView<const float> depth, std::size_t count,
                                      std::uint64_t seed, const PairCriteria& criteria = {});

}  // namespace vv::study
