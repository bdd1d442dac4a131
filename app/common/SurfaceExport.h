// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// Exporting a segmented vessel surface (File > Export Surface…,
// `vesselview-cli segment … -o FILE`): the mesh in patient LPS millimetres
// with its label array, and what made it — series and settings — in the
// file's field data (VTP), header (STL) or comments (PLY).

#include <filesystem>

#include "common/SegmentationProvenance.h"
#include "vv/meshio/MeshWriter.h"
#include "vv/scene/LabelMap.h"
#include "vv/scene/Mesh.h"

namespace vv::app {

/// What the exported file says of itself: fields "software" (VesselView and
/// its version), "coordinates" (DICOM patient LPS, mm; how to get RAS),
/// "created" (UTC, ISO 8601), the series ("series_instance_uid",
/// "series_description", "series_number", "modality"), then either the
/// segments of a SEG ("segments") or the segmentation's settings
/// ("threshold", "threshold_rule", "intensity_correction", "components",
/// "bone_removal", "surface"), and "label_meaning" (what the point array "label" holds);
/// the summary (the STL header) says software, frame, modality, threshold,
/// correction and description in that order.
[[nodiscard]] meshio::MeshFileMetadata surfaceMetadata(const SegmentationProvenance& provenance);

/// One mesh of a scene's meshes with a "label" point array: mesh i has label
/// i + 1, named after the mesh (Mesh::labelNames). Normals kept.
[[nodiscard]] scene::Mesh meshWithLabels(const scene::Scene& scene);

/// Writes the segmented `mesh` to `file` (meshio::writeMeshFile: .stl, .vtp,
/// .ply by extension, atomically) with surfaceMetadata(provenance); with
/// `labels` (the label map it was extracted from), a "label" point array
/// first (segmentation::surfaceLabels; label n named "component n").
/// Throws as writeMeshFile (InvalidArgumentError for another extension,
/// IoError naming the file).
void writeSegmentedSurface(scene::Mesh mesh, const scene::LabelMap* labels,
                           const std::filesystem::path& file,
                           const SegmentationProvenance& provenance);

}  // namespace vv::app
