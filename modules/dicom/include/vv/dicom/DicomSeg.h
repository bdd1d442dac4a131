// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// DICOM Segmentation objects (SEG) as label maps (DCMTK dcmseg
// behind this header; no DCMTK type shows here).

#include <filesystem>
#include <vector>

#include "vv/core/Progress.h"
#include "vv/scene/LabelMap.h"

namespace vv::dicom {

/// True when `path` is a regular file holding a DICOM Segmentation object
/// (SOP Class 1.2.840.10008.5.1.4.1.1.66.4). Never throws.
[[nodiscard]] bool isDicomSegFile(const std::filesystem::path& path);

/// Reads a DICOM SEG file (binary or fractional; fractional frames count as
/// set at half the maximum fractional value and above) into one label map per
/// segment, in segment number order: voxels 1 = in the segment, 0 = not;
/// segmentNames[0] = the Segment Label, components[0] = {1, voxel count,
/// volume}. All maps share one grid: the frames' Image Position (Patient)
/// projected on the normal of Image Orientation (Patient) give the slices
/// (sorted by position, never by frame number; slices no frame covers stay
/// empty; the slice step is the smallest gap between distinct positions),
/// Pixel Spacing the in-plane spacing; indexToWorld as Volume's.
/// Reports progress ("Reading DICOM SEG"). Throws IoError (missing file),
/// FormatError naming the file (not a SEG, no segments or frames, frames
/// without position / orientation / spacing, frames of different
/// orientations, positions off the slice grid, bad frame data),
/// CancelledError.
[[nodiscard]] std::vector<scene::LabelMap> loadDicomSegLabelMaps(const std::filesystem::path& file,
                                                                 const Progress& progress = {});

}  // namespace vv::dicom
