// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <array>
#include <cstddef>
#include <limits>

#include "vv/render/FrameCost.h"
#include "vv/render/FrameSettings.h"

namespace vv::render {

/// Progressive refinement of an interactive view, as plain logic (no GL, no
/// timers): the caller tells it what happens — the camera moved, the camera
/// settled, a frame was drawn, a moving frame took so long — and asks it
/// what the next frame is drawn with.
///
///  - Still: frames use the display settings as they are.
///  - Moving (a camera change with progressive refinement on, until
///    settle()): frames ask for a preview solve (VssSettings::preview), skip
///    the ambient occlusion and FXAA, draw the simplified geometry and run
///    at interactiveScale() of the full size (upscaled into the target),
///    their VSS solved and shaded at interactiveVssScale() of it.
///  - Settled (from settle() until a frame shows the exact VSS, or no VSS
///    at all): frames leave out the occlusion and FXAA, so the exact VSS
///    shows as early as it can; the frame that shows it asks for one more
///    frame, which adds them (Still again).
///
/// Dynamic resolution (a frame budget > 0): each moving frame's measured
/// cost (frameCostMilliseconds: CPU and GPU work, not wall time lost to
/// other processes) chooses the sizes of the next camera move's frames
/// among kScaleSteps / kVssScaleSteps (a preview VSS shows only at the size
/// it was solved at, so the sizes change only between moves). The policy
/// remembers what each step cost (the lower of its last two measurements,
/// so that one frame slowed by something else does not count; forgotten
/// kCostMemory measurements after that step was last measured) and
///  - steps down when the current step's last two measurements are both
///    over kStepDownFactor x the budget, or one is over kFarOverFactor x
///    (so the first, costlier frame at a new size — its framebuffers
///    are allocated then — does not push it further than it needs); from
///    kSmallestFaithfulStep down, only the latter (frames below it look
///    worse than a frame a little over the budget is slow);
///  - steps up when the step above is expected to fit the budget: its
///    remembered cost, or, not known, the current cost scaled by
///    kCostExponent of the steps' sizes (fitted on llvmpipe, where a frame
///    has a large part that does not shrink with the render size:
///    docs/benchmarks/render.md, "Moving frames, round 7");
///  - holds otherwise.
/// So it settles on the largest step that fits, and does not ping-pong
/// between a step that fits and one that does not. Down to 0.35, the VSS is
/// solved and shaded at the render size (the cheapest frames with SSIM >=
/// 0.9 against the settled frame are all at one size: docs/benchmarks/
/// render.md, "Moving frames, round 4"); below that, the VSS drops to a
/// quarter while the vessels keep the larger render size (sharper edges
/// than the VSS's size would give them), and only then does the render size
/// drop too.
class RefinementPolicy {
  public:
    enum class Phase { Still, Moving, Settled };

    /// The render scales dynamic resolution steps through, most expensive
    /// first, down to kMinInteractiveScale; kVssScaleSteps[i] is the scale
    /// the VSS of step i is solved and shaded at (of the full size, at most
    /// kScaleSteps[i]).
    static constexpr std::array<float, 10> kScaleSteps = {1.0F,  0.84F, 0.71F, 0.6F, 0.5F,
                                                          0.42F, 0.35F, 0.35F, 0.3F, 0.25F};
    static constexpr std::array<float, 10> kVssScaleSteps = {1.0F,  0.84F, 0.71F, 0.6F,  0.5F,
                                                             0.42F, 0.35F, 0.25F, 0.25F, 0.25F};
    static constexpr float kMinInteractiveScale = kScaleSteps.back();
    /// The default frame budget (ms of measured work per moving frame): a
    /// frame every 33 ms (30 fps) less the 2-4 ms of each frame interval
    /// outside the measured span on llvmpipe, less the ~10 % by which one
    /// view's frames cost more than another's (docs/benchmarks/render.md,
    /// "Moving frames, round 7").
    static constexpr double kDefaultFrameBudgetMs = 27.0;
    /// Step down when the remembered cost is over this times the budget.
    static constexpr double kStepDownFactor = 1.05;
    /// Step down at once when one frame costs over this times the budget.
    static constexpr double kFarOverFactor = 1.4;
    /// The smallest step whose moving frames stay at SSIM >= 0.9 against the
    /// settled frame on the bundled demo (0.42 / 0.42: docs/benchmarks/
    /// render.md, rounds 4 and 7): below it the sizes step down only for a
    /// frame over kFarOverFactor x the budget.
    static constexpr std::size_t kSmallestFaithfulStep = 5;
    /// A step's cost is expected to grow with its size to this power (the
    /// size: the mean of the render and VSS scales).
    static constexpr double kCostExponent = 0.7;
    /// A step's remembered cost is forgotten after this many measurements.
    static constexpr unsigned kCostMemory = 24;

    [[nodiscard]] Phase phase() const noexcept;
    /// True while the camera moves (frames use the preview VSS).
    [[nodiscard]] bool moving() const noexcept { return moving_; }
    /// True from settle() until the frame with the exact VSS is drawn.
    [[nodiscard]] bool occlusionDeferred() const noexcept { return deferOcclusion_; }

    /// Progressive refinement on (default) or off: off, camera changes never
    /// make the view move (every frame asks for the exact VSS). Turning it
    /// off does not settle a moving view: call settle() then.
    void setProgressive(bool on) noexcept { progressive_ = on; }
    [[nodiscard]] bool progressive() const noexcept { return progressive_; }

    /// Fixes the scale of moving frames to `scale`, clamped to [0.1, 1]
    /// (non-finite: 1), and their VSS's to `vssScale` (clamped to [0.1,
    /// scale]; non-finite, the default: `scale`), and turns the frame budget
    /// off.
    void setInteractiveScale(float scale,
                             float vssScale = std::numeric_limits<float>::quiet_NaN()) noexcept;
    /// The scale moving frames render at (with a budget: the one the last
    /// camera move chose, until the next move takes the newest choice).
    [[nodiscard]] float interactiveScale() const noexcept { return interactiveScale_; }
    /// The scale of the full size moving frames solve and shade their VSS
    /// at (at most interactiveScale(); chosen with it).
    [[nodiscard]] float interactiveVssScale() const noexcept { return interactiveVssScale_; }
    /// The frame budget in milliseconds (default kDefaultFrameBudgetMs); 0 =
    /// a fixed scale. Changing it forgets what the steps cost.
    /// Non-finite or negative values count as 0.
    void setFrameBudget(double milliseconds) noexcept;
    [[nodiscard]] double frameBudget() const noexcept { return frameBudgetMs_; }
    /// Forgets what the steps cost (the scene or the view's size changed):
    /// the next measurements choose from scratch.
    void forgetCosts() noexcept { stepCosts_ = {}; }

    /// The user changed the camera. Returns true when the view now moves
    /// (progressive refinement on): the caller (re)starts its settle timer.
    /// With a budget, the move takes the scale the last measurement chose.
    bool cameraMoved() noexcept;
    /// The camera stopped (button released, settle timer). Returns true when
    /// the view was moving: it is Settled now, and the caller starts the
    /// exact solve (ViewRenderer::settle) or draws a frame; false changes nothing.
    bool settle() noexcept;

    /// The settings of the next frame: `display` adjusted for the phase.
    [[nodiscard]] FrameSettings frameSettings(const FrameSettings& display) const noexcept;

    /// What follows a drawn frame (frameDrawn()).
    struct AfterFrame {
        /// A moving frame that showed a camera change with a budget set:
        /// measure its time (to the swap) and hand it to frameMeasured().
        bool measure = false;
        /// The frame showed a camera change (so it showed the newest preview).
        bool showedCameraMove = false;
        /// The exact VSS (or none) is on screen after settling: draw one more
        /// frame, which adds the occlusion and FXAA.
        bool occlusionFrame = false;
    };
    /// A frame drawn with frameSettings() showed a VSS with `status`.
    AfterFrame frameDrawn(const VssFrameStatus& status) noexcept;
    /// A measured moving frame (drawing to the swap) cost
    /// frameCostMilliseconds(`frame`): its own work, not the time other
    /// processes held the cores (a loaded machine does not push the sizes
    /// down). Chooses the scale of the next camera move (see the class
    /// comment).
    void frameMeasured(const FrameMeasurement& frame) noexcept;
    /// A measured moving frame known only by its wall time.
    void frameMeasured(double wallMilliseconds) noexcept {
        FrameMeasurement frame;
        frame.wallMilliseconds = wallMilliseconds;
        frameMeasured(frame);
    }
    /// The cost of the last measured frame (ms; 0 before any).
    [[nodiscard]] double lastFrameCost() const noexcept { return lastFrameCostMs_; }
    /// The scale the next camera move will take.
    [[nodiscard]] float nextInteractiveScale() const noexcept { return nextInteractiveScale_; }
    /// The scale the next camera move's VSS will take.
    [[nodiscard]] float nextInteractiveVssScale() const noexcept { return nextVssScale_; }

  private:
    /// What one step cost.
    struct StepCost {
        double last = 0.0;            ///< the last measurement
        double lowerOfLastTwo = 0.0;  ///< the lower of the last two
        unsigned samples = 0;         ///< 0: not known (or forgotten)
        unsigned long long when = 0;  ///< the measurement's number
    };
    static constexpr std::size_t kSteps = kScaleSteps.size();
    /// The step of the current scales (the first at or below them).
    [[nodiscard]] std::size_t currentStep() const noexcept;
    /// The remembered cost of `step`, or 0 when it is not known.
    [[nodiscard]] double rememberedCost(std::size_t step) const noexcept;
    /// What `to` is expected to cost, given that `from` costs `ms`.
    [[nodiscard]] double expectedCost(std::size_t to, std::size_t from, double ms) const noexcept;

    std::array<StepCost, kSteps> stepCosts_{};
    unsigned long long measurements_ = 0;
    bool progressive_ = true;
    bool moving_ = false;
    bool cameraMoved_ = false;     ///< the camera changed since the last frame
    bool deferOcclusion_ = false;  ///< settled, exact VSS not shown yet: no AO, no FXAA
    float interactiveScale_ = 0.5F;
    float interactiveVssScale_ = 0.5F;
    float nextInteractiveScale_ = 0.5F;
    float nextVssScale_ = 0.5F;
    double frameBudgetMs_ = kDefaultFrameBudgetMs;
    double lastFrameCostMs_ = 0.0;
};

}  // namespace vv::render
