// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QElapsedTimer>
#include <array>
#include <optional>

#include "vv/render/FrameCost.h"

class QOpenGLContext;
class QOpenGLFunctions_4_1_Core;

namespace vv::render {

/// Measures interactive frames for the frame budget (RefinementPolicy):
/// from the start of drawing to the swap of the window, the wall time, the
/// process's and the drawing thread's CPU time and, on a hardware GPU, the
/// GPU time of the frame's commands (GL timestamp queries). The caller
/// hands the result to RefinementPolicy::frameMeasured, which takes the
/// frame's cost from it (frameCostMilliseconds).
///
/// Use from the thread that draws. initialize(), release(), beginFrame()
/// and endFrame() need the frame's GL context current; atSwap() does not.
class FrameMeter {
  public:
    FrameMeter();
    FrameMeter(const FrameMeter&) = delete;
    FrameMeter& operator=(const FrameMeter&) = delete;
    FrameMeter(FrameMeter&&) = delete;
    FrameMeter& operator=(FrameMeter&&) = delete;
    ~FrameMeter();

    /// Reads the renderer (software rasteriser or GPU) and, on a GPU,
    /// makes the timer queries (when the GL times at all). May be called
    /// again for a new context (after release()).
    void initialize();
    /// Deletes the queries (the context current, or never made).
    void release() noexcept;
    /// True when the GL rasterises on the CPU (its work is CPU time).
    [[nodiscard]] bool softwareGl() const noexcept { return softwareGl_; }

    /// Drawing a frame starts: the clocks are read (and a GPU timestamp).
    void beginFrame();
    /// The frame's GL commands are issued. `measure`: this frame's
    /// measurement is kept for atSwap() (on a GPU this waits for the
    /// frame's GPU time); otherwise it is dropped.
    void endFrame(bool measure);
    /// The window showing the frame was swapped: the kept frame's
    /// measurement, once (nullopt when none is kept).
    [[nodiscard]] std::optional<FrameMeasurement> atSwap();

  private:
    QElapsedTimer clock_;
    QOpenGLContext* context_ = nullptr;
    QOpenGLFunctions_4_1_Core* gl_ = nullptr;
    bool softwareGl_ = false;
    std::array<unsigned, 2> queries_{};  ///< GPU timestamps: begin, end (0: none)
    bool queried_ = false;               ///< the begin timestamp of this frame was issued
    qint64 startNs_ = 0;
    std::optional<CpuTimes> startCpu_;
    std::optional<double> gpuMs_;
    bool kept_ = false;
};

}  // namespace vv::render
