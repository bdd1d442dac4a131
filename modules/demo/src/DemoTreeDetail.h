// SPDX-License-Identifier: GPL-3.0-or-later
// Private to vv::demo: what DemoTree.cpp and DemoSurface.cpp share.
#pragma once

#include "vv/demo/DemoTree.h"

namespace vv::demo::detail {

/// Pascal per millimetre of mercury (conventional mmHg).
inline constexpr double kPascalPerMmHg = 133.322387415;

/// Throws InvalidArgumentError naming the first option out of its documented range.
void validateDemoOptions(const DemoTreeOptions& options);

/// Throws InvalidArgumentError when the tree is not usable for a surface:
/// empty, ids not equal to indices, parents not before children, parent /
/// child links inconsistent, non-finite or non-positive radius, fewer than 2
/// or non-finite centreline points.
void validateVesselTree(const VesselTree& tree);

}  // namespace vv::demo::detail
