// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// The DICOM objects a report is exported as: Secondary Capture and
// Encapsulated PDF instances (DCMTK behind this header; no DCMTK or Qt type
// shows here). The report module fills these plain descriptions.

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace vv::dicom {

/// The patient module of an exported instance. Values as DICOM stores them
/// (PN "Doe^Jane", DA "YYYYMMDD").
struct ExportPatient {
    std::string name;
    std::string id;
    std::string birthDate;
    std::string sex;  ///< "F", "M", "O" or empty
    std::string accession;
    std::string referringPhysician;
    /// Follow the Basic Application Level Confidentiality Profile (PS3.15
    /// E.1): the identifiers, accession number, referring physician, study ID
    /// and every date and time are left empty (type 2) or left out (type 3);
    /// Patient Identity Removed (YES), De-identification Method (+ code
    /// 113100) and Longitudinal Temporal Information Modified (REMOVED) say
    /// so. The Study Instance UID is written as given: pass a pseudonym.
    bool anonymise = false;
};

/// The study an exported instance goes into.
struct ExportStudy {
    std::string studyInstanceUid;  ///< written as given
    std::string studyId;           ///< SH, may be empty
    std::string studyDate;         ///< DA
    std::string studyTime;         ///< TM
    /// nullopt writes the patient module empty (type 2 attributes present
    /// without value).
    std::optional<ExportPatient> patient;
};

/// The new series one instance is written in, and its dates (DA / TM, local).
struct ExportSeries {
    std::string description = "VesselView report";  ///< Series Description
    int seriesNumber = 900;
    std::string contentDate;  ///< Series / Content / Acquisition date
    std::string contentTime;
    std::string creationDate;  ///< Instance Creation Date / Time
    std::string creationTime;
    std::string softwareVersion;  ///< Software Versions
};

/// An 8-bit RGB image, rows top first, 3 bytes a pixel, no padding.
struct RgbImage {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> pixels;
};

/// Writes `image` as a Secondary Capture Image Storage instance (RGB, 8 bits,
/// modality OT, conversion type WSD) in a new series of `study` to `path`,
/// atomically. Returns the SOP Instance UID. Throws InvalidArgumentError for
/// an empty image, one larger than 65535 per side or with the wrong number
/// of bytes; IoError naming `path` when it cannot be written.
std::string writeSecondaryCapture(const std::filesystem::path& path, const RgbImage& image,
                                  const ExportStudy& study, const ExportSeries& series);

/// Writes `pdf` as an Encapsulated PDF Storage instance (modality DOC) in a
/// new series of `study` to `path`, atomically, with `title` as Document
/// Title. Returns the SOP Instance UID. Throws InvalidArgumentError when
/// `pdf` is not a PDF (no "%PDF-" header), IoError naming `path`.
std::string writeEncapsulatedPdf(const std::filesystem::path& path, std::string_view pdf,
                                 const std::string& title, const ExportStudy& study,
                                 const ExportSeries& series);

}  // namespace vv::dicom
