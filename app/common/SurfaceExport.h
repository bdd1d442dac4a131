// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// Exporting a segmented vessel surface (File > Export Surface…,
// `vesselview-cli segment … -o FILE`): the mesh in patient LPS millimetres
// with its label array, and what made it — series and settings — in the
// file's field data (VTP), header (STL) or comments (PLY).

#include <cstddef>
#include <filesystem>
#include <glm/glm.hpp>
#include <optional>
#include <string>
#include <vector>

#include "vv/meshio/MeshWriter.h"
#include "vv/scene/LabelMap.h"
#include "vv/scene/Mesh.h"
#include "vv/segmentation/SceneSource.h"
#include "vv/segmentation/SegmentationPipeline.h"
#include "vv/segmentation/VolumeSegmentation.h"

namespace vv::app {

/// Where a segmented surface came from and how it was made.
struct SurfaceProvenance {
    std::string seriesInstanceUid;
    std::string seriesDescription;
    std::string modality;
    std::optional<int> seriesNumber;
    /// A DICOM SEG object's segments (label i + 1 = segmentNames[i]); empty
    /// for a segmented image series, whose settings follow.
    std::vector<std::string> segmentNames;
    std::string unit;                    ///< of the threshold ("HU", or empty)
    segmentation::ThresholdRange range;  ///< the range used and its rule
    bool intensityCorrected = false;
    double gainLowest = 1.0;  ///< the correction's gain extremes
    double gainHighest = 1.0;
    std::optional<glm::ivec3> seed;  ///< the component under it, else the largest
    int keepComponents = 1;
    std::size_t componentsKept = 0;
    std::size_t componentsFound = 0;
    bool boneRemoved = false;
    std::size_t targetTriangles = 0;  ///< 0: no decimation
};

/// The provenance of what loadSceneSource() reported (`report`, from a DICOM
/// image series or SEG) with the options it was given.
[[nodiscard]] SurfaceProvenance provenanceOf(const segmentation::SceneSourceReport& report,
                                             const segmentation::SceneSourceOptions& options);

/// Sets the segmentation's part of `provenance` (range, correction, seed,
/// components, bone removal, triangle target) from a run of `request` that
/// gave `outcome`; the series stays.
void describeSegmentation(SurfaceProvenance& provenance,
                          const segmentation::SegmentationRequest& request,
                          const segmentation::SegmentationOutcome& outcome);

/// What the exported file says of itself: fields "software" (VesselView and
/// its version), "coordinates" (DICOM patient LPS, mm; how to get RAS),
/// "created" (UTC, ISO 8601), the series ("series_instance_uid",
/// "series_description", "series_number", "modality"), then either the
/// segments of a SEG ("segments") or the segmentation's settings
/// ("threshold", "threshold_rule", "intensity_correction", "components",
/// "bone_removal", "surface"), and "label_meaning" (what the point array "label" holds);
/// the summary (the STL header) says software, frame, modality, threshold,
/// correction and description in that order.
[[nodiscard]] meshio::MeshFileMetadata surfaceMetadata(const SurfaceProvenance& provenance);

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
                           const std::filesystem::path& file, const SurfaceProvenance& provenance);

}  // namespace vv::app
