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
/// Qt's (qtbase_<lang>.qm); an explicit `language` also becomes the default
/// QLocale (number formats). Returns the language installed ("en" when none
/// fits: English, the source language, needs no translator). Never throws.
QString installTranslations(QCoreApplication& app, const QString& language);

}  // namespace vv::app
