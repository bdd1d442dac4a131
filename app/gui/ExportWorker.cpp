// SPDX-License-Identifier: GPL-3.0-or-later
#include "gui/ExportWorker.h"

#include <QAbstractButton>
#include <QDir>
#include <QFileInfo>
#include <QMainWindow>
#include <QMessageBox>
#include <QOffscreenSurface>
#include <QProgressDialog>
#include <QPushButton>
#include <QStatusBar>
#include <QTimer>
#include <algorithm>
#include <cmath>
#include <exception>
#include <mutex>
#include <stdexcept>
#include <string>
#include <utility>

#include "gui/EngineTexts.h"
#include "gui/ViewSettings.h"
#include "gui/ViewerWidget.h"
#include "vv/core/Error.h"

namespace vv::gui {

namespace {

/// How long the status bar shows the outcome of an export (ms).
constexpr int kStatusTimeoutMs = 15000;

/// Relative difference of aspect ratios below which an export is framed as
/// the view (rounding of its pixel size).
constexpr double kSameAspect = 0.01;

/// "Visible vessels" -> the settled view's range as a fixed one, when the
/// export is framed as the view (currentViewOptions()), marked as pinned: its
/// legend measures from the screen's frontmost vessel, as the screen's does.
void pinVisibleDepthRange(const ViewerWidget& viewer, int width, int height,
                          vss::DepthRange& range) {
    const render::VssFrameStatus& shown = viewer.vssStatus();
    if (range.mode != vss::RangeMode::Visible || !shown.shown || !shown.current || shown.pending ||
        shown.preview || !std::isfinite(shown.dmin) || !std::isfinite(shown.dmax) ||
        shown.dmin > shown.dmax) {
        return;  // no settled view to match: the export's own visible range
    }
    const QSize view = viewPixelSize(viewer);
    const double viewAspect = static_cast<double>(view.width()) / view.height();
    const double aspect = static_cast<double>(width) / std::max(1, height);
    if (std::abs(aspect / viewAspect - 1.0) > kSameAspect) {
        return;  // framed otherwise: it shows vessels the view does not
    }
    range = {.mode = vss::RangeMode::Fixed,
             .dmin = shown.dmin,
             .dmax = shown.dmax,
             .pinnedVisible = true};
}

}  // namespace

render::OffscreenOptions currentViewOptions(const ViewerWidget& viewer, int width, int height) {
    render::OffscreenOptions options;
    options.width = width;
    options.height = height;
    // The exact VSS, as the view shows once settled, and FXAA, as the viewer runs it.
    options.display = displaySettings(viewer);
    options.display.legends = false;  // the export paints them (report::ViewExportOptions)
    options.camera = viewer.camera();
    options.volume = viewer.volume();  // a ray-cast volume, when one is shown
    options.isoValue = viewer.isoValue();
    // The smooth copy the view draws up close, for the same picture.
    if (viewer.smoothCopy().scene) {
        options.refined = viewer.smoothCopy();
    }
    pinVisibleDepthRange(viewer, width, height, options.display.vss.range);
    return options;
}

QSize viewPixelSize(const ViewerWidget& viewer) {
    const qreal ratio = viewer.devicePixelRatioF();
    return {std::max(1, static_cast<int>(std::lround(viewer.width() * ratio))),
            std::max(1, static_cast<int>(std::lround(viewer.height() * ratio)))};
}

void showExportProblem(QWidget* parent, const QString& title, const QString& message) {
    auto* box = new QMessageBox(QMessageBox::Warning, title, message, QMessageBox::Ok, parent);
    box->setObjectName(QStringLiteral("exportProblemBox"));
    box->setAttribute(Qt::WA_DeleteOnClose);
    box->open();
}

namespace {

QWidget* ownerOf(QWidget* dialog) {
    return dialog->parentWidget() != nullptr ? dialog->parentWidget() : dialog;
}

}  // namespace

ExportWorker* ExportWorker::launch(QString description, Job job, QWidget* dialog) {
    return launched(new ExportWorker(std::move(description), std::move(job), ownerOf(dialog)));
}

ExportWorker* ExportWorker::launch(QString description, FileJob job, QWidget* dialog) {
    return launched(new ExportWorker(std::move(description), std::move(job), ownerOf(dialog)));
}

ExportWorker* ExportWorker::launched(ExportWorker* worker) {
    if (auto* window = qobject_cast<QMainWindow*>(worker->parent())) {
        watch(worker, window);
    } else {
        connect(worker, &ExportWorker::finished, worker, &QObject::deleteLater);
    }
    worker->start();
    return worker;
}

bool ExportDialog::showProblem() {
    const QString wrong = problem();
    if (!wrong.isEmpty()) {
        showExportProblem(this, windowTitle(), wrong);
    }
    return !wrong.isEmpty();
}

void ExportDialog::accept() {
    if (showProblem()) {
        return;
    }
    QStringList existing;
    for (const QString& file : outputFiles()) {
        if (QFileInfo::exists(file)) {
            existing << file;
        }
    }
    if (!existing.isEmpty()) {
        askToReplace(existing);
        return;
    }
    startAndClose();
}

void ExportDialog::askToReplace(const QStringList& existing) {
    QString question;
    if (existing.size() == 1) {
        const QFileInfo file(existing.front());
        question = tr("%1 already exists in %2. Replace it?")
                       .arg(file.fileName(), QDir::toNativeSeparators(file.absolutePath()));
    } else {
        QStringList lines;
        for (const QString& file : existing) {
            lines << QDir::toNativeSeparators(file);
        }
        question =
            tr("These files already exist:\n%1\nReplace them?").arg(lines.join(QLatin1Char('\n')));
    }
    // Window-modal but not blocking, as showExportProblem(): the event loop
    // (and tests) keep running.
    auto* box =
        new QMessageBox(QMessageBox::Warning, windowTitle(), question, QMessageBox::Cancel, this);
    box->setObjectName(QStringLiteral("replaceFilesBox"));
    box->setAttribute(Qt::WA_DeleteOnClose);
    QPushButton* replace = box->addButton(tr("&Replace"), QMessageBox::DestructiveRole);
    box->setDefaultButton(QMessageBox::Cancel);
    box->setEscapeButton(QMessageBox::Cancel);
    connect(box, &QMessageBox::buttonClicked, this, [this, replace](QAbstractButton* clicked) {
        // The data shown may have changed while the box asked.
        if (clicked == replace && !showProblem()) {
            startAndClose();
        }
    });
    box->open();
}

void ExportDialog::startAndClose() {
    emit exportStarted(startExport());
    QDialog::accept();
}

ExportWorker::ExportWorker(QString description, Job job, QObject* parent)
    : QObject(parent), description_(std::move(description)), job_(std::move(job)) {}

ExportWorker::ExportWorker(QString description, FileJob job, QObject* parent)
    : QObject(parent), description_(std::move(description)), fileJob_(std::move(job)) {}

ExportWorker::~ExportWorker() {
    thread_.request_stop();
    if (thread_.joinable()) {
        thread_.join();
    }
    surface_.reset();  // on the GUI thread, after the worker's context is gone
}

void ExportWorker::start() {
    if (started_) {
        return;
    }
    started_ = true;
    running_ = true;
    if (!fileJob_) {
        try {
            surface_ = render::OffscreenRenderer::createSurface();
        } catch (const vv::Error& e) {
            const ProblemText problem = describeProblem(e, FileAccess::Writing);
            QTimer::singleShot(0, this, [this, problem] { deliver(Outcome::Failed, {}, problem); });
            return;
        }
    }
    thread_ = std::jthread(
        [this, surface = surface_.get()](const std::stop_token& stop) { run(surface, stop); });
}

void ExportWorker::cancel() {
    thread_.request_stop();
}

void ExportWorker::run(QOffscreenSurface* surface, const std::stop_token& stop) {
    // On the worker: touches only job_ (immutable while running) and emits
    // signals, which reach the GUI thread queued.
    // Throttled: a signal per 0.5 % or new stage (the engine may report from several threads).
    std::mutex mutex;
    int shownPermille = -1;
    std::string shownStage;
    const Progress progress(
        [&](double fraction, std::string_view stage) {
            const int permille =
                static_cast<int>(std::lround(std::clamp(fraction, 0.0, 1.0) * 1000.0));
            const std::lock_guard lock(mutex);
            if (std::abs(permille - shownPermille) < 5 && stage == shownStage) {
                return;
            }
            shownPermille = permille;
            shownStage = stage;
            emit progressChanged(permille / 1000.0,
                                 translatedStage(QString::fromStdString(shownStage)));
        },
        stop);
    Outcome outcome = Outcome::Failed;
    QString message;
    ProblemText problem;
    try {
        if (fileJob_) {
            progress.throwIfCancelled();
            message = fileJob_(progress);
        } else {
            render::OffscreenRenderer renderer(*surface);
            progress.throwIfCancelled();
            message = job_(renderer, progress);
        }
        outcome = Outcome::Succeeded;
    } catch (const CancelledError&) {
        outcome = Outcome::Cancelled;
    } catch (const std::exception& e) {
        problem = describeProblem(e, FileAccess::Writing);
    } catch (...) {
        problem = describeProblem(std::runtime_error("unknown exception"), FileAccess::Writing);
    }
    QMetaObject::invokeMethod(
        this, [this, outcome, message, problem] { deliver(outcome, message, problem); },
        Qt::QueuedConnection);
}

void ExportWorker::deliver(Outcome outcome, const QString& message, const ProblemText& problem) {
    running_ = false;
    switch (outcome) {
        case Outcome::Succeeded:
            emit succeeded(message);
            break;
        case Outcome::Failed:
            problem_ = problem;
            emit failed(problem.line());
            break;
        case Outcome::Cancelled:
            emit cancelled();
            break;
    }
    emit finished();
}

void ExportWorker::watch(ExportWorker* worker, QMainWindow* window) {
    auto* dialog = new QProgressDialog(worker->description(), tr("Cancel"), 0, 1000, window);
    dialog->setObjectName(QStringLiteral("exportProgress"));
    dialog->setWindowTitle(tr("Export"));
    dialog->setWindowModality(Qt::WindowModal);
    dialog->setAutoClose(false);
    dialog->setAutoReset(false);
    dialog->setMinimumDuration(0);
    dialog->setValue(0);
    connect(worker, &QObject::destroyed, dialog, &QObject::deleteLater);
    connect(dialog, &QProgressDialog::canceled, worker, [worker, dialog] {
        worker->cancel();
        dialog->setLabelText(tr("Cancelling…"));
    });
    connect(worker, &ExportWorker::progressChanged, dialog,
            [worker, dialog](double fraction, const QString& stage) {
                if (!dialog->wasCanceled()) {
                    dialog->setValue(static_cast<int>(std::lround(fraction * 1000.0)));
                    dialog->setLabelText(stage.isEmpty() ? worker->description()
                                                         : worker->description() +
                                                               QStringLiteral("\n") + stage);
                }
            });
    connect(worker, &ExportWorker::succeeded, window, [window](const QString& message) {
        window->statusBar()->showMessage(message, kStatusTimeoutMs);
    });
    connect(worker, &ExportWorker::cancelled, window, [window] {
        window->statusBar()->showMessage(tr("Export cancelled: nothing was written"),
                                         kStatusTimeoutMs);
    });
    connect(worker, &ExportWorker::failed, window, [window, worker] {
        const ProblemText& problem = worker->problem();
        window->statusBar()->showMessage(tr("Export failed: %1").arg(problem.summary),
                                         kStatusTimeoutMs);
        showProblem(window, QStringLiteral("exportErrorBox"), tr("Cannot export"), problem);
    });
    connect(worker, &ExportWorker::finished, dialog, &QProgressDialog::close);
    connect(worker, &ExportWorker::finished, worker, &QObject::deleteLater);
    dialog->show();
}

}  // namespace vv::gui
