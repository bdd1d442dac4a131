// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/render/FrameCost.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <string_view>

#if defined(__unix__) || defined(__APPLE__)
#include <ctime>
#define VV_HAS_CPU_CLOCKS 1  // NOLINT(cppcoreguidelines-macro-usage): selects code, not a value
#endif

namespace vv::render {

namespace {

/// `value` when it is a finite time >= 0, else nullopt.
std::optional<double> valid(std::optional<double> value) {
    if (value && std::isfinite(*value) && *value >= 0.0) {
        return value;
    }
    return std::nullopt;
}

#ifdef VV_HAS_CPU_CLOCKS
std::optional<double> clockMilliseconds(clockid_t clock) {
    timespec now{};
    if (clock_gettime(clock, &now) != 0) {
        return std::nullopt;
    }
    return 1e3 * static_cast<double>(now.tv_sec) + 1e-6 * static_cast<double>(now.tv_nsec);
}
#endif

}  // namespace

double frameCostMilliseconds(const FrameMeasurement& frame) noexcept {
    const double wall = valid(frame.wallMilliseconds).value_or(0.0);
    const std::optional<double> process = valid(frame.processCpuMilliseconds);
    const std::optional<double> thread = valid(frame.threadCpuMilliseconds);
    const std::optional<double> gpu = valid(frame.gpuMilliseconds);
    if (!process || !thread || (!frame.softwareGl && !gpu)) {
        return wall;
    }
    // The drawing thread's part runs alone; the rest (a software
    // rasteriser's threads, the preview solve) shares the cores.
    const double serial = std::min(*thread, *process);
    double cost = serial + (*process - serial) / static_cast<double>(std::max(frame.cores, 1));
    if (!frame.softwareGl) {
        cost = std::max(cost, *gpu);
    }
    return std::min(cost, wall);
}

std::optional<CpuTimes> cpuTimesNow() noexcept {
#ifdef VV_HAS_CPU_CLOCKS
    const std::optional<double> process = clockMilliseconds(CLOCK_PROCESS_CPUTIME_ID);
    const std::optional<double> thread = clockMilliseconds(CLOCK_THREAD_CPUTIME_ID);
    if (process && thread) {
        return CpuTimes{*process, *thread};
    }
#endif
    return std::nullopt;
}

bool isSoftwareRenderer(const char* glRenderer) noexcept {
    if (glRenderer == nullptr) {
        return false;
    }
    const std::string_view name(glRenderer);
    constexpr std::array<std::string_view, 5> kSoftware = {"llvmpipe", "softpipe", "SwiftShader",
                                                           "Software Rasterizer", "GDI Generic"};
    return std::ranges::any_of(kSoftware, [&](std::string_view software) {
        return name.find(software) != std::string_view::npos;
    });
}

}  // namespace vv::render
