// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// Measurements as a DICOM Structured Report: an Enhanced SR instance whose
// content is TID 1500 (Measurement Report) with one TID 1501 measurement
// group per measured thing, written through DCMTK's dcmsr and its Content
// Mapping Resource (cmr), so that a PACS and other viewers read the values
// as data, not pixels. DCMTK stays behind this header; the report module
// fills these plain descriptions.

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "vv/dicom/ExportObjects.h"

namespace vv::dicom {

/// A coded concept (Code Value, Coding Scheme Designator, Code Meaning).
struct SrCode {
    std::string value;
    std::string scheme;
    std::string meaning;
};

/// The concepts the measurements are made of (SNOMED CT, DICOM, UCUM).
namespace sr {
/// (81827009, SCT, "Diameter")
[[nodiscard]] SrCode diameter();
/// (42798000, SCT, "Area")
[[nodiscard]] SrCode area();
/// (121211, DCM, "Path length"): along a curve, here the centreline.
[[nodiscard]] SrCode pathLength();
/// (121206, DCM, "Distance"): straight.
[[nodiscard]] SrCode distance();
/// (110859, DCM, "Angle")
[[nodiscard]] SrCode angle();
/// (255605001, SCT, "Minimum") and (56851009, SCT, "Maximum"): derivations.
[[nodiscard]] SrCode minimum();
[[nodiscard]] SrCode maximum();
/// UCUM units: (mm, UCUM, "millimeter"), (mm2, ...), (deg, UCUM, "degree").
[[nodiscard]] SrCode millimetre();
[[nodiscard]] SrCode squareMillimetre();
[[nodiscard]] SrCode degree();
}  // namespace sr

/// One numeric measurement (TID 300).
struct SrNumber {
    SrCode name;                       ///< what is measured (the concept name)
    std::optional<SrCode> derivation;  ///< e.g. sr::minimum() for a minimum Feret diameter
    double value = 0.0;                ///< finite
    SrCode unit;
    /// What exactly the value is, in words (TID 300's Equivalent Meaning of
    /// Concept Name: "Equivalent diameter, 2 sqrt(area / pi)"); may be empty.
    std::string meaning;
};

/// One measurement group (TID 1501): a tracked thing and its measurements.
struct SrGroup {
    /// Unique within the report ("Neck at the lowest renal artery"); at most
    /// 64 characters.
    std::string trackingId;
    std::optional<SrCode> findingSite;
    std::vector<SrNumber> numbers;  ///< at least one
};

/// One instance of the series the measurements were made on (evidence).
struct SrSourceInstance {
    std::string sopClassUid;
    std::string sopInstanceUid;
};

/// The SOP Class and Instance UIDs of `files` (a source series' files, as
/// scanDicom() lists them), read from their headers up to the pixel data.
/// Throws IoError naming a file that cannot be read, FormatError naming one
/// without the two UIDs.
[[nodiscard]] std::vector<SrSourceInstance> readSourceInstances(
    const std::vector<std::filesystem::path>& files);

struct MeasurementReportContent {
    /// The modality of the source series ("CT", "MR"; empty for a mesh made
    /// elsewhere): chooses the procedure reported.
    std::string sourceModality;
    /// The source series (its study is ExportStudy's); empty for a mesh
    /// without a DICOM source, then no evidence is listed.
    std::string sourceSeriesUid;
    std::vector<SrSourceInstance> sourceInstances;
    std::vector<SrGroup> groups;  ///< at least one
};

/// Writes `content` as an Enhanced SR Storage instance (modality SR,
/// complete, unverified) in a new series of `study` to `path`, atomically:
/// TID 1500 with language English, VesselView as the device observer, an
/// empty image library, the source series' instances as the Current
/// Requested Procedure Evidence. Returns the SOP Instance UID. Throws
/// InvalidArgumentError for no group, a group without measurements, a
/// tracking identifier empty, repeated or over 64 characters, a non-finite
/// value or an empty code; IoError naming `path` when it cannot be written.
std::string writeMeasurementReport(const std::filesystem::path& path,
                                   const MeasurementReportContent& content,
                                   const ExportStudy& study, const ExportSeries& series);

}  // namespace vv::dicom
