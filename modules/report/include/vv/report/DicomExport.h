// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QByteArray>
#include <QDateTime>
#include <QImage>
#include <filesystem>
#include <optional>
#include <string>

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
    /// without value). With patient->anonymise the identifiers are left empty
    /// and Patient Identity Removed is YES.
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

}  // namespace vv::report
