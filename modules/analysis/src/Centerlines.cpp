// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/analysis/Centerlines.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <tuple>
#include <utility>

#include "AnalysisSteps.h"
#include "CurveGeometry.h"
#include "MinimalPaths.h"
#include "PreparedSurface.h"
#include "Release.h"
#include "SurfaceIndex.h"
#include "VoronoiGraph.h"
#include "VoronoiSamples.h"
#include "WallSmoothing.h"
#include "vv/core/NumberText.h"
#include "vv/core/Parallel.h"

namespace vv::analysis {
namespace {

using detail::handBackFreedMemory;
using detail::PathTree;
using detail::PreparedSurface;
using detail::release;
using detail::SurfaceIndex;
using detail::VoronoiGraph;

constexpr std::uint32_t kNone = UINT32_MAX;
/// A path's inscribed spheres, grown by this, hold what the path covers
/// (tip search).
constexpr double kCoverFactor = 1.5;
/// A tip is kept when its path runs this many radii beyond the covered part.
constexpr double kMinBranchRadii = 1.0;
/// Smoothing of the Voronoi path: sigma = this times the inscribed radius.
constexpr double kSmoothingRadii = 0.5;
/// Resolution of the raw path before smoothing, mm (at most the step).
constexpr double kRawStepMm = 0.1;
/// The raw path is resampled no finer than into this many samples over its
/// length and this many per smoothing sigma (its largest), which bounds the
/// smoothing's work (its window is 6 sigma) on a surface far larger than a
/// vessel in mm; vessels up to 2 m long and 40 mm wide keep kRawStepMm.
constexpr double kMaxRawSamples = 20'000.0;
constexpr double kRawSamplesPerSigma = 200.0;
/// A centreline from the source to one end has at most this many points at
/// the output step (50 m at the default 0.5 mm): a longer one means a
/// surface in other units than mm, or not a vessel; refused.
constexpr double kMaxPathPoints = 100'000.0;

std::string pointText(const glm::dvec3& p) {
    return "(" + fixedText(p.x, 2) + ", " + fixedText(p.y, 2) + ", " + fixedText(p.z, 2) + ")";
}

/// " (... is the surface in mm?)" when the surface's size says it may not
/// be in mm (under 2 or over 5000 across, as the command line warns), else
/// empty: a failure on such a surface most likely has that cause.
std::string unitsHint(const PreparedSurface& s) {
    if (s.diagonalMm >= 2.0 && s.diagonalMm <= 5000.0) {
        return {};
    }
    return " (the surface is " + fixedText(s.diagonalMm, 2) + " mm across: is the surface in mm?)";
}

/// What about the surface may explain a failure: its size (unitsHint) and
/// a wall that folds over itself (the inside of such a wall breaks up where
/// the vessel narrows); empty when neither.
std::string surfaceHints(const PreparedSurface& s) {
    std::string hints = unitsHint(s);
    if (folds(s)) {
        hints += s.foldedFractionBeforeSmoothing > 0.0
                     ? " (even smoothed, " + foldFinding(s) + ")"
                     : " (" + foldFinding(s) + "; smooth the surface first)";
    } else if (s.foldedFractionBeforeSmoothing > 0.0) {
        hints += " (the wall was smoothed first: it folded over itself at " +
                 fixedText(100.0 * s.foldedFractionBeforeSmoothing, 1) + " % of its vertices)";
    }
    return hints;
}

[[noreturn]] void fail(const PreparedSurface& s, const std::string& problem) {
    throw AnalysisError(s.source, (s.source.empty() ? s.name + ": " : "") + problem);
}

/// An opening whose cap's inscribed sphere is this many times wider than
/// the opening is a hole in a wall, not a vessel's end (at an end the
/// sphere is about as wide as the loop; behind a hole, as wide as the
/// vessel).
constexpr double kHoleRatio = 1.5;

/// The pole of a loop's cap: the largest inscribed sphere touching the
/// cap's centre, else (no inside tetrahedron has the centre as a corner, as
/// when the wall next to the rim had points added) the largest touching the
/// rim; kNone when neither has one.
std::uint32_t loopPole(const detail::BoundaryLoop& loop, const VoronoiGraph& g) {
    std::uint32_t pole = g.poles[loop.capCentre];
    if (pole != kNone) {
        return pole;
    }
    for (const std::uint32_t v : loop.vertices) {
        const std::uint32_t p = g.poles[v];
        if (p != kNone && (pole == kNone || g.radius(p) > g.radius(pole))) {
            pole = p;
        }
    }
    return pole;
}

/// Marks the loops that are holes and notes them.
void markHoles(PreparedSurface& s, const VoronoiGraph& g) {
    int holes = 0;
    for (detail::BoundaryLoop& loop : s.loops) {
        const std::uint32_t pole = loopPole(loop, g);
        loop.hole = pole != kNone && g.radius(pole) > kHoleRatio * loop.radiusMm;
        holes += loop.hole ? 1 : 0;
    }
    if (holes > 0) {
        s.notes.push_back(
            std::to_string(holes) +
            (holes == 1 ? " hole in a vessel wall was" : " holes in vessel walls were") +
            " closed, not taken for vessel ends.");
    }
}

/// An end resolved onto the Voronoi graph.
struct ResolvedEnd {
    EndPoint end;
    std::uint32_t vertex = kNone;  ///< where the minimal path ends
    int loop = -1;                 ///< the boundary loop it is the centre of
    /// A tip's Voronoi vertex farthest along its vessel, in its cap (`vertex`
    /// is cut back from it); kNone for other ends.
    std::uint32_t capVertex = kNone;
    /// A tip whose point on the surface is not yet known (placeTip): it is
    /// where the ray from `vertex`'s centre along `tipAxis` meets the
    /// surface, or (no ray: a zero axis, or no hit) the surface point
    /// nearest to `capVertex`'s centre.
    bool placed = true;
    glm::dvec3 tipAxis{0.0};
};

/// The pole of the surface vertex nearest to `p` among those of `triangle`
/// that have one.
std::uint32_t poleNear(const PreparedSurface& s, const VoronoiGraph& g, std::uint32_t triangle,
                       const glm::dvec3& p) {
    std::uint32_t best = kNone;
    double bestDistance = std::numeric_limits<double>::max();
    for (const std::uint32_t v : s.triangles[triangle]) {
        const double d = glm::length(s.positions[v] - p);
        if (g.poles[v] != kNone && d < bestDistance) {
            best = g.poles[v];
            bestDistance = d;
        }
    }
    return best;
}

ResolvedEnd loopEnd(const PreparedSurface& s, const VoronoiGraph& g, int loop) {
    const detail::BoundaryLoop& l = s.loops[static_cast<std::size_t>(loop)];
    ResolvedEnd r;
    r.end.kind = EndPoint::Kind::OpenEnd;
    r.end.position = l.centre;
    r.end.requested = l.centre;
    r.end.radiusMm = l.radiusMm;
    r.vertex = loopPole(l, g);
    r.loop = loop;
    return r;
}

/// A point the user gave: at an open end (the point within 1.5 loop radii
/// of its centre) the loop's centre; elsewhere the inscribed sphere touching the
/// nearest surface point.
ResolvedEnd givenEnd(const PreparedSurface& s, const VoronoiGraph& g, const SurfaceIndex& surface,
                     const glm::dvec3& point, const char* role) {
    // Before the minimal paths: scanned, not the tree built beside them.
    constexpr auto kLookup = SurfaceIndex::Lookup::ScanUnlessBuilt;
    const SurfaceIndex::Nearest nearest = surface.nearest(point, kLookup);
    for (std::size_t i = 0; i < s.loops.size(); ++i) {
        if (!s.loops[i].hole &&
            glm::length(point - s.loops[i].centre) <= 1.5 * s.loops[i].radiusMm) {
            ResolvedEnd r = loopEnd(s, g, static_cast<int>(i));
            r.end.kind = EndPoint::Kind::Given;
            r.end.requested = point;
            r.end.offsetMm = nearest.distance;
            return r;
        }
    }
    ResolvedEnd r;
    r.end.kind = EndPoint::Kind::Given;
    r.end.requested = point;
    r.end.offsetMm = nearest.distance;
    r.vertex = poleNear(s, g, nearest.triangle, nearest.point);
    if (r.vertex == kNone) {
        fail(s, std::string("no inscribed sphere touches the surface near the ") + role + " " +
                    pointText(point));
    }
    r.end.position = g.centre(r.vertex);
    r.end.radiusMm = g.radius(r.vertex);
    // The sphere touching the surface at the nearest point exactly: centred
    // halfway to the opposite wall along the inward normal there (the
    // diagram's pole may be a sample's, up to a quarter radius away), and the
    // diagram's vertex nearest that centre for the path.
    const detail::Triangle& t = s.triangles[nearest.triangle];
    const glm::dvec3 normal =
        glm::cross(s.positions[t[1]] - s.positions[t[0]], s.positions[t[2]] - s.positions[t[0]]);
    if (glm::dot(normal, normal) > 0.0) {
        const glm::dvec3 inward = -glm::normalize(normal);
        const double inset = 1e-6 * s.diagonalMm;
        const auto opposite = surface.firstHit(nearest.point + inset * inward, inward, kLookup);
        if (opposite && glm::length(*opposite - nearest.point) < 4.0 * r.end.radiusMm) {
            const glm::dvec3 centre = 0.5 * (nearest.point + *opposite);
            r.end.position = centre;
            r.end.radiusMm = 0.5 * glm::length(*opposite - nearest.point);
            double best = glm::length(g.centre(r.vertex) - centre);
            for (std::uint32_t v = 0; v < g.size(); ++v) {
                const double d = glm::length(g.centre(v) - centre);
                if (d < best) {
                    best = d;
                    r.vertex = v;
                }
            }
        }
    }
    // Farther from the surface than the vessel is wide: not this piece's point.
    if (nearest.distance > 3.0 * r.end.radiusMm + 1.0) {
        fail(s, std::string("the ") + role + " " + pointText(point) + " is " +
                    fixedText(nearest.distance, 1) +
                    " mm from the analysed surface (off the surface, or on another piece)");
    }
    return r;
}

/// A closed vessel's tip, found as the Voronoi vertex `tip` farthest along
/// its vessel. The medial axis fans out near a closed end (to the rim of a
/// flat cap, over a rounded one), so the path is cut back where it still has
/// two radii to go and continued straight along the vessel's axis there to
/// the surface: the centre of a flat cap, the apex of a rounded one.
ResolvedEnd tipEnd(const VoronoiGraph& g, const PathTree& tree, std::uint32_t tip) {
    const std::vector<std::uint32_t> path = tree.pathTo(tip);
    // Two radii from the tip, by the widest sphere on the way: on a rough
    // cap the path's last spheres are the spikes' (1 mm in a 10 mm
    // vessel), and two of their radii back is still off the axis (a
    // jittered 1M aneurysm's source ended 3 mm aside, its trunk 1.2 % long).
    std::size_t cut = path.size() - 1;
    double widest = g.radius(path[cut]);
    while (cut > 0 && tree.lengthMm(tip) - tree.lengthMm(path[cut]) < 2.0 * widest) {
        --cut;
        widest = std::max(widest, g.radius(path[cut]));
    }
    std::size_t back = cut;
    while (back > 0 && tree.lengthMm(path[cut]) - tree.lengthMm(path[back]) < 2.0 * widest) {
        --back;
    }
    ResolvedEnd r;
    r.end.kind = EndPoint::Kind::Tip;
    r.vertex = path[cut];
    r.capVertex = tip;
    r.end.radiusMm = g.radius(path[cut]);
    const glm::dvec3 along = g.centre(path[cut]) - g.centre(path[back]);
    if (back < cut && glm::length(along) > 0.0) {
        r.tipAxis = glm::normalize(along);
    }
    r.placed = false;
    return r;
}

/// Places a tip found by tipEnd on the surface (ResolvedEnd::placed). The
/// tips are found before the surface's index is built, which then never
/// shares the memory with the minimal paths' covering grids.
void placeTip(const VoronoiGraph& g, const SurfaceIndex& surface, ResolvedEnd& r) {
    if (r.placed) {
        return;
    }
    std::optional<glm::dvec3> hit;
    if (r.tipAxis != glm::dvec3(0.0)) {
        hit = surface.firstHit(g.centre(r.vertex), r.tipAxis);
    }
    r.end.position = hit ? *hit : surface.nearest(g.centre(r.capVertex)).point;
    r.end.requested = r.end.position;
    r.placed = true;
}

/// The radius a vessel has near its tip: going back along the path from the
/// tip until the path is two radii long.
double radiusBehindTip(const VoronoiGraph& g, const PathTree& tree, std::uint32_t tip) {
    const std::vector<std::uint32_t> path = tree.pathTo(tip);
    for (std::size_t i = path.size(); i-- > 0;) {
        if (tree.lengthMm(tip) - tree.lengthMm(path[i]) >= 2.0 * g.radius(path[i])) {
            return g.radius(path[i]);
        }
    }
    return g.radius(path.front());
}

/// Source end when none is given: the widest open end, or on a closed
/// surface the tip of the widest vessel.
ResolvedEnd defaultSource(const PreparedSurface& s, const VoronoiGraph& g,
                          const Progress& progress) {
    int widest = -1;
    for (std::size_t i = 0; i < s.loops.size(); ++i) {
        if (!s.loops[i].hole &&
            (widest < 0 ||
             s.loops[i].radiusMm > s.loops[static_cast<std::size_t>(widest)].radiusMm)) {
            widest = static_cast<int>(i);
        }
    }
    if (widest >= 0) {
        return loopEnd(s, g, widest);
    }
    const auto widestVertex = static_cast<std::uint32_t>(
        std::max_element(g.radii.begin(), g.radii.end()) - g.radii.begin());
    const PathTree fromWidest = detail::minimalPaths(g, widestVertex, progress);
    const std::vector<std::uint32_t> tips =
        detail::uncoveredTips(g, fromWidest, {}, kCoverFactor, kMinBranchRadii, progress);
    if (tips.empty()) {
        fail(s, "the surface has no vessel end to start from");
    }
    std::size_t best = 0;
    double bestRadius = 0.0;
    for (std::size_t i = 0; i < tips.size(); ++i) {
        const double r = radiusBehindTip(g, fromWidest, tips[i]);
        if (r > bestRadius) {
            bestRadius = r;
            best = i;
        }
    }
    return tipEnd(g, fromWidest, tips[best]);
}

/// One source-to-target path, smoothed and measured, at the output step.
struct PathProfile {
    std::vector<CenterlinePoint> points;  ///< abscissa from the source
    std::vector<double> abscissae;        ///< the points' abscissae
    /// Raw (Voronoi path) arc length -> abscissa, for locating graph vertices.
    std::vector<double> rawArc;
    std::vector<double> smoothArc;
    std::vector<std::uint32_t> vertices;  ///< the Voronoi path
    std::vector<double> vertexRawArc;     ///< raw arc length at each path vertex
    int endIndex = -1;

    [[nodiscard]] double abscissaOfVertex(std::size_t pathIndex) const {
        return detail::interpolate(rawArc, smoothArc, vertexRawArc[pathIndex]);
    }
    /// The centreline at abscissa `s`, interpolated between samples.
    [[nodiscard]] CenterlinePoint at(double s) const;
};

CenterlinePoint PathProfile::at(double s) const {
    s = std::clamp(s, abscissae.front(), abscissae.back());
    auto upper = std::upper_bound(abscissae.begin(), abscissae.end(), s);
    if (upper == abscissae.end()) {
        return points.back();
    }
    const auto i = static_cast<std::size_t>(upper - abscissae.begin());
    if (i == 0) {
        return points.front();
    }
    const CenterlinePoint& a = points[i - 1];
    const CenterlinePoint& b = points[i];
    const double span = b.abscissaMm - a.abscissaMm;
    const double t = span > 0.0 ? (s - a.abscissaMm) / span : 0.0;
    CenterlinePoint p;
    p.position = glm::mix(a.position, b.position, t);
    p.radiusMm = a.radiusMm + t * (b.radiusMm - a.radiusMm);
    p.abscissaMm = s;
    p.tangent = glm::normalize(glm::mix(a.tangent, b.tangent, t));
    const glm::dvec3 n = glm::mix(a.normal, b.normal, t);
    p.normal = glm::normalize(n - glm::dot(n, p.tangent) * p.tangent);
    p.curvature = a.curvature + t * (b.curvature - a.curvature);
    p.torsion = a.torsion + t * (b.torsion - a.torsion);
    return p;
}

/// `vertices` without the Voronoi vertices at either end that lie past the
/// end point (a given end between two samples' vertices): no hook back.
std::vector<std::uint32_t> trimmedAtTheEnds(const VoronoiGraph& g, const ResolvedEnd& source,
                                            const ResolvedEnd& target,
                                            std::vector<std::uint32_t> vertices) {
    const auto past = [&](std::uint32_t vertex, std::uint32_t inner, const glm::dvec3& end) {
        return glm::dot(g.centre(vertex) - g.centre(inner), end - g.centre(vertex)) < 0.0;
    };
    while (vertices.size() > 2 &&
           past(vertices.back(), vertices[vertices.size() - 2], target.end.position)) {
        vertices.pop_back();
    }
    std::size_t first = 0;
    while (vertices.size() - first > 2 &&
           past(vertices[first], vertices[first + 1], source.end.position)) {
        ++first;
    }
    vertices.erase(vertices.begin(), vertices.begin() + static_cast<std::ptrdiff_t>(first));
    return vertices;
}

PathProfile profilePath(const VoronoiGraph& g, const ResolvedEnd& source, const ResolvedEnd& target,
                        const std::vector<std::uint32_t>& vertices, double step) {
    PathProfile profile;
    profile.vertices = trimmedAtTheEnds(g, source, target, vertices);
    // The raw polyline: source end, the Voronoi centres, target end.
    std::vector<glm::dvec3> raw{source.end.position};
    std::vector<double> rawRadius{source.end.radiusMm};
    for (const std::uint32_t v : profile.vertices) {
        raw.push_back(g.centre(v));
        rawRadius.push_back(g.radius(v));
    }
    raw.push_back(target.end.position);
    rawRadius.push_back(std::max(target.end.radiusMm, g.radius(vertices.back())));
    const std::vector<double> rawAt = detail::arcLengths(raw);
    profile.vertexRawArc.assign(rawAt.begin() + 1, rawAt.end() - 1);

    const double fineStep =
        std::max({std::min(step, kRawStepMm), rawAt.back() / kMaxRawSamples,
                  kSmoothingRadii * *std::max_element(rawRadius.begin(), rawRadius.end()) /
                      kRawSamplesPerSigma});
    const std::vector<glm::dvec3> fine = detail::resample(raw, fineStep);
    const std::vector<double> fineAt = detail::arcLengths(fine);
    std::vector<double> sigma(fine.size());
    for (std::size_t i = 0; i < fine.size(); ++i) {
        sigma[i] = kSmoothingRadii * detail::interpolate(rawAt, rawRadius, fineAt[i]);
    }
    const std::vector<glm::dvec3> smooth = detail::smoothAlong(fine, sigma);
    profile.rawArc = fineAt;
    profile.smoothArc = detail::arcLengths(smooth);

    const std::vector<glm::dvec3> positions = detail::resample(smooth, step);
    const std::vector<double> at = detail::arcLengths(positions);
    const std::vector<glm::dvec3> t = detail::tangents(positions);
    const std::vector<glm::dvec3> normals = detail::rotationMinimisingNormals(positions, t);
    std::vector<double> scale(positions.size());
    for (std::size_t i = 0; i < positions.size(); ++i) {
        scale[i] = std::max(2.0 * step,
                            detail::interpolate(profile.smoothArc, sigma, at[i]) / kSmoothingRadii);
    }
    const std::vector<double> k = detail::curvatures(positions, scale);
    const std::vector<double> tau = detail::torsions(positions, scale);
    profile.points.resize(positions.size());
    for (std::size_t i = 0; i < positions.size(); ++i) {
        CenterlinePoint& p = profile.points[i];
        p.position = positions[i];
        p.abscissaMm = at[i];
        p.tangent = t[i];
        p.normal = normals[i];
        p.curvature = k[i];
        p.torsion = tau[i];
        // The Voronoi radius along the path, until measureRadii measures it.
        p.radiusMm = detail::interpolate(profile.smoothArc, sigma, at[i]) / kSmoothingRadii;
    }
    profile.abscissae = at;
    return profile;
}

/// Each branch point's inscribed-sphere radius: its distance to the surface
/// (measured once per point of the tree, not once per path through it).
void measureRadii(const SurfaceIndex& surface, std::vector<Branch>& branches,
                  const Progress& progress) {
    parallelFor(
        0, static_cast<long>(branches.size()), 1,
        [&](long begin, long end) {
            for (long b = begin; b < end; ++b) {
                auto& points = branches[static_cast<std::size_t>(b)].points;
                glm::dvec3 hint = surface.nearest(points.front().position).point;
                for (CenterlinePoint& p : points) {
                    p.radiusMm = surface.distance(p.position, hint);
                }
            }
        },
        progress.stopToken());
}

/// The points of `profile` over [from, to] every `step`, both ends included.
std::vector<CenterlinePoint> stretch(const PathProfile& profile, double from, double to,
                                     double step) {
    // A span that ends where it starts (a path whose end lies on another
    // path) may come out a rounding error short: it has no length, not a
    // negative one.
    to = std::max(to, from);
    std::vector<CenterlinePoint> points;
    for (double s = from; s < to - 1e-6 * step; s += step) {
        points.push_back(profile.at(s));
    }
    points.push_back(profile.at(to));
    if (points.size() < 2) {
        points.insert(points.begin(), profile.at(from));
    }
    return points;
}

/// A branch while the tree is assembled: which path owns it, over which
/// abscissae of that path.
struct BranchSpan {
    int path = 0;
    double from = 0.0;
    double to = 0.0;
    int parent = -1;
    std::vector<int> children;
    int endIndex = -1;
};

/// Two paths are one vessel while they run within this many of the local
/// inscribed radius of each other.
constexpr double kPartingRadii = 0.1;
/// The step at which two paths are compared past their last shared vertex,
/// in local radii at that vertex (at most kMaxPartingSteps steps in all).
constexpr double kPartingStepRadii = 0.25;
constexpr double kMaxPartingSteps = 1e5;

/// Where two paths that share a Voronoi vertex at abscissae `from` (of `k`)
/// and `x` (of `m`) really part: the minimal-path tree can fork early in a
/// wide straight lumen (its Voronoi vertices a cloud around the axis, two
/// routes through it as cheap as each other) and run two paths side by side
/// to the bifurcation; they are one vessel while they stay within
/// kPartingRadii of the local radius. Returns the pair moved to the last
/// point where they still do, at equal arc lengths along both.
std::pair<double, double> whereThePathsPart(const PathProfile& k, double from, const PathProfile& m,
                                            double x) {
    const double reach = std::min(k.abscissae.back() - from, m.abscissae.back() - x);
    const double radius = std::min(k.at(from).radiusMm, m.at(x).radiusMm);
    const double step = std::max(kPartingStepRadii * radius, reach / kMaxPartingSteps);
    if (!(step > 0.0)) {
        return {from, x};  // no length left, or no radius known
    }
    double along = 0.0;
    for (double d = step; d <= reach; d += step) {
        const CenterlinePoint a = k.at(from + d);
        const CenterlinePoint b = m.at(x + d);
        if (glm::length(a.position - b.position) >
            kPartingRadii * std::min(a.radiusMm, b.radiusMm)) {
            break;
        }
        along = d;
    }
    return {from + along, x + along};
}

/// Splits the paths into branches where they part (the last Voronoi vertex
/// a path shares with the paths before it, moved on while the two run side
/// by side: whereThePathsPart).
std::vector<BranchSpan> splitIntoBranches(const std::vector<PathProfile>& paths,
                                          std::size_t graphSize) {
    std::vector<BranchSpan> spans;
    std::vector<int> firstPath(graphSize, -1);
    std::vector<std::vector<int>> owned(paths.size());  // per path, its spans by abscissa
    for (std::size_t k = 0; k < paths.size(); ++k) {
        const PathProfile& path = paths[k];
        std::size_t junctionIndex = kNone;
        for (std::size_t i = 0; i < path.vertices.size(); ++i) {
            if (firstPath[path.vertices[i]] >= 0) {
                junctionIndex = i;
            }
        }
        BranchSpan span;
        span.path = static_cast<int>(k);
        span.to = path.abscissae.back();
        span.endIndex = path.endIndex;
        if (junctionIndex != kNone) {
            const auto m = static_cast<std::size_t>(firstPath[path.vertices[junctionIndex]]);
            const std::size_t inM = static_cast<std::size_t>(
                std::find(paths[m].vertices.begin(), paths[m].vertices.end(),
                          path.vertices[junctionIndex]) -
                paths[m].vertices.begin());
            double x = 0.0;
            std::tie(span.from, x) = whereThePathsPart(path, path.abscissaOfVertex(junctionIndex),
                                                       paths[m], paths[m].abscissaOfVertex(inM));
            // The span of path m that holds x; split it there unless x is its end.
            int holder = owned[m].back();
            for (const int id : owned[m]) {
                if (x >= spans[static_cast<std::size_t>(id)].from &&
                    x <= spans[static_cast<std::size_t>(id)].to) {
                    holder = id;
                    break;
                }
            }
            BranchSpan& h = spans[static_cast<std::size_t>(holder)];
            if (x < h.to - 1e-9) {
                BranchSpan rest = h;
                rest.from = x;
                rest.parent = holder;
                h.to = x;
                h.endIndex = -1;
                const int restId = static_cast<int>(spans.size());
                for (const int child : rest.children) {
                    spans[static_cast<std::size_t>(child)].parent = restId;
                }
                h.children = {restId};
                spans.push_back(rest);
                auto& list = owned[m];
                list.insert(std::find(list.begin(), list.end(), holder) + 1, restId);
            }
            span.parent = holder;
            spans[static_cast<std::size_t>(holder)].children.push_back(
                static_cast<int>(spans.size()));
        }
        owned[k].push_back(static_cast<int>(spans.size()));
        spans.push_back(span);
        for (const std::uint32_t v : path.vertices) {
            if (firstPath[v] < 0) {
                firstPath[v] = static_cast<int>(k);
            }
        }
    }
    return spans;
}

/// Parents before children, ids = indices.
std::vector<Branch> orderBranches(const std::vector<BranchSpan>& spans,
                                  const std::vector<PathProfile>& paths, double step) {
    std::vector<int> order{0};
    for (std::size_t i = 0; i < order.size(); ++i) {
        for (const int child : spans[static_cast<std::size_t>(order[i])].children) {
            order.push_back(child);
        }
    }
    std::vector<int> newId(spans.size(), -1);
    for (std::size_t i = 0; i < order.size(); ++i) {
        newId[static_cast<std::size_t>(order[i])] = static_cast<int>(i);
    }
    std::vector<Branch> branches(order.size());
    for (std::size_t i = 0; i < order.size(); ++i) {
        const BranchSpan& span = spans[static_cast<std::size_t>(order[i])];
        Branch& b = branches[i];
        b.id = static_cast<int>(i);
        b.parent = span.parent < 0 ? -1 : newId[static_cast<std::size_t>(span.parent)];
        for (const int child : span.children) {
            b.children.push_back(newId[static_cast<std::size_t>(child)]);
        }
        b.endIndex = span.endIndex;
        b.points = stretch(paths[static_cast<std::size_t>(span.path)], span.from, span.to, step);
        b.lengthMm = b.points.back().abscissaMm - b.points.front().abscissaMm;
        b.chordMm = glm::length(b.points.back().position - b.points.front().position);
    }
    return branches;
}

void validate(const CenterlineOptions& options) {
    if (!(options.stepMm >= 0.01 && options.stepMm <= 10.0)) {
        throw InvalidArgumentError("centrelines: the step must be in [0.01, 10] mm");
    }
    if (options.maxTriangles < 1000) {
        throw InvalidArgumentError("centrelines: the largest triangle count must be >= 1000");
    }
    const auto finite = [](const glm::dvec3& p) {
        return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
    };
    if (options.source && !finite(*options.source)) {
        throw InvalidArgumentError("centrelines: the source point is not finite");
    }
    for (const auto& target : options.targets) {
        if (!finite(target)) {
            throw InvalidArgumentError("centrelines: a target point is not finite");
        }
    }
}

/// The targets: the given ones, or every other open end and every tip the
/// paths to them leave uncovered.
std::vector<ResolvedEnd> resolveTargets(const PreparedSurface& s, const VoronoiGraph& g,
                                        const SurfaceIndex& surface, const ResolvedEnd& source,
                                        const PathTree& tree, const CenterlineOptions& options,
                                        const Progress& progress) {
    std::vector<ResolvedEnd> targets;
    if (!options.targets.empty()) {
        for (const glm::dvec3& point : options.targets) {
            targets.push_back(givenEnd(s, g, surface, point, "target"));
        }
        return targets;
    }
    std::vector<std::vector<std::uint32_t>> known;
    // A source at a closed tip: its own cap is covered, as a found tip's is,
    // or the medial axis' spikes over a rough cap read as short vessels.
    if (source.capVertex != kNone && tree.reaches(source.capVertex)) {
        known.push_back(tree.pathTo(source.capVertex));
    }
    for (std::size_t i = 0; i < s.loops.size(); ++i) {
        if (static_cast<int>(i) == source.loop || s.loops[i].hole) {
            continue;
        }
        ResolvedEnd end = loopEnd(s, g, static_cast<int>(i));
        if (end.vertex != kNone && tree.reaches(end.vertex)) {
            known.push_back(tree.pathTo(end.vertex));
        }
        targets.push_back(end);
    }
    for (const std::uint32_t tip :
         detail::uncoveredTips(g, tree, known, kCoverFactor, kMinBranchRadii, progress)) {
        targets.push_back(tipEnd(g, tree, tip));
    }
    return targets;
}

/// A target, and the minimal path to it from the source.
struct TargetPath {
    ResolvedEnd end;
    std::vector<std::uint32_t> vertices;  ///< source first
    double lengthMm = 0.0;                ///< along the graph
};

/// Refuses a path with more than kMaxPathPoints points at `step`.
void checkPathLengths(const PreparedSurface& s, const VoronoiGraph& g, const ResolvedEnd& source,
                      const std::vector<TargetPath>& targets, double step) {
    const double start = glm::length(g.centre(source.vertex) - source.end.position);
    for (const TargetPath& target : targets) {
        const ResolvedEnd& end = target.end;
        const double length =
            start + target.lengthMm + glm::length(end.end.position - g.centre(end.vertex));
        if (!(length / step <= kMaxPathPoints)) {
            fail(s, "the centreline to the end " + pointText(end.end.position) + " would be " +
                        fixedText(length, 0) + " mm long, more than " +
                        fixedText(kMaxPathPoints, 0) + " points at a step of " +
                        fixedText(step, 2) + " mm (is the surface in mm?)");
        }
    }
}

/// The targets (resolveTargets) and their paths in `tree`, longest first
/// (the main vessel is branch 0), every end placed on the surface. The
/// tree is freed before the surface's index is first asked for: the two
/// were the analysis' peak together.
std::vector<TargetPath> targetPaths(const PreparedSurface& s, const VoronoiGraph& g,
                                    const SurfaceIndex& surface, ResolvedEnd& source, PathTree tree,
                                    const CenterlineOptions& options, const Progress& progress) {
    std::vector<TargetPath> targets;
    for (ResolvedEnd& end : resolveTargets(s, g, surface, source, tree, options, progress)) {
        targets.push_back({.end = end, .vertices = {}, .lengthMm = 0.0});
    }
    if (targets.empty()) {
        fail(s, "the surface has only one vessel end; a centreline needs two");
    }
    for (TargetPath& target : targets) {
        const ResolvedEnd& end = target.end;
        if (end.vertex == kNone || !tree.reaches(end.vertex)) {
            placeTip(g, surface, source);
            fail(s, "no path inside the surface joins the source " +
                        pointText(source.end.position) + " and the end " +
                        pointText(end.end.position) + surfaceHints(s));
        }
        target.vertices = tree.pathTo(end.vertex);
        target.lengthMm = tree.lengthMm(end.vertex);
    }
    release(tree.labels);
    // The covering grids and the tree are freed: their pages handed back
    // before the index takes its own.
    handBackFreedMemory();
    placeTip(g, surface, source);
    for (TargetPath& target : targets) {
        placeTip(g, surface, target.end);
    }
    handBackFreedMemory();  // what building the index freed
    checkPathLengths(s, g, source, targets, options.stepMm);
    std::stable_sort(targets.begin(), targets.end(), [](const TargetPath& a, const TargetPath& b) {
        return a.lengthMm > b.lengthMm;
    });
    return targets;
}

}  // namespace

/// Prepares `mesh` for `options`, builds its diagram and then its index (the
/// tetrahedralisation is freed before the index takes its memory; the index
/// is built when a step first asks for it), and returns
/// step(surface, diagram, index).
template <class Step>
auto onPrepared(const scene::Mesh& mesh, const CenterlineOptions& options, const Progress& progress,
                Step&& step) {
    validate(options);
    progress.report(0.0, "Preparing the surface");
    PreparedSurface s =
        detail::prepareSurface(mesh, options.source, progress, options.maxTriangles);
    const VoronoiGraph g = detail::diagramOf(s, options.smoothFoldedWall, progress);
    // Built when first asked (a given end; else the tips, once the minimal
    // paths and their covering grids are freed: beside them it was the
    // analysis' peak).
    const SurfaceIndex surface(s, SurfaceIndex::Build::OnFirstQuery);
    return std::forward<Step>(step)(s, g, surface);
}

CenterlineTree computeCenterlines(const scene::Mesh& mesh, const CenterlineOptions& options,
                                  const Progress& progress) {
    return onPrepared(mesh, options, progress,
                      [&](PreparedSurface& s, const VoronoiGraph& g, const SurfaceIndex& surface) {
                          return detail::centerlinesOf(s, g, surface, options, progress);
                      });
}

VesselAnalysis analyseVessels(const scene::Mesh& mesh, const CenterlineOptions& options,
                              const Progress& progress) {
    return onPrepared(mesh, options, progress,
                      [&](PreparedSurface& s, const VoronoiGraph& g, const SurfaceIndex& surface) {
                          VesselAnalysis analysis;
                          analysis.tree = detail::centerlinesOf(s, g, surface, options, progress);
                          analysis.sections =
                              detail::sectionsOf(s, surface, analysis.tree, progress);
                          return analysis;
                      });
}

namespace detail {

VoronoiGraph diagramOf(PreparedSurface& s, bool smoothFoldedWall, const Progress& progress) {
    detail::VoronoiSamples samples = detail::chooseVoronoiSamples(s, progress);
    s.foldedFraction = samples.foldedFraction;
    if (smoothFoldedWall && smoothIfFolded(s, progress.sub(0.02, 0.05))) {
        samples = detail::chooseVoronoiSamples(s, progress);
    }
    if (samples.reduced) {
        s.notes.push_back(
            "the surface is finer than its vessels need: the Voronoi diagram was built from " +
            std::to_string(samples.kept.size()) + " of its " +
            std::to_string(s.cappedPositions.size()) +
            " points, one per quarter of the local radius (each left-out point within " +
            fixedText(samples.largestGapMm, 2) +
            " mm of one kept; the chords between kept points lie within 0.8 % of the radius of "
            "the wall); the sections use every point");
    }
    if (!samples.addedPositions.empty()) {
        s.notes.push_back("the surface is coarser than its vessels need (facets longer than " +
                          fixedText(kCoarseFacetRadii, 2) +
                          " of the local radius): the Voronoi diagram was built with " +
                          std::to_string(samples.addedPositions.size()) +
                          " points added on those facets, " +
                          fixedText(kDenseSpacingPerRadius * samples.addedSpacingScale, 3) +
                          " of the local radius apart; the sections cut the facets as they are");
    }
    if (folds(s)) {
        s.notes.push_back(
            (s.foldedFractionBeforeSmoothing > 0.0 ? "even smoothed, " : "") + foldFinding(s) +
            "; the centrelines and sections may follow the noise rather than the vessel, most "
            "where it narrows or bends" +
            (s.foldedFractionBeforeSmoothing > 0.0 ? "" : "; smooth the surface first"));
    }
    // The diagram reads the capped surface only, whose first points and
    // triangles are the wall's own: those are set aside while it is built
    // (the analysis' peak) and copied back after. Only the diagram needs
    // the caps' points and fans; they are released then.
    const auto vertexCount = static_cast<std::ptrdiff_t>(s.positions.size());
    const auto triangleCount = static_cast<std::ptrdiff_t>(s.triangles.size());
    release(s.positions);
    release(s.triangles);
    // What preparing the surface and choosing the samples freed, handed
    // back before the slabs take theirs (the demo tree's resident peak in
    // the diagram's stage 74-81 -> 74-75 MiB).
    handBackFreedMemory();
    VoronoiGraph g = detail::buildVoronoiGraph(s, samples, progress.sub(0.05, 0.6));
    s.positions.assign(s.cappedPositions.begin(), s.cappedPositions.begin() + vertexCount);
    s.triangles.assign(s.cappedTriangles.begin(), s.cappedTriangles.begin() + triangleCount);
    release(s.cappedPositions);
    release(s.cappedTriangles);
    handBackFreedMemory();
    markHoles(s, g);
    return g;
}

CenterlineTree centerlinesOf(PreparedSurface& s, const VoronoiGraph& g, const SurfaceIndex& surface,
                             const CenterlineOptions& options, const Progress& progress) {
    progress.report(0.6, "Finding the vessels' ends");

    ResolvedEnd source = options.source ? givenEnd(s, g, surface, *options.source, "source")
                                        : defaultSource(s, g, progress);
    if (source.vertex == kNone) {
        fail(s, "no inscribed sphere touches the source end");
    }
    std::vector<TargetPath> targets = targetPaths(
        s, g, surface, source, detail::minimalPaths(g, source.vertex, progress), options, progress);

    progress.report(0.7, "Tracing the centrelines");
    CenterlineTree result;
    result.voronoiVertices = g.size();
    result.notes = s.notes;
    result.ends.push_back(source.end);
    std::vector<PathProfile> paths;
    // The paths are independent: traced on every core (the surface's AABB
    // tree and the graph are only read).
    paths.resize(targets.size());
    parallelFor(
        0, static_cast<long>(targets.size()), 1,
        [&](long begin, long end) {
            for (long i = begin; i < end; ++i) {
                const TargetPath& target = targets[static_cast<std::size_t>(i)];
                paths[static_cast<std::size_t>(i)] =
                    profilePath(g, source, target.end, target.vertices, options.stepMm);
            }
        },
        progress.stopToken());
    for (std::size_t i = 0; i < targets.size(); ++i) {
        paths[i].endIndex = static_cast<int>(result.ends.size());
        result.ends.push_back(targets[i].end.end);
    }
    result.branches = orderBranches(splitIntoBranches(paths, g.size()), paths, options.stepMm);
    measureRadii(surface, result.branches, progress);
    progress.report(1.0, "Centrelines done");
    return result;
}

}  // namespace detail

}  // namespace vv::analysis
