// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// A slice plane in the patient frame (LPS, mm) and the stacks of axial,
// coronal and sagittal planes through a volume.

#include <cstdint>
#include <glm/glm.hpp>

#include "vv/scene/Volume.h"

namespace vv::slices {

/// The three standard views, in the radiological convention: the patient's
/// right on the screen's left in axial and coronal views (axial seen from the
/// feet, anterior up; coronal seen from the front, superior up) and anterior
/// on the left in sagittal views (superior up).
enum class SliceOrientation : std::uint8_t { Axial, Coronal, Sagittal };

/// A rectangle of width x height pixels in the patient frame. Pixel (c, r)
/// (column c, row r; centres at integers) lies at
/// origin + c * pixelSpacing * right + r * pixelSpacing * down.
struct SlicePlane {
    glm::dvec3 origin{0.0};           ///< centre of pixel (0, 0), LPS mm
    glm::dvec3 right{1.0, 0.0, 0.0};  ///< unit: one column to the right
    glm::dvec3 down{0.0, 1.0, 0.0};   ///< unit: one row down, orthogonal to right
    double pixelSpacing = 1.0;        ///< mm per pixel, > 0
    int width = 0;
    int height = 0;

    /// World position of the continuous pixel position (column, row).
    [[nodiscard]] glm::dvec3 worldAt(double column, double row) const noexcept {
        return origin + (column * pixelSpacing) * right + (row * pixelSpacing) * down;
    }
    /// The continuous pixel position (column, row) of `world` projected onto
    /// the plane along its normal.
    [[nodiscard]] glm::dvec2 pixelAt(const glm::dvec3& world) const noexcept {
        const glm::dvec3 d = world - origin;
        return {glm::dot(d, right) / pixelSpacing, glm::dot(d, down) / pixelSpacing};
    }
    /// right x down: the direction the viewer looks along.
    [[nodiscard]] glm::dvec3 normal() const noexcept { return glm::cross(right, down); }
};

/// The stack of parallel planes of one orientation through a volume: every
/// plane covers the volume's box around its voxel centres (its world bounds),
/// the slices are `step` mm apart along the orientation's world axis (x for
/// sagittal, y for coronal, z for axial) from `first` to first + (count - 1)
/// step, the world coordinate along that axis (the "slice position").
struct SliceStack {
    SliceOrientation orientation = SliceOrientation::Axial;
    SlicePlane plane;    ///< the plane of slice 0
    int axis = 2;        ///< world axis of the slice position: 0 x, 1 y, 2 z
    double first = 0.0;  ///< slice position of slice 0, mm
    double step = 1.0;   ///< mm between slices, > 0
    int count = 1;       ///< >= 1

    /// Slice position of slice `index` (not clamped), mm.
    [[nodiscard]] double position(int index) const noexcept { return first + index * step; }
    /// The slice nearest to the slice position `mm`, clamped to [0, count - 1].
    [[nodiscard]] int nearestIndex(double mm) const noexcept;
    /// The plane of slice `index`, clamped to [0, count - 1].
    [[nodiscard]] SlicePlane planeAt(int index) const noexcept;
};

/// The world axis (0 x, 1 y, 2 z) along which slices of `orientation` are
/// stacked, and the unit right / down directions of its planes.
[[nodiscard]] int sliceAxis(SliceOrientation orientation) noexcept;
[[nodiscard]] glm::dvec3 sliceRight(SliceOrientation orientation) noexcept;
[[nodiscard]] glm::dvec3 sliceDown(SliceOrientation orientation) noexcept;

/// The distance in mm along the unit direction `direction` after which the
/// continuous voxel index of `volume` has changed by one along some grid axis:
/// the grid's sampling distance in that direction (the spacing for a grid
/// axis; smaller across an oblique grid).
[[nodiscard]] double samplingDistance(const scene::Volume& volume, const glm::dvec3& direction);

/// The stack of `orientation` planes through `volume`: pixel spacing the
/// smaller sampling distance along right and down, slice step the sampling
/// distance along the slice axis (so an axis-aligned grid is sampled at its
/// voxel centres). Throws InvalidArgumentError for an empty volume or a
/// singular or non-finite indexToWorld, or when a plane would exceed
/// 16384 pixels along a side.
[[nodiscard]] SliceStack sliceStack(const scene::Volume& volume, SliceOrientation orientation);

}  // namespace vv::slices
