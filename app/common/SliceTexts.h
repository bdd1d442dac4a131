// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// The texts of the slice views in the UI language (QLocale()): view names,
// window presets, slice positions, the voxel read-out.

#include <QString>
#include <glm/glm.hpp>
#include <optional>

#include "vv/slices/SlicePlane.h"
#include "vv/slices/VoxelProbe.h"
#include "vv/slices/WindowLevel.h"

namespace vv::app {

/// "Axial", "Coronal", "Sagittal".
[[nodiscard]] QString orientationName(slices::SliceOrientation orientation);
/// "CTA", "MRA", "Soft tissue", "Bone", "Full range".
[[nodiscard]] QString presetName(slices::WindowPreset preset);
/// A number of mm with one decimal in the UI locale: "12.5 mm" / "12,5 mm".
[[nodiscard]] QString millimetres(double mm);
/// The slice position along world axis `axis` as patient side and distance:
/// "S 12.5 mm", "R 3.0 mm" (vv::slices::slicePositionText).
[[nodiscard]] QString slicePositionLabel(int axis, double mm);
/// A world point as its three patient coordinates: "L 12.3  P 4.5  S 67.8 mm".
[[nodiscard]] QString worldPointLabel(const glm::dvec3& world);
/// A voxel value with its unit: "412 HU" (integers without decimals,
/// otherwise up to 4 significant digits; no unit when unknown).
[[nodiscard]] QString voxelValueLabel(const slices::VoxelSample& sample);
/// The window as "W 600  L 300" (+ unit when known).
[[nodiscard]] QString windowLabel(const slices::Window& window, const QString& unit);

}  // namespace vv::app
