// SPDX-License-Identifier: GPL-3.0-or-later
// vesselview: the GUI. `vesselview [FILE...]` opens files (the demo when none);
// `vesselview --screenshot OUT.png [FILE...]` saves the first frame and quits;
// `--lang de` chooses the language (default: View > Language, else the system's).
#include <QApplication>
#include <QCommandLineParser>
#include <QCoreApplication>
#include <QLoggingCategory>
#include <QSettings>
#include <QString>
#include <clocale>

#include "gui/MainWindow.h"
#include "gui/Translations.h"
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

/// The value of --lang / --lang=X in the raw arguments (read before the
/// parser so that its help text is translated too); empty when not given.
QString languageArgument(const QStringList& arguments) {
    for (qsizetype i = 1; i < arguments.size(); ++i) {
        const QString& a = arguments[i];
        if ((a == QLatin1String("--lang") || a == QLatin1String("-lang")) &&
            i + 1 < arguments.size()) {
            return arguments[i + 1];
        }
        if (a.startsWith(QLatin1String("--lang="))) {
            return a.mid(7);
        }
    }
    return {};
}

}  // namespace

int main(int argc, char** argv) {
    // The GL format must be the default before the application exists.
    vv::gui::ViewerWidget::installDefaultFormat();
    QApplication app(argc, argv);
    // QApplication set the C library's locale from the environment; number
    // text for machines (std::snprintf, std::strtod in file readers and
    // writers) must stay C: "0.5", not "0,5" under de_DE. What people read
    // is formatted by QLocale, which this does not change.
    std::setlocale(LC_NUMERIC, "C");
    QApplication::setOrganizationName(QStringLiteral("VesselView"));
    QApplication::setApplicationName(QStringLiteral("VesselView"));
    QApplication::setApplicationVersion(QStringLiteral(VV_VERSION));
    vv::log::setSink(&qtSink);
    const QString language =
        vv::gui::chooseLanguage(languageArgument(QCoreApplication::arguments()), QSettings());
    vv::gui::installTranslations(app, language);
    // English instead of the language asked for is said, never silent.
    const QString missingTranslation = vv::gui::missingTranslation(language);
    if (!missingTranslation.isEmpty()) {
        qCWarning(vvCategory).noquote() << missingTranslation;
    }

    QCommandLineParser parser;
    parser.setApplicationDescription(QCoreApplication::translate(
        "main", "Vessel tree workstation. Opens the given mesh files, or the demo."));
    parser.addHelpOption();
    parser.addVersionOption();
    const QCommandLineOption screenshot(
        QStringLiteral("screenshot"),
        QCoreApplication::translate("main",
                                    "Save the first frame with the data to <png> and quit."),
        QStringLiteral("png"));
    parser.addOption(screenshot);
    const QCommandLineOption lang(
        QStringLiteral("lang"),
        QCoreApplication::translate(
            "main", "User interface language, e.g. en or de (default: the system's)."),
        QStringLiteral("language"));
    parser.addOption(lang);
    parser.addPositionalArgument(
        QStringLiteral("files"),
        QCoreApplication::translate(
            "main", "Mesh files (STL, OBJ, PLY, VTK, VTP, VTU), or one session file (.vvs)."),
        QStringLiteral("[files...]"));
    parser.process(app);

    vv::gui::MainWindow window;
    if (parser.isSet(screenshot)) {
        window.setScreenshotTarget(parser.value(screenshot));
    }
    window.show();
    if (!missingTranslation.isEmpty()) {
        window.showLanguageProblem(missingTranslation);
    }
    const QStringList files = parser.positionalArguments();
    if (files.isEmpty()) {
        window.openDemo();
    } else if (files.size() == 1 &&
               files.front().endsWith(QLatin1String(".vvs"), Qt::CaseInsensitive)) {
        window.openSession(files.front());
    } else {
        window.openFiles(files);
    }
    return QApplication::exec();
}
