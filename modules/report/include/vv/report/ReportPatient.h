// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <string>

namespace vv::report {

/// The patient / study block of a report and the patient module of its DICOM
/// exports. Only data that came from DICOM fills it (meshes carry no patient
/// data). Dates as DICOM gives them (YYYYMMDD) or already formatted text.
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

/// The text to print for `value`: "anonymised" when patient.anonymise,
/// "—" (not given) when empty, else `value` (a DICOM PN "Doe^Jane" as "Doe, Jane";
/// a YYYYMMDD date as YYYY-MM-DD).
[[nodiscard]] std::string displayName(const ReportPatient& patient, const std::string& value);
[[nodiscard]] std::string displayDate(const ReportPatient& patient, const std::string& value);
[[nodiscard]] std::string displayText(const ReportPatient& patient, const std::string& value);

}  // namespace vv::report
