// SPDX-License-Identifier: GPL-3.0-or-later
#include "common/Language.h"

#include <QCoreApplication>
#include <QDir>
#include <QLibraryInfo>
#include <QLocale>
#include <QStringList>
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

QString missingTranslation(const QString& language) {
    const QLocale locale = language.isEmpty() ? QLocale::system() : QLocale(language);
    if (locale.language() == QLocale::English || locale.language() == QLocale::C) {
        return {};
    }
    const QString name = QLocale::languageToString(locale.language());
    const auto dir = translationsDir();
    if (!dir) {
        QStringList searched;
        for (const auto& candidate : dataDirCandidates(executableDir())) {
            searched << QDir::toNativeSeparators(
                QString::fromStdString((candidate / "translations").string()));
        }
        return QStringLiteral(
                   "The %1 translation was not found: VesselView looks for its "
                   "translations next to the program (in %2). The user interface "
                   "is in English.")
            .arg(name, searched.isEmpty() ? QStringLiteral("no folder")
                                          : searched.join(QStringLiteral(", ")));
    }
    QTranslator probe;
    if (language.isEmpty() ||
        probe.load(locale, QStringLiteral("vesselview"), QStringLiteral("_"), *dir)) {
        return {};
    }
    return QStringLiteral("There is no %1 translation in %2. The user interface is in English.")
        .arg(name, QDir::toNativeSeparators(*dir));
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
    const auto english = [&app] {
        useEnglishLocale();
        // English's own plural forms ("1 scene", "2 scenes" for "%n scene(s)").
        if (const auto dir = translationsDir()) {
            auto* plurals = new QTranslator(&app);
            if (plurals->load(QStringLiteral("vesselview_en"), *dir)) {
                QCoreApplication::installTranslator(plurals);
            } else {
                delete plurals;
            }
        }
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
