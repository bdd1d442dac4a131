// SPDX-License-Identifier: GPL-3.0-or-later
#include "VoronoiGraph.h"

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Delaunay_triangulation_cell_base_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_cell_base_with_info_3.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

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
/// tetrahedralised from the points within `margin` of the core.
struct Slab {
    int axis = 0;
    double lo = -std::numeric_limits<double>::infinity();
    double hi = std::numeric_limits<double>::infinity();
    double margin = 0.0;
};

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
/// taken (within `margin` of the core, or beyond the last point on that
/// side); an inside one whose sphere reaches further means the margin was
/// too narrow, and the slab is done again with a wider one. `low` and
/// `high`: the smallest and largest coordinate of any point along the axis;
/// the centres and radii are kept in `frame`, in float.
SlabDiagram slabDiagram(const PreparedSurface& s, const SamplePoints& points,
                        const std::vector<std::uint32_t>& kept, Slab slab, double low, double high,
                        const LocalFrame& frame, const Progress& progress) {
    const int axis = slab.axis;
    for (SlabDiagram out;; ++out.retries) {
        const double from = slab.lo - slab.margin;
        const double to = slab.hi + slab.margin;
        const bool lowOpen = from <= low;
        const bool highOpen = to >= high;
        std::vector<std::uint32_t> ids;
        std::vector<std::pair<Kernel::Point_3, std::uint32_t>> input;
        for (const std::uint32_t i : kept) {
            const glm::dvec3& p = points.position(i);
            if (p[axis] >= from && p[axis] <= to) {
                input.emplace_back(Kernel::Point_3(p.x, p.y, p.z),
                                   static_cast<std::uint32_t>(ids.size()));
                ids.push_back(i);
            }
        }
        Delaunay delaunay(input.begin(), input.end());
        release(input);
        progress.throwIfCancelled();
        double needed = 0.0;
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
            const double c = (*centre)[axis];
            const bool empty = (lowOpen || c - radius >= from) && (highOpen || c + radius <= to);
            bool inside = true;
            for (const std::uint32_t id : g) {
                inside = inside && glm::dot(points.normal(id), *centre - points.position(id)) < 0.0;
            }
            if (!inside) {
                cell->info() = empty ? kOwnOutside : kElsewhere;
                continue;
            }
            if (!empty) {
                needed = std::max({needed, slab.lo - (c - radius), (c + radius) - slab.hi});
                continue;
            }
            cell->info() = static_cast<std::uint32_t>(out.radii.size());
            out.localCentres.push_back(frame.toLocal(*centre));
            out.radii.push_back(frame.toLocalLength(radius));
        }
        if (needed > 0.0) {
            slab.margin = std::max(1.25 * needed, 2.0 * slab.margin);
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
    return std::clamp<std::size_t>(std::max(cores, (points + most - 1) / most), 1, kMaxSlabs);
}

/// The `count` slabs for the kept points, across the
/// longest side of their bounding box, cut at the points' quantiles; each
/// with a first margin of `marginPerRadius` times the widest local radius of
/// the wall near its cuts, or its own width where the wall says nothing.
std::vector<Slab> slabsFor(const PreparedSurface& s, const SamplePoints& points,
                           const VoronoiSamples& samples, std::size_t count, double marginPerRadius,
                           double& low, double& high) {
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
    // The widest wall radius within half a slab of each cut.
    const double band = 0.5 * (high - low) / static_cast<double>(count);
    std::vector<double> widest(cuts.size(), 0.0);
    for (std::size_t v = 0; v < samples.wallRadiusMm.size(); ++v) {
        const double r = samples.wallRadiusMm[v];
        if (!(r > 0.0) || !std::isfinite(r)) {
            continue;
        }
        const double x = s.cappedPositions[v][axis];
        for (std::size_t k = 0; k < cuts.size(); ++k) {
            if (std::abs(x - cuts[k]) <= band) {
                widest[k] = std::max(widest[k], r);
            }
        }
    }
    for (std::size_t k = 0; k < count; ++k) {
        Slab& slab = slabs[k];
        if (k > 0) {
            slab.lo = cuts[k - 1];
        }
        if (k + 1 < count) {
            slab.hi = cuts[k];
        }
        double margin = 0.0;
        for (const std::size_t cut : {k - 1, k}) {
            if (cut < cuts.size()) {
                margin = std::max(margin,
                                  widest[cut] > 0.0 ? marginPerRadius * widest[cut] : 2.0 * band);
            }
        }
        slab.margin = margin;
    }
    return slabs;
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
    const std::vector<Slab> slabs =
        slabsFor(s, points, samples, slabCount(samples.kept.size(), policy), policy.marginPerRadius,
                 low, high);
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
#if defined(__GLIBC__)
    // The slabs' tetrahedra were freed on the worker threads, into arenas
    // this thread does not allocate from: handed back to the system, or the
    // graph and the surface index below take new memory beside them (the
    // demo tree's peak 184 -> 147 MiB, measured with one slab per core). One
    // slab ran on this thread.
    if (slabs.size() > 1) {
        malloc_trim(0);
    }
#endif
    progress.report(0.8, "Joining the Voronoi diagram");
    VoronoiGraph graph;
    graph.slabs = static_cast<int>(slabs.size());
    std::vector<std::uint32_t> base(parts.size() + 1, 0);
    for (std::size_t k = 0; k < parts.size(); ++k) {
        base[k + 1] = base[k] + static_cast<std::uint32_t>(parts[k].radii.size());
        graph.slabRetries += parts[k].retries;
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
#if defined(__GLIBC__)
    malloc_trim(0);
#endif
    return graph;
}

}  // namespace vv::analysis::detail
