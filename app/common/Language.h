// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QString>
#include <QStringList>

class QCoreApplication;

/// VesselView's translations, shared by the GUI (View > Language, --lang) and
/// the CLI (report --lang): Qt Linguist files translations/vesselview_<lang>.ts,
/// compiled at build time to vesselview_<lang>.qm in the translations folder
/// that findTranslationsDir() finds (build tree or installed).
namespace vv::app {

/// The languages there are: "en" (the source language, always) and every
/// <lang> with a vesselview_<lang>.qm in the translations folder.
[[nodiscard]] QStringList availableLanguages();

/// Installs the translators for `language` ("" = the system locale's UI
/// languages, "en" = none) on `app`: VesselView's own and, when Qt ships it,
/// Qt's (qtbase_<lang>.qm). Numbers and dates follow the language installed:
/// an explicit `language` becomes the default QLocale, and an English UI on
/// a system of another language gets useEnglishLocale(), so a text never
/// mixes English words with, say, German decimal commas. Returns the
/// language installed ("en" when none fits: English, the source language,
/// needs only its plural forms, vesselview_en.qm, installed when found).
/// Never throws.
QString installTranslations(QCoreApplication& app, const QString& language);

/// Why installTranslations(`language`) shows English although another
/// language was asked for: VesselView's translations folder was not found
/// next to the executable (a program started outside its build or install
/// tree: the folders searched are named), or `language` was asked for
/// explicitly and has no translation there. Empty when English was asked
/// for, the translation is there, or the system's language (`language`
/// empty) simply has no translation. In English: the translation itself is
/// what is missing. Never throws.
[[nodiscard]] QString missingTranslation(const QString& language);

/// Makes English the default QLocale when the system locale's language is
/// not English (an English system keeps its own, e.g. en_GB dates). For
/// texts in English: the CLI's images and any untranslated UI. Never throws.
void useEnglishLocale();

}  // namespace vv::app
