// SPDX-License-Identifier: GPL-3.0-or-later
// Private to vv::analysis: minimal paths over the internal Voronoi graph
// with cost 1/R (Dijkstra from one source), and the search for the tips a
// closed surface's vessels end in (TEASAR's idea, Sato et al. 2000: the
// farthest vertex not yet covered by the inscribed spheres of the paths
// found so far is the next tip).
#pragma once

#include <cstdint>
#include <vector>

#include "VoronoiGraph.h"
#include "vv/core/Progress.h"

namespace vv::analysis::detail {

/// The shortest-path tree from one Voronoi vertex: one 16-byte record per
/// vertex (its length in float; to 0.1 µm over 1 m) (a relaxation touches one cache line, and the
/// search's records are the tree, not copied into it: it is held through the analysis' peak).
struct PathTree {
    struct Label {
        double cost = 0.0;  ///< integral of ds / R along the path; +inf: unreachable
        /// Arc length of the same path in the graph's units (its frame's
        /// scale: lengthMm() in mm), so that a huge mesh's never overflows.
        float length = 0.0F;
        std::uint32_t previous = 0;  ///< towards the source; UINT32_MAX at the source
    };
    std::uint32_t source = 0;
    double scale = 1.0;  ///< mm per unit of Label::length (the graph's frame)
    std::vector<Label> labels;

    [[nodiscard]] double cost(std::uint32_t v) const { return labels[v].cost; }
    [[nodiscard]] double lengthMm(std::uint32_t v) const {
        return scale * static_cast<double>(labels[v].length);
    }
    [[nodiscard]] std::uint32_t previous(std::uint32_t v) const { return labels[v].previous; }
    [[nodiscard]] bool reaches(std::uint32_t v) const;
    /// The path from the source to `v`, source first. `v` must be reachable.
    [[nodiscard]] std::vector<std::uint32_t> pathTo(std::uint32_t v) const;
};

/// Dijkstra from `source`, an edge costing its length times the mean of 1/R
/// at its ends. Checks for a stop request now and then.
[[nodiscard]] PathTree minimalPaths(const VoronoiGraph& graph, std::uint32_t source,
                                    const Progress& progress);

/// Tips of the vessels that `known` (paths already taken, e.g. to the open
/// ends) do not reach: repeatedly the reachable vertex farthest (along its
/// path) from the source that no inscribed sphere of a path so far, grown by
/// `coverFactor`, holds; it is a tip when its path runs at least
/// `minLengthFactor` times the radius where it leaves the covered part
/// outside it. Returns the tips' vertices, farthest first.
[[nodiscard]] std::vector<std::uint32_t> uncoveredTips(
    const VoronoiGraph& graph, const PathTree& tree,
    const std::vector<std::vector<std::uint32_t>>& known, double coverFactor,
    double minLengthFactor, const Progress& progress);

}  // namespace vv::analysis::detail
