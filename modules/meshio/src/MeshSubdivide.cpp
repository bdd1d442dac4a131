// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/meshio/MeshSubdivide.h"

#include <vtkCellData.h>
#include <vtkGenericCell.h>
#include <vtkLoopSubdivisionFilter.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkStaticCellLocator.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "MeshChecks.h"
#include "vv/core/Error.h"
#include "vv/meshio/vtkext/RunAlgorithm.h"
#include "vv/meshio/vtkext/VtkConvert.h"

namespace vv::meshio {
namespace {

void checkSubdividable(const scene::Mesh& mesh, int levels) {
    if (levels < 1 || levels > 3) {
        throw InvalidArgumentError("subdivision needs 1 to 3 levels, got " +
                                   std::to_string(levels));
    }
    detail::checkTriangleMesh(mesh, "subdivide");
}

/// The point arrays of `input` at the point `p` of its triangle `t`
/// (barycentric weights `w`): interpolated linearly, as the input's own
/// triangles show them; an integer (id, label) array, or one with no data
/// at a corner that counts, takes the value of the nearest corner.
void transferArrays(const scene::Mesh& input, std::size_t t, const std::array<double, 3>& w,
                    std::vector<scene::DataArray>& arrays, std::size_t at) {
    const std::array<std::uint32_t, 3> corner{input.indices[3 * t], input.indices[3 * t + 1],
                                              input.indices[3 * t + 2]};
    const auto nearest = static_cast<std::size_t>(std::max_element(w.begin(), w.end()) - w.begin());
    for (std::size_t a = 0; a < arrays.size(); ++a) {
        const scene::DataArray& from = input.pointArrays[a];
        scene::DataArray& to = arrays[a];
        const auto n = static_cast<std::size_t>(std::max(from.components, 1));
        for (std::size_t c = 0; c < n; ++c) {
            const auto value = [&](std::size_t k) { return from.values[corner[k] * n + c]; };
            double sum = 0.0;
            bool finite = !from.integer;
            for (std::size_t k = 0; k < 3 && finite; ++k) {
                finite = w[k] <= 0.0 || std::isfinite(value(k));
                sum += w[k] * static_cast<double>(value(k));
            }
            to.values[at * n + c] = finite ? static_cast<float>(sum) : value(nearest);
        }
    }
}

/// Barycentric weights of `p` (on or near the triangle a, b, c), clamped to
/// the triangle.
std::array<double, 3> barycentric(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b,
                                  const glm::dvec3& c) {
    const glm::dvec3 u = b - a;
    const glm::dvec3 v = c - a;
    const glm::dvec3 d = p - a;
    const double uu = glm::dot(u, u);
    const double uv = glm::dot(u, v);
    const double vv = glm::dot(v, v);
    const double det = uu * vv - uv * uv;
    if (!(det > 0.0)) {
        return {1.0, 0.0, 0.0};  // a degenerate triangle: its first corner
    }
    double s = (vv * glm::dot(d, u) - uv * glm::dot(d, v)) / det;
    double t = (uu * glm::dot(d, v) - uv * glm::dot(d, u)) / det;
    s = std::clamp(s, 0.0, 1.0);
    t = std::clamp(t, 0.0, 1.0 - s);
    return {1.0 - s - t, s, t};
}

/// The nearest points of a surface's triangles (VTK's static cell locator).
class SurfaceLocator {
  public:
    explicit SurfaceLocator(vtkPolyData* surface) {
        locator_->SetDataSet(surface);
        locator_->BuildLocator();
    }
    struct Nearest {
        glm::dvec3 point{0.0};
        vtkIdType cell = -1;  ///< the triangle it lies on; -1 when none
        double distance = 0.0;
    };
    [[nodiscard]] Nearest closest(const glm::vec3& p) const {
        std::array<double, 3> query{p.x, p.y, p.z};
        std::array<double, 3> closest{};
        Nearest nearest;
        int subId = 0;
        double distance2 = 0.0;
        locator_->FindClosestPoint(query.data(), closest.data(), cell_, nearest.cell, subId,
                                   distance2);
        nearest.point = {closest[0], closest[1], closest[2]};
        nearest.distance = std::sqrt(std::max(distance2, 0.0));
        return nearest;
    }

  private:
    vtkNew<vtkStaticCellLocator> locator_;
    vtkNew<vtkGenericCell> cell_;  ///< scratch of FindClosestPoint
};

/// The largest distance of the input's vertices and triangle centres from
/// the refined surface: the other half of the Hausdorff distance (a convex
/// tip of the input stands out of the refined surface by more than any
/// refined point lies from the input).
double farthestFromRefined(const scene::Mesh& input, vtkPolyData* refined,
                           const Progress& progress) {
    const SurfaceLocator locator(refined);
    double largest = 0.0;
    const auto distanceOf = [&](const glm::vec3& p) {
        largest = std::max(largest, locator.closest(p).distance);
    };
    for (std::size_t i = 0; i < input.positions.size(); ++i) {
        if (i % 65536 == 0) {
            progress.throwIfCancelled();
        }
        distanceOf(input.positions[i]);
    }
    for (std::size_t t = 0; t + 2 < input.indices.size(); t += 3) {
        distanceOf((input.positions[input.indices[t]] + input.positions[input.indices[t + 1]] +
                    input.positions[input.indices[t + 2]]) /
                   3.0F);
    }
    return largest;
}

}  // namespace

SubdividedMesh subdividedMesh(const scene::Mesh& mesh, int levels, const Progress& progress) {
    checkSubdividable(mesh, levels);
    // The filter refines the bare triangles; normals are computed afresh
    // and the arrays taken from the input below (the filter's own averages
    // would smooth a peak of wall shear stress away, and mix labels).
    vtkNew<vtkLoopSubdivisionFilter> filter;
    filter->SetNumberOfSubdivisions(levels);
    filter->SetInputData(detail::bareTriangles(mesh));
    detail::runAlgorithm(filter, detail::describeMesh(mesh), "mesh subdivision", progress, 0.0, 0.8,
                         "subdividing");
    SubdividedMesh out;
    out.mesh = detail::meshFromPolyData(filter->GetOutput(), mesh.source);
    out.mesh.name = mesh.name;
    out.mesh.source = mesh.source;
    out.mesh.pointArrays.clear();
    out.mesh.cellArrays.clear();
    out.mesh.labelNames = mesh.labelNames;
    const std::size_t count = out.mesh.positions.size();
    for (const scene::DataArray& array : mesh.pointArrays) {
        scene::DataArray copy = array;
        copy.values.assign(count * static_cast<std::size_t>(std::max(array.components, 1)), 0.0F);
        out.mesh.pointArrays.push_back(std::move(copy));
    }
    // How far the refined surface lies from the input's triangles, and the
    // input's arrays where each point lies over them.
    vtkSmartPointer<vtkPolyData> surface = detail::bareTriangles(mesh);
    const SurfaceLocator locator(surface);
    double sum = 0.0;
    for (std::size_t i = 0; i < count; ++i) {
        if (i % 65536 == 0) {
            progress.throwIfCancelled();
        }
        const SurfaceLocator::Nearest nearest = locator.closest(out.mesh.positions[i]);
        out.largestDeviation = std::max(out.largestDeviation, nearest.distance);
        sum += nearest.distance;
        if (nearest.cell < 0 || out.mesh.pointArrays.empty()) {
            continue;
        }
        const auto t = static_cast<std::size_t>(nearest.cell);
        const auto corner = [&](std::size_t k) {
            return glm::dvec3(mesh.positions[mesh.indices[3 * t + k]]);
        };
        transferArrays(mesh, t, barycentric(nearest.point, corner(0), corner(1), corner(2)),
                       out.mesh.pointArrays, i);
    }
    out.meanDeviation = count == 0 ? 0.0 : sum / static_cast<double>(count);
    out.largestDeviation =
        std::max(out.largestDeviation, farthestFromRefined(mesh, filter->GetOutput(), progress));
    progress.report(1.0, "subdividing");
    return out;
}

SubdividedScene subdividedScene(const scene::Scene& scene, int levels, const Progress& progress) {
    SubdividedScene out;
    out.scene.frame = scene.frame;
    std::size_t done = 0;
    const std::size_t total = std::max<std::size_t>(scene.triangleCount(), 1);
    double sum = 0.0;
    std::size_t points = 0;
    for (const scene::Mesh& mesh : scene.meshes) {
        const double from = static_cast<double>(done) / static_cast<double>(total);
        done += mesh.triangleCount();
        const double to = static_cast<double>(done) / static_cast<double>(total);
        SubdividedMesh refined = subdividedMesh(mesh, levels, progress.sub(from, to));
        out.largestDeviation = std::max(out.largestDeviation, refined.largestDeviation);
        sum += refined.meanDeviation * static_cast<double>(refined.mesh.positions.size());
        points += refined.mesh.positions.size();
        out.scene.meshes.push_back(std::move(refined.mesh));
    }
    out.meanDeviation = points == 0 ? 0.0 : sum / static_cast<double>(points);
    return out;
}

}  // namespace vv::meshio
