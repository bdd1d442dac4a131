// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/segmentation/VolumeSurface.h"

#include <vtkFlyingEdges3D.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkUnsignedCharArray.h>
#include <vtkWindowedSincPolyDataFilter.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <utility>

#include "vv/core/Error.h"
#include "vv/meshio/MeshSimplify.h"
#include "vv/meshio/vtkext/RunAlgorithm.h"
#include "vv/meshio/vtkext/VtkConvert.h"
#include "vv/scene/MeshTopology.h"

namespace vv::segmentation {

namespace {

constexpr const char* kStage = "Extracting surface";

}  // namespace

scene::Mesh extractSurface(const scene::LabelMap& map, const std::vector<std::uint8_t>& labels,
                           const SurfaceOptions& options, const Progress& progress) {
    const glm::ivec3 dims = map.dims;
    if (glm::any(glm::lessThan(dims, glm::ivec3(1))) ||
        map.labels.size() != static_cast<std::size_t>(dims.x) * static_cast<std::size_t>(dims.y) *
                                 static_cast<std::size_t>(dims.z)) {
        throw InvalidArgumentError("label map: its size does not match its dimensions");
    }
    if (options.smoothingIterations < 0 || options.smoothingIterations > 1000 ||
        !(options.passBand > 0.0) || options.passBand > 2.0) {
        throw InvalidArgumentError(
            "surface options: smoothing iterations must be within 0..1000 and the pass band "
            "within (0, 2]");
    }
    if (options.targetTriangles != 0 && options.targetTriangles < 4) {
        throw InvalidArgumentError("surface options: the target triangle count must be 0 or >= 4");
    }
    bool selected[256] = {};
    if (labels.empty()) {
        std::fill(std::begin(selected) + 1, std::end(selected), true);
    } else {
        for (const std::uint8_t l : labels) {
            selected[l] = true;
        }
    }

    // The binary mask, padded by one background voxel on every side.
    const glm::ivec3 padded = dims + 2;
    vtkNew<vtkImageData> image;
    image->SetDimensions(padded.x, padded.y, padded.z);
    image->SetOrigin(-1.0, -1.0, -1.0);
    image->SetSpacing(1.0, 1.0, 1.0);
    vtkNew<vtkUnsignedCharArray> scalars;
    scalars->SetName("mask");
    scalars->SetNumberOfValues(static_cast<vtkIdType>(padded.x) * padded.y * padded.z);
    scalars->FillValue(0);
    std::size_t inside = 0;
    for (int k = 0; k < dims.z; ++k) {
        for (int j = 0; j < dims.y; ++j) {
            for (int i = 0; i < dims.x; ++i) {
                if (selected[map.labels[map.index(i, j, k)]]) {
                    const vtkIdType p =
                        (static_cast<vtkIdType>(k + 1) * padded.y + (j + 1)) * padded.x + (i + 1);
                    scalars->SetValue(p, 1);
                    ++inside;
                }
            }
        }
    }
    if (inside == 0) {
        throw FormatError("label map: no voxel carries the requested labels");
    }
    image->GetPointData()->SetScalars(scalars);
    progress.report(0.05, kStage);

    vtkNew<vtkFlyingEdges3D> contour;
    contour->SetInputData(image);
    contour->SetValue(0, 0.5);
    contour->ComputeNormalsOff();
    contour->ComputeGradientsOff();
    contour->ComputeScalarsOff();
    meshio::detail::runAlgorithm(contour, {}, "label map surface", progress, 0.05, 0.35, kStage);

    // Index space -> world (LPS, mm): any affine map, shear included.
    vtkPolyData* raw = contour->GetOutput();
    if (raw == nullptr || raw->GetNumberOfPolys() == 0 || raw->GetPoints() == nullptr) {
        throw FormatError("label map: the segment has no surface");
    }
    vtkNew<vtkPoints> world;
    world->SetDataTypeToDouble();
    world->SetNumberOfPoints(raw->GetNumberOfPoints());
    for (vtkIdType n = 0; n < raw->GetNumberOfPoints(); ++n) {
        double p[3];
        raw->GetPoint(n, p);
        const glm::dvec4 w = map.indexToWorld * glm::dvec4(p[0], p[1], p[2], 1.0);
        world->SetPoint(n, w.x, w.y, w.z);
    }
    vtkNew<vtkPolyData> surface;
    surface->SetPoints(world);
    surface->SetPolys(raw->GetPolys());

    vtkSmartPointer<vtkPolyData> smoothed = surface.Get();
    vtkNew<vtkWindowedSincPolyDataFilter> smooth;
    if (options.smoothingIterations > 0) {
        smooth->SetInputData(surface);
        smooth->SetNumberOfIterations(options.smoothingIterations);
        smooth->SetPassBand(options.passBand);
        smooth->BoundarySmoothingOff();
        smooth->FeatureEdgeSmoothingOff();
        smooth->NonManifoldSmoothingOn();
        smooth->NormalizeCoordinatesOn();
        meshio::detail::runAlgorithm(smooth, {}, "surface smoothing", progress, 0.35, 0.6, kStage);
        smoothed = smooth->GetOutput();
    }
    scene::Mesh mesh = meshio::detail::meshFromPolyData(smoothed, {});
    mesh.pointArrays.clear();
    mesh.cellArrays.clear();
    mesh.name = "vessels";
    scene::orientOutward(mesh);  // a mirroring indexToWorld turns the triangles inside out
    progress.report(0.65, kStage);
    if (options.targetTriangles != 0 && mesh.triangleCount() > options.targetTriangles) {
        mesh = meshio::simplifiedMesh(mesh, options.targetTriangles, progress.sub(0.65, 0.99));
    }
    scene::computeNormals(mesh);
    progress.report(1.0, kStage);
    return mesh;
}

scene::DataArray surfaceLabels(const scene::Mesh& mesh, const scene::LabelMap& map) {
    constexpr int kReach = 2;
    scene::DataArray labels;
    labels.name = "label";
    labels.integer = true;
    labels.values.reserve(mesh.vertexCount());
    const glm::dmat4 toIndex = glm::inverse(map.indexToWorld);
    for (const glm::vec3& p : mesh.positions) {
        const glm::dvec3 ijk(toIndex * glm::dvec4(glm::dvec3(p), 1.0));
        const glm::ivec3 centre(glm::round(ijk));
        double best = std::numeric_limits<double>::max();
        std::uint8_t label = 0;
        for (int k = centre.z - kReach; k <= centre.z + kReach; ++k) {
            for (int j = centre.y - kReach; j <= centre.y + kReach; ++j) {
                for (int i = centre.x - kReach; i <= centre.x + kReach; ++i) {
                    if (i < 0 || j < 0 || k < 0 || i >= map.dims.x || j >= map.dims.y ||
                        k >= map.dims.z) {
                        continue;
                    }
                    const std::uint8_t l = map.labels[map.index(i, j, k)];
                    const glm::dvec3 d = glm::dvec3(i, j, k) - ijk;
                    if (l != 0 && glm::dot(d, d) < best) {
                        best = glm::dot(d, d);
                        label = l;
                    }
                }
            }
        }
        labels.values.push_back(static_cast<float>(label));
    }
    return labels;
}

}  // namespace vv::segmentation
