// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// The PDF report's Measurements section from a measurement file: its
// tables worded in the UI language (context "vv::app::MeasurementText"),
// every value with its unit, a blank one with why.

#include <string>

#include "common/MeasurementFile.h"
#include "vv/report/PdfReport.h"
#include "vv/scene/Volume.h"
#include "vv/slices/WindowLevel.h"

namespace vv::app {

/// Profiles mark a graded narrowing from this diameter reduction on (%):
/// smaller ones lie within what the sections' own scatter gives on a healthy
/// vessel (a few percent), and marking them would hide the real ones.
inline constexpr double kMarkedStenosisPercent = 20.0;

/// A landmark preset's name in the UI language ("Lowest renal artery").
[[nodiscard]] std::string landmarkName(planning::LandmarkKind kind);

/// The side of the square a cross-section is shown in (mm): room around
/// its widest caliper, at least 20 mm.
[[nodiscard]] double sectionFieldMm(double maxDiameterMm) noexcept;

/// How the curved reformation samples a volume along a path whose widest
/// section is `widestMm`: half its width across the path (room around that
/// section, at least 10 mm) and its row spacing (the volume's finest voxel
/// spacing, within 0.25 to 1 mm).
struct ReformationGrid {
    double halfWidthMm = 10.0;
    double rowSpacingMm = 0.5;
};
[[nodiscard]] ReformationGrid reformationGrid(const scene::Volume& volume, double widestMm);

/// Adds to `section` (measurementSection(m)) what only the volume the
/// measurements were made on shows: the curved reformation along m's path
/// (slices::curvedReformation, turned `degrees` about it, its caption in the
/// UI language) and each landmark's section resliced in its plane, grey in
/// `window`. Leaves out what `m` has no positions for (files of the earlier
/// form) and what the volume cannot show. The command line's report and the
/// GUI's take the same pictures from the same file.
void addVolumePictures(report::ReportMeasurementSection& section, const ReportMeasurements& m,
                       const scene::Volume& volume, const slices::Window& window,
                       double degrees = 0.0);

/// Why a sizing value is blank, in the UI language.
[[nodiscard]] std::string blankNote(const planning::Blank& blank);

/// The tables: the landmarks' sections, the lengths between them, the
/// aortic diameters and the aortic lengths and angles (with a sizing table),
/// the branches. Tables without rows are left out.
[[nodiscard]] report::ReportMeasurementSection measurementSection(const ReportMeasurements& m);

}  // namespace vv::app
