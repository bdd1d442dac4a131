// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// The PDF report's Measurements section from a measurement file: its
// tables worded in the UI language (context "vv::app::MeasurementText"),
// every value with its unit, a blank one with why.

#include <string>

#include "common/MeasurementFile.h"
#include "vv/report/PdfReport.h"

namespace vv::app {

/// Profiles mark a graded narrowing from this diameter reduction on (%):
/// smaller ones lie within what the sections' own scatter gives on a healthy
/// vessel (a few percent), and marking them would hide the real ones.
inline constexpr double kMarkedStenosisPercent = 20.0;

/// A landmark preset's name in the UI language ("Lowest renal artery").
[[nodiscard]] std::string landmarkName(planning::LandmarkKind kind);

/// Why a sizing value is blank, in the UI language.
[[nodiscard]] std::string blankNote(const planning::Blank& blank);

/// The tables: the landmarks' sections, the lengths between them, the
/// aortic diameters and the aortic lengths and angles (with a sizing table),
/// the branches. Tables without rows are left out.
[[nodiscard]] report::ReportMeasurementSection measurementSection(const ReportMeasurements& m);

}  // namespace vv::app
