// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/report/ReportPatient.h"

#include <QDate>
#include <algorithm>
#include <cctype>

#include "ReportText.h"
#include "vv/dicom/PersonName.h"

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
    const std::string name = dicom::personNameText(value);
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
