// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/meshio/MeshSimplify.h"

#include <vtkCellArray.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkQuadricDecimation.h>
#include <vtkSmartPointer.h>
#include <vtkStaticPointLocator.h>

#include <algorithm>
#include <cstdint>
#include <string>

#include "vv/core/Error.h"
#include "vv/meshio/vtkext/RunAlgorithm.h"
#include "vv/meshio/vtkext/VtkConvert.h"

namespace vv::meshio {

namespace {

std::string describe(const scene::Mesh& mesh) {
    return mesh.source.empty() ? "mesh '" + mesh.name + "'" : mesh.source.string();
}

}  // namespace

scene::Mesh simplifiedMesh(const scene::Mesh& mesh, std::size_t targetTriangles,
                           const Progress& progress) {
    if (targetTriangles < 4) {
        throw InvalidArgumentError(
            "a simplified mesh needs a target of at least 4 triangles, got " +
            std::to_string(targetTriangles));
    }
    if (mesh.triangleCount() <= targetTriangles) {
        progress.report(1.0, "simplifying");
        return mesh;
    }
    for (const std::uint32_t index : mesh.indices) {
        if (index >= mesh.vertexCount()) {
            throw FormatError(describe(mesh), "a triangle refers to vertex " +
                                                  std::to_string(index) + " of " +
                                                  std::to_string(mesh.vertexCount()));
        }
    }
    const vtkSmartPointer<vtkPolyData> input = detail::bareTriangles(mesh);
    vtkNew<vtkQuadricDecimation> decimate;
    decimate->SetInputData(input);
    decimate->SetTargetReduction(1.0 - static_cast<double>(targetTriangles) /
                                           static_cast<double>(mesh.triangleCount()));
    decimate->VolumePreservationOn();
    decimate->AttributeErrorMetricOff();
    detail::runAlgorithm(decimate, describe(mesh), "mesh simplification", progress, 0.0, 0.85,
                         "simplifying");
    vtkPolyData* output = decimate->GetOutput();
    if (output == nullptr || output->GetNumberOfPolys() == 0 || output->GetPoints() == nullptr) {
        throw FormatError(describe(mesh), "simplification left no triangles");
    }

    scene::Mesh out;
    out.name = mesh.name;
    out.source = mesh.source;
    const vtkIdType pointCount = output->GetNumberOfPoints();
    out.positions.resize(static_cast<std::size_t>(pointCount));
    for (vtkIdType i = 0; i < pointCount; ++i) {
        double p[3];
        output->GetPoint(i, p);
        out.positions[static_cast<std::size_t>(i)] =
            glm::vec3(static_cast<float>(p[0]), static_cast<float>(p[1]), static_cast<float>(p[2]));
    }
    vtkCellArray* polys = output->GetPolys();
    out.indices.reserve(static_cast<std::size_t>(polys->GetNumberOfCells()) * 3);
    vtkNew<vtkIdList> cell;
    for (vtkIdType c = 0; c < polys->GetNumberOfCells(); ++c) {
        polys->GetCellAtId(c, cell);
        if (cell->GetNumberOfIds() != 3) {
            continue;  // the decimation only makes triangles; be safe anyway
        }
        for (vtkIdType k = 0; k < 3; ++k) {
            out.indices.push_back(static_cast<std::uint32_t>(cell->GetId(k)));
        }
    }
    if (out.indices.empty()) {
        throw FormatError(describe(mesh), "simplification left no triangles");
    }
    progress.report(0.9, "simplifying");

    // Arrays from the nearest original vertex.
    if (!mesh.pointArrays.empty()) {
        vtkNew<vtkStaticPointLocator> locator;
        locator->SetDataSet(input);
        locator->BuildLocator();
        std::vector<std::size_t> nearest(out.positions.size());
        for (std::size_t i = 0; i < out.positions.size(); ++i) {
            const double p[3] = {out.positions[i].x, out.positions[i].y, out.positions[i].z};
            const vtkIdType id = locator->FindClosestPoint(p);
            nearest[i] = id >= 0 ? static_cast<std::size_t>(id) : 0;
        }
        for (const scene::DataArray& array : mesh.pointArrays) {
            if (array.components < 1 || array.tupleCount() != mesh.vertexCount()) {
                continue;  // not one value per vertex: nothing to carry over
            }
            scene::DataArray copy = array;
            const auto components = static_cast<std::size_t>(array.components);
            copy.values.assign(out.positions.size() * components, 0.0F);
            for (std::size_t i = 0; i < nearest.size(); ++i) {
                std::copy_n(
                    array.values.begin() + static_cast<std::ptrdiff_t>(nearest[i] * components),
                    components, copy.values.begin() + static_cast<std::ptrdiff_t>(i * components));
            }
            out.pointArrays.push_back(std::move(copy));
        }
    }
    scene::computeNormals(out);
    progress.report(1.0, "simplifying");
    return out;
}

scene::Scene simplifiedScene(const scene::Scene& scene, std::size_t targetTriangles,
                             const Progress& progress) {
    const std::size_t total = scene.triangleCount();
    scene::Scene out;
    std::size_t done = 0;
    for (const scene::Mesh& mesh : scene.meshes) {
        const double share =
            total > 0 ? static_cast<double>(mesh.triangleCount()) / static_cast<double>(total)
                      : 0.0;
        const auto target = std::max<std::size_t>(
            4, static_cast<std::size_t>(share * static_cast<double>(targetTriangles)));
        const double begin =
            total > 0 ? static_cast<double>(done) / static_cast<double>(total) : 0.0;
        done += mesh.triangleCount();
        const double end = total > 0 ? static_cast<double>(done) / static_cast<double>(total) : 1.0;
        out.meshes.push_back(simplifiedMesh(mesh, target, progress.sub(begin, end)));
    }
    return out;
}

}  // namespace vv::meshio
