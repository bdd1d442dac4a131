// SPDX-License-Identifier: GPL-3.0-or-later
// vesselview: the GUI. `vesselview [FILE...]` opens files (the demo when none);
// `vesselview --screenshot OUT.png [FILE...]` saves the first frame and quits.
#include <QApplication>
#include <QCommandLineParser>
#include <QLoggingCategory>
#include <QString>

#include "gui/MainWindow.h"
#include "gui/ViewerWidget.h"
#include "vv/core/Log.h"

namespace {

Q_LOGGING_CATEGORY(vvCategory, "vv")

/// Forwards the engine's log messages to Qt's logging.
void qtSink(vv::log::Level level, std::string_view category, std::string_view message) {
    const QString text =
        QString::fromUtf8(category.data(), static_cast<qsizetype>(category.size())) +
        QStringLiteral(": ") +
        QString::fromUtf8(message.data(), static_cast<qsizetype>(message.size()));
    switch (level) {
        case vv::log::Level::Debug:
            qCDebug(vvCategory).noquote() << text;
            break;
        case vv::log::Level::Info:
            qCInfo(vvCategory).noquote() << text;
            break;
        case vv::log::Level::Warning:
            qCWarning(vvCategory).noquote() << text;
            break;
        case vv::log::Level::Error:
        case vv::log::Level::Off:
            qCCritical(vvCategory).noquote() << text;
            break;
    }
}

}  // namespace

int main(int argc, char** argv) {
    // The GL format must be the default before the application exists.
    vv::gui::ViewerWidget::installDefaultFormat();
    QApplication app(argc, argv);
    QApplication::setOrganizationName(QStringLiteral("VesselView"));
    QApplication::setApplicationName(QStringLiteral("VesselView"));
    QApplication::setApplicationVersion(QStringLiteral(VV_VERSION));
    vv::log::setSink(&qtSink);

    QCommandLineParser parser;
    parser.setApplicationDescription(
        QStringLiteral("Vessel tree workstation. Opens the given mesh files, or the demo."));
    parser.addHelpOption();
    parser.addVersionOption();
    const QCommandLineOption screenshot(
        QStringLiteral("screenshot"),
        QStringLiteral("Save the first frame with the data to <png> and quit."),
        QStringLiteral("png"));
    parser.addOption(screenshot);
    parser.addPositionalArgument(QStringLiteral("files"),
                                 QStringLiteral("Mesh files (STL, OBJ, PLY, VTK, VTP, VTU)."),
                                 QStringLiteral("[files...]"));
    parser.process(app);

    vv::gui::MainWindow window;
    if (parser.isSet(screenshot)) {
        window.setScreenshotTarget(parser.value(screenshot));
    }
    window.show();
    const QStringList files = parser.positionalArguments();
    if (files.isEmpty()) {
        window.openDemo();
    } else {
        window.openFiles(files);
    }
    return QApplication::exec();
}
