// SPDX-License-Identifier: GPL-3.0-or-later
#include "gui/ScreenshotMode.h"

#include <QCoreApplication>
#include <QFile>
#include <QImage>
#include <QTimer>
#include <cstdio>
#include <filesystem>
#include <utility>

#include "gui/EngineTexts.h"
#include "gui/ViewerWidget.h"
#include "vv/core/AtomicFile.h"
#include "vv/core/Error.h"

namespace vv::gui {

namespace {

/// Screenshot mode gives up when no frame was saved within this time.
constexpr int kTimeoutMs = 10 * 60 * 1000;

}  // namespace

ScreenshotMode::ScreenshotMode(ViewerWidget& viewer, QString path, QObject* parent)
    : QObject(parent), viewer_(viewer), path_(std::move(path)) {
    QTimer::singleShot(kTimeoutMs, this, [this] {
        if (pending_) {
            finish(false, tr("timed out waiting for the data to be shown"));
        }
    });
}

void ScreenshotMode::frameRendered() {
    if (!pending_ || !viewer_.scene() || viewer_.framesWithScene() == 0) {
        return;
    }
    // With the VSS on, wait for the frame that shows the solved surface (the
    // solve runs on a worker and triggers that frame), and for its occlusion.
    if ((viewer_.vssSettings().enabled && viewer_.vssStatus().pending) ||
        viewer_.occlusionDeferred()) {
        return;
    }
    pending_ = false;
    const QImage image = viewer_.grabFramebuffer();
    if (image.isNull()) {
        finish(false, tr("the viewer's frame could not be read"));
        return;
    }
    try {
        const std::filesystem::path target(QFile::encodeName(path_).toStdString());
        writeAtomically(target, [&](const std::filesystem::path& temporary) {
            if (!image.save(QFile::decodeName(temporary.c_str()), "PNG")) {
                throw IoError(target, "cannot write the PNG image");
            }
        });
    } catch (const vv::Error& e) {
        // As MainWindow::showError() prints a problem: the kind, then the detail.
        const ProblemText problem = describeProblem(e, FileAccess::Writing);
        finish(false, problem.summary + QLatin1Char(' ') + problem.details);
        return;
    }
    finish(true, tr("saved %1 (%2 x %3)").arg(path_).arg(image.width()).arg(image.height()));
}

void ScreenshotMode::fail(const QString& message) {
    finish(false, message);
}

void ScreenshotMode::finish(bool ok, const QString& message) {
    pending_ = false;
    const QByteArray text = (QStringLiteral("vesselview: ") + message + '\n').toLocal8Bit();
    std::fputs(text.constData(), ok ? stdout : stderr);
    std::fflush(ok ? stdout : stderr);
    const int code = ok ? 0 : 1;
    // Exit from the event loop, also when called before exec() started.
    QTimer::singleShot(0, qApp, [code] { QCoreApplication::exit(code); });
}

}  // namespace vv::gui
