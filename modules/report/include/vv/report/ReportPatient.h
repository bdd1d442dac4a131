// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <string>

namespace vv::report {

/// The patient / study block of a report and the patient module of its DICOM
/// exports: what DICOM data carries, or for meshes (which carry no patient
/// data) what the user entered. Dates as DICOM gives them
/// (YYYYMMDD) or already formatted text.
struct ReportPatient {
    std::string name;  ///< DICOM PN, e.g. "Doe^Jane"
    std::string id;
    std::string birthDate;
    std::string sex;  ///< "F", "M", "O" or empty
    std::string studyDate;
    std::string accession;
    std::string referringPhysician;  ///< DICOM PN
    /// Replace every field by "anonymised" in the PDF and leave the patient
    /// identifiers out of the DICOM exports.
    bool anonymise = false;
};

/// The text to print for `value`: "anonymised" (translated) when
/// patient.anonymise, "—" (not given) when empty, else `value` (a DICOM PN
/// "Doe^Jane" as "Doe, Jane"; a valid YYYYMMDD date in the report's date
/// format: YYYY-MM-DD in English, DD.MM.YYYY in German).
[[nodiscard]] std::string displayName(const ReportPatient& patient, const std::string& value);
[[nodiscard]] std::string displayDate(const ReportPatient& patient, const std::string& value);
[[nodiscard]] std::string displayText(const ReportPatient& patient, const std::string& value);

}  // namespace vv::report
