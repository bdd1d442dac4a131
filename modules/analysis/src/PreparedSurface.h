// SPDX-License-Identifier: GPL-3.0-or-later
// Private to vv::analysis: a vessel surface made fit for the Voronoi diagram
// and the sections: welded, without degenerate or repeated triangles, one
// connected piece, its boundary loops found, oriented outward, and a capped
// copy (each loop closed by a fan around its centre) whose vertex normals
// tell inside from outside.
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <glm/glm.hpp>
#include <optional>
#include <string>
#include <vector>

#include "vv/core/Progress.h"
#include "vv/scene/Mesh.h"

namespace vv::analysis::detail {

using Triangle = std::array<std::uint32_t, 3>;

/// An open end of the surface.
struct BoundaryLoop {
    std::vector<std::uint32_t> vertices;  ///< in order around the loop
    glm::dvec3 centre{0.0};               ///< the loop's centroid (by edge length)
    /// Unit, pointing into the vessel (for an outward-facing surface).
    glm::dvec3 inward{0.0};
    double radiusMm = 0.0;        ///< mean distance of the loop from its centre
    std::uint32_t capCentre = 0;  ///< the fan's centre vertex in the capped surface
    /// A hole in a vessel's wall rather than a vessel's end: the inscribed
    /// sphere behind its cap is much wider than the opening (set by the
    /// centreline step, which knows the spheres).
    bool hole = false;
};

struct PreparedSurface {
    std::filesystem::path source;  ///< the mesh's file, for messages
    std::string name;              ///< the mesh's name, for messages
    /// The kept piece: vertices (welded), triangles facing outward.
    std::vector<glm::dvec3> positions;
    std::vector<Triangle> triangles;
    std::vector<BoundaryLoop> loops;
    /// positions + one centre per loop; triangles + the caps' fans. Emptied
    /// once the Voronoi diagram is built (diagramOf in AnalysisSteps.h).
    std::vector<glm::dvec3> cappedPositions;
    std::vector<Triangle> cappedTriangles;
    /// Per capped vertex, unit, outward (area-weighted over its triangles).
    std::vector<glm::dvec3> cappedNormals;
    std::vector<std::string> notes;
    double diagonalMm = 0.0;  ///< of the kept piece's bounding box
    /// The fraction of its vertices where the wall folds over itself (set
    /// with the Voronoi samples: VoronoiSamples::foldedFraction).
    double foldedFraction = 0.0;
    /// foldedFraction before the wall was smoothed (WallSmoothing.h); 0 when
    /// it was not.
    double foldedFractionBeforeSmoothing = 0.0;
};

/// Prepares `mesh`. `anchor`, when given, picks the piece whose nearest
/// vertex is nearest to it; otherwise the piece with the most triangles. A
/// mesh of more than `maxTriangles` triangles has its points merged into
/// cubic cells sized to leave about that many (each cell's first point
/// stands for it), and a note says so and how far a point moved at most.
/// Throws AnalysisError for no triangles, non-finite coordinates or indices
/// out of range; CancelledError on a stop request.
[[nodiscard]] PreparedSurface prepareSurface(const scene::Mesh& mesh,
                                             const std::optional<glm::dvec3>& anchor,
                                             const Progress& progress, std::size_t maxTriangles);

/// Moves the kept piece's vertices to `positions` (one per vertex, in their
/// order) and re-measures what depends on them: the loops' centres, radii
/// and directions, the caps, the normals and the diagonal.
void movePositions(PreparedSurface& s, std::vector<glm::dvec3> positions);

/// The message prefix naming the mesh: its file, else its name.
[[nodiscard]] std::string meshLabel(const PreparedSurface& surface);

}  // namespace vv::analysis::detail
