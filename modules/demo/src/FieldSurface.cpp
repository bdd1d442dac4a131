// SPDX-License-Identifier: GPL-3.0-or-later
#include "FieldSurface.h"

#include <vtkCellArray.h>
#include <vtkFloatArray.h>
#include <vtkFlyingEdges3D.h>
#include <vtkImageData.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyDataNormals.h>
#include <vtkWindowedSincPolyDataFilter.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "vv/core/Error.h"
#include "vv/meshio/vtkext/RunAlgorithm.h"
#include "vv/meshio/vtkext/VtkConvert.h"
#include "vv/scene/MeshTopology.h"

namespace vv::demo::detail {

namespace {

constexpr int kSlabVoxels = 32;  // voxel layers extracted at a time
constexpr int kSmoothingIterations = 20;
constexpr double kSmoothingPassBand = 0.05;

/// Points of a slab's output that lie on a grid plane z = const, by their
/// (x, y) voxel cell, to join them with the next slab's.
class PlanePoints {
  public:
    explicit PlanePoints(long nx) : nx_(nx) {}
    void clear() { cells_.clear(); }
    [[nodiscard]] bool empty() const { return cells_.empty(); }
    void add(const glm::vec3& p, vtkIdType id) {
        cells_.emplace(key(cellOf(p.x), cellOf(p.y)), Entry{p, id});
    }
    /// The id of the point within tolerance of p in (x, y), or -1.
    [[nodiscard]] vtkIdType find(const glm::vec3& p, float tolerance) const {
        const long cx = cellOf(p.x);
        const long cy = cellOf(p.y);
        for (long dy = -1; dy <= 1; ++dy) {
            for (long dx = -1; dx <= 1; ++dx) {
                const auto [first, last] = cells_.equal_range(key(cx + dx, cy + dy));
                for (auto it = first; it != last; ++it) {
                    if (std::abs(it->second.p.x - p.x) <= tolerance &&
                        std::abs(it->second.p.y - p.y) <= tolerance) {
                        return it->second.id;
                    }
                }
            }
        }
        return -1;
    }

  private:
    struct Entry {
        glm::vec3 p;
        vtkIdType id;
    };
    static long cellOf(float v) { return static_cast<long>(std::floor(v)); }
    [[nodiscard]] long key(long cx, long cy) const { return (cx + 1) + (nx_ + 3) * (cy + 1); }
    long nx_;
    std::unordered_multimap<long, Entry> cells_;
};

}  // namespace

// kSlabVoxels layers of voxels at a time, neighbours sharing one layer.
// Flying edges runs in index space (origin 0, spacing 1, the slab's z
// extent), so the points a slab makes on its last layer are the next slab's
// points on its first layer; they are joined into one point.
vtkSmartPointer<vtkPolyData> extractZeroLevel(const FieldGrid& grid, const SlabSampler& sample,
                                              const Progress& progress) {
    const std::string_view stage = "Extracting surface";
    // Surface points are at least this far (in voxels) from any grid plane
    // they do not lie in, thanks to the guard; joining tolerates a quarter.
    const auto tolerance = static_cast<float>(0.25 * kZeroGuardVoxels / (2.0 * kBandVoxels));
    std::vector<glm::vec3> points;  // index space
    std::vector<vtkIdType> triangles;
    PlanePoints below(grid.nx);  // previous slab's points on this slab's first layer
    PlanePoints above(grid.nx);
    const int slabCount = std::max(1, (grid.nz - 1 + kSlabVoxels - 1) / kSlabVoxels);
    auto scalars = vtkSmartPointer<vtkFloatArray>::New();
    for (int slab = 0; slab < slabCount; ++slab) {
        progress.report(static_cast<double>(slab) / slabCount, stage);
        const int z0 = slab * kSlabVoxels;
        const int z1 = std::min(grid.nz - 1, z0 + kSlabVoxels);
        scalars->SetNumberOfTuples(static_cast<vtkIdType>(grid.nx) * grid.ny * (z1 - z0 + 1));
        if (!sample(z0, z1, scalars->GetPointer(0))) {
            below.clear();  // the surface does not reach the slab
            continue;
        }
        auto image = vtkSmartPointer<vtkImageData>::New();
        image->SetExtent(0, grid.nx - 1, 0, grid.ny - 1, z0, z1);
        image->SetOrigin(0.0, 0.0, 0.0);
        image->SetSpacing(1.0, 1.0, 1.0);
        image->GetPointData()->SetScalars(scalars);

        auto extract = vtkSmartPointer<vtkFlyingEdges3D>::New();
        extract->SetInputData(image);
        extract->SetNumberOfContours(1);
        extract->SetValue(0, 0.0);
        extract->ComputeNormalsOff();
        extract->ComputeGradientsOff();
        extract->ComputeScalarsOff();
        extract->InterpolateAttributesOff();
        extract->Update();
        vtkPolyData* out = extract->GetOutput();

        const vtkIdType localCount = out->GetNumberOfPoints();
        std::vector<vtkIdType> globalId(static_cast<std::size_t>(localCount));
        above.clear();
        for (vtkIdType i = 0; i < localCount; ++i) {
            double x[3];
            out->GetPoint(i, x);
            const glm::vec3 p(static_cast<float>(x[0]), static_cast<float>(x[1]),
                              static_cast<float>(x[2]));
            vtkIdType id = -1;
            if (std::abs(p.z - static_cast<float>(z0)) <= tolerance) {
                id = below.find(p, tolerance);
                if (id < 0) {
                    throw Error(
                        "vessel surface: internal error, slabs do not join at voxel layer " +
                        std::to_string(z0));
                }
            } else {
                id = static_cast<vtkIdType>(points.size());
                points.push_back(p);
            }
            if (std::abs(p.z - static_cast<float>(z1)) <= tolerance) {
                above.add(p, id);
            }
            globalId[static_cast<std::size_t>(i)] = id;
        }
        vtkCellArray* polys = out->GetPolys();
        vtkIdType count = 0;
        const vtkIdType* ids = nullptr;
        for (polys->InitTraversal(); polys->GetNextCell(count, ids) != 0;) {
            if (count != 3) {
                throw Error("vessel surface: internal error, flying edges made a non-triangle");
            }
            for (vtkIdType k = 0; k < 3; ++k) {
                triangles.push_back(globalId[static_cast<std::size_t>(ids[k])]);
            }
        }
        std::swap(below, above);
    }
    progress.report(1.0, stage);

    auto worldPoints = vtkSmartPointer<vtkPoints>::New();
    worldPoints->SetDataTypeToFloat();
    worldPoints->SetNumberOfPoints(static_cast<vtkIdType>(points.size()));
    for (std::size_t i = 0; i < points.size(); ++i) {
        const glm::dvec3 w = grid.origin + grid.spacing * glm::dvec3(points[i]);
        worldPoints->SetPoint(static_cast<vtkIdType>(i), w.x, w.y, w.z);
    }
    auto cells = vtkSmartPointer<vtkCellArray>::New();
    cells->AllocateExact(static_cast<vtkIdType>(triangles.size() / 3),
                         static_cast<vtkIdType>(triangles.size()));
    for (std::size_t t = 0; t < triangles.size(); t += 3) {
        cells->InsertNextCell(3, triangles.data() + t);
    }
    auto surface = vtkSmartPointer<vtkPolyData>::New();
    surface->SetPoints(worldPoints);
    surface->SetPolys(cells);
    return surface;
}

namespace {

/// Keeps only the connected component with the most triangles. The tubes are
/// joined by construction; anything else flying edges finds can only be a
/// speck a voxel or two wide (sampling of a thin tube or of a blend).
void keepLargestComponent(scene::Mesh& mesh) {
    const std::size_t vertexCount = mesh.positions.size();
    std::vector<std::uint32_t> parent(vertexCount);
    for (std::uint32_t v = 0; v < vertexCount; ++v) {
        parent[v] = v;
    }
    const auto find = [&](std::uint32_t v) {
        while (parent[v] != v) {
            parent[v] = parent[parent[v]];
            v = parent[v];
        }
        return v;
    };
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        const std::uint32_t a = find(mesh.indices[t]);
        parent[find(mesh.indices[t + 1])] = a;
        parent[find(mesh.indices[t + 2])] = a;
    }
    std::vector<std::size_t> triangles(vertexCount, 0);
    for (std::size_t t = 0; t < mesh.indices.size(); t += 3) {
        ++triangles[find(mesh.indices[t])];
    }
    const auto largest = static_cast<std::uint32_t>(
        std::max_element(triangles.begin(), triangles.end()) - triangles.begin());
    if (triangles[largest] * 3 == mesh.indices.size()) {
        return;  // one component
    }
    std::vector<std::uint32_t> newIndex(vertexCount, std::numeric_limits<std::uint32_t>::max());
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;
    std::vector<std::uint32_t> indices;
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        if (find(mesh.indices[t]) != largest) {
            continue;
        }
        for (std::size_t k = 0; k < 3; ++k) {
            const std::uint32_t v = mesh.indices[t + k];
            if (newIndex[v] == std::numeric_limits<std::uint32_t>::max()) {
                newIndex[v] = static_cast<std::uint32_t>(positions.size());
                positions.push_back(mesh.positions[v]);
                normals.push_back(mesh.normals[v]);
            }
            indices.push_back(newIndex[v]);
        }
    }
    mesh.positions = std::move(positions);
    mesh.normals = std::move(normals);
    mesh.indices = std::move(indices);
}

}  // namespace

/// Runs the filter with meshio's progress forwarding and error capture
/// (meshio::detail::runAlgorithm); returns a copy of its output (so the
/// filter and its input can go). Throws CancelledError when cancelled and
/// FormatError when the filter reports an error.
vtkSmartPointer<vtkPolyData> runFilter(vtkPolyDataAlgorithm* filter, const Progress& progress,
                                       std::string_view stage) {
    progress.report(0.0, stage);
    meshio::detail::runAlgorithm(filter, {}, "demo surface", progress, 0.0, 1.0,
                                 std::string(stage));
    progress.report(1.0, stage);
    auto output = vtkSmartPointer<vtkPolyData>::New();
    output->ShallowCopy(filter->GetOutput());
    return output;
}

vtkSmartPointer<vtkPolyData> smoothSurface(vtkPolyData* surface, const Progress& progress) {
    auto smoother = vtkSmartPointer<vtkWindowedSincPolyDataFilter>::New();
    smoother->SetInputData(surface);
    smoother->SetNumberOfIterations(kSmoothingIterations);
    smoother->SetPassBand(kSmoothingPassBand);
    smoother->BoundarySmoothingOff();
    smoother->FeatureEdgeSmoothingOff();
    smoother->NonManifoldSmoothingOn();
    smoother->NormalizeCoordinatesOn();
    return runFilter(smoother, progress, "Smoothing surface");
}

scene::Mesh finishSurface(vtkSmartPointer<vtkPolyData> surface, const Progress& progress) {
    auto normals = vtkSmartPointer<vtkPolyDataNormals>::New();
    normals->SetInputData(surface);
    normals->SplittingOff();
    normals->ConsistencyOn();
    normals->AutoOrientNormalsOff();
    normals->ComputePointNormalsOn();
    normals->ComputeCellNormalsOff();
    surface = runFilter(normals, progress, "Computing normals");

    scene::Mesh mesh = meshio::detail::meshFromPolyData(surface, {});
    surface = nullptr;
    if (!mesh.pointArrays.empty() || !mesh.cellArrays.empty()) {
        throw Error("vessel surface: internal error, unexpected data arrays on the surface");
    }
    keepLargestComponent(mesh);
    scene::orientOutward(mesh);
    return mesh;
}

}  // namespace vv::demo::detail
