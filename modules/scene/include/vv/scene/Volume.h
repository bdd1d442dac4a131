// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <cstddef>
#include <cstdint>
#include <glm/glm.hpp>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "vv/core/Error.h"
#include "vv/core/Math.h"

namespace vv::scene {

/// How a Volume stores its voxels. Both hold the *rescaled* value (Hounsfield
/// units for CT): Int16 when every value is an integer in [-32768, 32767] —
/// half the memory of Float32 — and Float32 otherwise.
enum class VoxelType : std::uint8_t { Int16, Float32 };

/// Size in bytes of one voxel of `type`.
[[nodiscard]] constexpr std::size_t voxelBytes(VoxelType type) noexcept {
    return type == VoxelType::Int16 ? 2 : 4;
}

/// A volume would not fit in the memory available; thrown before allocating.
class MemoryError : public vv::Error {
    using Error::Error;
};

/// A 3-D scalar image on a regular grid, x fastest: voxel (i, j, k) is column
/// i, row j of slice k, at data index (k * dims.y + j) * dims.x + i.
///
/// Geometry: indexToWorld() maps a voxel index (i, j, k, 1) — voxel centres at
/// integer indices — to world coordinates in millimetres. The world frame is
/// DICOM's patient frame, LPS (+x left, +y posterior, +z superior), the frame
/// meshes and the renderer's anatomical views use too. Column 0 is the row
/// direction times the column spacing, column 1 the column direction times the
/// row spacing, column 2 the step from one slice to the next (along the slice
/// normal, or sheared when the series has a gantry tilt), column 3 the centre
/// of voxel (0, 0, 0).
class Volume {
  public:
    Volume() = default;
    /// `dims` voxels of `type`, all zero, identity geometry (1 mm spacing).
    /// Throws InvalidArgumentError when a dimension is < 1, MemoryError when
    /// the allocation fails.
    Volume(glm::ivec3 dims, VoxelType type);

    [[nodiscard]] glm::ivec3 dims() const noexcept { return dims_; }
    [[nodiscard]] VoxelType voxelType() const noexcept { return type_; }
    [[nodiscard]] std::size_t voxelCount() const noexcept {
        return static_cast<std::size_t>(dims_.x) * static_cast<std::size_t>(dims_.y) *
               static_cast<std::size_t>(dims_.z);
    }
    [[nodiscard]] bool empty() const noexcept { return voxelCount() == 0; }
    /// Bytes held by the voxels.
    [[nodiscard]] std::size_t byteSize() const noexcept { return voxelCount() * voxelBytes(type_); }
    /// Bytes a volume of `dims` and `type` would need; saturates at
    /// UINT64_MAX instead of overflowing.
    [[nodiscard]] static std::uint64_t byteSize(std::uint64_t x, std::uint64_t y, std::uint64_t z,
                                                VoxelType type) noexcept;

    /// Data index of voxel (i, j, k); no bounds check.
    [[nodiscard]] std::size_t index(int i, int j, int k) const noexcept {
        return (static_cast<std::size_t>(k) * static_cast<std::size_t>(dims_.y) +
                static_cast<std::size_t>(j)) *
                   static_cast<std::size_t>(dims_.x) +
               static_cast<std::size_t>(i);
    }
    /// The value (HU for CT) at data index `n`; no bounds check.
    [[nodiscard]] float valueAt(std::size_t n) const noexcept {
        return type_ == VoxelType::Int16 ? static_cast<float>(int16_[n]) : float_[n];
    }
    /// The value at voxel (i, j, k); no bounds check.
    [[nodiscard]] float value(int i, int j, int k) const noexcept {
        return valueAt(index(i, j, k));
    }
    /// Stores `v` at data index `n`: rounded to the nearest integer and
    /// clamped to [-32768, 32767] for Int16.
    void setValueAt(std::size_t n, float v) noexcept;

    /// The voxels when voxelType() is Int16, else empty.
    [[nodiscard]] std::span<std::int16_t> int16Voxels() noexcept { return int16_; }
    [[nodiscard]] std::span<const std::int16_t> int16Voxels() const noexcept { return int16_; }
    /// The voxels when voxelType() is Float32, else empty.
    [[nodiscard]] std::span<float> floatVoxels() noexcept { return float_; }
    [[nodiscard]] std::span<const float> floatVoxels() const noexcept { return float_; }

    /// Smallest and largest value; (0, 0) for an empty volume.
    [[nodiscard]] std::pair<float, float> valueRange() const noexcept;

    /// Voxel index -> world (LPS patient, mm); see the class comment.
    [[nodiscard]] const glm::dmat4& indexToWorld() const noexcept { return indexToWorld_; }
    void setIndexToWorld(const glm::dmat4& m) noexcept { indexToWorld_ = m; }
    /// World (LPS patient, mm) -> continuous voxel index.
    [[nodiscard]] glm::dmat4 worldToIndex() const { return glm::inverse(indexToWorld_); }
    /// World position of the continuous voxel index `ijk`.
    [[nodiscard]] glm::dvec3 worldPosition(const glm::dvec3& ijk) const noexcept {
        return {indexToWorld_ * glm::dvec4(ijk, 1.0)};
    }
    /// Voxel size in mm: x between columns, y between rows, z between slices
    /// measured along the slice normal.
    [[nodiscard]] glm::dvec3 spacing() const noexcept;
    /// Unit row direction, column direction and slice normal (right-handed)
    /// as the columns of a rotation matrix.
    [[nodiscard]] glm::dmat3 orientation() const noexcept;
    /// True when the slice step is not along the slice normal (gantry tilt):
    /// the grid is a parallelepiped, not a box.
    [[nodiscard]] bool sheared() const noexcept;
    /// World-space box around the eight corner voxel centres.
    [[nodiscard]] Aabb worldBounds() const noexcept;

    /// Free text about the values: "HU" for CT, empty when unknown.
    [[nodiscard]] const std::string& unit() const noexcept { return unit_; }
    void setUnit(std::string unit) { unit_ = std::move(unit); }
    /// DICOM modality ("CT", "MR", ...); empty for generated volumes.
    [[nodiscard]] const std::string& modality() const noexcept { return modality_; }
    void setModality(std::string modality) { modality_ = std::move(modality); }

  private:
    glm::ivec3 dims_{0};
    VoxelType type_ = VoxelType::Float32;
    std::vector<std::int16_t> int16_;
    std::vector<float> float_;
    glm::dmat4 indexToWorld_{1.0};
    std::string unit_;
    std::string modality_;
};

}  // namespace vv::scene
