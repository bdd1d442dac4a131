// SPDX-License-Identifier: GPL-3.0-or-later
#include "VtkConvert.h"

#include <cmath>
#include <string>

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkFloatArray.h>
#include <vtkIdList.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkTriangleFilter.h>

#include "vv/core/Error.h"

namespace vv::io::detail {

namespace {

bool isIntegerType(int vtkType) {
    switch (vtkType) {
        case VTK_CHAR:
        case VTK_SIGNED_CHAR:
        case VTK_UNSIGNED_CHAR:
        case VTK_SHORT:
        case VTK_UNSIGNED_SHORT:
        case VTK_INT:
        case VTK_UNSIGNED_INT:
        case VTK_LONG:
        case VTK_UNSIGNED_LONG:
        case VTK_LONG_LONG:
        case VTK_UNSIGNED_LONG_LONG:
        case VTK_ID_TYPE:
            return true;
        default:
            return false;
    }
}

DataArray toDataArray(vtkDataArray* array, int index) {
    DataArray out;
    const char* rawName = array->GetName();
    const std::string vtkName =
        (rawName != nullptr && rawName[0] != '\0') ? rawName : "array_" + std::to_string(index);
    std::tie(out.name, out.unit) = splitNameAndUnit(vtkName);
    out.components = array->GetNumberOfComponents();
    out.integer = isIntegerType(array->GetDataType());
    const vtkIdType tuples = array->GetNumberOfTuples();
    out.values.resize(static_cast<std::size_t>(tuples) * static_cast<std::size_t>(out.components));
    for (vtkIdType t = 0; t < tuples; ++t) {
        for (int c = 0; c < out.components; ++c) {
            const double v = array->GetComponent(t, c);
            out.values[static_cast<std::size_t>(t) * static_cast<std::size_t>(out.components) +
                       static_cast<std::size_t>(c)] =
                std::isfinite(v) ? static_cast<float>(v) : std::numeric_limits<float>::quiet_NaN();
        }
    }
    return out;
}

vtkSmartPointer<vtkFloatArray> toVtkArray(const DataArray& array) {
    auto out = vtkSmartPointer<vtkFloatArray>::New();
    out->SetName(joinNameAndUnit(array.name, array.unit).c_str());
    out->SetNumberOfComponents(array.components);
    out->SetNumberOfTuples(static_cast<vtkIdType>(array.tupleCount()));
    std::copy(array.values.begin(), array.values.end(), out->GetPointer(0));
    return out;
}

}  // namespace

std::pair<std::string, std::string> splitNameAndUnit(const std::string& vtkName) {
    const auto open = vtkName.rfind(" [");
    if (open != std::string::npos && vtkName.size() > open + 3 && vtkName.back() == ']') {
        return {vtkName.substr(0, open), vtkName.substr(open + 2, vtkName.size() - open - 3)};
    }
    return {vtkName, ""};
}

std::string joinNameAndUnit(const std::string& name, const std::string& unit) {
    return unit.empty() ? name : name + " [" + unit + "]";
}

Mesh meshFromPolyData(vtkPolyData* input, const std::filesystem::path& file) {
    if (input == nullptr || input->GetNumberOfPoints() == 0) {
        throw FormatError(file, "the file holds no points (empty mesh)");
    }
    // Triangulate polygons and strips; lines and vertices are dropped.
    auto triangulate = vtkSmartPointer<vtkTriangleFilter>::New();
    triangulate->SetInputData(input);
    triangulate->PassVertsOff();
    triangulate->PassLinesOff();
    triangulate->Update();
    vtkPolyData* poly = triangulate->GetOutput();

    Mesh mesh;
    mesh.source = file;
    mesh.name = file.stem().string();

    const vtkIdType pointCount = input->GetNumberOfPoints();
    mesh.positions.resize(static_cast<std::size_t>(pointCount));
    for (vtkIdType i = 0; i < pointCount; ++i) {
        double p[3];
        input->GetPoint(i, p);
        const glm::vec3 v(static_cast<float>(p[0]), static_cast<float>(p[1]), static_cast<float>(p[2]));
        if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]) || !isFinite(v)) {
            throw FormatError(file, "point " + std::to_string(i) + " has a non-finite coordinate");
        }
        mesh.positions[static_cast<std::size_t>(i)] = v;
    }

    // The triangle filter keeps point ids, so triangles index the input points.
    vtkCellArray* polys = poly->GetPolys();
    mesh.indices.reserve(static_cast<std::size_t>(polys->GetNumberOfCells()) * 3);
    std::vector<vtkIdType> sourceCell;  // input cell id of each triangle, for cell arrays
    sourceCell.reserve(static_cast<std::size_t>(polys->GetNumberOfCells()));
    auto ids = vtkSmartPointer<vtkIdList>::New();
    polys->InitTraversal();
    vtkIdType cellIndex = 0;
    const vtkIdType nonPolyCells = poly->GetNumberOfVerts() + poly->GetNumberOfLines();
    while (polys->GetNextCell(ids) != 0) {
        if (ids->GetNumberOfIds() == 3) {
            for (int k = 0; k < 3; ++k) {
                const vtkIdType id = ids->GetId(k);
                if (id < 0 || id >= pointCount) {
                    throw FormatError(file, "a triangle refers to point " + std::to_string(id) +
                                                " but there are only " + std::to_string(pointCount));
                }
                mesh.indices.push_back(static_cast<std::uint32_t>(id));
            }
            sourceCell.push_back(nonPolyCells + cellIndex);
        }
        ++cellIndex;
    }
    if (mesh.indices.empty()) {
        throw FormatError(file, "the file holds no surface triangles (empty mesh)");
    }
    double area2 = 0.0;
    for (std::size_t t = 0; t < mesh.indices.size(); t += 3) {
        area2 += doubleTriangleArea(mesh.positions[mesh.indices[t]], mesh.positions[mesh.indices[t + 1]],
                                    mesh.positions[mesh.indices[t + 2]]);
    }
    if (!(area2 > 0.0)) {
        throw FormatError(file, "the surface has zero area (all triangles degenerate)");
    }

    vtkPointData* pointData = input->GetPointData();
    vtkDataArray* normals = pointData->GetNormals();
    for (int a = 0; a < pointData->GetNumberOfArrays(); ++a) {
        vtkDataArray* array = pointData->GetArray(a);
        if (array == nullptr || array == normals || array->GetNumberOfTuples() != pointCount) {
            continue;
        }
        mesh.pointArrays.push_back(toDataArray(array, a));
    }
    // Cell arrays follow the triangle filter, which copies cell data per output cell.
    vtkCellData* cellData = poly->GetCellData();
    for (int a = 0; a < cellData->GetNumberOfArrays(); ++a) {
        vtkDataArray* array = cellData->GetArray(a);
        if (array == nullptr || array->GetNumberOfTuples() != poly->GetNumberOfCells()) {
            continue;
        }
        DataArray full = toDataArray(array, a);
        DataArray perTriangle = full;
        perTriangle.values.clear();
        const auto comps = static_cast<std::size_t>(full.components);
        for (const vtkIdType c : sourceCell) {
            const auto begin = full.values.begin() + static_cast<std::ptrdiff_t>(static_cast<std::size_t>(c) * comps);
            perTriangle.values.insert(perTriangle.values.end(), begin, begin + static_cast<std::ptrdiff_t>(comps));
        }
        mesh.cellArrays.push_back(std::move(perTriangle));
    }

    bool normalsOk = normals != nullptr && normals->GetNumberOfComponents() == 3 &&
                     normals->GetNumberOfTuples() == pointCount;
    if (normalsOk) {
        mesh.normals.resize(mesh.positions.size());
        for (vtkIdType i = 0; i < pointCount && normalsOk; ++i) {
            double n[3];
            normals->GetTuple(i, n);
            glm::vec3 v(static_cast<float>(n[0]), static_cast<float>(n[1]), static_cast<float>(n[2]));
            const float len = glm::length(v);
            if (!(len > 0.0F) || !std::isfinite(len)) {
                normalsOk = false;
                break;
            }
            mesh.normals[static_cast<std::size_t>(i)] = v / len;
        }
    }
    if (!normalsOk) {
        computeNormals(mesh);
    }
    return mesh;
}

vtkSmartPointer<vtkPolyData> polyDataFromMesh(const Mesh& mesh) {
    auto points = vtkSmartPointer<vtkPoints>::New();
    points->SetDataTypeToFloat();
    points->SetNumberOfPoints(static_cast<vtkIdType>(mesh.positions.size()));
    for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
        const auto& p = mesh.positions[i];
        points->SetPoint(static_cast<vtkIdType>(i), p.x, p.y, p.z);
    }
    auto polys = vtkSmartPointer<vtkCellArray>::New();
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        const vtkIdType tri[3] = {mesh.indices[t], mesh.indices[t + 1], mesh.indices[t + 2]};
        polys->InsertNextCell(3, tri);
    }
    auto poly = vtkSmartPointer<vtkPolyData>::New();
    poly->SetPoints(points);
    poly->SetPolys(polys);
    if (mesh.normals.size() == mesh.positions.size()) {
        auto normals = vtkSmartPointer<vtkFloatArray>::New();
        normals->SetName("Normals");
        normals->SetNumberOfComponents(3);
        normals->SetNumberOfTuples(static_cast<vtkIdType>(mesh.normals.size()));
        for (std::size_t i = 0; i < mesh.normals.size(); ++i) {
            const auto& n = mesh.normals[i];
            normals->SetTuple3(static_cast<vtkIdType>(i), n.x, n.y, n.z);
        }
        poly->GetPointData()->SetNormals(normals);
    }
    for (const auto& array : mesh.pointArrays) {
        poly->GetPointData()->AddArray(toVtkArray(array));
    }
    for (const auto& array : mesh.cellArrays) {
        poly->GetCellData()->AddArray(toVtkArray(array));
    }
    return poly;
}

}  // namespace vv::io::detail
