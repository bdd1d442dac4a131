// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QString>
#include <QStringList>

class QCoreApplication;
class QSettings;

namespace vv::gui {

/// The GUI's translations: Qt Linguist files translations/vesselview_<lang>.ts,
/// compiled at build time to vesselview_<lang>.qm in the translations folder
/// that app::findTranslationsDir() finds (build tree or installed).

/// The QSettings key of the language chosen in View > Language ("" or
/// missing = the system's).
inline constexpr const char* kLanguageKey = "language";

/// The languages the GUI can show: "en" (the source language, always) and
/// every <lang> with a vesselview_<lang>.qm in the translations folder.
[[nodiscard]] QStringList availableLanguages();

/// The language to use: `commandLine` when not empty (--lang), else the one
/// stored under kLanguageKey in `settings`, else "" (the system locale).
[[nodiscard]] QString chooseLanguage(const QString& commandLine, const QSettings& settings);

/// Installs the translators for `language` ("" = the system locale's UI
/// languages, "en" = none) on `app`: VesselView's own and, when Qt ships it,
/// Qt's (qtbase_<lang>.qm); an explicit `language` also becomes the default
/// QLocale (number formats). Returns the language installed ("en" when none
/// fits: English, the source language, needs no translator). Call once,
/// before any widget exists. Never throws.
QString installTranslations(QCoreApplication& app, const QString& language);

/// app::missingTranslation(): why the UI is English although `language` (as
/// given to installTranslations()) asks for another; empty when it is not.
[[nodiscard]] QString missingTranslation(const QString& language);

/// The language's name in that language ("English", "Deutsch", …).
[[nodiscard]] QString languageName(const QString& language);

}  // namespace vv::gui
