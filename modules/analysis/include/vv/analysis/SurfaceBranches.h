// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// The surface split into branches: which branch of a centreline tree each
// vertex of the vessel surface belongs to.

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "vv/analysis/Centerlines.h"
#include "vv/scene/Mesh.h"

namespace vv::analysis {

/// Per vertex of `mesh` (the mesh the tree was made from), the id of the
/// branch it belongs to: of the centreline points nearest to it, the one
/// it is nearest to in units of that point's inscribed radius (the branch
/// whose tube holds it best), so that a daughter's wall near a bifurcation
/// goes to the daughter. -1 for a vertex of a piece the tree does not run
/// through (farther than four inscribed radii from every centreline point).
[[nodiscard]] std::vector<std::int32_t> surfaceBranchIds(const scene::Mesh& mesh,
                                                         const CenterlineTree& tree);

/// `mesh` with a point array "branch_id" (integer, no unit) from
/// surfaceBranchIds() and the label names "branch N" (the categorical-label
/// path: legends with swatches, the probe naming the branch); NaN where -1.
/// An existing "branch_id" array is replaced.
[[nodiscard]] scene::Mesh withBranchIds(scene::Mesh mesh, const CenterlineTree& tree);

}  // namespace vv::analysis
