// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/dicom/PersonName.h"

#include <vector>

namespace vv::dicom {

namespace {

std::string trimmed(std::string_view value) {
    const auto first = value.find_first_not_of(" \t");
    if (first == std::string_view::npos) {
        return {};
    }
    return std::string(value.substr(first, value.find_last_not_of(" \t") - first + 1));
}

/// `parts` joined with `separator`, empty ones left out.
std::string joined(const std::vector<std::string>& parts, const char* separator) {
    std::string out;
    for (const std::string& part : parts) {
        if (!part.empty()) {
            out += (out.empty() ? "" : separator) + part;
        }
    }
    return out;
}

}  // namespace

std::string personNameText(std::string_view pn) {
    const std::string_view alphabetic = pn.substr(0, pn.find('='));
    std::vector<std::string> parts;  // family, given, middle, prefix, suffix
    std::size_t start = 0;
    while (true) {
        const auto caret = alphabetic.find('^', start);
        parts.push_back(trimmed(alphabetic.substr(start, caret - start)));
        if (caret == std::string_view::npos) {
            break;
        }
        start = caret + 1;
    }
    parts.resize(5);
    std::string name = joined({parts[0], joined({parts[1], parts[2]}, " ")}, ", ");
    name = joined({parts[3], name}, " ");
    return joined({name, parts[4]}, ", ");
}

std::string personNameFromText(std::string_view typed) {
    std::string text = trimmed(typed);
    if (text.find('^') != std::string::npos) {
        return text;
    }
    const auto comma = text.find(',');
    if (comma == std::string::npos) {
        return text;
    }
    const std::string family = trimmed(std::string_view(text).substr(0, comma));
    const std::string given = trimmed(std::string_view(text).substr(comma + 1));
    return given.empty() ? family : family + "^" + given;
}

}  // namespace vv::dicom
