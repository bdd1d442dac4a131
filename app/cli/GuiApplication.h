// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <string>

namespace vv::cli {

/// Makes sure the process has a QGuiApplication (needed for OpenGL contexts
/// and for fonts), creating one the first time: on Qt's default platform
/// when a display (or QT_QPA_PLATFORM) is set, else on the "offscreen"
/// platform, so that a missing X server gives a clear RenderError later
/// instead of xcb aborting the process. The application lives until the
/// process ends (Qt allows one per process). Qt sets the C library's locale
/// from the environment when it creates the application; LC_NUMERIC is put
/// back to "C" then, so that the engine's std::snprintf / std::strtod keep
/// reading and writing "0.5" under any locale.
/// Throws vv::RenderError when the process already has a QCoreApplication
/// that is not a QGuiApplication.
void ensureGuiApplication();

/// `language` checked against the installed translations (app::
/// availableLanguages); throws UsageError "<command>: --lang must be one of
/// ..." when it is not one of them.
void checkLanguage(const std::string& command, const std::string& language);

/// A report's language: its translator installed and, for numbers and
/// dates, the default QLocale (after ensureGuiApplication()).
void useLanguage(const std::string& language);

}  // namespace vv::cli
