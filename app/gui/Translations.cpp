// SPDX-License-Identifier: GPL-3.0-or-later
#include "gui/Translations.h"

#include <QLocale>
#include <QSettings>

#include "common/Language.h"

namespace vv::gui {

QStringList availableLanguages() {
    return vv::app::availableLanguages();
}

QString chooseLanguage(const QString& commandLine, const QSettings& settings) {
    if (!commandLine.isEmpty()) {
        return commandLine;
    }
    return settings.value(QLatin1String(kLanguageKey)).toString();
}

QString installTranslations(QCoreApplication& app, const QString& language) {
    return vv::app::installTranslations(app, language);
}

QString missingTranslation(const QString& language) {
    return vv::app::missingTranslation(language);
}

QString languageName(const QString& language) {
    if (language == QLatin1String("en")) {
        return QStringLiteral("English");
    }
    const QString name = QLocale(language).nativeLanguageName();
    if (name.isEmpty()) {
        return language;
    }
    return name.left(1).toUpper() + name.mid(1);
}

}  // namespace vv::gui
