// SPDX-License-Identifier: GPL-3.0-or-later
#include "gui/StageProgress.h"

#include <algorithm>
#include <chrono>
#include <memory>
#include <mutex>
#include <string>
#include <utility>

#include "gui/EngineTexts.h"

namespace vv::gui {

namespace {

/// Progress signals of one stage at most this often.
constexpr std::chrono::milliseconds kProgressInterval{50};

struct Throttle {
    std::mutex lock;
    std::chrono::steady_clock::time_point last;
    std::string lastStage;
};

}  // namespace

Progress stageProgress(std::function<void(double, const QString&)> report, std::stop_token stop) {
    auto throttle = std::make_shared<Throttle>();
    return {[throttle, report = std::move(report)](double fraction, std::string_view stage) {
                const auto now = std::chrono::steady_clock::now();
                {
                    const std::lock_guard guard(throttle->lock);
                    if (stage == throttle->lastStage && now - throttle->last < kProgressInterval) {
                        return;
                    }
                    throttle->last = now;
                    throttle->lastStage = std::string(stage);
                }
                report(std::clamp(fraction, 0.0, 1.0),
                       translatedStage(
                           QString::fromUtf8(stage.data(), static_cast<qsizetype>(stage.size()))));
            },
            std::move(stop)};
}

}  // namespace vv::gui
