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
#include "VoronoiSamples.h"
#include "WallSmoothing.h"
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

/// A closed loop of the cut: its points and the wall's normal at each (in
/// the plane, unit; zero where the normals give none).
struct CutLoop {
    std::vector<glm::dvec3> points;
    std::vector<glm::dvec3> normals;
};

/// A lumen contour in the section's plane coordinates, counter-clockwise,
/// with the wall's normal at each point.
struct FlatContour {
    std::vector<glm::dvec2> points;
    std::vector<glm::dvec2> normals;
};

/// Edges whose normals turn by more than 60 degrees (cosine below this)
/// are creases, not a sampled curve: cut straight.
constexpr double kCreaseCosine = 0.5;

/// The plane's cut through `triangles`: closed loops of points (open
/// chains, where the surface has a hole, are dropped), each on the curved
/// wall the edge's normals describe.
class PlaneCut {
  public:
    /// A point of the cut and the wall's normal there (in the plane, unit;
    /// zero where the normals give none).
    struct CutPoint {
        glm::dvec3 point{0.0};
        glm::dvec3 normal{0.0};
    };

    PlaneCut(const PreparedSurface& s, const glm::dvec3& point, const glm::dvec3& normal)
        : s_(s), point_(point), normal_(normal) {}

    std::vector<CutLoop> loops(const std::vector<std::uint32_t>& triangles) {
        for (const std::uint32_t t : triangles) {
            addTriangle(s_.triangles[t]);
        }
        std::vector<CutLoop> result;
        std::unordered_map<EdgeKey, bool> used;
        for (const auto& [start, linked] : links_) {
            if (used[start] || linked.size() != 2) {
                continue;
            }
            CutLoop loop;
            EdgeKey previous = kNoEdge;
            EdgeKey at = start;
            bool closed = false;
            while (true) {
                used[at] = true;
                const CutPoint& cut = points_.at(at);
                loop.points.push_back(cut.point);
                loop.normals.push_back(cut.normal);
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
            if (closed && loop.points.size() >= 3) {
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

    /// The point at `u` along the edge (a, b), moved off the straight edge
    /// onto the curved wall its end normals describe: a faceted surface's
    /// edge is a chord of the vessel's wall. A wall whose normals turn from
    /// n_a to n_b over the chord d = b - a (a circle's arc, whatever the
    /// chord's slant along a tube) lies (d . (n_b - n_a)) / 8 from the
    /// chord's middle, outward where the normals spread (convex), inward
    /// where they close; at u, 4 u (1 - u) times that (a parabola). Moved
    /// along the normal interpolated at u, within the cut plane, which is
    /// returned with the point (straight across a crease). On a fine
    /// smooth surface the move is tiny; on a 1k tube it restores the circle
    /// the polygon's chords cut inside.
    [[nodiscard]] CutPoint onCurvedEdge(std::uint32_t a, std::uint32_t b, double u) const {
        const glm::dvec3& pa = s_.positions[a];
        const glm::dvec3& pb = s_.positions[b];
        const glm::dvec3& na = s_.cappedNormals[a];
        const glm::dvec3& nb = s_.cappedNormals[b];
        CutPoint cut{.point = pa + u * (pb - pa), .normal = (1.0 - u) * na + u * nb};
        cut.normal -= glm::dot(cut.normal, normal_) * normal_;
        const double norm = glm::length(cut.normal);
        if (!(norm > 0.0)) {
            cut.normal = glm::dvec3(0.0);  // no normal: cut straight
            return cut;
        }
        cut.normal /= norm;
        if (glm::dot(na, nb) >= kCreaseCosine) {  // not a crease the normals do not describe
            const double sag = glm::dot(pb - pa, nb - na) / 8.0;
            cut.point += 4.0 * u * (1.0 - u) * sag * cut.normal;
        }
        return cut;
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
            const auto [at, added] = points_.try_emplace(key);
            if (added) {
                at->second = onCurvedEdge(a, b, da / (da - db));
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
    std::unordered_map<EdgeKey, CutPoint> points_;
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
std::optional<FlatContour> lumenContour(const std::vector<CutLoop>& loops,
                                        const CrossSection& section) {
    std::optional<FlatContour> best;
    double bestArea = 0.0;
    const auto flatten = [&](const glm::dvec3& d) {
        return glm::dvec2(glm::dot(d, section.axisU), glm::dot(d, section.axisV));
    };
    for (const auto& loop : loops) {
        FlatContour flat;
        flat.points.reserve(loop.points.size());
        for (std::size_t i = 0; i < loop.points.size(); ++i) {
            flat.points.push_back(flatten(loop.points[i] - section.centre));
            flat.normals.push_back(flatten(loop.normals[i]));
        }
        if (!detail::contourHolds(flat.points, glm::dvec2(0.0))) {
            continue;
        }
        const double area = std::abs(signedArea(flat.points));
        if (!best || area < bestArea) {
            bestArea = area;
            best = std::move(flat);
        }
    }
    if (best && signedArea(best->points) < 0.0) {
        std::reverse(best->points.begin(), best->points.end());
        std::reverse(best->normals.begin(), best->normals.end());
    }
    return best;
}

/// What the curved wall adds to a contour's polygon between its points:
/// the wall's normals m_i, m_j at two neighbours describe an arc over their
/// chord c whose sag is h = (c . (m_j - m_i)) / 8 (as onCurvedEdge()); the
/// arc's segment holds 2 c h / 3 (negative where the wall is concave) and
/// is about 8 h^2 / (3 c) longer than the chord. Creases (normals more than
/// 60 degrees apart) and points without a normal add nothing.
struct WallBulge {
    double area = 0.0;
    double perimeter = 0.0;
};
WallBulge wallBulge(const FlatContour& contour) {
    WallBulge bulge;
    const std::size_t n = contour.points.size();
    for (std::size_t i = 0; i < n; ++i) {
        const std::size_t j = (i + 1) % n;
        const glm::dvec2 chord = contour.points[j] - contour.points[i];
        const glm::dvec2& mi = contour.normals[i];
        const glm::dvec2& mj = contour.normals[j];
        const double c = glm::length(chord);
        if (glm::dot(mi, mi) < 0.25 || glm::dot(mj, mj) < 0.25 || !(c > 0.0) ||
            glm::dot(glm::normalize(mi), glm::normalize(mj)) < kCreaseCosine) {
            continue;
        }
        const double h = glm::dot(chord, mj - mi) / 8.0;
        bulge.area += 2.0 * c * h / 3.0;
        bulge.perimeter += 8.0 * h * h / (3.0 * c);
    }
    return bulge;
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
    WallBulge bulge;
    for (const double reach : {6.0, 24.0}) {
        const glm::dvec3 half(reach * std::max(p.radiusMm, step));
        PlaneCut cut(s, p.position, p.tangent);
        const auto contour =
            lumenContour(cut.loops(index.trianglesOnPlane(p.position, p.tangent, p.position - half,
                                                          p.position + half)),
                         section);
        if (contour) {
            section.contour = contour->points;
            bulge = wallBulge(*contour);
            break;
        }
    }
    if (section.contour.empty()) {
        return section;
    }
    detail::ContourSize size = detail::measureContour(section.contour);
    size.area += bulge.area;
    size.perimeter += bulge.perimeter;
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

FeretCalipers feretCalipers(const std::vector<glm::dvec2>& contour) {
    const detail::ContourSize size = detail::measureContour(contour);
    FeretCalipers c;
    c.minMm = size.minFeret;
    c.maxMm = size.maxFeret;
    c.minSegment = {size.minFrom, size.minTo};
    c.maxSegment = {size.maxFrom, size.maxTo};
    return c;
}

std::vector<std::vector<CrossSection>> computeSections(const scene::Mesh& mesh,
                                                       const CenterlineTree& tree,
                                                       const Progress& progress) {
    if (tree.branches.empty()) {
        return {};
    }
    PreparedSurface s = detail::prepareSurface(mesh, tree.branches.front().points.front().position,
                                               progress, kDefaultMaxTriangles);
    // A wall that folds over itself is cut smoothed, as computeCenterlines
    // smooths it by default.
    s.foldedFraction = detail::foldedFractionOf(s);
    detail::smoothIfFolded(s, progress.sub(0.0, 0.1));
    const SurfaceIndex index(s);
    return detail::sectionsOf(s, index, tree, progress.sub(0.1, 1.0));
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
