// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/core/NumberText.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <limits>
#include <system_error>

namespace vv {

namespace {

std::string nonFinite(double value) {
    return std::isnan(value) ? "nan" : (value > 0 ? "inf" : "-inf");
}

template <typename T>
std::string shortest(T value) {
    if (!std::isfinite(value)) {
        return nonFinite(static_cast<double>(value));
    }
    std::array<char, 64> buffer{};
    const auto [end, ec] = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
    return ec == std::errc() ? std::string(buffer.data(), end) : std::string("nan");
}

/// std::to_chars with a format and precision: printf's text in the C locale.
std::string formatted(double value, std::chars_format format, int digits) {
    if (!std::isfinite(value)) {
        return nonFinite(value);
    }
    // Fixed notation of 1e308 with many digits needs more than 330 characters.
    std::array<char, 512> buffer{};
    const auto [end, ec] = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value,
                                         format, std::max(digits, 0));
    return ec == std::errc() ? std::string(buffer.data(), end) : std::string("nan");
}

}  // namespace

std::string shortestText(double value) {
    return shortest(value);
}

std::string shortestText(float value) {
    return shortest(value);
}

std::string readableText(double value) {
    return significantText(value, 6);
}

std::string fixedText(double value, int digits) {
    return formatted(value, std::chars_format::fixed, digits);
}

std::string significantText(double value, int digits) {
    return formatted(value, std::chars_format::general, digits);
}

std::string scientificText(double value, int digits) {
    return formatted(value, std::chars_format::scientific, digits);
}

std::optional<double> parseFiniteNumber(std::string_view text) noexcept {
    double value = 0.0;
    const char* end = text.data() + text.size();
    const auto [ptr, ec] = std::from_chars(text.data(), end, value);
    if (text.empty() || ec != std::errc() || ptr != end || !std::isfinite(value)) {
        return std::nullopt;
    }
    return value;
}

std::optional<int> parseWholeNumber(std::string_view text) noexcept {
    int value = 0;
    const char* end = text.data() + text.size();
    const auto [ptr, ec] = std::from_chars(text.data(), end, value);
    if (text.empty() || ec != std::errc() || ptr != end) {
        return std::nullopt;
    }
    return value;
}

std::optional<double> parseDecimalNumber(std::string_view text) noexcept {
    // std::from_chars takes no '+' (strtod does, once, before the number).
    const bool plus = !text.empty() && text.front() == '+';
    const std::string_view number = plus ? text.substr(1) : text;
    if (number.empty() || (plus && number.front() == '-')) {
        return std::nullopt;
    }
    double value = 0.0;
    const char* end = number.data() + number.size();
    const auto [ptr, ec] = std::from_chars(number.data(), end, value);
    if (ptr != end) {
        return std::nullopt;
    }
    if (ec == std::errc::result_out_of_range) {
        // Too large or too small for a double: strtod gives ±HUGE_VAL or ±0.
        // Which one follows from the exponent's sign, or, without one, from
        // whether digits come before the point (a long "0.000…1" underflows).
        const bool negative = number.front() == '-';
        const std::size_t e = number.find_first_of("eE");
        const bool huge = e != std::string_view::npos
                              ? (e + 1 >= number.size() || number[e + 1] != '-')
                              : number.find_first_of("123456789") < number.find('.');
        const double magnitude = huge ? std::numeric_limits<double>::infinity() : 0.0;
        return negative ? -magnitude : magnitude;
    }
    if (ec != std::errc()) {
        return std::nullopt;
    }
    return value;
}

}  // namespace vv
