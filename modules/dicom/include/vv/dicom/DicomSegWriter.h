// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// Writing a label map as a DICOM Segmentation object (binary SEG; DCMTK's
// dcmseg behind this header), e.g. to send a segmentation back to the PACS.

#include <filesystem>
#include <string>

#include "vv/dicom/ExportObjects.h"
#include "vv/scene/LabelMap.h"

namespace vv::dicom {

/// Writes `labelMap` as a binary Segmentation Storage instance (modality SEG)
/// in a new series of `study` to `path`, atomically: one segment per label
/// that has voxels (Segment Label = its segment name, else "Vessels" or
/// "Vessels <label>" when there are several; category Tissue, type Blood
/// vessel, algorithm type AUTOMATIC), one frame per segment and slice that
/// holds a voxel of it, with the slice's Image Position (Patient), the
/// grid's Image Orientation (Patient) and Pixel Spacing from
/// labelMap.indexToWorld, in `frameOfReferenceUid` (the source series'; a new
/// one when empty). The patient module as writeSecondaryCapture() writes it
/// (name, ID, birth date, sex; empty when anonymised or unknown). Reads back
/// with loadDicomSegLabelMaps(). Returns the SOP Instance UID.
/// Throws InvalidArgumentError when the map is empty, larger than 65535 per
/// side, its labels do not match its dims, or no voxel is labelled; IoError
/// naming `path` when it cannot be written.
std::string writeDicomSeg(const std::filesystem::path& path, const scene::LabelMap& labelMap,
                          const ExportStudy& study, const std::string& frameOfReferenceUid,
                          const ExportSeries& series);

}  // namespace vv::dicom
