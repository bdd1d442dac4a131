// SPDX-License-Identifier: GPL-3.0-or-later
// The flow data on the demo tree's surface: per vertex the pressure, the wall
// shear stress, the segment id and the generation of its nearest centreline
// piece. See docs/demo-data.md.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

#include "DemoSurfaceDetail.h"
#include "vv/core/Parallel.h"

namespace vv::demo::detail {

namespace {

constexpr double kWssBump = 0.15;      // +-15 % near junctions
constexpr double kWssBumpRadii = 2.0;  // within 2 radii of a junction

/// Per segment: what the point data need besides the tree.
struct SegmentData {
    float pressureIn = 0.0F;
    float pressureOut = 0.0F;
    float length = 0.0F;
    float wss = 0.0F;
    float bumpWidth = 0.0F;  // kWssBumpRadii radii
    float emerges = 0.0F;    // arc length where it leaves its parent's tube: the parent's radius
    bool hasParent = false;
    bool hasChildren = false;
    glm::vec3 dividerDirection{0.0F};  // towards the siblings, across the start tangent
    float generation = 0.0F;
};

std::vector<SegmentData> makeSegmentData(const VesselTree& tree) {
    const auto& segments = tree.segments;
    std::vector<glm::dvec3> startTangent(segments.size());
    for (std::size_t i = 0; i < segments.size(); ++i) {
        const auto& line = segments[i].centerline;
        const glm::dvec3 d = glm::dvec3(line[1]) - glm::dvec3(line[0]);
        const double len = glm::length(d);
        startTangent[i] = len > 0.0 ? d / len : glm::dvec3(0.0);
    }
    std::vector<SegmentData> data(segments.size());
    for (std::size_t i = 0; i < segments.size(); ++i) {
        const auto& s = segments[i];
        SegmentData& d = data[i];
        d.pressureIn = static_cast<float>(s.pressureInMmHg);
        d.pressureOut = static_cast<float>(s.pressureOutMmHg);
        d.length = static_cast<float>(s.lengthMm);
        d.wss = static_cast<float>(s.wssPa);
        d.bumpWidth = static_cast<float>(kWssBumpRadii * s.radiusMm);
        d.emerges = s.parent >= 0
                        ? static_cast<float>(segments[static_cast<std::size_t>(s.parent)].radiusMm)
                        : 0.0F;
        d.hasParent = s.parent >= 0;
        d.hasChildren = !s.children.empty();
        d.generation = static_cast<float>(s.generation);
        if (d.hasParent) {
            glm::dvec3 towards(0.0);
            for (const int sibling : segments[static_cast<std::size_t>(s.parent)].children) {
                if (sibling != s.id) {
                    towards += startTangent[static_cast<std::size_t>(sibling)];
                }
            }
            towards -= startTangent[i] * glm::dot(towards, startTangent[i]);
            const double len = glm::length(towards);
            d.dividerDirection = len > 1e-9 ? glm::vec3(towards / len) : glm::vec3(0.0F);
        }
    }
    return data;
}

/// A smooth bump: 1 at distance 0, falling to 0 (with zero slope) at width.
inline float bump(float distance, float width) {
    if (!(distance < width)) {
        return 0.0F;
    }
    const float u = distance / width;
    const float v = 1.0F - u * u;
    return v * v;
}

/// Nearest centreline piece of p by distance to the drawn tube wall; ties go to
/// the lower piece index. Searches p's bin, or everything when the bin is empty.
std::uint32_t nearestPiece(const glm::vec3& p, const std::vector<Piece>& pieces, const Bins& bins,
                           float& tOut) {
    auto candidates = bins.at(bins.binOf(p));
    std::uint32_t best = 0;
    float bestDistance = std::numeric_limits<float>::max();
    const auto visit = [&](std::uint32_t index) {
        float t = 0.0F;
        const Piece& piece = pieces[index];
        const float d = std::sqrt(pieceDistance2(piece, p, t)) - piece.radius;
        if (d < bestDistance) {
            bestDistance = d;
            best = index;
            tOut = t;
        }
    };
    if (candidates.empty()) {
        for (std::uint32_t i = 0; i < pieces.size(); ++i) {
            visit(i);
        }
    } else {
        for (const std::uint32_t index : candidates) {
            visit(index);
        }
    }
    return best;
}

}  // namespace

void addFlowFields(scene::Mesh& mesh, const VesselTree& tree, const std::vector<Piece>& pieces,
                   const Bins& bins, const Progress& progress) {
    const std::vector<SegmentData> segments = makeSegmentData(tree);
    const std::size_t n = mesh.positions.size();
    scene::DataArray pressure{"pressure", "mmHg", 1, std::vector<float>(n), false, false};
    scene::DataArray wss{"wss", "Pa", 1, std::vector<float>(n), false, false};
    scene::DataArray segmentId{"segment_id", "", 1, std::vector<float>(n), true, false};
    scene::DataArray generation{"generation", "", 1, std::vector<float>(n), true, false};

    const auto body = [&](long begin, long end) {
        for (long v = begin; v < end; ++v) {
            const auto i = static_cast<std::size_t>(v);
            const glm::vec3& p = mesh.positions[i];
            float t = 0.0F;
            const Piece& piece = pieces[nearestPiece(p, pieces, bins, t)];
            const SegmentData& s = segments[static_cast<std::size_t>(piece.segment)];
            const float arc = piece.arcStart + t * piece.length;
            const float along = s.length > 0.0F ? std::clamp(arc / s.length, 0.0F, 1.0F) : 0.0F;
            pressure.values[i] = s.pressureIn + (s.pressureOut - s.pressureIn) * along;

            float factor = 1.0F;
            if (s.hasChildren) {
                // Into the junction the cross-section widens and the flow slows.
                factor *= 1.0F - static_cast<float>(kWssBump) * bump(s.length - arc, s.bumpWidth);
            }
            if (s.hasParent) {
                // Out of it the flow divider (facing the siblings) sees more
                // shear, the outer wall less.
                const glm::vec3 radial = p - (piece.a + piece.ab * t);
                const float len = glm::length(radial);
                const float facing = len > 0.0F ? glm::dot(radial / len, s.dividerDirection) : 0.0F;
                factor *= 1.0F + static_cast<float>(kWssBump) * facing *
                                     bump(std::max(0.0F, arc - s.emerges), s.bumpWidth);
            }
            wss.values[i] = s.wss * factor;
            segmentId.values[i] = static_cast<float>(piece.segment);
            generation.values[i] = s.generation;
        }
    };
    constexpr long kBatches = 5;
    const auto total = static_cast<long>(n);
    for (long batch = 0; batch < kBatches; ++batch) {
        progress.report(static_cast<double>(batch) / kBatches, "Assigning vessel data");
        parallelFor(total * batch / kBatches, total * (batch + 1) / kBatches, 2048, body,
                    progress.stopToken());
    }
    mesh.pointArrays.push_back(std::move(pressure));
    mesh.pointArrays.push_back(std::move(wss));
    mesh.pointArrays.push_back(std::move(segmentId));
    mesh.pointArrays.push_back(std::move(generation));
    progress.report(1.0, "Assigning vessel data");
}

}  // namespace vv::demo::detail
