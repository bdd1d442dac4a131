// SPDX-License-Identifier: GPL-3.0-or-later
#include "cli/CenterlineDrawing.h"

#include <algorithm>
#include <cstddef>
#include <limits>
#include <utility>

#include "vv/analysis/Centerlines.h"
#include "vv/analysis/Sections.h"
#include "vv/core/Error.h"
#include "vv/core/NumberText.h"

namespace vv::cli {

namespace {

/// A warning when the surface's size says it is not in mm.
void warnAboutUnits(const scene::Mesh& mesh, std::ostream& err) {
    const double across = glm::length(glm::dvec3(mesh.bounds().size()));
    if (across > 0.0 && across < 2.0) {
        err << "vesselview-cli: warning: the surface is " << significantText(across, 3)
            << " across: if it is in metres, give --scale 1000 (scene units are mm)\n";
    } else if (across > 5000.0) {
        err << "vesselview-cli: warning: the surface is " << significantText(across, 3)
            << " mm across: if it is in micrometres, give --scale 0.001 (scene units are mm)\n";
    }
}

}  // namespace

const scene::Mesh& analysedSurface(const scene::Scene& scene, const std::filesystem::path& input,
                                   std::ostream& err) {
    if (scene.meshes.empty()) {
        throw FormatError(input, "holds no surface to analyse");
    }
    const scene::Mesh& mesh = scene.meshes.front();
    if (scene.meshes.size() > 1) {
        err << "vesselview-cli: note: " << input.string() << " holds " << scene.meshes.size()
            << " surfaces; the first, '" << mesh.name << "', is analysed\n";
    }
    warnAboutUnits(mesh, err);
    return mesh;
}

render::CenterlineOverlay centerlineOverlay(const scene::Scene& scene,
                                            const std::filesystem::path& input,
                                            render::CenterlineColouring colouring,
                                            colormaps::ColorMap vesselMap, std::ostream& err) {
    const scene::Mesh& mesh = analysedSurface(scene, input, err);
    const analysis::CenterlineTree tree = analysis::computeCenterlines(mesh);
    for (const auto& note : tree.notes) {
        err << "vesselview-cli: note: " << note << "\n";
    }
    render::CenterlineOverlay overlay;
    overlay.colouring = colouring;
    overlay.map = vesselMap == colormaps::ColorMap::Inferno ? colormaps::ColorMap::Cividis
                                                            : colormaps::ColorMap::Inferno;
    // The legend spans the vessels' diameters: outside the end zones (a
    // closed tip's radius falls to 0 on the surface, a junction's grows in
    // the merged lumen), unless no branch is long enough to have such points.
    float lo = std::numeric_limits<float>::infinity();
    float hi = -lo;
    float allLo = lo;
    float allHi = hi;
    for (const auto& branch : tree.branches) {
        render::OverlayPolyline line;
        line.branch = branch.id;
        const analysis::EndZones zones = analysis::endZones(branch);
        for (std::size_t i = 0; i < branch.points.size(); ++i) {
            line.points.emplace_back(branch.points[i].position);
            line.radiiMm.push_back(static_cast<float>(branch.points[i].radiusMm));
            const float diameter = 2.0F * line.radiiMm.back();
            allLo = std::min(allLo, diameter);
            allHi = std::max(allHi, diameter);
            if (!zones.contains(branch, i)) {
                lo = std::min(lo, diameter);
                hi = std::max(hi, diameter);
            }
        }
        overlay.lines.push_back(std::move(line));
    }
    if (lo > hi) {
        lo = allLo;
        hi = allHi;
    }
    if (lo <= hi) {
        overlay.min = lo;
        overlay.max = hi;
    }
    return overlay;
}

}  // namespace vv::cli
