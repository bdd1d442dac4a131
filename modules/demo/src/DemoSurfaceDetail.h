// SPDX-License-Identifier: GPL-3.0-or-later
// Private to vv::demo: what the surface of the demo tree (DemoSurface.cpp) and
// its per-vertex flow data (DemoFlowFields.cpp) share: the straight pieces of
// the centrelines and their bins.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <glm/glm.hpp>
#include <span>
#include <vector>

#include "vv/core/Progress.h"
#include "vv/demo/DemoTree.h"
#include "vv/scene/Mesh.h"

namespace vv::demo::detail {

/// One straight piece of a centreline, with what the field and the point data need.
struct Piece {
    glm::vec3 a{0.0F};
    glm::vec3 ab{0.0F};
    float invLength2 = 0.0F;  // 0 for a degenerate piece
    float length = 0.0F;
    float arcStart = 0.0F;  // arc length of a along its segment, mm
    float radius = 0.0F;    // drawn radius, mm
    float blend = 0.0F;     // smooth-union width, mm
    int segment = 0;
};

/// Pieces binned into a coarse grid: a bin lists (in piece order, so grouped by
/// segment) every piece whose box padded by radius + blend + band reaches it.
/// Outside those boxes a piece cannot change the clamped field.
struct Bins {
    glm::dvec3 origin{0.0};
    double size = 0.0;
    int nx = 0;
    int ny = 0;
    int nz = 0;
    std::vector<std::uint32_t> start;  // nx * ny * nz + 1 offsets into items
    std::vector<std::uint32_t> items;  // piece indices
    /// The items of one segment within a bin.
    struct Run {
        int segment = 0;
        std::uint32_t begin = 0;
        std::uint32_t end = 0;
    };
    std::vector<std::uint32_t> runStart;  // nx * ny * nz + 1 offsets into runs
    std::vector<Run> runs;                // per bin in segment order
    std::size_t maxRunsPerBin = 0;

    [[nodiscard]] long count() const { return static_cast<long>(nx) * ny * nz; }
    [[nodiscard]] std::span<const std::uint32_t> at(long bin) const {
        const auto b = static_cast<std::size_t>(bin);
        return {items.data() + start[b], items.data() + start[b + 1]};
    }
    [[nodiscard]] std::span<const Run> runsAt(long bin) const {
        const auto b = static_cast<std::size_t>(bin);
        return {runs.data() + runStart[b], runs.data() + runStart[b + 1]};
    }
    [[nodiscard]] long binOf(const glm::vec3& p) const {
        const auto index = [&](float v, double o, int n) {
            const double i = std::floor((static_cast<double>(v) - o) / size);
            return static_cast<long>(std::clamp(i, 0.0, static_cast<double>(n - 1)));
        };
        return index(p.x, origin.x, nx) +
               static_cast<long>(nx) *
                   (index(p.y, origin.y, ny) + static_cast<long>(ny) * index(p.z, origin.z, nz));
    }
};

/// Closest point parameter t in [0, 1] on the piece and the squared distance.
inline float pieceDistance2(const Piece& piece, const glm::vec3& p, float& t) {
    const glm::vec3 ap = p - piece.a;
    t = std::clamp(glm::dot(ap, piece.ab) * piece.invLength2, 0.0F, 1.0F);
    const glm::vec3 d = ap - piece.ab * t;
    return glm::dot(d, d);
}

/// Adds the point arrays `pressure` [mmHg], `wss` [Pa], `segment_id` and
/// `generation` to the surface of the tree: each vertex takes the values of
/// its nearest piece (nearest tube wall; ties to the lower piece index) at the
/// closest point along it, pressure interpolated along the segment, wall shear
/// stress modulated near the junctions. pieces and bins are those the surface
/// was extracted with. Reports progress; throws CancelledError when stopped.
void addFlowFields(scene::Mesh& mesh, const VesselTree& tree, const std::vector<Piece>& pieces,
                   const Bins& bins, const Progress& progress);

}  // namespace vv::demo::detail
