// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <optional>
#include <string>
#include <string_view>

/// Numbers as text for machines (JSON, CSV, DICOM values, messages that
/// quote values) and back: always the C locale, whatever the process locale
/// (QCoreApplication sets it from the environment; std::snprintf and
/// std::strtod follow it), and round-trippable.
namespace vv {

/// The shortest text that reads back as exactly `value` ("0.5", "2",
/// "1e+20", "-0.1"); "nan", "inf", "-inf" when not finite.
[[nodiscard]] std::string shortestText(double value);
/// As above for a float: the shortest text that reads back as this float
/// (0.1F gives "0.1", not the double's "0.10000000149011612").
[[nodiscard]] std::string shortestText(float value);

/// `value` for people to read in messages and help: at most six significant
/// digits ("0.000196078", "0.55", "1e+12"); C locale.
[[nodiscard]] std::string readableText(double value);

// printf's fixed formats, in the C locale whatever the process locale
// (std::snprintf follows LC_NUMERIC and would write "0,5" under de_DE):
// the same text as printf gives in the C locale; "nan", "inf", "-inf" when
// not finite. `digits` below 0 counts as 0.

/// "%.*f": `digits` digits after the point (fixedText(0.5, 2) = "0.50").
[[nodiscard]] std::string fixedText(double value, int digits);
/// "%.*g": at most `digits` significant digits, trailing zeros dropped
/// (significantText(0.25, 1) = "0.2", significantText(1e20, 6) = "1e+20").
[[nodiscard]] std::string significantText(double value, int digits);
/// "%.*e": one digit, the point, `digits` digits and the exponent
/// (scientificText(1234.5, 2) = "1.23e+03").
[[nodiscard]] std::string scientificText(double value, int digits);

/// `text` as a finite double (all of it, C locale); nullopt otherwise.
[[nodiscard]] std::optional<double> parseFiniteNumber(std::string_view text) noexcept;
/// `text` as an int (all of it, decimal); nullopt otherwise.
[[nodiscard]] std::optional<int> parseWholeNumber(std::string_view text) noexcept;

/// All of `text` as a number the way std::strtod reads it in the C locale,
/// for numbers in data files: an optional sign ('+' too), decimal digits
/// with an optional point and exponent, or inf / infinity / nan (any case);
/// a value beyond double's range gives ±inf, one below its smallest ±0.
/// nullopt for anything else (empty, "1,5", "0x1p3", trailing text).
[[nodiscard]] std::optional<double> parseDecimalNumber(std::string_view text) noexcept;

}  // namespace vv
