// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <chrono>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace vv::render {

/// Hooks around every pass that RenderGraph::execute() runs (not around
/// culled passes, nor around cached passes it skips). The GL renderer's
/// observer pushes a debug group named after the pass and brackets it with
/// timer queries. Calls come in order: beginFrame, then balanced
/// beginPass/endPass pairs (endPass also when the pass throws; an exception
/// from that endPass is swallowed so the pass's own error propagates), then
/// endFrame (not called when a pass threw).
class PassObserver {
  public:
    virtual ~PassObserver() = default;

    virtual void beginFrame() {}
    virtual void beginPass(std::string_view pass) = 0;
    virtual void endPass(std::string_view pass) = 0;
    virtual void endFrame() {}

  protected:
    PassObserver() = default;
    PassObserver(const PassObserver&) = default;
    PassObserver& operator=(const PassObserver&) = default;
    PassObserver(PassObserver&&) = default;
    PassObserver& operator=(PassObserver&&) = default;
};

/// The time one pass took in one frame.
struct PassTiming {
    std::string pass;
    double milliseconds = 0.0;
};

/// A PassObserver that measures wall-clock (CPU) time with std::chrono's
/// steady clock. For GL passes this is submission time, not GPU time.
class CpuPassTimer final : public PassObserver {
  public:
    /// Forgets the previous frame's timings.
    void beginFrame() override;
    void beginPass(std::string_view pass) override;
    /// Records the time since the matching beginPass(); ignored without one.
    void endPass(std::string_view pass) override;

    /// The passes timed since the last beginFrame(), in execution order.
    [[nodiscard]] const std::vector<PassTiming>& timings() const noexcept { return timings_; }
    /// The time of `pass` in this frame; nullopt if it was not timed.
    [[nodiscard]] std::optional<double> milliseconds(std::string_view pass) const noexcept;

  private:
    using Clock = std::chrono::steady_clock;

    std::vector<PassTiming> timings_;
    std::string running_;
    std::optional<Clock::time_point> start_;
};

}  // namespace vv::render
