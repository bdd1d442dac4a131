// SPDX-License-Identifier: GPL-3.0-or-later
#include "common/SceneFiles.h"

#include <algorithm>
#include <utility>

#include "vv/io/MeshLoader.h"

namespace vv::app {

io::Scene loadSceneFiles(const std::vector<std::filesystem::path>& files,
                         const io::SceneSourceOptions& dicom, const Progress& progress,
                         io::SceneSourceReport* report) {
    if (std::none_of(files.begin(), files.end(),
                     [](const auto& f) { return io::isDicomSource(f); })) {
        return io::loadScene(files, {}, progress);
    }
    // DICOM sources are segmented one by one; meshes load as before.
    io::Scene scene;
    const auto n = static_cast<double>(files.size());
    for (std::size_t i = 0; i < files.size(); ++i) {
        const Progress part =
            progress.sub(static_cast<double>(i) / n, static_cast<double>(i + 1) / n);
        io::SceneSourceReport loaded;
        const bool dicomSource = io::isDicomSource(files[i]);
        io::Scene one = dicomSource ? io::loadSceneSource(files[i], dicom, part, &loaded)
                                    : io::loadScene({files[i]}, {}, part);
        if (dicomSource && report != nullptr) {
            *report = std::move(loaded);
        }
        for (auto& mesh : one.meshes) {
            scene.meshes.push_back(std::move(mesh));
        }
    }
    return scene;
}

}  // namespace vv::app
