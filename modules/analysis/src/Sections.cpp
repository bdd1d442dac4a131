// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/analysis/Sections.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <optional>
#include <unordered_map>
#include <utility>

#include "AnalysisSteps.h"
#include "ContourSize.h"
#include "PreparedSurface.h"
#include "SurfaceIndex.h"
#include "vv/core/Parallel.h"

namespace vv::analysis {
namespace {

using detail::PreparedSurface;
using detail::SurfaceIndex;

/// A cut's contour points sit on mesh edges: an edge names its point.
using EdgeKey = std::uint64_t;
constexpr EdgeKey kNoEdge = UINT64_MAX;
EdgeKey edgeKey(std::uint32_t a, std::uint32_t b) {
    return a < b ? (static_cast<EdgeKey>(a) << 32U) | b : (static_cast<EdgeKey>(b) << 32U) | a;
}

/// The plane's cut through `triangles`: closed loops of points (open
/// chains, where the surface has a hole, are dropped).
class PlaneCut {
  public:
    PlaneCut(const PreparedSurface& s, const glm::dvec3& point, const glm::dvec3& normal)
        : s_(s), point_(point), normal_(normal) {}

    std::vector<std::vector<glm::dvec3>> loops(const std::vector<std::uint32_t>& triangles) {
        for (const std::uint32_t t : triangles) {
            addTriangle(s_.triangles[t]);
        }
        std::vector<std::vector<glm::dvec3>> result;
        std::unordered_map<EdgeKey, bool> used;
        for (const auto& [start, linked] : links_) {
            if (used[start] || linked.size() != 2) {
                continue;
            }
            std::vector<glm::dvec3> loop;
            EdgeKey previous = kNoEdge;
            EdgeKey at = start;
            bool closed = false;
            while (true) {
                used[at] = true;
                loop.push_back(points_.at(at));
                const auto around = links_.find(at);
                if (around == links_.end() || around->second.size() != 2) {
                    break;  // a hole or a non-manifold edge: not a closed lumen
                }
                const auto& ends = around->second;
                const EdgeKey following = ends[0] != previous ? ends[0] : ends[1];
                previous = at;
                at = following;
                if (at == start) {
                    closed = true;
                    break;
                }
                if (used[at]) {
                    break;
                }
            }
            if (closed && loop.size() >= 3) {
                result.push_back(std::move(loop));
            }
        }
        return result;
    }

  private:
    /// Signed distance to the plane; a point on it counts as above, so
    /// that every edge is either crossed or not.
    [[nodiscard]] double side(std::uint32_t v) const {
        const double d = glm::dot(s_.positions[v] - point_, normal_);
        return d == 0.0 ? std::numeric_limits<double>::min() : d;
    }

    void addTriangle(const detail::Triangle& t) {
        std::array<EdgeKey, 2> crossed{};
        int count = 0;
        for (int e = 0; e < 3 && count < 2; ++e) {
            const std::uint32_t a = t[static_cast<std::size_t>(e)];
            const std::uint32_t b = t[static_cast<std::size_t>((e + 1) % 3)];
            const double da = side(a);
            const double db = side(b);
            if ((da > 0.0) == (db > 0.0)) {
                continue;
            }
            const EdgeKey key = edgeKey(a, b);
            if (!points_.contains(key)) {
                const double u = da / (da - db);
                points_[key] = s_.positions[a] + u * (s_.positions[b] - s_.positions[a]);
            }
            crossed[static_cast<std::size_t>(count++)] = key;
        }
        if (count == 2) {
            links_[crossed[0]].push_back(crossed[1]);
            links_[crossed[1]].push_back(crossed[0]);
        }
    }

    const PreparedSurface& s_;
    glm::dvec3 point_;
    glm::dvec3 normal_;
    std::unordered_map<EdgeKey, glm::dvec3> points_;
    std::unordered_map<EdgeKey, std::vector<EdgeKey>> links_;
};

double signedArea(const std::vector<glm::dvec2>& contour) {
    double twice = 0.0;
    for (std::size_t i = 0; i < contour.size(); ++i) {
        const glm::dvec2& a = contour[i];
        const glm::dvec2& b = contour[(i + 1) % contour.size()];
        twice += a.x * b.y - b.x * a.y;
    }
    return 0.5 * twice;
}

/// Of the loops that hold the centre, the smallest; nullopt when none does.
std::optional<std::vector<glm::dvec2>> lumenContour(
    const std::vector<std::vector<glm::dvec3>>& loops, const CrossSection& section) {
    std::optional<std::vector<glm::dvec2>> best;
    double bestArea = 0.0;
    for (const auto& loop : loops) {
        std::vector<glm::dvec2> flat;
        flat.reserve(loop.size());
        for (const glm::dvec3& p : loop) {
            const glm::dvec3 d = p - section.centre;
            flat.emplace_back(glm::dot(d, section.axisU), glm::dot(d, section.axisV));
        }
        if (!detail::contourHolds(flat, glm::dvec2(0.0))) {
            continue;
        }
        const double area = std::abs(signedArea(flat));
        if (!best || area < bestArea) {
            bestArea = area;
            best = std::move(flat);
        }
    }
    if (best && signedArea(*best) < 0.0) {
        std::reverse(best->begin(), best->end());
    }
    return best;
}

CrossSection sectionAt(const PreparedSurface& s, const SurfaceIndex& index, const Branch& branch,
                       int branchId, std::size_t i, double step) {
    const CenterlinePoint& p = branch.points[i];
    CrossSection section;
    section.branch = branchId;
    section.pointIndex = i;
    section.abscissaMm = p.abscissaMm;
    section.centre = p.position;
    section.normal = p.tangent;
    section.axisU = p.normal;
    section.axisV = glm::cross(p.tangent, p.normal);
    section.inscribedDiameterMm = 2.0 * p.radiusMm;
    // Look near the point first (the lumen lies within a few inscribed
    // radii of it), then farther (an oval or a bulging lumen).
    for (const double reach : {6.0, 24.0}) {
        const glm::dvec3 half(reach * std::max(p.radiusMm, step));
        PlaneCut cut(s, p.position, p.tangent);
        const auto contour =
            lumenContour(cut.loops(index.trianglesOnPlane(p.position, p.tangent, p.position - half,
                                                          p.position + half)),
                         section);
        if (contour) {
            section.contour = *contour;
            break;
        }
    }
    if (section.contour.empty()) {
        return section;
    }
    const detail::ContourSize size = detail::measureContour(section.contour);
    section.status = CrossSection::Status::Ok;
    section.areaMm2 = size.area;
    section.perimeterMm = size.perimeter;
    section.equivalentDiameterMm = 2.0 * std::sqrt(size.area / std::numbers::pi);
    section.minDiameterMm = size.minFeret;
    section.maxDiameterMm = size.maxFeret;
    section.circularity = size.perimeter > 0.0 ? 4.0 * std::numbers::pi * size.area /
                                                     (size.perimeter * size.perimeter)
                                               : 0.0;
    section.centreOffsetMm = glm::length(size.centroid);
    return section;
}

}  // namespace

EndZones endZones(const Branch& branch) {
    if (branch.points.empty()) {
        return {};
    }
    // A closed tip's cap, where the radius grows from 0 on the surface to
    // the vessel's, is one radius long; a junction's end point lies in the
    // merged lumen, whose radius is the larger.
    std::vector<double> radii;
    radii.reserve(branch.points.size());
    for (const CenterlinePoint& p : branch.points) {
        radii.push_back(p.radiusMm);
    }
    const auto middle = radii.begin() + static_cast<std::ptrdiff_t>(radii.size() / 2);
    std::nth_element(radii.begin(), middle, radii.end());
    return {.startMm = std::max(2.0 * *middle, 1.5 * branch.points.front().radiusMm),
            .endMm = std::max(2.0 * *middle, 1.5 * branch.points.back().radiusMm)};
}

bool EndZones::contains(const Branch& branch, std::size_t i) const noexcept {
    if (i >= branch.points.size()) {
        return false;
    }
    const double at = branch.points[i].abscissaMm;
    return at < branch.points.front().abscissaMm + startMm ||
           at > branch.points.back().abscissaMm - endMm;
}

std::vector<std::vector<CrossSection>> computeSections(const scene::Mesh& mesh,
                                                       const CenterlineTree& tree,
                                                       const Progress& progress) {
    if (tree.branches.empty()) {
        return {};
    }
    const PreparedSurface s = detail::prepareSurface(
        mesh, tree.branches.front().points.front().position, progress, kDefaultMaxTriangles);
    const SurfaceIndex index(s);
    return detail::sectionsOf(s, index, tree, progress);
}

std::vector<std::vector<CrossSection>> detail::sectionsOf(const PreparedSurface& s,
                                                          const SurfaceIndex& index,
                                                          const CenterlineTree& tree,
                                                          const Progress& progress) {
    std::vector<std::vector<CrossSection>> sections(tree.branches.size());
    // Every (branch, point) as one job: the sections are independent, cut on
    // every core (the index is only read) in batches, progress between them.
    std::vector<std::pair<std::size_t, std::size_t>> jobs;
    std::vector<double> steps(tree.branches.size(), 0.5);
    std::vector<EndZones> zones(tree.branches.size());
    for (std::size_t b = 0; b < tree.branches.size(); ++b) {
        const Branch& branch = tree.branches[b];
        sections[b].resize(branch.points.size());
        zones[b] = endZones(branch);
        if (branch.points.size() > 1) {
            steps[b] = branch.points[1].abscissaMm - branch.points[0].abscissaMm;
        }
        for (std::size_t i = 0; i < branch.points.size(); ++i) {
            jobs.emplace_back(b, i);
        }
    }
    constexpr std::size_t kBatch = 512;
    progress.report(0.0, "Cutting the sections");
    for (std::size_t first = 0; first < jobs.size(); first += kBatch) {
        const std::size_t last = std::min(jobs.size(), first + kBatch);
        parallelFor(
            static_cast<long>(first), static_cast<long>(last), 16,
            [&](long begin, long end) {
                for (long j = begin; j < end; ++j) {
                    const auto [b, i] = jobs[static_cast<std::size_t>(j)];
                    const Branch& branch = tree.branches[b];
                    CrossSection& section = sections[b][i];
                    section = sectionAt(s, index, branch, static_cast<int>(b), i, steps[b]);
                    section.inEndZone = zones[b].contains(branch, i);
                }
            },
            progress.stopToken());
        progress.report(static_cast<double>(last) / static_cast<double>(jobs.size()),
                        "Cutting the sections");
    }
    return sections;
}

}  // namespace vv::analysis
