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
#include <string>

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

}  // namespace

SubdividedMesh subdividedMesh(const scene::Mesh& mesh, int levels, const Progress& progress) {
    checkSubdividable(mesh, levels);
    vtkSmartPointer<vtkPolyData> input = detail::polyDataFromMesh(mesh);
    // Normals are computed afresh from the finer triangles; a cell array
    // would have to be spread over each triangle's children, which the
    // filter does not do.
    input->GetPointData()->SetNormals(nullptr);
    input->GetCellData()->Initialize();
    vtkNew<vtkLoopSubdivisionFilter> filter;
    filter->SetNumberOfSubdivisions(levels);
    filter->SetInputData(input);
    detail::runAlgorithm(filter, detail::describeMesh(mesh), "mesh subdivision", progress, 0.0, 0.8,
                         "subdividing");
    SubdividedMesh out;
    out.mesh = detail::meshFromPolyData(filter->GetOutput(), mesh.source);
    out.mesh.name = mesh.name;
    out.mesh.source = mesh.source;
    // How far the refined surface lies from the input's triangles.
    vtkSmartPointer<vtkPolyData> surface = detail::bareTriangles(mesh);
    vtkNew<vtkStaticCellLocator> locator;
    locator->SetDataSet(surface);
    locator->BuildLocator();
    vtkNew<vtkGenericCell> cell;
    double sum = 0.0;
    for (std::size_t i = 0; i < out.mesh.positions.size(); ++i) {
        if (i % 65536 == 0) {
            progress.throwIfCancelled();
        }
        const glm::vec3& p = out.mesh.positions[i];
        std::array<double, 3> query{p.x, p.y, p.z};
        std::array<double, 3> closest{};
        vtkIdType cellId = -1;
        int subId = 0;
        double distance2 = 0.0;
        locator->FindClosestPoint(query.data(), closest.data(), cell, cellId, subId, distance2);
        const double d = std::sqrt(std::max(distance2, 0.0));
        out.largestDeviation = std::max(out.largestDeviation, d);
        sum += d;
    }
    out.meanDeviation =
        out.mesh.positions.empty() ? 0.0 : sum / static_cast<double>(out.mesh.positions.size());
    progress.report(1.0, "subdividing");
    return out;
}

}  // namespace vv::meshio
