// SPDX-License-Identifier: GPL-3.0-or-later
#include "cli/GuiApplication.h"

#include <QCoreApplication>
#include <QGuiApplication>
#include <QLocale>
#include <QStringList>
#include <clocale>

#include "cli/Cli.h"
#include "common/Language.h"
#include "vv/core/Error.h"

namespace vv::cli {

void ensureGuiApplication() {
    if (QCoreApplication::instance() != nullptr) {
        if (qobject_cast<QGuiApplication*>(QCoreApplication::instance()) == nullptr) {
            throw RenderError("a QGuiApplication is needed, the process has a QCoreApplication");
        }
        return;
    }
    const bool platformChosen = !qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM");
    const bool haveDisplay =
        !qEnvironmentVariableIsEmpty("DISPLAY") || !qEnvironmentVariableIsEmpty("WAYLAND_DISPLAY");
    static int argc = 1;
    static char name[] = "vesselview-cli";
    static char platformFlag[] = "-platform";
    static char offscreen[] = "offscreen";
    static char* argv[] = {name, nullptr, nullptr, nullptr};
    if (!platformChosen && !haveDisplay) {
        argv[1] = platformFlag;
        argv[2] = offscreen;
        argc = 3;
    }
    // Lives until the process ends: tearing it down during static
    // destruction is fragile.
    new QGuiApplication(argc, argv);
    // It set the C library's locale from the environment: numbers written
    // and read by the engine (std::snprintf, std::strtod) stay C.
    std::setlocale(LC_NUMERIC, "C");
    // The text drawn into images (legends, scale bar) is English unless a
    // command installs a language (report --lang): its numbers too.
    app::useEnglishLocale();
}

void checkLanguage(const std::string& command, const std::string& language) {
    const QStringList known = app::availableLanguages();
    if (!known.contains(QString::fromStdString(language))) {
        throw UsageError(command + ": --lang must be one of " +
                         known.join(QStringLiteral(", ")).toStdString() + ", got '" + language +
                         "'");
    }
}

void useLanguage(const std::string& language) {
    const QString name = QString::fromStdString(language);
    (void)app::installTranslations(*QCoreApplication::instance(), name);
    QLocale::setDefault(QLocale(name));
}

}  // namespace vv::cli
