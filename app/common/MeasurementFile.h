// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// A measurement file (issue 35): the planning measurements as `vesselview-cli
// centerline --json` and the GUI's Analysis section write them (format
// "vesselview-measurements-1"), read back for the report, and turned into the
// measurement groups of a DICOM TID 1500 Structured Report. Here, not in vv::report: it reads
// vv::planning's types, and the report module reaches no VTK (docs/architecture.md).

#include <array>
#include <filesystem>
#include <glm/vec3.hpp>
#include <iosfwd>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "vv/analysis/Sections.h"
#include "vv/analysis/Stenosis.h"
#include "vv/dicom/MeasurementReport.h"
#include "vv/planning/AorticSizing.h"
#include "vv/planning/VesselPath.h"

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
    /// Where its narrowest point lies along the file's path; nullopt off it.
    std::optional<double> stenosisPathMm;
};

struct MeasuredLandmark {
    std::string name;
    planning::LandmarkKind kind = planning::LandmarkKind::Free;
    /// Its section; nullopt where the section has no closed contour.
    std::optional<planning::SectionSizes> section;
    /// Where it lies along the file's path; nullopt off it.
    std::optional<double> pathMm;
    /// The section's lumen contour and calipers in its plane, (u, v) mm about
    /// the centreline point; empty / nullopt in files without them.
    std::vector<glm::dvec2> contour;
    std::optional<std::array<glm::dvec2, 2>> minCaliper;
    std::optional<std::array<glm::dvec2, 2>> maxCaliper;
    /// The section's plane (its centre and in-plane axes u, v), in files
    /// that have it: where a volume is resliced to show the section.
    struct Plane {
        glm::dvec3 centre{0.0};
        glm::dvec3 u{1.0, 0.0, 0.0};
        glm::dvec3 v{0.0, 1.0, 0.0};
    };
    std::optional<Plane> plane;
};

/// The diameter profile along the file's path.
struct MeasuredProfile {
    int fromEnd = 0;
    int toEnd = 0;
    double lengthMm = 0.0;
    bool chosen = false;  ///< chosen by the user (else the source to the farthest end)
    struct Point {
        double pathMm = 0.0;
        /// nullopt where no section measures the vessel (an end, a junction).
        std::optional<double> equivalentMm, minMm, maxMm, areaMm2;
        /// The centreline point, in files that have it (the reformation's path).
        std::optional<glm::dvec3> position;
    };
    std::vector<Point> points;
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
    /// The profile along the path; nullopt in files without one.
    std::optional<MeasuredProfile> profile;
};

/// The format a measurement file names itself with.
inline constexpr const char* kMeasurementFormat = "vesselview-measurements-1";

// Writing ---------------------------------------------------------------------

/// A landmark placed on the tree, and, when it was placed from a point (the
/// command line's --landmark), that point and its distance from the
/// centreline.
struct PlacedLandmark {
    planning::Landmark landmark;
    std::optional<glm::dvec3> given;
    double distanceMm = 0.0;
};

/// What a measurement file is written from: the analysis, the landmarks,
/// the names the user gave branches (by branch id; others are "Branch N"),
/// and the path chosen to measure along (from one end to another), if any.
struct MeasurementInput {
    const analysis::VesselAnalysis* analysis = nullptr;  ///< not null
    std::vector<PlacedLandmark> landmarks;
    std::map<int, std::string> branchNames;
    /// The stenosis references the user set, by branch id (others automatic).
    std::map<int, analysis::StenosisReference> stenosisReferences;
    struct Path {
        int fromEnd = 0;
        int toEnd = 0;
    };
    std::optional<Path> path;
};

/// The narrowest and widest sections of a branch by equivalent diameter,
/// outside its end zones (analysis::CrossSection::measuresTheVessel());
/// null where none measures the vessel.
struct BranchExtremes {
    const analysis::CrossSection* narrowest = nullptr;
    const analysis::CrossSection* widest = nullptr;
};
[[nodiscard]] BranchExtremes branchExtremes(const std::vector<analysis::CrossSection>& sections);

/// Writes the measurement file's JSON to `out`: the format name, the
/// diameters' definitions, each branch (its name when given, length,
/// tortuosity, narrowest and widest sections, stenosis), the bifurcations,
/// the analysis's notes, the chosen path, and with landmarks each one's
/// place and section, the lengths along the centreline and straight between
/// every two, and, when a preset is among them, the aortic sizing table
/// (each value, or null with why). Numbers in the C locale, shortest exact
/// form. Throws InvalidArgumentError for landmarks or a path that do not lie
/// on the analysis's tree.
void writeMeasurementJson(std::ostream& out, const MeasurementInput& input);

/// writeMeasurementJson() into `path`, atomically. Throws IoError naming
/// `path` when it cannot be written.
void writeMeasurementFile(const std::filesystem::path& path, const MeasurementInput& input);

/// What readMeasurements() would read from the file writeMeasurementJson()
/// writes: the report's measurements straight from the analysis, by the one
/// format's one reader.
[[nodiscard]] ReportMeasurements measurementsOf(const MeasurementInput& input);

// Reading ---------------------------------------------------------------------

/// Reads a measurement file. Throws IoError naming `path` when it cannot be
/// read, FormatError naming it and the problem when it is not a VesselView
/// measurement file (not JSON, another format, a member missing, of the wrong
/// type or not finite, an unknown landmark kind or blank reason, larger than
/// 64 MiB). Never changes the file.
[[nodiscard]] ReportMeasurements readMeasurements(const std::filesystem::path& path);
/// Reads a measurement file's `text`, naming `file` in its errors (FormatError
/// as readMeasurements()).
[[nodiscard]] ReportMeasurements readMeasurementText(const std::string& text,
                                                     const std::filesystem::path& file);

/// The measurements as TID 1500 measurement groups: one per landmark (its
/// section's diameters and area), one for the lengths between landmarks,
/// one for the aortic sizing table's values, one per branch (length,
/// narrowest and widest equivalent diameters). Blank values are left out.
/// Texts in English (an SR's concept meanings are English).
[[nodiscard]] std::vector<dicom::SrGroup> measurementGroups(const ReportMeasurements& m);

}  // namespace vv::app
