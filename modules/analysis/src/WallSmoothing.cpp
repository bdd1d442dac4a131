// SPDX-License-Identifier: GPL-3.0-or-later
#include "WallSmoothing.h"

#include <algorithm>
#include <cstddef>
#include <vector>

#include "VoronoiSamples.h"
#include "vv/analysis/AnalysisError.h"
#include "vv/core/Error.h"
#include "vv/core/NumberText.h"
#include "vv/meshio/MeshSmooth.h"

namespace vv::analysis::detail {

WallSmoothing smoothWall(PreparedSurface& s, const Progress& progress) {
    scene::Mesh wall;
    wall.name = s.name;
    wall.source = s.source;
    wall.positions.reserve(s.positions.size());
    for (const glm::dvec3& p : s.positions) {
        wall.positions.emplace_back(p);
    }
    wall.indices.reserve(3 * s.triangles.size());
    for (const Triangle& t : s.triangles) {
        wall.indices.insert(wall.indices.end(), t.begin(), t.end());
    }
    meshio::SmoothingOptions options;
    options.iterations = kSmoothingIterations;
    options.passBand = kSmoothingPassBand;
    options.keepBoundary = true;  // the open ends' rims decide their centres
    scene::Mesh smoothed;
    try {
        smoothed = meshio::smoothedMesh(wall, options, progress);
    } catch (const FormatError& e) {  // VTK failed (out of memory): the analysis' error
        throw AnalysisError(s.source, (s.source.empty() ? s.name + ": " : "") +
                                          "smoothing its folded wall failed: " + e.problem());
    }
    std::vector<glm::dvec3> positions(s.positions.size());
    WallSmoothing moved;
    for (std::size_t i = 0; i < positions.size(); ++i) {
        positions[i] = glm::dvec3(smoothed.positions[i]);
        const double move = glm::length(positions[i] - s.positions[i]);
        moved.meanMoveMm += move;
        moved.largestMoveMm = std::max(moved.largestMoveMm, move);
    }
    moved.meanMoveMm /= static_cast<double>(std::max<std::size_t>(positions.size(), 1));
    movePositions(s, std::move(positions));
    return moved;
}

bool folds(const PreparedSurface& s) {
    return s.foldedFraction > kFoldedFraction;
}

std::string foldFinding(const PreparedSurface& s) {
    return "the wall folds over itself at " + fixedText(100.0 * s.foldedFraction, 1) +
           " % of its vertices: its noise is larger than its triangles";
}

bool smoothIfFolded(PreparedSurface& s, const Progress& progress) {
    if (!folds(s)) {
        return false;
    }
    const std::string finding = foldFinding(s);
    s.foldedFractionBeforeSmoothing = s.foldedFraction;
    const WallSmoothing moved = smoothWall(s, progress);
    s.foldedFraction = foldedFractionOf(s);
    s.notes.push_back(finding +
                      "; it was smoothed before the analysis (a low-pass filter over "
                      "its mesh that keeps the vessel's shape, its open ends where they are), "
                      "moving its points by " +
                      fixedText(moved.meanMoveMm, 3) + " mm on average and " +
                      fixedText(moved.largestMoveMm, 3) +
                      " mm at most; the centrelines and sections are those of the smoothed "
                      "wall");
    return true;
}

}  // namespace vv::analysis::detail
