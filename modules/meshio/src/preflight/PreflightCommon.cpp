// SPDX-License-Identifier: GPL-3.0-or-later
#include "PreflightCommon.h"

#include <algorithm>
#include <cctype>
#include <limits>
#include <utility>

namespace vv::meshio::detail {

std::string lower(std::string_view s) {
    std::string out(s);
    std::transform(out.begin(), out.end(), out.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return out;
}

std::uint64_t mulSat(std::uint64_t a, std::uint64_t b) {
    if (a != 0 && b > std::numeric_limits<std::uint64_t>::max() / a) {
        return std::numeric_limits<std::uint64_t>::max();
    }
    return a * b;
}

std::optional<std::uint64_t> parseCount(std::string_view token) {
    if (token.empty() || token.size() > 20) {
        return std::nullopt;
    }
    std::uint64_t value = 0;
    for (const char c : token) {
        if (c < '0' || c > '9') {
            return std::nullopt;
        }
        const auto digit = static_cast<std::uint64_t>(c - '0');
        if (value > (std::numeric_limits<std::uint64_t>::max() - digit) / 10) {
            return std::numeric_limits<std::uint64_t>::max();
        }
        value = value * 10 + digit;
    }
    return value;
}

std::vector<std::string_view> splitWords(std::string_view line) {
    std::vector<std::string_view> words;
    std::size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && std::isspace(static_cast<unsigned char>(line[i])) != 0) {
            ++i;
        }
        const std::size_t start = i;
        while (i < line.size() && std::isspace(static_cast<unsigned char>(line[i])) == 0) {
            ++i;
        }
        if (i > start) {
            words.push_back(line.substr(start, i - start));
        }
    }
    return words;
}

std::string printable(std::string_view text, std::size_t max) {
    std::string out;
    for (const char c : text.substr(0, max)) {
        const auto u = static_cast<unsigned char>(c);
        out += (u >= 0x20 && u < 0x7F) ? c : '?';
    }
    if (text.size() > max) {
        out += "...";
    }
    return out;
}

PreflightTicker::PreflightTicker(const Progress& progress, std::uintmax_t size, std::string stage)
    : progress_(progress), size_(size), stage_(std::move(stage)) {}

void PreflightTicker::operator()(std::uint64_t position) {
    if (position >= next_) {
        next_ = position + (4U << 20);
        // The checks take the first tenth of the load's progress.
        progress_.report(
            size_ > 0 ? 0.1 * static_cast<double>(position) / static_cast<double>(size_) : 0.0,
            stage_);
    }
}

}  // namespace vv::meshio::detail
