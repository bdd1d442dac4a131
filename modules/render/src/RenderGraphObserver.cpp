// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/render/RenderGraphObserver.h"

namespace vv::render {

void CpuPassTimer::beginFrame() {
    timings_.clear();
    running_.clear();
    start_.reset();
}

void CpuPassTimer::beginPass(std::string_view pass) {
    running_.assign(pass);
    start_ = Clock::now();
}

void CpuPassTimer::endPass(std::string_view pass) {
    if (!start_.has_value() || running_ != pass) {
        return;
    }
    const std::chrono::duration<double, std::milli> elapsed = Clock::now() - *start_;
    start_.reset();
    timings_.push_back(PassTiming{std::string(pass), elapsed.count()});
}

std::optional<double> CpuPassTimer::milliseconds(std::string_view pass) const noexcept {
    for (const PassTiming& timing : timings_) {
        if (timing.pass == pass) {
            return timing.milliseconds;
        }
    }
    return std::nullopt;
}

}  // namespace vv::render
