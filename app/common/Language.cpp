// SPDX-License-Identifier: GPL-3.0-or-later
#include "common/Language.h"

#include <QCoreApplication>
#include <QDir>
#include <QLibraryInfo>
#include <QLocale>
#include <QTranslator>
#include <optional>

#include "common/ResourcePaths.h"

namespace vv::app {

namespace {

const QString kPrefix = QStringLiteral("vesselview_");

std::optional<QString> translationsDir() {
    if (const auto dir = findTranslationsDir()) {
        return QDir::cleanPath(QString::fromStdString(dir->string()));
    }
    return std::nullopt;
}

}  // namespace

QStringList availableLanguages() {
    QStringList languages{QStringLiteral("en")};
    if (const auto dir = translationsDir()) {
        const QStringList files =
            QDir(*dir).entryList({kPrefix + QStringLiteral("*.qm")}, QDir::Files, QDir::Name);
        for (const QString& file : files) {
            const QString language = file.mid(kPrefix.size()).chopped(3);
            if (!language.isEmpty() && !languages.contains(language)) {
                languages << language;
            }
        }
    }
    return languages;
}

void useEnglishLocale() {
    if (QLocale::system().language() != QLocale::English) {
        QLocale::setDefault(QLocale(QLocale::English, QLocale::UnitedStates));
    } else {
        QLocale::setDefault(QLocale::system());
    }
}

QString installTranslations(QCoreApplication& app, const QString& language) {
    const QLocale locale = language.isEmpty() ? QLocale::system() : QLocale(language);
    const auto english = [] {
        useEnglishLocale();
        return QStringLiteral("en");
    };
    if (locale.language() == QLocale::English || locale.language() == QLocale::C) {
        return english();
    }
    const auto dir = translationsDir();
    if (!dir) {
        return english();
    }
    auto* own = new QTranslator(&app);
    // Tries vesselview_de_DE.qm, vesselview_de.qm, … for each UI language.
    if (!own->load(locale, QStringLiteral("vesselview"), QStringLiteral("_"), *dir)) {
        delete own;
        return english();
    }
    QCoreApplication::installTranslator(own);
    if (!language.isEmpty()) {
        QLocale::setDefault(locale);  // numbers and dates as in the chosen language
    }
    auto* qt = new QTranslator(&app);
    if (qt->load(locale, QStringLiteral("qtbase"), QStringLiteral("_"),
                 QLibraryInfo::path(QLibraryInfo::TranslationsPath))) {
        QCoreApplication::installTranslator(qt);
    } else {
        delete qt;
    }
    return own->language().isEmpty() ? QLocale::languageToCode(locale.language())
                                     : own->language().section(QLatin1Char('_'), 0, 0);
}

}  // namespace vv::app
