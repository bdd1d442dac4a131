// SPDX-License-Identifier: GPL-3.0-or-later
#include "SmoothCopy.h"

#include <algorithm>
#include <memory>
#include <vector>

#include "vv/core/Error.h"
#include "vv/core/NumberText.h"
#include "vv/meshio/MeshSubdivide.h"

namespace vv::app {

double medianEdgeLength(const scene::Scene& scene) {
    std::vector<float> lengths;
    lengths.reserve(3 * scene.triangleCount());
    for (const scene::Mesh& mesh : scene.meshes) {
        for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
            for (std::size_t k = 0; k < 3; ++k) {
                const std::uint32_t a = mesh.indices[t + k];
                const std::uint32_t b = mesh.indices[t + (k + 1) % 3];
                if (a < mesh.positions.size() && b < mesh.positions.size()) {
                    lengths.push_back(glm::length(mesh.positions[a] - mesh.positions[b]));
                }
            }
        }
    }
    std::erase_if(lengths, [](float l) { return !std::isfinite(l); });
    if (lengths.empty()) {
        return 0.0;
    }
    const auto middle = lengths.begin() + static_cast<std::ptrdiff_t>(lengths.size() / 2);
    std::nth_element(lengths.begin(), middle, lengths.end());
    return static_cast<double>(*middle);
}

std::optional<render::RefinedGeometry> smoothCopyOf(const scene::Scene& scene,
                                                    const Progress& progress, std::string* why) {
    const auto refuse = [&](std::string reason) -> std::optional<render::RefinedGeometry> {
        if (why != nullptr) {
            *why = std::move(reason);
        }
        return std::nullopt;
    };
    const std::size_t triangles = scene.triangleCount();
    if (triangles == 0) {
        return refuse("no triangles");
    }
    if (triangles >= kMaxSmoothedTriangles) {
        return refuse("fine enough (" + std::to_string(triangles) + " triangles)");
    }
    const double edge = medianEdgeLength(scene);
    try {
        meshio::SubdividedScene copy = meshio::subdividedScene(scene, 1, progress);
        if (!(copy.largestDeviation <= kMaxSmoothDeviationEdges * edge)) {
            return refuse("smoothing would move the wall by " +
                          fixedText(copy.largestDeviation, 2) +
                          ", more than half its median edge (" + fixedText(edge, 2) + ")");
        }
        render::RefinedGeometry geometry;
        geometry.scene = std::make_shared<const scene::Scene>(std::move(copy.scene));
        geometry.sourceEdgeMm = edge;
        geometry.largestDeviationMm = copy.largestDeviation;
        geometry.meanDeviationMm = copy.meanDeviation;
        return geometry;
    } catch (const CancelledError&) {
        throw;
    } catch (const Error& e) {
        return refuse(e.what());
    }
}

std::string smoothCopyNote(const render::RefinedGeometry& copy) {
    return "coarse facets are drawn smoothed where they are large on screen (Loop subdivision, "
           "the wall moved by at most " +
           fixedText(copy.largestDeviationMm, 2) + " mm, " + fixedText(copy.meanDeviationMm, 3) +
           " mm on average)";
}

}  // namespace vv::app
