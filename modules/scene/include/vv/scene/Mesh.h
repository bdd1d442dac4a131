// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <cstdint>
#include <filesystem>
#include <glm/glm.hpp>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "vv/core/Math.h"

namespace vv::scene {

/// A per-vertex (or per-triangle) data array such as wall shear stress.
/// Non-finite values are kept as NaN and counted: they mean "no data here".
struct DataArray {
    std::string name;           ///< e.g. "wss"
    std::string unit;           ///< e.g. "Pa"; empty when unknown
    int components = 1;         ///< 1 = scalar, 3 = vector, ...
    std::vector<float> values;  ///< tuple-major: values[i * components + c]
    bool integer = false;       ///< true for id / label arrays (segment_id, generation)
    bool fromCells = false;     ///< converted from a cell array to a point array

    [[nodiscard]] std::size_t tupleCount() const noexcept {
        return components > 0 ? values.size() / static_cast<std::size_t>(components) : 0;
    }
    /// Number of tuples with at least one non-finite component.
    [[nodiscard]] std::size_t nonFiniteCount() const noexcept;
    /// Range of the finite values (of the magnitude for vectors); nullopt when
    /// no value is finite.
    [[nodiscard]] std::optional<std::pair<float, float>> finiteRange() const;
};

/// A triangle surface with per-vertex normals and data arrays, in scene units
/// (millimetres unless the loader was told otherwise).
struct Mesh {
    std::string name;              ///< shown in the UI; file stem by default
    std::filesystem::path source;  ///< the file it came from; empty if generated
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;      ///< one per position, unit length
    std::vector<std::uint32_t> indices;  ///< three per triangle
    std::vector<DataArray> pointArrays;  ///< tupleCount() == positions.size()
    std::vector<DataArray> cellArrays;   ///< tupleCount() == triangleCount()
    /// Names of label values (segment ids) by array name, where the file
    /// gives them (meshio: the field-data string array "<array>_names").
    std::map<std::string, std::map<std::int64_t, std::string>> labelNames;

    [[nodiscard]] std::size_t vertexCount() const noexcept { return positions.size(); }
    [[nodiscard]] std::size_t triangleCount() const noexcept { return indices.size() / 3; }
    [[nodiscard]] Aabb bounds() const noexcept;
    /// The point array called `name`, or nullptr.
    [[nodiscard]] const DataArray* pointArray(const std::string& name) const noexcept;
};

/// The frame a scene's coordinates are given in: whether they carry anatomy.
enum class SceneFrame : std::uint8_t {
    /// Unknown (mesh files): the axes have no anatomical meaning; views and
    /// the orientation marker name them x, y, z.
    Unknown,
    /// DICOM's patient frame, LPS, mm: +x towards the patient's left, +y
    /// posterior, +z superior (head). Scenes made from DICOM images or a
    /// DICOM SEG (segmentation::loadSceneSource) say so; they open in the
    /// anterior view and the marker names patient directions.
    PatientLps,
};

/// Everything that is loaded at once: one or more meshes in one frame.
struct Scene {
    std::vector<Mesh> meshes;
    /// What the coordinates mean; set by whoever made the scene from data
    /// that says (DICOM), Unknown otherwise.
    SceneFrame frame = SceneFrame::Unknown;
    [[nodiscard]] Aabb bounds() const noexcept;
    /// Triangles of all meshes.
    [[nodiscard]] std::size_t triangleCount() const noexcept {
        std::size_t n = 0;
        for (const Mesh& mesh : meshes) {
            n += mesh.triangleCount();
        }
        return n;
    }
};

/// Recomputes area-weighted per-vertex normals from the triangles.
/// Vertices in no triangle get (0, 0, 1).
void computeNormals(Mesh& mesh);

}  // namespace vv::scene
