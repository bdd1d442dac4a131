// SPDX-License-Identifier: GPL-3.0-or-later
// Private to vv::meshio: the structural checks ("preflight") every mesh file passes
// before a VTK reader sees it. VTK's readers trust their input: some allocate
// whatever a header claims, some read out of bounds on bad indices. Each check
// refuses what would make its reader crash, hang or allocate absurdly.
// All of them throw FormatError naming the file for what they refuse, IoError
// when the file cannot be read, and CancelledError (through the ticker) when
// the load is cancelled.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace vv::meshio::detail {

class PreflightTicker;

/// The mesh file formats loadMesh reads.
enum class Format { Stl, Obj, Ply, LegacyVtk, Vtp, Vtu };

/// A scalar vertex or face property vtkPLYReader ignores; we attach it ourselves.
struct PlyExtra {
    std::string element;  // "vertex" or "face"
    std::string name;
    bool integer = false;
    std::vector<float> values;
};

/// What the PLY check learnt: the extra properties with their values, the counts.
struct PlyData {
    std::vector<PlyExtra> extras;
    std::uint64_t vertexCount = 0;
    std::uint64_t faceCount = 0;
};

/// The kind of dataset a legacy VTK file holds.
enum class LegacyDataset { PolyData, UnstructuredGrid };

/// Checks a binary STL file (told from ASCII as vtkSTLReader does; ASCII files
/// pass unchecked): a full header, a triangle count matching the size, and at
/// least one triangle.
void preflightStl(const std::filesystem::path& file, std::uintmax_t size);

/// Checks an OBJ file line by line: text only, finite vertices, references
/// that exist and keep one form (v, v/vt, v//vn, v/vt/vn) within elements and
/// across faces.
void preflightObj(const std::filesystem::path& file, PreflightTicker& tick);

/// Parses the header, then walks all element data to be sure vtkPLYReader
/// (which trusts every count and index) can read it safely. Collects the
/// scalar vertex / face properties VTK does not read.
[[nodiscard]] PlyData preflightPly(const std::filesystem::path& file, std::uintmax_t size,
                                   PreflightTicker& tick);

/// Walks a legacy VTK file the way vtkPolyDataReader / vtkUnstructuredGridReader
/// read it, without storing it, and refuses everything those readers would
/// stumble over: their error paths are not safe (some crash), they allocate
/// declared counts before reading, import old-format cells trusting every cell
/// size, and accept arrays cut short by the end of the file. So: known
/// keywords and data types only, counts that fit in the file, complete data,
/// well-formed cells, supported cell types matching the cells, attribute
/// counts matching the points and cells. Returns the dataset type.
[[nodiscard]] LegacyDataset preflightLegacyVtk(const std::filesystem::path& file,
                                               std::uintmax_t size, PreflightTicker& tick);

/// Scans the XML structure of a .vtp / .vtu file: the root must be a VTKFile
/// of the expected type; the counts the pieces and arrays declare, and the
/// headers of binary arrays (inline or appended), must fit in the file given
/// its compression, since vtkXMLReader allocates them before reading data.
/// `format` is Format::Vtp or Format::Vtu.
void preflightXml(const std::filesystem::path& file, std::uintmax_t size, Format format,
                  PreflightTicker& tick);

}  // namespace vv::meshio::detail
