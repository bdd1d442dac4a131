// SPDX-License-Identifier: GPL-3.0-or-later
// Private to vv::meshio: reading each mesh format with its VTK reader, after the
// file has passed its preflight check (MeshPreflight.h). Every reader reports
// progress from 0.1 to 0.8 of `progress` (`stage` names the reading) and
// returns a non-null polydata; each throws FormatError naming the file when
// VTK fails or reports an error, CancelledError when cancelled.
#pragma once

#include <vtkSmartPointer.h>

#include <filesystem>
#include <string>

#include "preflight/MeshPreflight.h"
#include "vv/core/Progress.h"

class vtkPolyData;

namespace vv::meshio::detail {

/// Reads an STL file; refuses an empty one and non-finite coordinates, merges
/// identical corners into shared points.
[[nodiscard]] vtkSmartPointer<vtkPolyData> readStl(const std::filesystem::path& file,
                                                   const Progress& progress,
                                                   const std::string& stage);

/// Reads an OBJ file (with vtkOBJReader's "GroupIds" cell array).
[[nodiscard]] vtkSmartPointer<vtkPolyData> readObj(const std::filesystem::path& file,
                                                   const Progress& progress,
                                                   const std::string& stage);

/// Reads a PLY file and attaches the extra properties `ply` collected; refuses
/// a point count other than the declared one.
[[nodiscard]] vtkSmartPointer<vtkPolyData> readPly(const std::filesystem::path& file,
                                                   const PlyData& ply, const Progress& progress,
                                                   const std::string& stage);

/// Reads a legacy VTK file holding `dataset`; an unstructured grid is checked
/// and its outer surface returned.
[[nodiscard]] vtkSmartPointer<vtkPolyData> readLegacy(const std::filesystem::path& file,
                                                      LegacyDataset dataset,
                                                      const Progress& progress,
                                                      const std::string& stage);

/// Reads a VTK XML polydata (.vtp) file.
[[nodiscard]] vtkSmartPointer<vtkPolyData> readVtp(const std::filesystem::path& file,
                                                   const Progress& progress,
                                                   const std::string& stage);

/// Reads a VTK XML unstructured grid (.vtu) file, checks it and returns its
/// outer surface.
[[nodiscard]] vtkSmartPointer<vtkPolyData> readVtu(const std::filesystem::path& file,
                                                   const Progress& progress,
                                                   const std::string& stage);

}  // namespace vv::meshio::detail
