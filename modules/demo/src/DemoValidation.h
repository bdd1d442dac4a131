// SPDX-License-Identifier: GPL-3.0-or-later
// Private to vv::demo: the checks of the demo options and of a vessel tree that
// both the tree generator (DemoTree.cpp) and the surface (DemoSurface.cpp) run
// on their inputs. Their own header, so that neither of the two needs the other's.
#pragma once

#include "vv/demo/DemoTree.h"

namespace vv::demo::detail {

/// Throws InvalidArgumentError naming the first option out of its documented range.
void validateDemoOptions(const DemoTreeOptions& options);

/// Throws InvalidArgumentError when the tree is not usable for a surface:
/// empty, ids not equal to indices, parents not before children, parent /
/// child links inconsistent, non-finite or non-positive radius, fewer than 2
/// or non-finite centreline points.
void validateVesselTree(const VesselTree& tree);

}  // namespace vv::demo::detail
