// SPDX-License-Identifier: GPL-3.0-or-later
// The UI language of a GUI test, set as gui/Translations.cpp sets it for the
// app: our translations and Qt's, and numbers and dates in that language.
// Call before any widget exists; undo with removeUiLanguage(). Header only.
#pragma once

#include <gtest/gtest.h>

#include <QCoreApplication>
#include <QLibraryInfo>
#include <QLocale>
#include <QTranslator>

namespace vv::test {

/// Installs the translations of `language` ("de"; "en" installs none) from
/// `qmDir`; true when ours loaded (or none were needed).
[[nodiscard]] inline bool installUiLanguage(const char* language, const char* qmDir) {
    if (QLatin1String(language) == QLatin1String("en")) {
        return true;
    }
    const QLocale locale(QString::fromLatin1(language));
    auto* own = new QTranslator(QCoreApplication::instance());
    if (!own->load(locale, QStringLiteral("vesselview"), QStringLiteral("_"),
                   QString::fromLatin1(qmDir))) {
        return false;
    }
    QCoreApplication::installTranslator(own);
    auto* qt = new QTranslator(QCoreApplication::instance());
    if (qt->load(locale, QStringLiteral("qtbase"), QStringLiteral("_"),
                 QLibraryInfo::path(QLibraryInfo::TranslationsPath))) {
        QCoreApplication::installTranslator(qt);
    }
    QLocale::setDefault(locale);
    return true;
}

/// Removes every translator and sets the default locale back to US English.
inline void removeUiLanguage() {
    for (auto* translator : QCoreApplication::instance()->findChildren<QTranslator*>()) {
        QCoreApplication::removeTranslator(translator);
        delete translator;
    }
    QLocale::setDefault(QLocale(QLocale::English, QLocale::UnitedStates));
}

}  // namespace vv::test
