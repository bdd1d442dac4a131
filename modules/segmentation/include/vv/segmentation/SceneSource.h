// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// One entry point for "open this path": a mesh file, or DICOM (a folder, a
// DICOMDIR or a file) whose series is segmented into vessel surfaces.

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "vv/core/Progress.h"
#include "vv/dicom/Dicom.h"
#include "vv/meshio/MeshLoader.h"
#include "vv/segmentation/VolumeSegmentation.h"
#include "vv/segmentation/VolumeSurface.h"

namespace vv::segmentation {

struct SceneSourceOptions {
    meshio::MeshLoadOptions mesh;  ///< for mesh files
    /// DICOM: the series to load; empty = the only one (several: error).
    std::string seriesInstanceUid;
    dicom::DicomLoadOptions dicom;
    SegmentationOptions segmentation;
    SurfaceOptions surface;
};

/// What loadSceneSource() did, for summaries ("segmented 1 component ...").
struct SceneSourceReport {
    bool fromVolume = false;              ///< true: DICOM image series, segmented
    bool fromSegmentationObject = false;  ///< true: a DICOM SEG, one mesh per segment
    std::string seriesInstanceUid;
    /// What the loaded series says of itself, to name it to a user (never by
    /// its UID): Series Description, Modality, Series Number and its study's
    /// Study Date (YYYYMMDD as in the file); empty / none where absent, and
    /// for a single DICOM SEG file.
    std::string seriesDescription;
    std::string modality;
    std::optional<int> seriesNumber;
    std::string studyDate;
    glm::ivec3 volumeDims{0};
    ThresholdRange range;
    std::size_t componentsFound = 0;
    std::size_t componentsKept = 0;
    std::size_t boneComponents = 0;
    bool intensityCorrected = false;  ///< the intensity correction ran (MR)
    double gainLowest = 1.0;          ///< its gain's extremes
    double gainHighest = 1.0;
    /// Bright tubes continuing past the segmentation (findCutOffVessels()).
    std::vector<CutOffVessel> cutOff;
    std::vector<dicom::DicomWarning> warnings;
    /// The loaded volume (fromVolume), kept so that it can be segmented
    /// again without reading the files (the GUI's Segmentation panel).
    std::shared_ptr<const scene::Volume> volume;
    /// The label map of that segmentation (fromVolume): the slice overlay.
    std::shared_ptr<const scene::LabelMap> labelMap;
};

/// Loads `path` as a scene: a mesh file (loadMesh(), by extension) gives one
/// mesh; anything else that isDicomSource() — a folder, a DICOMDIR, a file
/// with the DICM prefix or a .dcm file — is scanned, the chosen series loaded
/// (loadDicomVolume()), segmented (segmentVessels()) and its kept components
/// extracted as one surface (extractSurface()) in patient coordinates (LPS,
/// mm), named "vessels" with `source` = path. A DICOM Segmentation object
/// (isDicomSegFile(), or a chosen series of them in a folder) gives one mesh
/// per segment (loadDicomSegMeshes(), with options.surface). A scene from
/// DICOM has frame scene::SceneFrame::PatientLps, a mesh file's Unknown.
/// `report`, when given, says what happened. Reports progress over the whole chain.
/// Throws as loadMesh / loadDicomVolume / segmentVessels / extractSurface
/// (IoError, FormatError, MemoryError, InvalidArgumentError, CancelledError);
/// a path that is not DICOM goes to loadMesh() and fails as it does (unknown
/// extension, missing file).
[[nodiscard]] scene::Scene loadSceneSource(const std::filesystem::path& path,
                                           const SceneSourceOptions& options = {},
                                           const Progress& progress = {},
                                           SceneSourceReport* report = nullptr);

/// Loads `files` into one scene, in order, as the GUI and a session open
/// them: DICOM sources (isDicomSource()) through loadSceneSource() with
/// `options` one by one, the meshes with meshio::loadScene() (as one batch
/// when there is no DICOM source); in the patient frame when any source is
/// DICOM. `report`, when given, says what loading the last DICOM source did. Reports progress over
/// all files. Throws as meshio::loadScene() / loadSceneSource() (IoError, FormatError, ...,
/// CancelledError).
[[nodiscard]] scene::Scene loadSceneSources(const std::vector<std::filesystem::path>& files,
                                            const SceneSourceOptions& options = {},
                                            const Progress& progress = {},
                                            SceneSourceReport* report = nullptr);

/// The command-line spelling of the DICOM options, shared by the CLI commands
/// that open a scene (render, report): when `name` is one of
///   --series UID           the series to load
///   --threshold LO:HI      threshold range (also LO,HI), e.g. 150:600
///   --components N         keep the N largest components (1..255)
///   --seed I,J,K           keep the component under voxel (I, J, K)
///   --bone-removal on|off  bone removal (default: on for CT)
///   --intensity-correction on|off  divide out the MR signal fall-off (default: on for MR)
///   --triangles N          surface decimation target (0 = none, else >= 4)
/// sets it from `value` and returns true; returns false for other names.
/// Throws InvalidArgumentError naming the option for a bad value.
bool setSceneSourceOption(const std::string& name, const std::string& value,
                          SceneSourceOptions& options);

/// True when loadSceneSource() would read `path` as DICOM: not a file with a
/// supported mesh extension, and looksLikeDicom() or a ".dcm" extension.
[[nodiscard]] bool isDicomSource(const std::filesystem::path& path);

/// dicom::loadDicomSegLabelMaps() then extractSurface() of each segment that
/// has voxels: one mesh per segment, named after its Segment Label, `source` =
/// file, in the patient frame. Throws as both; FormatError when no segment has a voxel.
[[nodiscard]] scene::Scene loadDicomSegMeshes(const std::filesystem::path& file,
                                              const SurfaceOptions& options = {},
                                              const Progress& progress = {});

}  // namespace vv::segmentation
