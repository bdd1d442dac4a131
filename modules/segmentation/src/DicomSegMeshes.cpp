// SPDX-License-Identifier: GPL-3.0-or-later
#include <cstddef>
#include <utility>
#include <vector>

#include "vv/core/Error.h"
#include "vv/dicom/DicomSeg.h"
#include "vv/segmentation/SceneSource.h"
#include "vv/segmentation/VolumeSurface.h"

namespace vv::segmentation {

scene::Scene loadDicomSegMeshes(const std::filesystem::path& file, const SurfaceOptions& options,
                                const Progress& progress) {
    const std::vector<scene::LabelMap> maps =
        dicom::loadDicomSegLabelMaps(file, progress.sub(0.0, 0.3));
    scene::Scene scene;
    scene.frame = scene::SceneFrame::PatientLps;
    std::size_t withVoxels = 0;
    for (const scene::LabelMap& map : maps) {
        withVoxels += map.components.front().voxels > 0 ? 1 : 0;
    }
    std::size_t done = 0;
    for (const scene::LabelMap& map : maps) {
        if (map.components.front().voxels == 0) {
            continue;
        }
        const double begin =
            0.3 + 0.7 * static_cast<double>(done) / static_cast<double>(withVoxels);
        ++done;
        const double end = 0.3 + 0.7 * static_cast<double>(done) / static_cast<double>(withVoxels);
        scene::Mesh mesh = extractSurface(map, {1}, options, progress.sub(begin, end));
        mesh.name = map.segmentNames.front();
        mesh.source = file;
        scene.meshes.push_back(std::move(mesh));
    }
    if (scene.meshes.empty()) {
        throw FormatError(file, "no segment has a voxel");
    }
    return scene;
}

}  // namespace vv::segmentation
