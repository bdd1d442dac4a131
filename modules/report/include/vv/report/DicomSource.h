// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <optional>
#include <string_view>

#include "vv/dicom/Dicom.h"
#include "vv/report/DicomExport.h"
#include "vv/report/ReportPatient.h"

namespace vv::report {

/// The patient and study a report of DICOM data belongs to.
struct SourceStudy {
    /// Name, ID and study date as the scan read them. Birth date, sex,
    /// accession number and referring physician stay empty: io's scan does
    /// not read them (yet).
    ReportPatient patient;
    /// The source study (its UID and date) with `patient`: the exports go
    /// into it, each in a new series.
    DicomStudy study;
};

/// The patient and study of series `seriesInstanceUid` in `scan`; nullopt
/// when the scan has no such series.
[[nodiscard]] std::optional<SourceStudy> sourceStudy(const dicom::DicomScanResult& scan,
                                                     std::string_view seriesInstanceUid);

}  // namespace vv::report
