// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/demo/BifurcationPhantom.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "FieldSurface.h"
#include "vv/core/Error.h"
#include "vv/meshio/MeshSimplify.h"

namespace vv::demo {
namespace {

void require(bool ok, const std::string& what) {
    if (!ok) {
        throw InvalidArgumentError("bifurcation phantom: " + what);
    }
}

VesselSegment straightSegment(int id, int parent, const glm::dvec3& from, const glm::dvec3& to,
                              double radius) {
    VesselSegment s;
    s.id = id;
    s.parent = parent;
    const int samples = 32;
    for (int i = 0; i <= samples; ++i) {
        s.centerline.emplace_back(glm::mix(from, to, static_cast<double>(i) / samples));
    }
    s.radiusMm = radius;
    s.lengthMm = glm::length(to - from);
    return s;
}

double tubeArea(const VesselTree& tree) {
    double area = 0.0;
    for (const auto& s : tree.segments) {
        area += 2.0 * std::numbers::pi * s.radiusMm * s.lengthMm;
    }
    return area;
}

}  // namespace

BifurcationPhantom makeBifurcationPhantom(const BifurcationPhantomOptions& options,
                                          const Progress& progress) {
    const BifurcationPhantomOptions& o = options;
    require(std::isfinite(o.parentRadiusMm) && o.parentRadiusMm > 0.0, "radius must be positive");
    require(std::isfinite(o.daughterRadiusMm) && o.daughterRadiusMm >= 0.0 &&
                o.daughterRadiusMm <= o.parentRadiusMm,
            "daughter radius must be in [0, parent radius]");
    require(std::isfinite(o.angleDeg) && o.angleDeg >= 10.0 && o.angleDeg <= 170.0,
            "angle must be in [10, 170] degrees");
    require(
        o.parentLengthMm >= 4.0 * o.parentRadiusMm && o.daughterLengthMm >= 4.0 * o.parentRadiusMm,
        "lengths must be at least 4 parent radii");
    require(o.targetTriangles >= 1000 && o.targetTriangles <= 5'000'000,
            "target triangles must be in 1000..5000000");

    BifurcationPhantom phantom;
    phantom.options = o;
    const double daughter =
        o.daughterRadiusMm > 0.0 ? o.daughterRadiusMm : o.parentRadiusMm / std::cbrt(2.0);
    const double half = o.angleDeg * std::numbers::pi / 360.0;
    phantom.daughterDirections = {glm::dvec3(std::sin(half), 0.0, std::cos(half)),
                                  glm::dvec3(-std::sin(half), 0.0, std::cos(half))};
    auto& segments = phantom.tree.segments;
    segments.push_back(
        straightSegment(0, -1, {0.0, 0.0, -o.parentLengthMm}, glm::dvec3(0.0), o.parentRadiusMm));
    for (int i = 0; i < 2; ++i) {
        const glm::dvec3 end =
            o.daughterLengthMm * phantom.daughterDirections[static_cast<std::size_t>(i)];
        segments.push_back(straightSegment(i + 1, 0, glm::dvec3(0.0), end, daughter));
        segments[0].children.push_back(i + 1);
        segments.back().generation = 1;
    }

    // Flying edges gives about 2 triangles per voxel face of surface; one
    // more extraction corrects the guess. A coarse phantom is a finer one
    // decimated (kFinestExtractionTriangles).
    const std::size_t extracted = std::max(o.targetTriangles, detail::kFinestExtractionTriangles);
    DemoTreeOptions surface;
    surface.maxTriangles = 0;
    const auto target = static_cast<double>(extracted);
    surface.voxelSizeMm = std::sqrt(2.0 * tubeArea(phantom.tree) / target);
    phantom.mesh = buildVesselSurface(phantom.tree, surface, progress.sub(0.0, 0.4));
    const auto got = static_cast<double>(phantom.mesh.triangleCount());
    if (std::abs(got / target - 1.0) > 0.2) {
        surface.voxelSizeMm *= std::sqrt(got / target);
        phantom.mesh = buildVesselSurface(phantom.tree, surface, progress.sub(0.4, 0.8));
    }
    if (o.targetTriangles < extracted) {
        phantom.mesh =
            meshio::simplifiedMesh(phantom.mesh, o.targetTriangles, progress.sub(0.8, 1.0));
    }
    phantom.mesh.name = "bifurcation phantom";
    phantom.mesh.pointArrays.clear();
    return phantom;
}

}  // namespace vv::demo
