// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// The vessel analysis of the shown surface on a worker thread: the Analysis
// panel's "Find centrelines" (issue 35). The analysis itself is
// analysis::analyseVessels().

#include <QObject>
#include <QString>
#include <memory>
#include <stop_token>

#include "gui/EngineTexts.h"
#include "gui/WorkerRun.h"
#include "vv/analysis/Sections.h"
#include "vv/scene/Mesh.h"

namespace vv::gui {

/// analysis::analyseVessels() of the first mesh of `scene` on a worker thread
/// (QtConcurrent), never on the GUI thread. Progress arrives through
/// progressChanged() (queued, at most every 50 ms per stage, the stage in the
/// UI language); exactly one of succeeded(), failed() or cancelled() follows
/// on the GUI thread, then finished(). cancel() stops the worker at its next
/// progress report and discards a result that arrives anyway. The destructor
/// cancels and waits for the worker. The scene is shared, never modified.
class AnalysisTask : public QObject {
    Q_OBJECT

  public:
    AnalysisTask(std::shared_ptr<const scene::Scene> scene, analysis::CenterlineOptions options,
                 QObject* parent = nullptr);

    /// Starts the worker; a second call does nothing.
    void start();
    void cancel() noexcept { run_.cancel(); }
    [[nodiscard]] bool isRunning() const { return run_.isRunning(); }
    /// How long the worker took (wall seconds), once finished() came.
    [[nodiscard]] double workSeconds() const noexcept { return workSeconds_; }

  signals:
    void progressChanged(double fraction, const QString& stage);
    void succeeded(std::shared_ptr<const vv::analysis::VesselAnalysis> analysis);
    /// `problem`: why (describeProblem(); an analysis::AnalysisError says
    /// what the surface lacks).
    void failed(const vv::gui::ProblemText& problem);
    void cancelled();
    /// After succeeded(), failed() or cancelled().
    void finished();

  private:
    struct Result {
        std::shared_ptr<const analysis::VesselAnalysis> analysis;
        ProblemText problem;
        bool cancelled = false;
        double seconds = 0.0;
    };
    [[nodiscard]] Result work(std::stop_token stop);
    void deliver();

    std::shared_ptr<const scene::Scene> scene_;
    analysis::CenterlineOptions options_;
    double workSeconds_ = 0.0;
    WorkerRun<Result> run_;  ///< after what the work reads: waits for the worker before they go
};

}  // namespace vv::gui
