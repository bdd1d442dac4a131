// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <optional>

namespace vv::render {

/// What one interactive frame cost, as the frame budget (RefinementPolicy)
/// should see it: the work of this process's frame, not the time other
/// processes took the cores away from it.
///
/// The caller measures from the start of drawing to the swap of the window:
/// the wall time, and where it can the CPU time of the whole process and of
/// the thread that drew the frame (cpuTimesNow()), and on a hardware GPU the
/// GPU time of the frame's commands (timer queries).
struct FrameMeasurement {
    double wallMilliseconds = 0.0;
    /// CPU time of every thread of the process over the frame (software
    /// rasterisers' threads, the preview solve, the drawing thread).
    std::optional<double> processCpuMilliseconds;
    /// CPU time of the thread that drew the frame (its serial part).
    std::optional<double> threadCpuMilliseconds;
    /// GPU time of the frame's GL commands; only where the GL runs on a GPU.
    std::optional<double> gpuMilliseconds;
    /// The cores the process's other threads share (at least 1).
    int cores = 1;
    /// The GL rasterises on the CPU (llvmpipe, softpipe, SwiftShader): its
    /// work is CPU time of this process, and its timer queries measure wall
    /// time, not work.
    bool softwareGl = false;
};

/// The frame's cost in milliseconds, what it would take on the machine
/// with no other process running:
///  - with both CPU times: the drawing thread's CPU time (serial) plus the
///    other threads' CPU time spread over the cores, and with a GPU (not
///    softwareGl) at least the GPU time; without a GPU time on a hardware
///    GL, the wall time (the GPU's work is unknown);
///  - never more than the wall time (what a free machine cannot beat);
///  - without CPU times, the wall time.
/// Negative or non-finite inputs count as missing (the wall time as 0).
[[nodiscard]] double frameCostMilliseconds(const FrameMeasurement& frame) noexcept;

/// This process's and the calling thread's CPU time so far, in
/// milliseconds; nullopt where the platform does not tell.
struct CpuTimes {
    double processMilliseconds = 0.0;
    double threadMilliseconds = 0.0;
};
[[nodiscard]] std::optional<CpuTimes> cpuTimesNow() noexcept;

/// True when the GL_RENDERER string names a software rasteriser (llvmpipe,
/// softpipe, SwiftShader, Microsoft's GDI renderer).
[[nodiscard]] bool isSoftwareRenderer(const char* glRenderer) noexcept;

}  // namespace vv::render
