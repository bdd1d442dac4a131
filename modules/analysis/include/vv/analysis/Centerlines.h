// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// Centrelines of a vessel surface by the method VMTK uses (Antiga et al.
// 2008, "An image-based modeling framework for patient-specific
// computational hemodynamics"): the Delaunay tetrahedralisation of the
// surface's points (CGAL, exact predicates) gives the internal Voronoi
// diagram, each of its vertices the centre of a maximal inscribed sphere;
// a centreline is the minimal path over it with cost 1/R (it keeps to the
// middle of the lumen), from a source end to each target end. The paths
// share their common part, which makes the branch tree: where two paths part
// is a bifurcation. docs/analysis.md tells the method, its choices and their
// measured error.

#include <cstdint>
#include <glm/glm.hpp>
#include <optional>
#include <string>
#include <vector>

#include "vv/analysis/AnalysisError.h"
#include "vv/core/Progress.h"
#include "vv/scene/Mesh.h"

namespace vv::analysis {

/// Where a centreline starts or ends, and how that place was found.
struct EndPoint {
    enum class Kind : std::uint8_t {
        OpenEnd,  ///< the centre of an open boundary loop (a cut vessel end)
        Tip,      ///< the end of a closed vessel (found automatically)
        Given,    ///< a point the user gave
    };
    Kind kind = Kind::OpenEnd;
    glm::dvec3 position{0.0};   ///< where the centreline ends, mm
    glm::dvec3 requested{0.0};  ///< Given: the point as given; otherwise = position
    /// Given: distance from the given point to the nearest surface point, mm
    /// (what the user should be told when it is large); otherwise 0.
    double offsetMm = 0.0;
    /// OpenEnd: the loop's mean radius, mm; otherwise the inscribed sphere's
    /// radius where the centreline ends.
    double radiusMm = 0.0;
};

/// One point of a centreline, resampled at a fixed step.
struct CenterlinePoint {
    glm::dvec3 position{0.0};  ///< mm
    /// Radius of the largest sphere centred here that stays inside the
    /// surface (the distance to the nearest surface point), mm. VMTK's
    /// MaximumInscribedSphereRadius: half the *inscribed* diameter, which is
    /// the smallest diameter the lumen has through this point, not the
    /// equivalent diameter of the section.
    double radiusMm = 0.0;
    double abscissaMm = 0.0;  ///< arc length from the branch tree's source, mm
    glm::dvec3 tangent{0.0};  ///< unit, towards the target
    /// Rotation-minimising frame (double reflection, Wang et al. 2008):
    /// normal and binormal = tangent x normal never twist about the tangent,
    /// so sections along the centreline keep their orientation.
    glm::dvec3 normal{0.0};
    double curvature = 0.0;  ///< 1/mm, measured over about one radius either side
    double torsion = 0.0;    ///< 1/mm, signed; 0 where the curvature is ~0
};

/// A stretch of centreline between two nodes of the tree (source, a
/// bifurcation or an end).
struct Branch {
    int id = 0;
    int parent = -1;  ///< the branch this one leaves at its first point; -1 at the source
    std::vector<int> children;
    std::vector<CenterlinePoint> points;  ///< >= 2, from the parent's end to the tip
    double lengthMm = 0.0;                ///< along the centreline
    double chordMm = 0.0;                 ///< between the first and the last point
    /// length / chord - 1 (0 for a straight branch).
    [[nodiscard]] double tortuosity() const noexcept {
        return chordMm > 0.0 ? lengthMm / chordMm - 1.0 : 0.0;
    }
    int endIndex = -1;  ///< CenterlineTree::ends index of its far end; -1 at a bifurcation
};

/// CenterlineOptions::maxTriangles by default.
inline constexpr std::size_t kDefaultMaxTriangles = 3'000'000;

struct CenterlineOptions {
    /// The source end; nullopt: the largest open end, or, on a closed
    /// surface, the end of the widest vessel.
    std::optional<glm::dvec3> source;
    /// The target ends; empty: every other open end and every closed tip.
    std::vector<glm::dvec3> targets;
    double stepMm = 0.5;  ///< resampling step along the centrelines, in [0.01, 10]
    /// A surface of more triangles is analysed coarsened to about this many:
    /// its points merged into cells (each moves at most a cell's diagonal,
    /// which a note states); >= 1000. Bounds time and memory (a 10M-triangle
    /// export of a segmentation is far finer than its vessels need).
    std::size_t maxTriangles = kDefaultMaxTriangles;
    /// A wall whose noise is larger than its triangles folds over itself, and
    /// its inside breaks up where the vessel narrows: such a wall is smoothed
    /// first (a low-pass filter over the mesh that keeps the vessel's shape;
    /// a note says how far its points moved). false: analysed as it is, with
    /// a note that the results may follow the noise.
    bool smoothFoldedWall = true;
};

struct CenterlineTree {
    std::vector<Branch> branches;  ///< [0] starts at the source; parents before children
    std::vector<EndPoint> ends;    ///< [0] is the source
    /// What the user should know: pieces left out, points moved onto the
    /// surface, a surface that was repaired. Plain sentences.
    std::vector<std::string> notes;
    std::size_t voronoiVertices = 0;  ///< inside the surface (the diagram's size)
};

/// Centrelines of `mesh` (mm). The mesh may be open (its boundary loops are
/// the ends) or closed; duplicate points, degenerate and repeated triangles
/// are dropped; of several pieces the one the source lies on (or the largest)
/// is taken and the others noted. Progress is reported; a stop request
/// throws CancelledError. Throws InvalidArgumentError for options out of
/// range, AnalysisError (naming the mesh's source) when the surface cannot be
/// analysed: no triangles, no inside, fewer than two ends, an end on another
/// piece, non-finite coordinates, a centreline of more than 100,000 points at
/// the step (a surface in other units than mm).
[[nodiscard]] CenterlineTree computeCenterlines(const scene::Mesh& mesh,
                                                const CenterlineOptions& options = {},
                                                const Progress& progress = {});

}  // namespace vv::analysis
