// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// Resampling a volume or a label map onto a slice plane.

#include <cstdint>
#include <stop_token>

#include "vv/core/Image.h"
#include "vv/scene/LabelMap.h"
#include "vv/scene/Volume.h"
#include "vv/slices/SlicePlane.h"

namespace vv::slices {

enum class Interpolation : std::uint8_t {
    Linear,   ///< trilinear between the eight surrounding voxel centres
    Nearest,  ///< the value of the nearest voxel
};

/// The values of `volume` (as stored: HU for CT) at the centres of the
/// plane's pixels, through volume.worldToIndex() (oblique and sheared grids
/// exact). A pixel is inside when its continuous voxel index lies in
/// [-0.5, dims - 0.5] on every axis (the voxels' own extent); outside pixels
/// are NaN. Linear samples within half a voxel of the border take the border
/// voxels' values (clamped). Rows are computed in parallel, each from its
/// first index and one index step per column, over the columns where the row
/// is inside the volume only.
/// Throws InvalidArgumentError (empty volume, a plane with a side < 1 or
/// > 16384 pixels, pixel spacing <= 0, non-finite geometry), CancelledError
/// when `stop` is requested.
[[nodiscard]] Image<float> reslice(const scene::Volume& volume, const SlicePlane& plane,
                                   Interpolation interpolation = Interpolation::Linear,
                                   const std::stop_token& stop = {});

/// The labels of `map` at the plane's pixel centres (nearest voxel, through
/// map.indexToWorld, which may differ from the volume's: a preview's coarse
/// grid); 0 outside the map. Throws as reslice(), and InvalidArgumentError
/// when the map's labels do not match its dims.
[[nodiscard]] Image<std::uint8_t> resliceLabels(const scene::LabelMap& map, const SlicePlane& plane,
                                                const std::stop_token& stop = {});

}  // namespace vv::slices
