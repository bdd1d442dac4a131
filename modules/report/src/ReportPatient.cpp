// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/report/ReportPatient.h"

#include <QDate>
#include <algorithm>
#include <cctype>
#include <vector>

#include "ReportText.h"

namespace vv::report {

namespace {

constexpr const char* kNotGiven = "\u2014";  // em dash

std::string trimmed(const std::string& value) {
    const auto first = value.find_first_not_of(" \t");
    if (first == std::string::npos) {
        return {};
    }
    return value.substr(first, value.find_last_not_of(" \t") - first + 1);
}

}  // namespace

std::string displayText(const ReportPatient& patient, const std::string& value) {
    if (patient.anonymise) {
        return QCoreApplication::translate("vv::report::ReportText", "anonymised").toStdString();
    }
    const std::string text = trimmed(value);
    return text.empty() ? kNotGiven : text;
}

std::string displayName(const ReportPatient& patient, const std::string& value) {
    if (patient.anonymise || trimmed(value).empty()) {
        return displayText(patient, value);
    }
    // DICOM PN: family^given^middle^prefix^suffix (first component group only).
    const std::string alphabetic = value.substr(0, value.find('='));
    std::vector<std::string> parts;
    std::size_t start = 0;
    while (true) {
        const auto caret = alphabetic.find('^', start);
        parts.push_back(trimmed(alphabetic.substr(start, caret - start)));
        if (caret == std::string::npos) {
            break;
        }
        start = caret + 1;
    }
    std::string given;
    for (std::size_t i = 1; i < std::min<std::size_t>(parts.size(), 3); ++i) {
        if (!parts[i].empty()) {
            given += (given.empty() ? "" : " ") + parts[i];
        }
    }
    std::string name = parts[0];
    if (!given.empty()) {
        name += (name.empty() ? "" : ", ") + given;
    }
    if (parts.size() > 3 && !parts[3].empty()) {
        name = parts[3] + " " + name;
    }
    return name.empty() ? displayText(patient, {}) : name;
}

std::string displayDate(const ReportPatient& patient, const std::string& value) {
    const std::string text = trimmed(value);
    if (patient.anonymise || text.empty()) {
        return displayText(patient, text);
    }
    const bool dicomDate = text.size() == 8 && std::all_of(text.begin(), text.end(), [](char c) {
                               return std::isdigit(static_cast<unsigned char>(c)) != 0;
                           });
    if (dicomDate) {
        const QDate date =
            QDate::fromString(QString::fromStdString(text), QStringLiteral("yyyyMMdd"));
        if (date.isValid()) {
            return formatDate(date).toStdString();
        }
    }
    return text;
}

}  // namespace vv::report
