// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QByteArray>
#include <QDateTime>
#include <QImage>
#include <filesystem>
#include <optional>
#include <string>

#include "vv/dicom/MeasurementReport.h"
#include "vv/report/ReportPatient.h"

namespace vv::report {

/// The study the exports of one report go into. A new one unless the data
/// came from DICOM (then the source study's UID and patient).
struct DicomStudy {
    std::string studyInstanceUid;  ///< "1.2...."; newStudy() makes one
    std::string studyId;           ///< DICOM SH, may be empty
    QDateTime studyDateTime;       ///< Study Date / Time unless given below
    std::string studyDate;  ///< the source study's Study Date (DA); empty = from studyDateTime
    std::string studyTime;  ///< ... Study Time (TM); used only with studyDate
    /// The patient module; nullopt writes it empty (type 2 attributes present
    /// without value). With patient->anonymise the export follows the Basic
    /// Application Level Confidentiality Profile (DICOM PS3.15 E.1): the patient
    /// identifiers, accession number, referring physician, study ID and every
    /// date and time are left empty (type 2) or left out (type 3), the Study
    /// Instance UID becomes anonymisedUid() of the source's, and Patient
    /// Identity Removed (YES), De-identification Method (+ code 113100) and
    /// Longitudinal Temporal Information Modified (REMOVED) say so.
    std::optional<ReportPatient> patient;
};

/// A new study: a fresh Study Instance UID (dcmGenerateUniqueIdentifier) and now.
[[nodiscard]] DicomStudy newStudy();

/// What one exported instance is.
struct DicomSeries {
    std::string description = "VesselView report";  ///< Series Description
    int seriesNumber = 900;
    QDateTime contentDateTime = QDateTime::currentDateTime();
};

/// A fresh DICOM UID (DCMTK's root and generator).
[[nodiscard]] std::string newDicomUid();

/// The pseudonym of `uid` in anonymised exports: "2.25." + a 128-bit number
/// (PS3.5 B.2) from SHA-256 of a per-process random salt and `uid`. The same
/// `uid` gives the same pseudonym within one process (the report's instances
/// stay in one study) and an unrelated one in another process; it cannot be
/// traced back to `uid`.
[[nodiscard]] std::string anonymisedUid(const std::string& uid);

/// Writes `image` as a Secondary Capture Image Storage instance (RGB, 8 bits,
/// modality OT, conversion type WSD) in a new series of `study` to `path`,
/// atomically. Alpha is dropped (composited over black). Returns the SOP
/// Instance UID. Throws InvalidArgumentError for an empty image or one larger
/// than 65535 per side, IoError naming `path` when it cannot be written.
std::string writeSecondaryCapture(const std::filesystem::path& path, const QImage& image,
                                  const DicomStudy& study, const DicomSeries& series = {});

/// Writes `pdf` as an Encapsulated PDF Storage instance (modality DOC) in a
/// new series of `study` to `path`, atomically, with `title` as Document
/// Title. Returns the SOP Instance UID. Throws InvalidArgumentError when
/// `pdf` is not a PDF (no "%PDF-" header), IoError naming `path`.
std::string writeEncapsulatedPdf(const std::filesystem::path& path, const QByteArray& pdf,
                                 const std::string& title, const DicomStudy& study,
                                 const DicomSeries& series = {});

/// Writes the planning measurements `content` (dicom::MeasurementReport.h:
/// TID 1500 measurement groups, the source series' instances as evidence)
/// as an Enhanced SR instance in a new series of `study` to `path`,
/// atomically. Returns the SOP Instance UID. Throws as
/// dicom::writeMeasurementReport.
std::string writeMeasurementSr(const std::filesystem::path& path,
                               const dicom::MeasurementReportContent& content,
                               const DicomStudy& study, const DicomSeries& series = {});

}  // namespace vv::report
