// SPDX-License-Identifier: GPL-3.0-or-later
#include "VoronoiGraph.h"

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Delaunay_triangulation_cell_base_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_cell_base_with_info_3.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <utility>

#include "CutMargins.h"
#include "Release.h"
#include "vv/analysis/AnalysisError.h"
#include "vv/core/Parallel.h"

namespace vv::analysis::detail {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using VertexBase = CGAL::Triangulation_vertex_base_with_info_3<std::uint32_t, Kernel>;
using CellBase =
    CGAL::Triangulation_cell_base_with_info_3<std::uint32_t, Kernel,
                                              CGAL::Delaunay_triangulation_cell_base_3<Kernel>>;
using Tds = CGAL::Triangulation_data_structure_3<VertexBase, CellBase>;
using Delaunay = CGAL::Delaunay_triangulation_3<Kernel, Tds>;

constexpr std::uint32_t kOutside = UINT32_MAX;

/// The most points the slabs may take with their first margins, per point
/// kept, before they are made fewer and wider (chooseSlabs). The demo
/// tree's take 1.65 with margins per column.
constexpr double kMostTakenPerKept = 2.0;

/// Below this volume, relative to the product of its edges from one corner,
/// a tetrahedron is flat to the digits of a double: its circumcentre is
/// rounding noise (four points on one facet of a coarse surface give one
/// anywhere, e.g. 60 mm outside a 5 mm tube).
constexpr double kFlatVolume = 1e-10;

/// The circumcentre of the tetrahedron (a, b, c, d), computed relative to
/// `a` (which keeps the digits of small tetrahedra far from the origin);
/// nullopt when it is flat (kFlatVolume).
std::optional<glm::dvec3> circumcentre(const glm::dvec3& a, const glm::dvec3& b,
                                       const glm::dvec3& c, const glm::dvec3& d) {
    const glm::dvec3 u = b - a;
    const glm::dvec3 v = c - a;
    const glm::dvec3 w = d - a;
    const double det = 2.0 * glm::dot(u, glm::cross(v, w));
    if (!(std::abs(det) > 2.0 * kFlatVolume * glm::length(u) * glm::length(v) * glm::length(w))) {
        return std::nullopt;
    }
    const glm::dvec3 offset =
        (glm::dot(u, u) * glm::cross(v, w) + glm::dot(v, v) * glm::cross(w, u) +
         glm::dot(w, w) * glm::cross(u, v)) /
        det;
    if (!std::isfinite(offset.x) || !std::isfinite(offset.y) || !std::isfinite(offset.z)) {
        return std::nullopt;
    }
    return a + offset;
}

/// The samples' points and normals by id: the capped surface's vertices,
/// then the points added on coarse facets.
class SamplePoints {
  public:
    SamplePoints(const PreparedSurface& s, const VoronoiSamples& samples)
        : s_(s), samples_(samples), first_(s.cappedPositions.size()) {}

    [[nodiscard]] const glm::dvec3& position(std::uint32_t id) const {
        return id < first_ ? s_.cappedPositions[id] : samples_.addedPositions[id - first_];
    }
    [[nodiscard]] const glm::dvec3& normal(std::uint32_t id) const {
        return id < first_ ? s_.cappedNormals[id] : samples_.addedNormals[id - first_];
    }
    [[nodiscard]] bool onSurfaceVertex(std::uint32_t id) const { return id < first_; }

  private:
    const PreparedSurface& s_;
    const VoronoiSamples& samples_;
    std::size_t first_;
};

/// Spreads the low 21 bits of `x` to every third bit.
std::uint64_t spreadBits(std::uint64_t x) {
    x &= 0x1fffffULL;
    x = (x | x << 32U) & 0x1f00000000ffffULL;
    x = (x | x << 16U) & 0x1f0000ff0000ffULL;
    x = (x | x << 8U) & 0x100f00f00f00f00fULL;
    x = (x | x << 4U) & 0x10c30c30c30c30c3ULL;
    x = (x | x << 2U) & 0x1249249249249249ULL;
    return x;
}

/// Per point (`count` of them, `point(i)` the i-th), its rank along a
/// Z-order (Morton) curve through the points' bounding box, 2^21 steps per
/// axis; equal keys keep their order.
template <class PointAt>
std::vector<std::uint32_t> zOrderRanks(std::size_t count, const PointAt& point) {
    glm::dvec3 lo(std::numeric_limits<double>::max());
    glm::dvec3 hi(std::numeric_limits<double>::lowest());
    for (std::size_t i = 0; i < count; ++i) {
        lo = glm::min(lo, point(i));
        hi = glm::max(hi, point(i));
    }
    const double extent = std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z, 1e-300});
    const double scale = 2097151.0 / extent;
    std::vector<std::pair<std::uint64_t, std::uint32_t>> keys(count);
    for (std::size_t i = 0; i < count; ++i) {
        const glm::dvec3 q = glm::clamp((point(i) - lo) * scale, 0.0, 2097151.0);
        keys[i] = {spreadBits(static_cast<std::uint64_t>(q.x)) |
                       spreadBits(static_cast<std::uint64_t>(q.y)) << 1U |
                       spreadBits(static_cast<std::uint64_t>(q.z)) << 2U,
                   static_cast<std::uint32_t>(i)};
    }
    std::sort(keys.begin(), keys.end());
    std::vector<std::uint32_t> rank(count);
    for (std::size_t i = 0; i < keys.size(); ++i) {
        rank[keys[i].second] = static_cast<std::uint32_t>(i);
    }
    return rank;
}

/// A slab of space across `axis`: the diagram's vertices whose centres lie
/// in [lo, hi) belong to it (its core; ±infinity at the ends), and it is
/// tetrahedralised from the points of the core and those within a margin
/// of it, per column (`below` past lo, `above` past hi).
struct Slab {
    int axis = 0;
    double lo = -std::numeric_limits<double>::infinity();
    double hi = std::numeric_limits<double>::infinity();
    CutMargins below;
    CutMargins above;

    /// Whether the slab takes the point `p`.
    [[nodiscard]] bool takes(const glm::dvec3& p) const {
        const double x = p[axis];
        if (x < lo) {
            return x >= lo - below.at(p);
        }
        return x <= hi || x <= hi + above.at(p);
    }
};

/// How far the sphere of `radius` about `centre` reaches past the points
/// `slab` took, below and above (0 where it stays within them: every point
/// inside it was taken). `low`, `high`: the extreme coordinates of all the
/// points along the axis (a margin that reaches past them took every point).
std::array<double, 2> reachPast(const Slab& slab, const glm::dvec3& centre, double radius,
                                double low, double high) {
    std::array<double, 2> reach{0.0, 0.0};
    const double c = centre[slab.axis];
    if (slab.lo > low && c - radius < slab.lo) {
        const double margin = slab.below.leastOver(centre, radius);
        const double past = slab.lo - (c - radius);
        reach[0] = past > margin && slab.lo - margin > low ? past : 0.0;
    }
    if (slab.hi < high && c + radius > slab.hi) {
        const double margin = slab.above.leastOver(centre, radius);
        const double past = (c + radius) - slab.hi;
        reach[1] = past > margin && slab.hi + margin < high ? past : 0.0;
    }
    return reach;
}

/// A sphere that reached past the points its slab took.
struct Overreach {
    glm::dvec3 centre{0.0};
    double radius = 0.0;
    std::array<double, 2> reach{};
};

/// Widens `slab`'s margins so that each of `spheres` stays within them, by
/// a quarter more than it reached, at least doubling the columns it
/// covers; from the third try on, every column to the widest (the old
/// uniform margin, doubling each time).
void widen(Slab& slab, const std::vector<Overreach>& spheres, int retries) {
    // Doubled from the margins the spheres were found with (doubling the
    // raised ones in turn grew them without bound).
    const std::array<CutMargins, 2> before{slab.below, slab.above};
    for (const Overreach& o : spheres) {
        std::array<CutMargins*, 2> side{&slab.below, &slab.above};
        for (std::size_t k = 0; k < 2; ++k) {
            if (o.reach[k] > 0.0) {
                const double least = before[k].leastOver(o.centre, o.radius);
                side[k]->raise(o.centre, o.radius, std::max(1.25 * o.reach[k], 2.0 * least));
            }
        }
    }
    if (retries >= 2) {
        slab.below.raiseAll(slab.below.largest());
        slab.above.raiseAll(slab.above.largest());
    }
}

/// A face of a tetrahedron (its three point ids, ascending) and the diagram
/// vertex on one side of it, its number within its slab.
struct FaceRecord {
    std::array<std::uint32_t, 3> face{};
    std::uint32_t cell = 0;
};

/// A surface vertex and a diagram vertex (within its slab) whose sphere
/// touches it.
struct PoleCandidate {
    std::uint32_t vertex = 0;
    std::uint32_t cell = 0;
};

/// What one slab gives: its diagram vertices, the edges between them (rows
/// by their numbers within the slab), the faces through which its vertices
/// may meet another slab's, and the poles its spheres offer.
struct SlabDiagram {
    std::vector<glm::vec3> localCentres;  ///< as VoronoiGraph's, in its frame
    std::vector<float> radii;
    std::vector<std::uint32_t> offsets;
    std::vector<std::uint32_t> neighbours;
    std::vector<FaceRecord> faces;
    std::vector<PoleCandidate> poles;
    int retries = 0;
    std::size_t points = 0;  ///< tetrahedralised in the last try
};

/// A cell of a slab's triangulation that is not one of its diagram
/// vertices: its sphere is not known to be empty of every point, or its
/// centre is another slab's (kElsewhere); or it is this slab's, empty, and
/// outside the surface (kOwnOutside: no diagram vertex lies across its faces).
constexpr std::uint32_t kElsewhere = UINT32_MAX;
constexpr std::uint32_t kOwnOutside = UINT32_MAX - 1;

/// The Delaunay diagram inside the surface of the points of `slab`, the
/// vertices whose centres lie in its core. A tetrahedron of the slab's points
/// is one of all the points' when its circumsphere lies within the points
/// taken (reachPast: within the margins of the columns it covers, or beyond
/// the last point on that side); an inside one whose sphere reaches further
/// means those margins were too narrow, and the slab is done again with
/// them widened (widen). `low` and
/// `high`: the smallest and largest coordinate of any point along the axis;
/// the centres and radii are kept in `frame`, in float.
SlabDiagram slabDiagram(const PreparedSurface& s, const SamplePoints& points,
                        const std::vector<std::uint32_t>& kept, Slab slab, double low, double high,
                        const LocalFrame& frame, const Progress& progress) {
    const int axis = slab.axis;
    for (SlabDiagram out;; ++out.retries) {
        std::vector<std::uint32_t> ids;
        std::vector<std::pair<Kernel::Point_3, std::uint32_t>> input;
        for (const std::uint32_t i : kept) {
            const glm::dvec3& p = points.position(i);
            if (slab.takes(p)) {
                input.emplace_back(Kernel::Point_3(p.x, p.y, p.z),
                                   static_cast<std::uint32_t>(ids.size()));
                ids.push_back(i);
            }
        }
        out.points = input.size();
        Delaunay delaunay(input.begin(), input.end());
        release(input);
        progress.throwIfCancelled();
        std::vector<Overreach> overreaching;
        std::size_t visited = 0;
        for (auto cell = delaunay.finite_cells_begin(); cell != delaunay.finite_cells_end();
             ++cell) {
            cell->info() = kElsewhere;
            if (++visited % 65536 == 0) {
                progress.throwIfCancelled();
            }
            // By ascending id: the same four points give the same centre, to
            // the last bit, in every slab that has them.
            std::array<std::uint32_t, 4> g{};
            for (int i = 0; i < 4; ++i) {
                g[i] = ids[cell->vertex(i)->info()];
            }
            std::sort(g.begin(), g.end());
            const auto centre = circumcentre(points.position(g[0]), points.position(g[1]),
                                             points.position(g[2]), points.position(g[3]));
            if (!centre || !((*centre)[axis] >= slab.lo && (*centre)[axis] < slab.hi)) {
                continue;
            }
            const double radius = glm::length(*centre - points.position(g[0]));
            if (!(radius < s.diagonalMm)) {
                continue;
            }
            const std::array<double, 2> reach = reachPast(slab, *centre, radius, low, high);
            const bool empty = reach[0] == 0.0 && reach[1] == 0.0;
            bool inside = true;
            for (const std::uint32_t id : g) {
                inside = inside && glm::dot(points.normal(id), *centre - points.position(id)) < 0.0;
            }
            if (!inside) {
                cell->info() = empty ? kOwnOutside : kElsewhere;
                continue;
            }
            if (!empty) {
                overreaching.push_back({*centre, radius, reach});
                continue;
            }
            cell->info() = static_cast<std::uint32_t>(out.radii.size());
            out.localCentres.push_back(frame.toLocal(*centre));
            out.radii.push_back(frame.toLocalLength(radius));
        }
        if (!overreaching.empty()) {
            widen(slab, overreaching, out.retries);
            out.localCentres.clear();
            out.radii.clear();
            continue;
        }
        // Per point of the slab, its widest sphere here.
        std::vector<std::uint32_t> best(ids.size(), kElsewhere);
        const auto isVertex = [](std::uint32_t info) { return info < kOwnOutside; };
        for (auto cell = delaunay.finite_cells_begin(); cell != delaunay.finite_cells_end();
             ++cell) {
            if (!isVertex(cell->info())) {
                continue;
            }
            for (int i = 0; i < 4; ++i) {
                std::uint32_t& b = best[cell->vertex(i)->info()];
                if (b == kElsewhere || out.radii[b] < out.radii[cell->info()]) {
                    b = cell->info();
                }
            }
        }
        for (std::size_t i = 0; i < ids.size(); ++i) {
            if (best[i] != kElsewhere && points.onSurfaceVertex(ids[i])) {
                out.poles.push_back({ids[i], best[i]});
            }
        }
        release(best);
        // The edges within the slab, in compressed rows (count, then fill);
        // across a face whose other side is not known here, a record.
        out.localCentres.shrink_to_fit();
        out.radii.shrink_to_fit();
        out.offsets.assign(out.radii.size() + 1, 0);
        const auto forEachFace = [&](const auto& visit) {
            for (auto cell = delaunay.finite_cells_begin(); cell != delaunay.finite_cells_end();
                 ++cell) {
                if (isVertex(cell->info())) {
                    for (int i = 0; i < 4; ++i) {
                        visit(cell, i, cell->neighbor(i));
                    }
                }
            }
        };
        forEachFace([&](const auto& cell, int, const auto& other) {
            if (!delaunay.is_infinite(other) && isVertex(other->info())) {
                ++out.offsets[cell->info() + 1];
            }
        });
        for (std::size_t v = 1; v < out.offsets.size(); ++v) {
            out.offsets[v] += out.offsets[v - 1];
        }
        out.neighbours.resize(out.offsets.back());
        std::vector<std::uint32_t> fill(out.offsets.begin(), out.offsets.end() - 1);
        forEachFace([&](const auto& cell, int i, const auto& other) {
            const bool finite = !delaunay.is_infinite(other);
            if (finite && isVertex(other->info())) {
                out.neighbours[fill[cell->info()]++] = other->info();
            } else if (!finite || other->info() == kElsewhere) {
                FaceRecord record{.face = {}, .cell = cell->info()};
                for (int k = 0, j = 0; k < 4; ++k) {
                    if (k != i) {
                        record.face[j++] = ids[cell->vertex(k)->info()];
                    }
                }
                std::sort(record.face.begin(), record.face.end());
                out.faces.push_back(record);
            }
        });
        return out;
    }
}

/// How many slabs `points` points are cut into under `policy`.
std::size_t slabCount(std::size_t points, const SlabPolicy& policy) {
    if (points < std::max<std::size_t>(policy.splitFrom, 1)) {
        return 1;
    }
    const auto cores = static_cast<std::size_t>(policy.cores > 0 ? policy.cores : workerCount());
    const std::size_t most = std::max<std::size_t>(policy.maxPointsPerSlab, 1);
    const std::size_t needed = points / most + (points % most != 0 ? 1 : 0);
    return std::clamp<std::size_t>(std::max(cores, needed), 1, kMaxSlabs);
}

/// The `count` slabs for the kept points, across the
/// longest side of their bounding box, cut at the points' quantiles; each
/// with a first margin per column of the policy's marginPerRadius times the widest
/// local radius of the wall near its cuts there, or half a slab's width
/// where the wall says nothing near a cut.
std::vector<Slab> slabsFor(const PreparedSurface& s, const SamplePoints& points,
                           const VoronoiSamples& samples, std::size_t count,
                           const SlabPolicy& policy, double& low, double& high) {
    glm::dvec3 lo(std::numeric_limits<double>::max());
    glm::dvec3 hi(std::numeric_limits<double>::lowest());
    for (const std::uint32_t i : samples.kept) {
        lo = glm::min(lo, points.position(i));
        hi = glm::max(hi, points.position(i));
    }
    const glm::dvec3 size = hi - lo;
    const int axis = size.x >= size.y && size.x >= size.z ? 0 : (size.y >= size.z ? 1 : 2);
    low = lo[axis];
    high = hi[axis];
    std::vector<Slab> slabs(count);
    for (Slab& slab : slabs) {
        slab.axis = axis;
    }
    if (count == 1) {
        return slabs;
    }
    std::vector<double> coordinates;
    coordinates.reserve(samples.kept.size());
    for (const std::uint32_t i : samples.kept) {
        coordinates.push_back(points.position(i)[axis]);
    }
    std::vector<double> cuts;
    for (std::size_t k = 1; k < count; ++k) {
        const auto at = static_cast<std::ptrdiff_t>(k * coordinates.size() / count);
        std::nth_element(coordinates.begin(), coordinates.begin() + at, coordinates.end());
        cuts.push_back(coordinates[static_cast<std::size_t>(at)]);
    }
    release(coordinates);
    // Per cut and column, the margin for the widest wall radius whose
    // spheres may cross the cut there: a sphere of radius r touching a
    // vertex lies within 2r of it. A cut with no radius near it (a rough or
    // flat wall) takes half a slab on each side everywhere.
    const double band = 0.5 * (high - low) / static_cast<double>(count);
    std::vector<CutMargins> margins(cuts.size(),
                                    CutMargins(axis, lo, hi, policy.marginColumns, 0.0));
    std::vector<bool> seen(cuts.size(), false);
    for (std::size_t v = 0; v < samples.wallRadiusMm.size(); ++v) {
        const double r = samples.wallRadiusMm[v];
        if (!(r > 0.0) || !std::isfinite(r)) {
            continue;
        }
        const glm::dvec3& p = s.cappedPositions[v];
        for (std::size_t k = 0; k < cuts.size(); ++k) {
            if (std::abs(p[axis] - cuts[k]) <= std::min(2.0 * r, band)) {
                margins[k].raise(p, 2.0 * r, policy.marginPerRadius * r);
                seen[k] = true;
            }
        }
    }
    for (std::size_t k = 0; k < cuts.size(); ++k) {
        if (!seen[k]) {
            margins[k].raiseAll(2.0 * band);
        }
    }
    for (std::size_t k = 0; k < count; ++k) {
        Slab& slab = slabs[k];
        if (k > 0) {
            slab.lo = cuts[k - 1];
            slab.below = margins[k - 1];
        }
        if (k + 1 < count) {
            slab.hi = cuts[k];
            slab.above = margins[k];
        }
    }
    return slabs;
}

/// How many points the slabs take in all, their margins' with their cores'.
std::size_t pointsTaken(const SamplePoints& points, const std::vector<std::uint32_t>& kept,
                        const std::vector<Slab>& slabs) {
    std::size_t taken = 0;
    for (const std::uint32_t i : kept) {
        for (const Slab& slab : slabs) {
            taken += slab.takes(points.position(i)) ? 1 : 0;
        }
    }
    return taken;
}

/// The slabs for the policy: slabCount() of them, fewer (not below one
/// per core) while their first margins would take more than
/// kMostTakenPerKept times the kept points. Slabs thinner than the
/// vessels across them are mostly margin: a rough 1M-triangle aneurysm
/// (every point kept) in 36 slabs 5 mm wide, its sac 50 mm across, took
/// 2.4M points for its 491k and 6.9 s for the 2.4 s of one slab.
std::vector<Slab> chooseSlabs(const PreparedSurface& s, const SamplePoints& points,
                              const VoronoiSamples& samples, const SlabPolicy& policy, double& low,
                              double& high) {
    const auto cores = std::clamp<std::size_t>(
        static_cast<std::size_t>(policy.cores > 0 ? policy.cores : workerCount()), 1, kMaxSlabs);
    std::size_t count = slabCount(samples.kept.size(), policy);
    for (;;) {
        std::vector<Slab> slabs = slabsFor(s, points, samples, count, policy, low, high);
        if (count <= cores || static_cast<double>(pointsTaken(points, samples.kept, slabs)) <=
                                  kMostTakenPerKept * static_cast<double>(samples.kept.size())) {
            return slabs;
        }
        count = std::max(cores, count * 2 / 3);
    }
}

/// The graph's frame for the kept points: the middle of their box, half
/// its diagonal (the smallest positive double when they coincide).
LocalFrame frameOf(const SamplePoints& points, const std::vector<std::uint32_t>& kept) {
    LocalFrame frame;
    if (kept.empty()) {
        return frame;
    }
    glm::dvec3 lo(std::numeric_limits<double>::max());
    glm::dvec3 hi(std::numeric_limits<double>::lowest());
    for (const std::uint32_t i : kept) {
        lo = glm::min(lo, points.position(i));
        hi = glm::max(hi, points.position(i));
    }
    frame.origin = 0.5 * (lo + hi);
    frame.scale = std::max(0.5 * glm::length(hi - lo), std::numeric_limits<double>::min());
    return frame;
}

}  // namespace

VoronoiGraph buildVoronoiGraph(const PreparedSurface& s, const VoronoiSamples& samples,
                               const Progress& progress, const SlabPolicy& policy) {
    progress.report(0.0, "Tetrahedralising the surface");
    const SamplePoints points(s, samples);
    double low = 0.0;
    double high = 0.0;
    const std::vector<Slab> slabs = chooseSlabs(s, points, samples, policy, low, high);
    // The centres are kept in float from this point (VoronoiGraph).
    const LocalFrame frame = frameOf(points, samples.kept);
    // The slabs on every core; each frees its tetrahedralisation when done,
    // so at most one per core is held.
    std::vector<SlabDiagram> parts(slabs.size());
    parallelFor(
        0, static_cast<long>(slabs.size()), 1,
        [&](long begin, long end) {
            for (long k = begin; k < end; ++k) {
                const auto i = static_cast<std::size_t>(k);
                parts[i] =
                    slabDiagram(s, points, samples.kept, slabs[i], low, high, frame, progress);
            }
        },
        progress.stopToken());
    // The slabs' tetrahedra were freed on the worker threads, into arenas
    // this thread does not allocate from: handed back to the system, or the
    // graph and the surface index below take new memory beside them (the
    // demo tree's peak 184 -> 147 MiB, measured with one slab per core). One
    // slab ran on this thread.
    if (slabs.size() > 1) {
        handBackFreedMemory();
    }
    progress.report(0.8, "Joining the Voronoi diagram");
    VoronoiGraph graph;
    graph.slabs = static_cast<int>(slabs.size());
    std::vector<std::uint32_t> base(parts.size() + 1, 0);
    for (std::size_t k = 0; k < parts.size(); ++k) {
        base[k + 1] = base[k] + static_cast<std::uint32_t>(parts[k].radii.size());
        graph.slabRetries += parts[k].retries;
        graph.tetrahedralisedPoints += parts[k].points;
    }
    const std::size_t total = base.back();
    if (total == 0) {
        throw AnalysisError(s.source, (s.source.empty() ? s.name + ": " : "") +
                                          "the surface encloses no space (no inside was found)");
    }
    // Numbered along a Z-order curve: the walks over the graph (minimal
    // paths, tips, covering) then read neighbouring memory.
    std::vector<std::uint32_t> partOf(total);
    for (std::size_t k = 0; k < parts.size(); ++k) {
        std::fill(partOf.begin() + base[k], partOf.begin() + base[k + 1],
                  static_cast<std::uint32_t>(k));
    }
    const auto centreAt = [&](std::size_t v) -> const glm::vec3& {
        return parts[partOf[v]].localCentres[v - base[partOf[v]]];
    };
    const auto wideCentreAt = [&](std::size_t v) { return glm::dvec3(centreAt(v)); };
    const std::vector<std::uint32_t> rank = zOrderRanks(total, wideCentreAt);
    graph.frame = frame;
    graph.localCentres.resize(total);
    graph.radii.resize(total);
    for (std::size_t v = 0; v < total; ++v) {
        graph.localCentres[rank[v]] = centreAt(v);
        graph.radii[rank[v]] = parts[partOf[v]].radii[v - base[partOf[v]]];
    }
    release(partOf);
    // A surface vertex's pole: its widest sphere over the slabs (the first
    // slab's among equals).
    graph.poles.assign(s.cappedPositions.size(), kOutside);
    for (std::size_t k = 0; k < parts.size(); ++k) {
        for (const PoleCandidate& candidate : parts[k].poles) {
            const std::uint32_t v = rank[base[k] + candidate.cell];
            std::uint32_t& pole = graph.poles[candidate.vertex];
            if (pole == kOutside || graph.radii[pole] < graph.radii[v]) {
                pole = v;
            }
        }
        release(parts[k].poles);
        release(parts[k].localCentres);
        release(parts[k].radii);
    }
    // A vertex left out of the diagram has its representative's pole.
    for (std::size_t v = 0; v < graph.poles.size(); ++v) {
        const std::uint32_t r = samples.representative[v];
        if (r != v) {
            graph.poles[v] = graph.poles[r];
        }
    }
    // The edges across slabs: the two sides of one face.
    std::vector<FaceRecord> faces;
    for (std::size_t k = 0; k < parts.size(); ++k) {
        for (FaceRecord record : parts[k].faces) {
            record.cell = rank[base[k] + record.cell];
            faces.push_back(record);
        }
        release(parts[k].faces);
    }
    std::sort(faces.begin(), faces.end(), [](const FaceRecord& a, const FaceRecord& b) {
        return a.face < b.face || (a.face == b.face && a.cell < b.cell);
    });
    std::vector<std::pair<std::uint32_t, std::uint32_t>> across;
    for (std::size_t i = 0; i + 1 < faces.size(); ++i) {
        if (faces[i].face == faces[i + 1].face && faces[i].cell != faces[i + 1].cell) {
            across.emplace_back(faces[i].cell, faces[i + 1].cell);
            ++i;
        }
    }
    release(faces);
    // Compressed rows, each row ascending: the same graph however the
    // points were cut into slabs.
    const auto forEachEdge = [&](const auto& visit) {
        for (std::size_t k = 0; k < parts.size(); ++k) {
            const SlabDiagram& part = parts[k];
            for (std::size_t a = 0; a + 1 < part.offsets.size(); ++a) {
                for (std::uint32_t e = part.offsets[a]; e < part.offsets[a + 1]; ++e) {
                    visit(rank[base[k] + a], rank[base[k] + part.neighbours[e]]);
                }
            }
        }
        for (const auto& [a, b] : across) {
            visit(a, b);
            visit(b, a);
        }
    };
    graph.offsets.assign(total + 1, 0);
    forEachEdge([&](std::uint32_t a, std::uint32_t) { ++graph.offsets[a + 1]; });
    for (std::size_t v = 1; v < graph.offsets.size(); ++v) {
        graph.offsets[v] += graph.offsets[v - 1];
    }
    graph.neighbours.resize(graph.offsets.back());
    std::vector<std::uint32_t> fill(graph.offsets.begin(), graph.offsets.end() - 1);
    forEachEdge([&](std::uint32_t a, std::uint32_t b) { graph.neighbours[fill[a]++] = b; });
    for (std::size_t v = 0; v < total; ++v) {
        std::sort(graph.neighbours.begin() + graph.offsets[v],
                  graph.neighbours.begin() + graph.offsets[v + 1]);
    }
    // The slabs' parts were held while the graph was built beside them;
    // freed, and handed back (glibc), so that they are not counted with what
    // the analysis holds from here on (the demo tree's peak about 5 MiB lower).
    release(parts);
    handBackFreedMemory();
    return graph;
}

}  // namespace vv::analysis::detail
