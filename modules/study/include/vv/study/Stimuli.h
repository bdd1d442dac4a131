// SPDX-License-Identifier: GPL-3.0-or-later
// The study's stimuli (issue 34, the paper's "Stimuli"): for each scene, its
// marker pairs (MarkerPairs.h, from the G-buffer's depth of the view), and
// for each pair and condition an image with the two markers; a study folder
// with the images and a manifest that the runner and the analysis read.
#pragma once

#include <QImage>
#include <QPoint>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "vv/core/Progress.h"
#include "vv/render/DisplaySettings.h"
#include "vv/render/OffscreenRenderer.h"
#include "vv/scene/Mesh.h"
#include "vv/study/MarkerPairs.h"
#include "vv/study/Results.h"

namespace vv::study {

/// A display condition: its name in the results and the settings it shows.
struct StimulusCondition {
    std::string name;
    render::DisplaySettings display;
    /// How the settings were given (`study make --condition`'s text), for
    /// the manifest; empty for the paper's conditions.
    std::string settings;
};

/// The paper's five conditions: VSS-CD and VSS-PCD (the VSS in chromadepth /
/// pseudo-chromadepth, the vessels plain), vessel-CD and vessel-PCD (no VSS,
/// the vessels in chromadepth / pseudo-chromadepth), baseline (neither).
/// Iso-lines, ambient occlusion, legends and annotations are off in all of
/// them (each a cue of its own, added as a condition of its own).
[[nodiscard]] std::vector<StimulusCondition> paperConditions();

struct StimulusScene {
    std::string name;    ///< in file names and the manifest
    std::string source;  ///< what the scene was loaded from (the manifest says it)
    scene::Scene scene;
};

struct StimulusOptions {
    int width = 1280;
    int height = 720;
    std::size_t pairsPerScene = 5;  ///< the paper: 5 pairs per model
    /// Further pairs per scene for the training phase (never shown in the
    /// main block); 0 for none.
    std::size_t trainingPairsPerScene = 1;
    std::uint64_t seed = 1;
    PairCriteria criteria;
};

/// One image of the study.
struct Stimulus {
    std::string id;     ///< "<scene>-p<pair>-<condition>" ("-t<pair>-" for training)
    std::string image;  ///< its file, relative to the study folder
    std::string scene;
    std::string condition;
    std::size_t pair = 0;  ///< the pair's index within its scene and block
    MarkerPair markers;
    Block block = Block::Main;
};

struct StudyStimuli {
    std::vector<Stimulus> stimuli;
    std::vector<std::string> notes;  ///< the pair picker's, per scene
};

/// Draws the paper's marker at `centre`: a cross of four separated arms
/// (white, a black border) around a gap that leaves the marked point itself
/// visible; `radius` is the arms' outer reach, px.
void drawMarker(QImage& image, QPoint centre, int radius);

/// Makes the stimuli of `scenes` x `conditions` into `folder` (created when
/// missing): `folder`/stimuli/<id>.png and `folder`/manifest.json (the
/// options, the conditions, each scene's camera and its pairs, each
/// stimulus with its markers' pixels and depths, the answer and the
/// criteria' values), every file written atomically. Every condition of a
/// scene is rendered from the same camera (the scene's home view fitted).
/// A scene's training pairs are picked after its main pairs, from the same
/// image, so that they never repeat a main pair; a scene short of pairs
/// gives its main block what it has first.
/// Progress per image; a stop request throws CancelledError. Throws
/// InvalidArgumentError for no scenes, no conditions, duplicate names or an
/// image size out of range, StudyError when a scene gives no pair, IoError
/// naming a file that cannot be written, RenderError without OpenGL.
StudyStimuli makeStimuli(render::OffscreenRenderer& renderer,
                         const std::vector<StimulusScene>& scenes,
                         const std::vector<StimulusCondition>& conditions,
                         const StimulusOptions& options, const std::filesystem::path& folder,
                         const Progress& progress = {});

}  // namespace vv::study
