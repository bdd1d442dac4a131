// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QDate>
#include <QString>
#include <optional>

/// Dates as people read and type them in the UI language: one format for
/// every date the GUI shows or asks for, the one the PDF report prints
/// (2025-03-07 in English, 07.03.2025 in German: day and month never in an
/// order a reader can take the other way round).
namespace vv::gui {

/// The QDate format of dates in the UI language ("yyyy-MM-dd", German
/// "dd.MM.yyyy"); translation context "vv::gui::StudyDate".
[[nodiscard]] QString uiDateFormat();

/// What a date field shows while empty: uiDateFormat() in the letters a
/// reader of the UI language knows ("YYYY-MM-DD", German "TT.MM.JJJJ").
[[nodiscard]] QString uiDatePlaceholder();

/// A typed date: in uiDateFormat(), as ISO 8601 (2025-03-07) in every
/// language, or as a DICOM date (20250307); surrounding spaces ignored. An
/// empty text is a date not given: a null QDate. nullopt when the text is
/// no valid date in any of these forms.
[[nodiscard]] std::optional<QDate> parseUiDate(const QString& typed);

}  // namespace vv::gui
