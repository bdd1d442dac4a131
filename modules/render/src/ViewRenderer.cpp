// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/render/ViewRenderer.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <utility>

#include "vv/core/Error.h"

namespace vv::render {

void ViewRenderer::initialize() {
    frame_.initialize();
    // A new context has none of the earlier one's objects.
    uploaded_.reset();
    sceneDirty_ = true;
    styleDirty_ = true;
}

void ViewRenderer::setScene(std::shared_ptr<const scene::Scene> scene) {
    scene_ = std::move(scene);
    labelCache_.invalidate();
    content_.reset();
    revision_ = ++nextRevision_;
    sceneDirty_ = true;
    previews_ = {};
    refined_ = {};
    closures_.clear();
    closuresKnown_ = false;
    closuresDirty_ = false;
}

void ViewRenderer::setScene(std::shared_ptr<const scene::Scene> scene, std::uint64_t content) {
    if (uploaded_ && *uploaded_ == content && scene != nullptr) {
        // The content on the GPU: its meshes, levels and closures stay.
        scene_ = std::move(scene);
        content_ = content;
        revision_ = content;
        sceneDirty_ = true;  // attached by the next frame
        return;
    }
    setScene(std::move(scene));
    content_ = content;
    revision_ = content;
}

void ViewRenderer::detachScene() noexcept {
    frame_.meshRenderer().detachScene();
    scene_.reset();
    sceneDirty_ = false;
    // No scene: a frame now draws nothing, not the last G-buffer. Attaching
    // the same content again restores the revision (the cache holds).
    revision_ = ++nextRevision_;
    frame_.setSceneRevision(revision_);
}

bool ViewRenderer::uploadScene() {
    if (!sceneDirty_) {
        return false;
    }
    MeshRenderer& meshes = frame_.meshRenderer();
    const bool attach = content_ && uploaded_ == content_ && scene_ != nullptr;
    if (attach) {
        meshes.attachScene(scene_);
    } else {
        uploaded_.reset();
        meshes.setScene(scene_);
        uploaded_ = scene_ ? content_ : std::nullopt;
        previewDirty_ = true;
        refinedDirty_ = true;
        closuresDirty_ = closuresKnown_;  // the upload left every mesh Open
    }
    frame_.setSceneRevision(revision_);
    sceneDirty_ = false;
    styleDirty_ = true;
    return !attach;
}

void ViewRenderer::setPreviewGeometry(PreviewGeometry geometry) {
    previews_ = std::move(geometry);
    previewDirty_ = true;
}

void ViewRenderer::setRefinedGeometry(RefinedGeometry geometry) {
    refined_ = std::move(geometry);
    refinedDirty_ = true;
}

std::vector<std::size_t> ViewRenderer::previewLevelTriangles() const {
    std::vector<std::size_t> levels;
    for (const auto& preview : previews_.scenes) {
        levels.push_back(preview->triangleCount());
    }
    return levels;
}

void ViewRenderer::setSurfaceClosures(std::vector<scene::SurfaceClosure> closures) {
    closures_ = std::move(closures);
    closuresKnown_ = true;
    closuresDirty_ = true;  // the next frame culls; this one's pixels stay right
}

void ViewRenderer::setVolume(std::shared_ptr<const scene::Volume> volume, float isoValue) {
    isoValue_ = isoValue;
    nearest_.reset();
    frame_.setVolume(std::move(volume), isoValue);  // uploads lazily, no context needed
}

Aabb ViewRenderer::dataBounds() const noexcept {
    Aabb box = scene_ ? scene_->bounds() : Aabb{};
    if (const auto& volume = frame_.volume(); volume && !volume->empty()) {
        box.extend(volume->worldBounds());
    }
    return box;
}

void ViewRenderer::setStyle(const MeshStyle& style) {
    style_ = style;
    styleDirty_ = true;
}

void ViewRenderer::setDisplay(const DisplaySettings& display) {
    setStyle(display.style);
    display_ = render::frameSettings(display);  // not the member frameSettings()
}

void ViewRenderer::prepareFrame() {
    MeshRenderer& meshes = frame_.meshRenderer();
    uploadScene();
    if (previewDirty_) {
        meshes.setPreviewScenes(previews_.scenes);
        for (std::size_t level = 0; level < previews_.closures.size(); ++level) {
            meshes.setSurfaceClosures(level + 1, previews_.closures[level]);
        }
        previewDirty_ = false;
    }
    if (refinedDirty_) {
        meshes.setRefinedScene(scene_ ? refined_.scene : nullptr, refined_.sourceEdgeMm);
        refinedDirty_ = false;
        closuresDirty_ = closuresKnown_;  // the refined copy's meshes start Open
    }
    if (closuresDirty_ && scene_) {
        // Subdivision keeps a surface closed or open: the copy culls as the scene.
        meshes.setSurfaceClosures(0, closures_);
        if (meshes.hasRefinedScene()) {
            meshes.setSurfaceClosures(kRefinedLevel, closures_);
        }
        closuresDirty_ = false;
    }
    if (styleDirty_) {
        meshes.setStyle(style_);
        styleDirty_ = false;
    }
}

RefinementPolicy::AfterFrame ViewRenderer::render(const Camera& camera, const FrameTarget& target) {
    prepareFrame();
    const FrameSettings settings = frameSettings();
    frame_.render(camera, settings, target);
    lastSettings_ = settings;
    ++frames_;
    if (recordTimings_) {
        timings_ = frame_.lastTimings();
    }
    return refinement_.frameDrawn(frame_.vssStatus());
}

Image<float> ViewRenderer::renderDepth(const Camera& camera, const FrameTarget& target) {
    prepareFrame();
    return frame_.renderDepth(camera, frameSettings(), target);
}

SettleResult ViewRenderer::settle(const Camera& camera, const FrameTarget& target,
                                  const std::function<void()>& makeCurrent) {
    const auto start = std::chrono::steady_clock::now();
    SettleResult result = SettleResult::None;
    try {
        // The last preview frame read back the depth of this very view (same
        // camera, same render size): start the exact solve now, and let its
        // arrival draw the one frame that shows it.
        if (frame_.requestSolve(camera, frameSettings(), target)) {
            result = SettleResult::Requested;
        } else {
            // The last frame was smaller or drew the simplified meshes: draw
            // only this view's full G-buffer and start its solve; the solve's
            // arrival draws the frame (its G-buffer then cached).
            makeCurrent();
            if (frame_.prepareSolve(camera, frameSettings(), target)) {
                result = SettleResult::Prepared;
            }
        }
    } catch (const vv::Error&) {
        result = SettleResult::None;  // the next frame reports the problem
    }
    if (result == SettleResult::Requested) {
        ++requested_;
    } else if (result == SettleResult::Prepared) {
        ++prepared_;
    }
    settleMilliseconds_ =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    return result;
}

std::optional<ViewProbe> ViewRenderer::probe(const Camera& camera, int x, int y) {
    const std::optional<ProbeSample> sample = frame_.probe(camera, x, y);
    if (!sample) {
        return std::nullopt;
    }
    if (!nearest_ || nearest_->first != frames_) {
        const auto range = frame_.visibleDepthRange();
        nearest_.emplace(frames_, range ? std::optional<float>(range->first) : std::nullopt);
    }
    const std::size_t meshCount = scene_ ? scene_->meshes.size() : 0U;
    const bool volumeShown = frame_.volume() != nullptr;
    if (sample->objectId == 0 || sample->objectId > meshCount + (volumeShown ? 1U : 0U)) {
        return std::nullopt;
    }
    ViewProbe result;
    result.linearDepth = sample->linearDepth;
    result.depthBelowNearest =
        std::max(0.0F, sample->linearDepth - nearest_->second.value_or(sample->linearDepth));
    result.depthReference = depthReference(lastSettings_.vss);
    result.worldPosition = sample->worldPosition;
    result.value = std::numeric_limits<float>::quiet_NaN();
    if (sample->objectId > meshCount) {
        return result;  // the ray-cast volume (1 + mesh count): position and depth, no value
    }
    const std::size_t index = sample->objectId - 1U;
    result.meshIndex = static_cast<int>(index);
    // The array this object shows (its own choice or the scene's).
    result.arrayName = style_.arrayOf(index);
    if (result.arrayName.empty()) {
        return result;
    }
    if (const scene::DataArray* values = scene_->meshes[index].pointArray(result.arrayName)) {
        result.unit = values->unit;
    }
    result.value = sample->value;
    if (const std::vector<scene::Label>* labels =
            labelsOf(labelCache_.get(*scene_, style_), result.arrayName);
        labels != nullptr && std::isfinite(result.value)) {
        for (const scene::Label& label : *labels) {
            if (static_cast<float>(label.value) == result.value) {
                result.label = label;
            }
        }
    }
    return result;
}

Legends ViewRenderer::legends() const {
    return legendsFor(scene_.get(), style_, shownRange(), lastSettings_, frame_.vssStatus(),
                      frame_.lastCueDepthRange(),
                      scene_ ? &labelCache_.get(*scene_, style_) : nullptr);
}

}  // namespace vv::render
