// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// Re-segmenting a loaded volume on a worker thread: the Segmentation panel's
// live preview (a downsampled copy, coarse surface) and its Apply (full
// resolution). The pipeline itself is segmentation::runSegmentation().

#include <QObject>
#include <QString>
#include <cstddef>
#include <glm/glm.hpp>
#include <memory>
#include <optional>
#include <stop_token>

#include "gui/EngineTexts.h"
#include "gui/WorkerRun.h"
#include "vv/segmentation/SegmentationPipeline.h"

namespace vv::gui {

/// segmentation::runSegmentation() on a worker thread (QtConcurrent), never on the GUI
/// thread. Progress arrives through progressChanged() (queued, at most every
/// 50 ms per stage); exactly one of succeeded(), failed() or cancelled()
/// follows on the GUI thread, then finished(). cancel() stops the worker at
/// its next progress report (std::stop_source) and discards a result that
/// arrives anyway. The destructor cancels and waits for the worker.
class SegmentationTask : public QObject {
    Q_OBJECT

  public:
    explicit SegmentationTask(segmentation::SegmentationRequest request, QObject* parent = nullptr);

    /// Starts the worker; a second call does nothing.
    void start();
    void cancel() noexcept { run_.cancel(); }
    [[nodiscard]] bool isRunning() const { return run_.isRunning(); }
    [[nodiscard]] const segmentation::SegmentationRequest& request() const noexcept {
        return request_;
    }

  signals:
    void progressChanged(double fraction, const QString& stage);
    void succeeded(std::shared_ptr<const vv::segmentation::SegmentationOutcome> outcome);
    /// `problem`: why (describeProblem()).
    void failed(const vv::gui::ProblemText& problem);
    void cancelled();
    /// After succeeded(), failed() or cancelled().
    void finished();

  private:
    struct Result {
        std::shared_ptr<const segmentation::SegmentationOutcome> outcome;
        ProblemText problem;
        bool cancelled = false;
    };
    [[nodiscard]] Result work(std::stop_token stop);
    void deliver();

    segmentation::SegmentationRequest request_;
    WorkerRun<Result> run_;  ///< after request_: waits for the worker before it goes
};

}  // namespace vv::gui
