// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <cstdint>
#include <filesystem>
#include <glm/glm.hpp>
#include <string>
#include <utility>
#include <vector>

#include "vv/scene/Mesh.h"

namespace vv::meshio {

/// Writes `mesh` as VTK XML polydata (.vtp, binary, zlib-compressed) with its
/// normals, point and cell arrays; units travel in the array names as
/// "name [unit]". Integer arrays (DataArray::integer) are written as 32-bit
/// integers when all their values are finite and in range, so they load back
/// as integer; otherwise as floats. Point arrays converted from a cell array
/// of the mesh (DataArray::fromCells) are not written: loading the file with
/// MeshLoadOptions::cellArraysToPoints recreates them. NaN values are kept.
/// Written atomically (temporary file in the same folder + rename): on failure
/// neither `file` nor a temporary file is left behind, and an existing `file`
/// is unchanged.
/// Throws IoError naming `file` when it cannot be written (missing folder, no
/// permission, disk full); InvalidArgumentError when the mesh is inconsistent
/// (indices out of range, array sizes not matching the vertex / triangle
/// count, unnamed or duplicate array names).
void writeVtp(const scene::Mesh& mesh, const std::filesystem::path& file);

/// What a mesh file says of itself (provenance): where it came from and how
/// it was made, for other tools and for the next reader.
struct MeshFileMetadata {
    /// Name-value pairs, in order; names are lower-case words with '_'.
    std::vector<std::pair<std::string, std::string>> fields;
    /// One short line for a format with little room (the STL header).
    std::string summary;
};

/// The extensions writeMeshFile() writes: ".stl", ".vtp", ".ply".
[[nodiscard]] const std::vector<std::string>& writableMeshExtensions();

/// Writes `mesh` in the format of `file`'s extension (any case), atomically
/// (as writeVtp: on failure nothing is left behind, an existing file stays):
/// - .vtp: as writeVtp(), and each metadata field as a one-value string
///   array of the field data, named as the field;
/// - .stl: binary STL, the geometry only (STL has no normals per vertex, no
///   arrays); the 80-byte header is metadata.summary (control characters
///   made spaces, cut at 80 bytes on a UTF-8 character boundary; "solid" at
///   its start, which readers take for ASCII STL, becomes "Solid");
/// - .ply: binary little-endian PLY, the geometry (VTK's PLY writer writes
///   neither normals nor scalar arrays) and one comment "name: value" per
///   field (line breaks made spaces).
/// Throws InvalidArgumentError naming `file` for another extension or an
/// inconsistent mesh (as writeVtp), IoError naming `file` when it cannot be
/// written.
void writeMeshFile(const scene::Mesh& mesh, const std::filesystem::path& file,
                   const MeshFileMetadata& metadata = {});

/// Polylines with per-point and per-line arrays: centrelines for other tools
/// (VMTK, 3D Slicer, ParaView).
struct PolylineSet {
    std::vector<glm::dvec3> points;
    std::vector<std::vector<std::uint32_t>> lines;  ///< each >= 2 indices into points
    /// Written under their names as they are (no "[unit]" added).
    std::vector<scene::DataArray> pointArrays;  ///< tupleCount() == points.size()
    std::vector<scene::DataArray> lineArrays;   ///< tupleCount() == lines.size()
};

/// Writes `lines` as VTK XML polydata (.vtp, binary, zlib-compressed; points
/// in double precision, integer arrays as 32-bit integers) with each
/// metadata field as a one-value string array of the field data; atomically
/// (as writeVtp). Throws InvalidArgumentError naming `file` for an index out
/// of range, a line of fewer than two points or arrays that do not fit
/// (as writeVtp), IoError naming `file` when it cannot be written.
void writePolylinesVtp(const PolylineSet& lines, const std::filesystem::path& file,
                       const MeshFileMetadata& metadata = {});

}  // namespace vv::meshio
