// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <filesystem>
#include <vector>

#include "vv/core/Progress.h"
#include "vv/io/Mesh.h"
#include "vv/io/SceneSource.h"

namespace vv::app {

/// Loads `files` into one scene, in order, as the GUI opens them: DICOM
/// sources (io::isDicomSource) segmented with `dicom` one by one, the meshes
/// with io::loadScene (as one batch when there is no DICOM source).
/// `report` (optional) says what loading the last DICOM source did.
/// Reports progress over all files. Throws as io::loadScene /
/// io::loadSceneSource (IoError, FormatError, ..., CancelledError).
[[nodiscard]] io::Scene loadSceneFiles(const std::vector<std::filesystem::path>& files,
                                       const io::SceneSourceOptions& dicom,
                                       const Progress& progress = {},
                                       io::SceneSourceReport* report = nullptr);

}  // namespace vv::app
