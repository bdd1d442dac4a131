// SPDX-License-Identifier: GPL-3.0-or-later
// A study folder's manifest (manifest.json, written by makeStimuli), read
// back for the runner: which images there are, what each shows, and which
// of its two markers is closer.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "vv/study/Results.h"

namespace vv::study {

/// A marker's pixel in its image (origin top left).
struct MarkerPixel {
    int x = 0;
    int y = 0;
};

/// One image of a study folder.
struct ManifestStimulus {
    std::string id;
    std::filesystem::path image;  ///< absolute: inside the folder's stimuli/ directory
    std::string scene;
    std::string condition;
    int pair = 1;  ///< the pair's number within its scene and block, from 1
    Block block = Block::Main;
    Side correctAnswer = Side::Left;  ///< the closer marker
    MarkerPixel left;
    MarkerPixel right;
};

struct StudyManifest {
    std::filesystem::path folder;
    std::string seed;  ///< as makeStimuli wrote it
    int width = 0;     ///< the images' size, px
    int height = 0;
    std::vector<std::string> conditions;  ///< in the manifest's order
    std::vector<ManifestStimulus> stimuli;

    /// The indices (into `stimuli`) of the block's images, in manifest order.
    [[nodiscard]] std::vector<std::size_t> indicesOf(Block block) const;
};

/// Reads `folder`/manifest.json (or the manifest file itself when given).
/// Throws StudyError naming the file and the problem: missing or unreadable,
/// larger than 16 MiB, not JSON, not the format "vesselview-study-1", a
/// stimulus with a field missing or of the wrong type, an id used twice, a
/// second image of a scene's pair in the same condition and block, a
/// condition the manifest does not list, an image path that is absolute or
/// leaves the folder's stimuli/ directory, an image that is missing, a marker
/// outside the image, or no main-block image at all. Manifests written
/// before training pairs existed (no "block") read as main-block images.
[[nodiscard]] StudyManifest readManifest(const std::filesystem::path& folder);

}  // namespace vv::study
