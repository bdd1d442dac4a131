// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QDialog>
#include <QObject>
#include <QSize>
#include <QString>
#include <QStringList>
#include <functional>
#include <memory>
#include <stop_token>
#include <thread>

#include "gui/EngineTexts.h"
#include "vv/core/Progress.h"
#include "vv/render/OffscreenRenderer.h"

class QMainWindow;
class QOffscreenSurface;
class QWidget;

namespace vv::gui {

class ViewerWidget;

/// Offscreen options that reproduce what `viewer` shows: its camera,
/// ray-cast volume and display settings (displaySettings(): background, mesh
/// style with array, colour map, range and bins, VSS with the exact solve,
/// never the preview, vessel cue, ambient occlusion, FXAA, orientation marker
/// and scale bar), at width x height pixels. Legends are left to
/// report::renderView().
/// With the depth range "Visible vessels", an export framed as the view (the
/// same aspect) takes the settled view's range as a fixed one, so that its
/// depth colours and legend are the screen's: at another resolution a few
/// vessel pixels more or less (a vessel seen end-on) would move it. That range
/// is marked vss::DepthRange::pinnedVisible, so its legend keeps the screen's
/// title and numbers (depth behind the frontmost vessel), not a user's fixed
/// range's (viewing distance).
[[nodiscard]] render::OffscreenOptions currentViewOptions(const ViewerWidget& viewer, int width,
                                                          int height);

/// The viewer's size in device pixels (what "View size" exports).
[[nodiscard]] QSize viewPixelSize(const ViewerWidget& viewer);

/// A window-modal, non-blocking warning box over `parent` (object name
/// "exportProblemBox") for a dialog field that is wrong.
void showExportProblem(QWidget* parent, const QString& title, const QString& message);

/// Runs one export job on its own worker thread, never on the GUI thread.
///
/// start() creates the OffscreenSurface on the GUI thread (Qt requires it
/// there) and starts a std::jthread that makes an OffscreenRenderer on that
/// surface (its OpenGL context is created and current on the worker), runs
/// the job and destroys the renderer there (a FileJob gets neither: it only
/// runs on the std::jthread). Progress arrives through
/// progressChanged() (queued, throttled); then exactly one of succeeded(),
/// failed() or cancelled(), and finished(), all on the GUI thread. cancel()
/// asks the job to stop at its next progress report. The destructor cancels
/// and waits for the worker (at most the step running), then frees the
/// surface on the GUI thread.
class ExportWorker : public QObject {
    Q_OBJECT

  public:
    /// Runs on the worker with a renderer of that thread; returns the status
    /// bar message. Throws vv::Error (CancelledError when stopped).
    using Job =
        std::function<QString(render::OffscreenRenderer& renderer, const Progress& progress)>;
    /// A job that renders nothing (it writes files from data): no OpenGL
    /// surface or context is made for it.
    using FileJob = std::function<QString(const Progress& progress)>;

    ExportWorker(QString description, Job job, QObject* parent = nullptr);
    ExportWorker(QString description, FileJob job, QObject* parent = nullptr);
    ~ExportWorker() override;
    ExportWorker(const ExportWorker&) = delete;
    ExportWorker& operator=(const ExportWorker&) = delete;
    ExportWorker(ExportWorker&&) = delete;
    ExportWorker& operator=(ExportWorker&&) = delete;

    /// Starts the worker (call on the GUI thread); a second call does nothing.
    void start();
    /// Asks the job to stop; cancelled() follows unless it already finished.
    void cancel();
    [[nodiscard]] bool isRunning() const noexcept { return running_; }
    /// What the job does, for the progress dialog ("Exporting view.png").
    [[nodiscard]] const QString& description() const noexcept { return description_; }
    /// Why the job failed, once failed() came (describeProblem()).
    [[nodiscard]] const ProblemText& problem() const noexcept { return problem_; }

    /// A window-modal progress dialog with Cancel for `worker` (deleted with
    /// it), and the outcome in `window`: a status bar message on success, a
    /// message box naming the file and the problem on failure. The worker
    /// deletes itself when finished.
    static void watch(ExportWorker* worker, QMainWindow* window);
    /// A started worker for `job`, owned by `dialog`'s parent (the main
    /// window, which watch()es it) so that it outlives the dialog.
    static ExportWorker* launch(QString description, Job job, QWidget* dialog);
    static ExportWorker* launch(QString description, FileJob job, QWidget* dialog);

  signals:
    void progressChanged(double fraction, const QString& stage);
    void succeeded(const QString& message);
    /// problem().line(): the file and the problem in the UI language.
    void failed(const QString& message);
    void cancelled();
    /// After succeeded(), failed() or cancelled().
    void finished();

  private:
    enum class Outcome { Succeeded, Failed, Cancelled };
    /// `surface`: null for a FileJob.
    void run(QOffscreenSurface* surface, const std::stop_token& stop);
    /// Watches and starts a worker owned by `dialog`'s parent (launch()).
    static ExportWorker* launched(ExportWorker* worker);
    /// `message`: the status bar's on success; `problem` on failure.
    void deliver(Outcome outcome, const QString& message, const ProblemText& problem = {});

    QString description_;
    ProblemText problem_;
    Job job_;
    FileJob fileJob_;
    std::unique_ptr<QOffscreenSurface> surface_;
    bool started_ = false;
    bool running_ = false;
    std::jthread thread_;  // last: joins before the members above go
};

/// A dialog whose Export button (accept()) checks the fields and starts an
/// ExportWorker: ExportImageDialog, ReportDialog.
class ExportDialog : public QDialog {
    Q_OBJECT

  public:
    using QDialog::QDialog;

    /// What is wrong with the fields; empty when they are fine.
    [[nodiscard]] virtual QString problem() const = 0;
    /// The files the export writes (absolute paths), as the fields give them.
    [[nodiscard]] virtual QStringList outputFiles() const = 0;

    /// With a problem(): shows it in a message box (showExportProblem) and
    /// stays open. When some outputFiles() exist: asks in a window-modal,
    /// non-blocking box (object name "replaceFilesBox") naming each of them,
    /// Replace / Cancel (the default); Cancel writes nothing and stays open.
    /// Else (or on Replace) starts the export (exportStarted()) and closes.
    void accept() override;

  signals:
    /// The export was started on `worker` (watched by the main window).
    void exportStarted(vv::gui::ExportWorker* worker);

  protected:
    /// Remembers the choices (QSettings) and returns the started worker
    /// (ExportWorker::launch). Called only when problem() is empty.
    virtual ExportWorker* startExport() = 0;

  private:
    /// Shows problem() in a message box, if there is one; true then.
    bool showProblem();
    /// Asks whether to replace `existing`; Replace starts the export.
    void askToReplace(const QStringList& existing);
    /// Starts the export and closes (problem() is empty).
    void startAndClose();
};

}  // namespace vv::gui
