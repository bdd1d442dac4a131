// SPDX-License-Identifier: GPL-3.0-or-later
// Private to vv::io: conversion between vtkPolyData and vv::io::Mesh. Keeps VTK
// types out of the public headers.
#pragma once

#include <filesystem>

#include <vtkSmartPointer.h>

#include "vv/io/Mesh.h"

class vtkPolyData;
class vtkDataArray;

namespace vv::io::detail {

/// Converts a polydata (any polygons; they are triangulated) into a Mesh.
/// Point and cell data arrays become DataArrays (names kept; a unit is taken
/// from a trailing "[unit]" or "_unit" suffix in the name when present, see
/// splitNameAndUnit). Normals are taken from the point normals when present,
/// else computed. Non-finite array values are kept.
/// Throws FormatError naming `file` for: no points, no triangles, non-finite
/// coordinates, zero total area, indices out of range.
[[nodiscard]] Mesh meshFromPolyData(vtkPolyData* polyData, const std::filesystem::path& file);

/// Converts a Mesh into a polydata with point normals, point and cell arrays.
/// Array units are kept in the array name as "name [unit]".
[[nodiscard]] vtkSmartPointer<vtkPolyData> polyDataFromMesh(const Mesh& mesh);

/// Splits "wss [Pa]" into {"wss", "Pa"}; a name without brackets gives {name, ""}.
[[nodiscard]] std::pair<std::string, std::string> splitNameAndUnit(const std::string& vtkName);

/// Joins {"wss", "Pa"} into "wss [Pa]"; an empty unit gives the bare name.
[[nodiscard]] std::string joinNameAndUnit(const std::string& name, const std::string& unit);

}  // namespace vv::io::detail
