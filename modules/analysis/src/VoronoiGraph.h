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

/// The vertices are numbered along a Z-order curve through their centres,
/// so that the walks over the graph read neighbouring memory.
struct VoronoiGraph {
    std::vector<glm::dvec3> centres;
    std::vector<double> radii;
    /// Adjacency in compressed rows: the neighbours of v are
    /// neighbours[offsets[v] .. offsets[v + 1]).
    std::vector<std::uint32_t> offsets;
    std::vector<std::uint32_t> neighbours;
    /// Per capped-surface vertex: its pole, the Voronoi vertex of the largest
    /// inscribed sphere that touches it (UINT32_MAX when none does).
    std::vector<std::uint32_t> poles;

    [[nodiscard]] std::size_t size() const noexcept { return centres.size(); }
};

/// The diagram of `surface`'s capped points chosen by `samples` (and their
/// outward normals); a left-out point's pole is its representative's:
/// a tetrahedron counts as inside when its circumcentre lies behind the
/// tangent plane of each of its four points (VMTK's test), and its
/// circumradius is finite and below the surface's diagonal. Throws
/// AnalysisError when nothing is inside; CancelledError on a stop.
[[nodiscard]] VoronoiGraph buildVoronoiGraph(const PreparedSurface& surface,
                                             const VoronoiSamples& samples,
                                             const Progress& progress);

}  // namespace vv::analysis::detail
