// SPDX-License-Identifier: GPL-3.0-or-later
#include "MeshReaders.h"

#include <vtkAlgorithm.h>
#include <vtkCellData.h>
#include <vtkCleanPolyData.h>
#include <vtkDataSetSurfaceFilter.h>
#include <vtkFloatArray.h>
#include <vtkIntArray.h>
#include <vtkOBJReader.h>
#include <vtkPLYReader.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkPolyDataReader.h>
#include <vtkSTLReader.h>
#include <vtkUnstructuredGrid.h>
#include <vtkUnstructuredGridReader.h>
#include <vtkXMLPolyDataReader.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "vv/core/Error.h"
#include "vv/meshio/vtkext/RunAlgorithm.h"
#include "vv/meshio/vtkext/VtkConvert.h"

namespace vv::meshio::detail {

namespace fs = std::filesystem;

namespace {

vtkSmartPointer<vtkPolyData> polyDataOutput(vtkAlgorithm* algorithm, const fs::path& file,
                                            const std::string& what) {
    vtkSmartPointer<vtkPolyData> poly =
        vtkPolyData::SafeDownCast(algorithm->GetOutputDataObject(0));
    if (poly == nullptr) {
        throw FormatError(file, "the " + what + " reader produced no polydata");
    }
    return poly;
}

/// Extracts the outer surface of a checked unstructured grid.
vtkSmartPointer<vtkPolyData> surfaceOf(vtkUnstructuredGrid* grid, const fs::path& file,
                                       const Progress& progress) {
    detail::checkUnstructuredGrid(grid, file);
    auto surface = vtkSmartPointer<vtkDataSetSurfaceFilter>::New();
    surface->SetInputData(grid);
    runAlgorithm(surface, file, "unstructured grid surface", progress, 0.7, 0.8,
                 "Extracting the surface");
    return polyDataOutput(surface, file, "surface");
}

template <typename ArrayType>
vtkSmartPointer<vtkDataArray> plyExtraArray(const PlyExtra& extra) {
    auto array = vtkSmartPointer<ArrayType>::New();
    array->SetName(extra.name.c_str());
    array->SetNumberOfComponents(1);
    array->SetNumberOfTuples(static_cast<vtkIdType>(extra.values.size()));
    for (std::size_t i = 0; i < extra.values.size(); ++i) {
        array->SetValue(static_cast<vtkIdType>(i),
                        static_cast<typename ArrayType::ValueType>(extra.values[i]));
    }
    return array;
}

}  // namespace

vtkSmartPointer<vtkPolyData> readStl(const fs::path& file, const Progress& progress,
                                     const std::string& stage) {
    auto reader = vtkSmartPointer<vtkSTLReader>::New();
    reader->SetFileName(file.c_str());
    reader->MergingOff();  // merged below, after the coordinates are known finite
    reader->ScalarTagsOff();
    runAlgorithm(reader, file, "STL", progress, 0.1, 0.7, stage);
    auto raw = polyDataOutput(reader, file, "STL");
    if (raw->GetNumberOfPoints() == 0) {
        throw FormatError(file, "the STL file holds no triangles (empty mesh)");
    }
    for (vtkIdType i = 0; i < raw->GetNumberOfPoints(); ++i) {
        double p[3];
        raw->GetPoint(i, p);
        if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2])) {
            throw FormatError(file,
                              "triangle " + std::to_string(i / 3) + " has a non-finite coordinate");
        }
    }
    // STL stores every triangle's corners separately: merge identical points.
    auto clean = vtkSmartPointer<vtkCleanPolyData>::New();
    clean->SetInputData(raw);
    clean->PointMergingOn();
    clean->SetTolerance(0.0);
    runAlgorithm(clean, file, "STL", progress, 0.7, 0.8, "Merging points");
    return polyDataOutput(clean, file, "STL");
}

vtkSmartPointer<vtkPolyData> readObj(const fs::path& file, const Progress& progress,
                                     const std::string& stage) {
    auto reader = vtkSmartPointer<vtkOBJReader>::New();
    reader->SetFileName(file.c_str());
    runAlgorithm(reader, file, "OBJ", progress, 0.1, 0.8, stage);
    return polyDataOutput(reader, file, "OBJ");
}

vtkSmartPointer<vtkPolyData> readPly(const fs::path& file, const PlyData& ply,
                                     const Progress& progress, const std::string& stage) {
    auto reader = vtkSmartPointer<vtkPLYReader>::New();
    reader->SetFileName(file.c_str());
    runAlgorithm(reader, file, "PLY", progress, 0.1, 0.8, stage);
    auto poly = polyDataOutput(reader, file, "PLY");
    if (static_cast<std::uint64_t>(poly->GetNumberOfPoints()) != ply.vertexCount) {
        throw FormatError(file,
                          "the PLY reader returned " + std::to_string(poly->GetNumberOfPoints()) +
                              " points but the file declares " + std::to_string(ply.vertexCount));
    }
    for (const auto& extra : ply.extras) {
        const bool onPoints = extra.element == "vertex";
        const bool fits =
            onPoints ? extra.values.size() == ply.vertexCount
                     : extra.values.size() == ply.faceCount &&
                           static_cast<std::uint64_t>(poly->GetNumberOfCells()) == ply.faceCount;
        if (!fits) {
            continue;  // faces VTK dropped: the per-face values no longer line up
        }
        // Integer properties with NaN-free values become int arrays (NaN cannot be an int).
        const bool asInt =
            extra.integer && std::all_of(extra.values.begin(), extra.values.end(), [](float v) {
                return std::isfinite(v) && std::abs(v) < 2.0e9F;
            });
        auto array =
            asInt ? plyExtraArray<vtkIntArray>(extra) : plyExtraArray<vtkFloatArray>(extra);
        if (onPoints) {
            poly->GetPointData()->AddArray(array);
        } else {
            poly->GetCellData()->AddArray(array);
        }
    }
    return poly;
}

vtkSmartPointer<vtkPolyData> readLegacy(const fs::path& file, LegacyDataset dataset,
                                        const Progress& progress, const std::string& stage) {
    const auto configure = [](auto* reader) {
        reader->ReadAllScalarsOn();
        reader->ReadAllVectorsOn();
        reader->ReadAllNormalsOn();
        reader->ReadAllTensorsOn();
        reader->ReadAllColorScalarsOn();
        reader->ReadAllTCoordsOn();
        reader->ReadAllFieldsOn();
    };
    if (dataset == LegacyDataset::PolyData) {
        auto reader = vtkSmartPointer<vtkPolyDataReader>::New();
        reader->SetFileName(file.c_str());
        configure(reader.Get());
        runAlgorithm(reader, file, "legacy VTK", progress, 0.1, 0.8, stage);
        return polyDataOutput(reader, file, "legacy VTK");
    }
    auto reader = vtkSmartPointer<vtkUnstructuredGridReader>::New();
    reader->SetFileName(file.c_str());
    configure(reader.Get());
    runAlgorithm(reader, file, "legacy VTK", progress, 0.1, 0.7, stage);
    auto* grid = vtkUnstructuredGrid::SafeDownCast(reader->GetOutputDataObject(0));
    if (grid == nullptr) {
        throw FormatError(file, "the legacy VTK reader produced no unstructured grid");
    }
    return surfaceOf(grid, file, progress);
}

vtkSmartPointer<vtkPolyData> readVtp(const fs::path& file, const Progress& progress,
                                     const std::string& stage) {
    auto reader = vtkSmartPointer<vtkXMLPolyDataReader>::New();
    reader->SetFileName(file.c_str());
    runAlgorithm(reader, file, "VTP", progress, 0.1, 0.8, stage);
    return polyDataOutput(reader, file, "VTP");
}

vtkSmartPointer<vtkPolyData> readVtu(const fs::path& file, const Progress& progress,
                                     const std::string& stage) {
    auto reader = vtkSmartPointer<vtkXMLUnstructuredGridReader>::New();
    reader->SetFileName(file.c_str());
    runAlgorithm(reader, file, "VTU", progress, 0.1, 0.7, stage);
    auto* grid = vtkUnstructuredGrid::SafeDownCast(reader->GetOutputDataObject(0));
    if (grid == nullptr) {
        throw FormatError(file, "the VTU reader produced no unstructured grid");
    }
    return surfaceOf(grid, file, progress);
}

}  // namespace vv::meshio::detail
