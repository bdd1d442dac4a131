// SPDX-License-Identifier: GPL-3.0-or-later
// The checks of the demo options and of a vessel tree (DemoValidation.h).
#include "DemoValidation.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "vv/core/Error.h"
#include "vv/core/Math.h"

namespace vv::demo {

namespace {

constexpr int kMinTriangleLimit = 10000;

void requirePositive(double value, const char* what) {
    if (!(std::isfinite(value) && value > 0.0)) {
        throw InvalidArgumentError(std::string("demo tree: ") + what +
                                   " must be a positive finite number, got " +
                                   std::to_string(value));
    }
}

}  // namespace

namespace detail {

void validateDemoOptions(const DemoTreeOptions& options) {
    if (options.generations < 1 || options.generations > 10) {
        throw InvalidArgumentError("demo tree: generations must be in 1..10, got " +
                                   std::to_string(options.generations));
    }
    requirePositive(options.rootRadiusMm, "root radius (mm)");
    requirePositive(options.rootLengthMm, "root length (mm)");
    requirePositive(options.inletFlowMlPerS, "inlet flow (ml/s)");
    requirePositive(options.viscosityPaS, "viscosity (Pa s)");
    if (options.rootLengthMm < 2.0 * options.rootRadiusMm) {
        throw InvalidArgumentError("demo tree: root length (" +
                                   std::to_string(options.rootLengthMm) +
                                   " mm) must be at least twice the root radius (" +
                                   std::to_string(options.rootRadiusMm) + " mm)");
    }
    if (!std::isfinite(options.inletPressureMmHg)) {
        throw InvalidArgumentError("demo tree: inlet pressure must be finite");
    }
    if (!(std::isfinite(options.voxelSizeMm) && options.voxelSizeMm >= 0.0)) {
        throw InvalidArgumentError("demo tree: voxel size must be 0 (automatic) or positive, got " +
                                   std::to_string(options.voxelSizeMm));
    }
    if (options.maxTriangles != 0 && options.maxTriangles < kMinTriangleLimit) {
        throw InvalidArgumentError("demo tree: triangle limit must be 0 (none) or at least " +
                                   std::to_string(kMinTriangleLimit) + ", got " +
                                   std::to_string(options.maxTriangles));
    }
}

void validateVesselTree(const VesselTree& tree) {
    const auto& segments = tree.segments;
    if (segments.empty()) {
        throw InvalidArgumentError("vessel tree: no segments");
    }
    const int count = static_cast<int>(segments.size());
    for (int i = 0; i < count; ++i) {
        const auto& s = segments[static_cast<std::size_t>(i)];
        const std::string where = "vessel tree: segment " + std::to_string(i);
        if (s.id != i) {
            throw InvalidArgumentError(where + " has id " + std::to_string(s.id));
        }
        if ((i == 0) != (s.parent == -1) || s.parent >= i || s.parent < -1) {
            throw InvalidArgumentError(where + " has parent " + std::to_string(s.parent) +
                                       " (the root must come first, parents before children)");
        }
        if (s.parent >= 0) {
            const auto& siblings = segments[static_cast<std::size_t>(s.parent)].children;
            if (std::count(siblings.begin(), siblings.end(), i) != 1) {
                throw InvalidArgumentError(where +
                                           " is not listed once among its parent's children");
            }
        }
        for (const int c : s.children) {
            if (c <= i || c >= count || segments[static_cast<std::size_t>(c)].parent != i) {
                throw InvalidArgumentError(where + " lists child " + std::to_string(c) +
                                           " which is not its child");
            }
        }
        if (!(std::isfinite(s.radiusMm) && s.radiusMm > 0.0)) {
            throw InvalidArgumentError(where + " has a non-positive radius");
        }
        if (s.centerline.size() < 2) {
            throw InvalidArgumentError(where + " has fewer than 2 centreline points");
        }
        for (const auto& p : s.centerline) {
            if (!isFinite(p)) {
                throw InvalidArgumentError(where + " has a non-finite centreline point");
            }
        }
    }
}

}  // namespace detail

}  // namespace vv::demo
