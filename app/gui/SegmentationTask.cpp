// SPDX-License-Identifier: GPL-3.0-or-later
#include "gui/SegmentationTask.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>
#include <limits>
#include <mutex>
#include <string>
#include <utility>

#include "gui/EngineTexts.h"
#include "vv/core/Error.h"

namespace vv::gui {

namespace {

/// Progress signals of one stage at most this often.
constexpr std::chrono::milliseconds kProgressInterval{50};

}  // namespace

SegmentationTask::SegmentationTask(segmentation::SegmentationRequest request, QObject* parent)
    : QObject(parent), request_(std::move(request)) {
    connect(&run_.watcher(), &QFutureWatcher<Result>::finished, this, &SegmentationTask::deliver);
}

void SegmentationTask::start() {
    run_.start([this](std::stop_token stop) { return work(std::move(stop)); });
}

SegmentationTask::Result SegmentationTask::work(std::stop_token stop) {
    // Worker thread: reads request_ (immutable while running), emits
    // progressChanged (queued to the GUI thread).
    Result result;
    std::mutex lock;
    auto last = std::chrono::steady_clock::time_point{};
    std::string lastStage;
    const Progress progress(
        [this, &lock, &last, &lastStage](double fraction, std::string_view stage) {
            const auto now = std::chrono::steady_clock::now();
            const std::lock_guard guard(lock);
            if (stage == lastStage && now - last < kProgressInterval) {
                return;
            }
            last = now;
            lastStage = std::string(stage);
            emit progressChanged(std::clamp(fraction, 0.0, 1.0),
                                 translatedStage(QString::fromUtf8(
                                     stage.data(), static_cast<qsizetype>(stage.size()))));
        },
        std::move(stop));
    try {
        result.outcome = std::make_shared<const segmentation::SegmentationOutcome>(
            segmentation::runSegmentation(request_, progress));
    } catch (const CancelledError&) {
        result.cancelled = true;
    } catch (const std::exception& e) {
        result.problem = describeProblem(e, FileAccess::Reading);
    }
    return result;
}

void SegmentationTask::deliver() {
    const Result result = run_.result();
    if (result.cancelled || run_.stopRequested()) {
        emit cancelled();
    } else if (result.outcome) {
        emit succeeded(result.outcome);
    } else {
        emit failed(result.problem);
    }
    emit finished();
}

}  // namespace vv::gui
