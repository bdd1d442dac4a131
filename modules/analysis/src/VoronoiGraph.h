// SPDX-License-Identifier: GPL-3.0-or-later
// Private to vv::analysis: the internal Voronoi diagram of a prepared
// surface as a graph. Its vertices are the circumcentres of the Delaunay
// tetrahedra of the (capped) surface's points that lie inside the surface,
// each the centre of a maximal inscribed sphere of radius R; its edges join
// tetrahedra that share a face.
#pragma once

#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

#include "PreparedSurface.h"
#include "VoronoiSamples.h"

namespace vv::analysis::detail {

/// Where the graph's float coordinates are measured from: `origin` (the
/// middle of the points' box), in units of `scale` mm (half its diagonal),
/// so that every centre and radius is a few units at most whatever the
/// mesh's size (in mm, a huge mesh's far circumcentres overflow a float).
struct LocalFrame {
    glm::dvec3 origin{0.0};
    double scale = 1.0;  ///< > 0

    [[nodiscard]] glm::vec3 toLocal(const glm::dvec3& p) const {
        return static_cast<glm::vec3>((p - origin) / scale);
    }
    [[nodiscard]] float toLocalLength(double mm) const { return static_cast<float>(mm / scale); }
    [[nodiscard]] glm::dvec3 fromLocal(const glm::vec3& p) const {
        return origin + scale * glm::dvec3(p);
    }
};

/// The vertices are numbered along a Z-order curve through their centres,
/// so that the walks over the graph read neighbouring memory. Centres and
/// radii are computed in double and kept in float in `frame`: rounded to
/// one part in 16 million of half the points' box (0.01 µm on a 300 mm
/// tree), far below the wall's own sampling, at half the memory; the graph
/// is held through the whole analysis.
struct VoronoiGraph {
    LocalFrame frame;
    std::vector<glm::vec3> localCentres;  ///< frame.toLocal(centre)
    std::vector<float> radii;             ///< frame.toLocalLength(radius)
    /// Adjacency in compressed rows: the neighbours of v are
    /// neighbours[offsets[v] .. offsets[v + 1]).
    std::vector<std::uint32_t> offsets;
    std::vector<std::uint32_t> neighbours;
    /// Per capped-surface vertex: its pole, the Voronoi vertex of the largest
    /// inscribed sphere that touches it (UINT32_MAX when none does).
    std::vector<std::uint32_t> poles;

    /// How many slabs the points were tetrahedralised in, and how many
    /// times a slab was done again with a wider margin.
    int slabs = 1;
    int slabRetries = 0;
    /// Points in the slabs' tetrahedralisations (each slab's last try):
    /// the points kept, in one slab; in several, the margins' points too.
    std::size_t tetrahedralisedPoints = 0;

    [[nodiscard]] std::size_t size() const noexcept { return radii.size(); }
    [[nodiscard]] glm::dvec3 centre(std::size_t v) const {
        return frame.fromLocal(localCentres[v]);
    }
    [[nodiscard]] double radius(std::size_t v) const {
        return frame.scale * static_cast<double>(radii[v]);
    }
};

/// How the points are cut into slabs, each tetrahedralised on its own (on
/// every core; each slab with the points within a margin of it).
struct SlabPolicy {
    /// From this many points on, one slab per core: the demo tree's 150k
    /// points take 1.2 s in two slabs on two cores against 1.6-1.8 s in one
    /// (`bench/analysis_accuracy --slabs`); below, the margins cost more
    /// than the cores give.
    std::size_t splitFrom = 60'000;
    /// At most about this many points per slab (its margins aside): the
    /// tetrahedralisation takes about 500 bytes per point, and one slab per
    /// core is held at a time. With 14k, margins per column and the float
    /// graph, the demo tree's peak heap is 72 MB above the analysis' start
    /// on two cores (196 MB with 400k, one margin per cut and the graph in
    /// double), for about 0.15 s more (`bench/analysis_accuracy --demo`,
    /// docs/benchmarks/analysis.md), and a 10M-triangle surface is never
    /// tetrahedralised whole.
    std::size_t maxPointsPerSlab = 14'000;
    /// Slabs wanted from splitFrom on (the worker threads by default).
    int cores = 0;
    /// A slab's first margin, in the widest local radius of the wall near
    /// its cuts (the inscribed spheres there are about that wide); a slab
    /// whose margin proves too narrow is done again with a wider one.
    double marginPerRadius = 1.25;
    /// The margins are set per column of a grid across the slabs' axis,
    /// this many columns along its longer side (1: one margin per cut, set
    /// by the widest vessel there). With 64, the demo tree's slabs take
    /// 1.4 times their core's points, against 1.8 with one margin per cut.
    int marginColumns = 64;
};
inline constexpr std::size_t kMaxSlabs = 256;

/// The diagram of `surface`'s capped points chosen by `samples` (and their
/// outward normals; only the capped arrays are read); a left-out point's pole is its
/// representative's: a tetrahedron counts as inside when its circumcentre lies behind the tangent
/// plane of each of its four points (VMTK's test), and its circumradius is finite and below the
/// surface's diagonal. Throws AnalysisError when nothing is inside; CancelledError on a stop.
///
/// The points are cut across the longest side of their box into slabs
/// (`policy`); a slab's tetrahedra whose circumspheres lie within
/// the points it took are those of all the points, and each diagram vertex
/// is taken from the slab its centre lies in. The graph is the same however
/// the points were cut (each row ascending; the numbering of vertices with
/// equal Z-order keys aside).
[[nodiscard]] VoronoiGraph buildVoronoiGraph(const PreparedSurface& surface,
                                             const VoronoiSamples& samples,
                                             const Progress& progress,
                                             const SlabPolicy& policy = {});

}  // namespace vv::analysis::detail
