// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QByteArray>
#include <QDateTime>
#include <QImage>
#include <array>
#include <filesystem>
#include <glm/vec2.hpp>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "vv/colormaps/ColorMap.h"
#include "vv/render/FrameSettings.h"
#include "vv/render/LegendPainter.h"
#include "vv/report/ParameterStats.h"
#include "vv/report/ReportPatient.h"

namespace vv::report {

enum class PaperSize {
    A4,      ///< 210 x 297 mm
    Letter,  ///< 8.5 x 11 in
};

/// "a4" / "letter" (ASCII case-insensitive); nullopt otherwise.
[[nodiscard]] std::optional<PaperSize> paperSizeFromName(std::string_view name) noexcept;

/// Pixels across the report's content width at 300 dpi for `paper`: render
/// the views at least this wide (wider is fine; narrower is refused).
[[nodiscard]] int reportImageWidth(PaperSize paper) noexcept;

/// One rendered view in the report. The image carries no legends: the
/// report paints `legends` over it as vectors (render::paintLegends, the same
/// boxes as on screen, at the size they have on a 1100-pixel-wide view).
struct ReportView {
    QImage image;
    std::string caption;  ///< e.g. "Far view" (already translated)
    render::Legends legends;
};

/// The parameter part of a report: only when the scene shows an array.
struct ReportParameter {
    std::string name;                           ///< the point array
    std::string unit;                           ///< e.g. "Pa"; empty when unknown
    std::pair<float, float> range{0.0F, 1.0F};  ///< the colour map's range
    colormaps::ColorMap map = colormaps::ColorMap::Viridis;
    int bins = 0;
    StatsThresholds thresholds;
    std::vector<ParameterStats> stats;  ///< one row per object
};

/// How the vessels were segmented from the DICOM series: the report's
/// "Segmentation" section, under the data. Its texts are in the report's
/// language, made by the caller (the front ends: app::reportSegmentation).
struct ReportSegmentation {
    /// Label and value of each setting, e.g. {"Threshold", "200 – 700 HU (CT
    /// angiography default)"}, in this order.
    std::vector<std::pair<std::string, std::string>> settings;
    /// What the reader must know about it, one sentence each (e.g. that a
    /// vessel may be cut off): printed under the settings in the warning colour.
    std::vector<std::string> warnings;
};

/// The rendering settings the report lists.
struct ReportSettings {
    render::VssSettings vss;
    double errorBound = 0.0;  ///< of the solver (vss::Solver::errorBound); NaN = none
    render::VesselCueSettings cue;
    bool ambientOcclusion = true;
    bool antialiasing = true;
    std::string view;  ///< the camera, e.g. "far"
    /// When a view drew the smooth copy of a coarse scene (OffscreenOptions::
    /// refined): the most it moves the wall, mm.
    std::optional<double> smoothedWallMm;
};

/// One value of a measurement table: a number with its unit and decimals,
/// or blank (a dash) with the reason, which the table's note lists.
struct MeasurementCell {
    std::optional<double> value;
    int decimals = 1;
    std::string unit;       ///< "mm", "mm²", "°"; empty = none
    std::string blankNote;  ///< why it is blank, in the report's language
};

/// A measurement as the report prints it: the number in the UI locale without
/// group separators and with its unit ("15,0 mm", "35°"), or a dash when blank.
/// UTF-8; the GUI's tables print the same.
[[nodiscard]] std::string measurementCellText(const MeasurementCell& cell);

/// One row: what is measured and its values, one per column after the first.
struct MeasurementRow {
    std::string label;
    std::vector<MeasurementCell> cells;
};

/// One table of the Measurements section, every text in the report's
/// language (the front end words them).
struct MeasurementTable {
    std::string title;                 ///< printed above it
    std::vector<std::string> columns;  ///< headers, the label column's first
    std::vector<MeasurementRow> rows;
    std::string note;  ///< under it (the definitions of its values)
};

/// A place marked along a profile or a reformation: a landmark (its name)
/// or a stenosis (its percent).
struct PathMark {
    double pathMm = 0.0;
    std::string label;
};

/// The diameter profile along a path, drawn as a chart: each series against
/// the distance along the path, a gap where a value is NaN (no section
/// measures the vessel there), the landmarks as dashed vertical lines with
/// their names, the stenoses as marks with their percent.
struct ProfileFigure {
    std::string title;  ///< above it
    std::string note;   ///< under it: what the lines are
    double lengthMm = 0.0;
    std::vector<double> pathMm;
    struct Series {
        std::string name;            ///< in the legend
        std::vector<double> values;  ///< one per pathMm, mm; NaN = a gap
    };
    /// Drawn in the report's colours in order: equivalent, minimum, maximum.
    std::vector<Series> series;
    std::vector<PathMark> landmarks;
    std::vector<PathMark> stenoses;
    std::string xTitle;  ///< "Distance along the path (mm)"
    std::string yTitle;  ///< "Diameter (mm)"
};

/// A cross-section at a landmark: the lumen contour and the calipers of its
/// minimum and maximum diameter, in the section's plane ((u, v) mm about the
/// centreline point, v up), over the volume resliced there when there is one.
struct SectionFigure {
    std::string title;    ///< the landmark's name
    std::string caption;  ///< its sizes in words
    std::vector<glm::dvec2> contour;
    std::optional<std::array<glm::dvec2, 2>> minCaliper;
    std::optional<std::array<glm::dvec2, 2>> maxCaliper;
    double fieldMm = 40.0;  ///< the square's side
    QImage image;           ///< optional: the resliced volume over that square
};

/// The stretched curved reformation along the path: the path straight along
/// x (0 .. lengthMm), across it +-halfWidthMm; the landmarks marked.
struct ReformationFigure {
    QImage image;
    double lengthMm = 0.0;
    double halfWidthMm = 0.0;
    std::vector<PathMark> landmarks;
    std::string caption;
};

/// The planning measurements (issue 35): the landmarks, the lengths between
/// them, the aortic sizing table, the branches; the diameter profile, the
/// curved reformation and the cross-section at each landmark.
struct ReportMeasurementSection {
    std::vector<MeasurementTable> tables;
    std::optional<ProfileFigure> profile;
    std::optional<ReformationFigure> reformation;
    std::vector<SectionFigure> sections;
};

/// The report's title when none is given: "Vessel tree report", translated.
[[nodiscard]] std::string defaultReportTitle();

/// The disclaimer line when none is configured: "Not for diagnostic use.",
/// translated (call after the translator is installed).
[[nodiscard]] std::string defaultDisclaimer();
/// Whether `text` is the default disclaimer, in the UI language or in English
/// (what a setting keeps must follow the UI language when it is the default).
[[nodiscard]] bool isDefaultDisclaimer(std::string_view text);

/// Everything the PDF report shows, in this order: the title block and the
/// disclaimer, the patient (when given), the findings, the view(s), the
/// parameter statistics, the measurements, the data (file names, provenance), the segmentation
/// and the rendering settings. Absent parts are left out of the page (no
/// patient block without `patient`, no parameter legend and table without
/// `parameter`, no second view without `secondView`, no segmentation section
/// without `segmentation`). Every text is translated
/// (QCoreApplication::translate, context "vv::report::ReportText") and every
/// number and date is formatted in the default QLocale (the UI language).
struct ReportContent {
    std::string title;  ///< empty = defaultReportTitle()
    /// The line under the title, e.g. "Not for diagnostic use."; empty = none.
    std::string disclaimer = defaultDisclaimer();
    std::optional<ReportPatient> patient;
    /// The data files: listed by file name only (folders often hold user or
    /// patient names); only their count when the patient is anonymised.
    std::vector<std::filesystem::path> sources;
    /// The DICOM series the data came from, by name (ReportSource::seriesName);
    /// listed before the files; empty = none.
    std::string series;
    /// The data is VesselView's synthetic demo tree, not patient data: the
    /// report says so.
    bool syntheticDemo = false;
    /// How the series was segmented (after the data); none for meshes.
    std::optional<ReportSegmentation> segmentation;
    ReportView view;
    std::optional<ReportView> secondView;
    /// A slice of the volume with its segmentation overlay (DICOM data),
    /// under the view(s); no legends.
    std::optional<ReportView> slice;
    std::optional<ReportParameter> parameter;
    /// The Measurements section, after the parameter statistics; none = left out.
    std::optional<ReportMeasurementSection> measurements;
    ReportSettings settings;
    std::string findings;  ///< free text; may have several lines
    QDateTime created = QDateTime::currentDateTime();
};

/// The report as PDF bytes on `paper`. Throws InvalidArgumentError when the
/// view is missing or narrower than reportImageWidth(paper) (print resolution).
[[nodiscard]] QByteArray renderPdf(const ReportContent& content, PaperSize paper);

/// renderPdf() written to `path` atomically (no partial file on failure, an
/// existing file untouched). Throws InvalidArgumentError as renderPdf(),
/// IoError naming `path` when it cannot be written.
void writePdf(const std::filesystem::path& path, const ReportContent& content, PaperSize paper);

/// Writes PDF bytes made by renderPdf() to `path` atomically (as writePdf).
/// Throws IoError naming `path` when it cannot be written.
void writePdfBytes(const std::filesystem::path& path, const QByteArray& pdf);

}  // namespace vv::report
