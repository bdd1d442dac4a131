// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// A measurement file (issue 35): the planning measurements as `vesselview-cli
// centerline --json` writes them (format "vesselview-measurements-1"), read
// back for the report, and turned into the measurement groups of a DICOM
// TID 1500 Structured Report. Here, not in vv::report: it reads vv::planning's
// types, and the report module reaches no VTK (docs/architecture.md).

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "vv/dicom/MeasurementReport.h"
#include "vv/planning/AorticSizing.h"

namespace vv::app {

struct MeasuredBranch {
    int id = 0;
    std::string name;  ///< as the user named it; empty = "Branch <id>"
    double lengthMm = 0.0;
    /// Its narrowest and widest sections by equivalent diameter (outside its
    /// end zones); nullopt where none measures the vessel.
    std::optional<planning::SectionSizes> narrowest;
    std::optional<planning::SectionSizes> widest;
    /// At the narrowest point against the reference; nullopt = not graded.
    std::optional<double> stenosisDiameterPercent;
    std::optional<double> stenosisAreaPercent;
};

struct MeasuredLandmark {
    std::string name;
    planning::LandmarkKind kind = planning::LandmarkKind::Free;
    /// Its section; nullopt where the section has no closed contour.
    std::optional<planning::SectionSizes> section;
};

struct MeasuredLength {
    std::string from;
    std::string to;
    double alongMm = 0.0;  ///< along the centreline
    double straightMm = 0.0;
};

struct ReportMeasurements {
    std::vector<MeasuredBranch> branches;
    std::vector<MeasuredLandmark> landmarks;
    std::vector<MeasuredLength> lengths;  ///< between every two landmarks
    /// The aortic sizing table; nullopt when no preset landmark was placed.
    std::optional<planning::AorticSizing> sizing;
};

/// The format a measurement file names itself with.
inline constexpr const char* kMeasurementFormat = "vesselview-measurements-1";

/// Reads a measurement file. Throws IoError naming `path` when it cannot be
/// read, FormatError naming it and the problem when it is not a VesselView
/// measurement file (not JSON, another format, a member missing, of the wrong
/// type or not finite, an unknown landmark kind or blank reason, larger than
/// 64 MiB). Never changes the file.
[[nodiscard]] ReportMeasurements readMeasurements(const std::filesystem::path& path);

/// The measurements as TID 1500 measurement groups: one per landmark (its
/// section's diameters and area), one for the lengths between landmarks,
/// one for the aortic sizing table's values, one per branch (length,
/// narrowest and widest equivalent diameters). Blank values are left out.
/// Texts in English (an SR's concept meanings are English).
[[nodiscard]] std::vector<dicom::SrGroup> measurementGroups(const ReportMeasurements& m);

}  // namespace vv::app
