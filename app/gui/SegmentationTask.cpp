// SPDX-License-Identifier: GPL-3.0-or-later
#include "gui/SegmentationTask.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>
#include <limits>
#include <string>
#include <utility>

#include "gui/EngineTexts.h"
#include "gui/StageProgress.h"
#include "vv/core/Error.h"

namespace vv::gui {

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
    const Progress progress = stageProgress(
        [this](double fraction, const QString& stage) { emit progressChanged(fraction, stage); },
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
