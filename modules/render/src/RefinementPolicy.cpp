// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/render/RefinementPolicy.h"

#include <algorithm>
#include <cmath>

namespace vv::render {

RefinementPolicy::Phase RefinementPolicy::phase() const noexcept {
    if (moving_) {
        return Phase::Moving;
    }
    return deferOcclusion_ ? Phase::Settled : Phase::Still;
}

void RefinementPolicy::setInteractiveScale(float scale, float vssScale) noexcept {
    frameBudgetMs_ = 0.0;  // a fixed scale
    interactiveScale_ = std::isfinite(scale) ? std::clamp(scale, 0.1F, 1.0F) : 1.0F;
    interactiveVssScale_ =
        std::isfinite(vssScale) ? std::clamp(vssScale, 0.1F, interactiveScale_) : interactiveScale_;
    nextInteractiveScale_ = interactiveScale_;
    nextVssScale_ = interactiveVssScale_;
}

void RefinementPolicy::setFrameBudget(double milliseconds) noexcept {
    frameBudgetMs_ = std::isfinite(milliseconds) ? std::max(milliseconds, 0.0) : 0.0;
    forgetCosts();  // what fitted one budget says nothing about another
}

bool RefinementPolicy::cameraMoved() noexcept {
    if (!progressive_) {
        return false;
    }
    moving_ = true;
    cameraMoved_ = true;  // this frame may set the next move's size
    if (frameBudgetMs_ > 0.0) {
        interactiveScale_ = nextInteractiveScale_;
        interactiveVssScale_ = nextVssScale_;
    }
    return true;
}

bool RefinementPolicy::settle() noexcept {
    if (!moving_) {
        return false;
    }
    moving_ = false;
    deferOcclusion_ = true;  // the exact VSS first, the occlusion in the frame after
    return true;
}

FrameSettings RefinementPolicy::frameSettings(const FrameSettings& display) const noexcept {
    FrameSettings settings = display;
    if (moving_) {
        // Preview while the camera moves: a quicker solve, no occlusion, no
        // FXAA (a reduced render size is upscaled instead), a reduced render
        // size, a VSS below it and the simplified geometry.
        settings.vss.preview = true;
        settings.ao.enabled = false;
        settings.antialiasing = false;
        settings.resolutionScale = interactiveScale_;
        // The VSS's size relative to the render size.
        settings.vssResolutionScale = interactiveVssScale_ / interactiveScale_;
        settings.simplifiedGeometry = true;
    } else if (deferOcclusion_) {
        // Until the exact VSS is on screen: without the occlusion and FXAA
        // (~120 ms and ~20 ms at 720p on llvmpipe), which the next frame adds.
        settings.ao.enabled = false;
        settings.antialiasing = false;
    }
    return settings;
}

RefinementPolicy::AfterFrame RefinementPolicy::frameDrawn(const VssFrameStatus& status) noexcept {
    AfterFrame after;
    // Dynamic resolution: this frame's time sets the size of the next camera
    // move's frames. Frames in between (a preview solve arrived) keep this
    // size: the preview was solved at it.
    after.measure = moving_ && cameraMoved_ && frameBudgetMs_ > 0.0;
    after.showedCameraMove = cameraMoved_;
    cameraMoved_ = false;
    if (deferOcclusion_ && !moving_ && !status.pending && !status.preview) {
        // The exact VSS (or no VSS at all) is on screen: now the occlusion.
        deferOcclusion_ = false;
        after.occlusionFrame = true;
    }
    return after;
}

std::size_t RefinementPolicy::currentStep() const noexcept {
    for (std::size_t i = 0; i < kSteps; ++i) {
        if (kScaleSteps[i] <= interactiveScale_ + 1e-4F &&
            kVssScaleSteps[i] <= interactiveVssScale_ + 1e-4F) {
            return i;
        }
    }
    return kSteps - 1;
}

double RefinementPolicy::rememberedCost(std::size_t step) const noexcept {
    const StepCost& cost = stepCosts_[step];
    const bool known = cost.samples > 0 && measurements_ - cost.when < kCostMemory;
    return known ? cost.lowerOfLastTwo : 0.0;
}

double RefinementPolicy::expectedCost(std::size_t to, std::size_t from, double ms) const noexcept {
    if (const double remembered = rememberedCost(to); remembered > 0.0) {
        return remembered;
    }
    const auto size = [](std::size_t step) {
        return 0.5 *
               (static_cast<double>(kScaleSteps[step]) + static_cast<double>(kVssScaleSteps[step]));
    };
    return ms * std::pow(size(to) / size(from), kCostExponent);
}

void RefinementPolicy::frameMeasured(const FrameMeasurement& frame) noexcept {
    const double milliseconds = frameCostMilliseconds(frame);
    lastFrameCostMs_ = milliseconds;
    ++measurements_;
    std::size_t step = currentStep();
    StepCost& cost = stepCosts_[step];
    if (rememberedCost(step) > 0.0) {
        cost.lowerOfLastTwo = std::min(cost.last, milliseconds);
        ++cost.samples;
    } else {
        cost.lowerOfLastTwo = milliseconds;
        cost.samples = 1;
    }
    cost.last = milliseconds;
    cost.when = measurements_;
    // Too slow: two frames in a row over the budget (one costly frame, such
    // as the first at a new size, is not enough), or one far over it. Below
    // the smallest step at SSIM >= 0.9 only a frame far over the budget
    // counts: a frame a little over it is not worth a frame that looks
    // worse (most of such a frame's cost does not shrink with the size).
    const bool farOver = milliseconds > kFarOverFactor * frameBudgetMs_;
    const bool over = cost.samples >= 2 && cost.lowerOfLastTwo > kStepDownFactor * frameBudgetMs_;
    const bool tooSlow = farOver || (over && step < kSmallestFaithfulStep);
    if (tooSlow) {
        step = std::min(step + 1, kSteps - 1);
    } else if (step > 0 && expectedCost(step - 1, step, cost.lowerOfLastTwo) <= frameBudgetMs_) {
        --step;  // the larger step is expected to fit
    }
    nextInteractiveScale_ = kScaleSteps[step];
    nextVssScale_ = kVssScaleSteps[step];
}

}  // namespace vv::render
