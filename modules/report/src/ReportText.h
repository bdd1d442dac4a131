// SPDX-License-Identifier: GPL-3.0-or-later
// The report's text: its translation context and how it formats numbers and
// dates for a person (the default QLocale: the GUI's UI language, the CLI's
// --lang). Private to vv::report.
#pragma once

#include <QCoreApplication>
#include <QDate>
#include <QDateTime>
#include <QString>
#include <string>
#include <utility>

namespace vv::report {

/// The translation context of every string of the report
/// (QCoreApplication::translate("vv::report::ReportText", ...)).
class ReportText {
    Q_DECLARE_TR_FUNCTIONS(vv::report::ReportText)
};

/// `text` from UTF-8.
[[nodiscard]] QString qs(const std::string& text);

/// Up to 3 significant digits in the default locale ("0,125" in German), no
/// exponent for ordinary magnitudes, no group separators; "—" when not finite.
[[nodiscard]] QString number(double value);
/// Both ends of a range with the same decimals, those number() gives the
/// larger magnitude ("0.45 – 1.31", as the legend, not "0.450 – 1.31");
/// number() of each when one is not finite or the larger is outside
/// number()'s fixed-point magnitudes.
[[nodiscard]] std::pair<QString, QString> rangeNumbers(double low, double high);
/// A value as given (a threshold, p): up to 6 significant digits, no trailing zeros.
[[nodiscard]] QString exact(double value);
/// A share 0..1 as "6.3 %" (one decimal, the locale's separator).
[[nodiscard]] QString percent(double fraction);
/// An integer in the default locale, without group separators.
[[nodiscard]] QString integer(long long value);
/// `value` with `decimals` decimals in the default locale, without group
/// separators ("1257,3" in German).
[[nodiscard]] QString fixed(double value, int decimals);
/// `value` with `unit` after a narrow no-break space ("15,0 mm"); a degree
/// sign follows it directly ("35°"); `value` alone without unit.
[[nodiscard]] QString withUnit(const QString& value, const std::string& unit);
/// A date / a date and time in the report's (translated) format.
[[nodiscard]] QString formatDate(const QDate& date);
[[nodiscard]] QString formatDateTime(const QDateTime& dateTime);

/// The name of a colour map, depth scale or depth cue (the engine's English
/// name, e.g. "Inferno", "Vessel chromadepth") as the GUI's panels translate it.
[[nodiscard]] QString engineName(std::string_view name);

}  // namespace vv::report
