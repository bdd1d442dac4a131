// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "vv/core/Error.h"
#include "vv/core/Progress.h"
#include "vv/dicom/MeasurementReport.h"
#include "vv/render/CenterlineOverlay.h"
#include "vv/render/OffscreenRenderer.h"
#include "vv/render/ViewPresets.h"
#include "vv/report/ParameterStats.h"
#include "vv/report/PdfReport.h"
#include "vv/scene/Mesh.h"
#include "vv/vss/DepthNormalization.h"

namespace vv::report {

/// Where the data of a report came from.
struct ReportSource {
    /// The data files, listed in the report by file name.
    std::vector<std::filesystem::path> files;
    /// DICOM data: the path the series was loaded from (folder, DICOMDIR or
    /// file); empty for meshes (then the patient block is what
    /// ReportJobOptions::patient gives, and the DICOM exports go into a new study).
    std::filesystem::path dicomPath;
    /// The loaded series; empty = the only image series under dicomPath.
    std::string seriesInstanceUid;
    /// The loaded series as a user knows it (its description, else modality
    /// and number; never its UID): the report lists it as the data in place
    /// of dicomPath's name (a study store's folder is a UID). Empty = list
    /// dicomPath by its name.
    std::string seriesName;
    /// The data is VesselView's synthetic demo tree (the report says so).
    bool syntheticDemo = false;
    /// How the vessels were segmented from the series (the settings that made
    /// the segmentation shown and sent, and its warnings); none for meshes and SEGs.
    std::optional<ReportSegmentation> segmentation;
};

/// The files of one report; empty paths are not written.
struct ReportOutputs {
    std::filesystem::path pdf;
    std::filesystem::path png;       ///< the view as an image (legends, transparency as asked)
    std::filesystem::path dicomSc;   ///< that image as DICOM Secondary Capture
    std::filesystem::path dicomPdf;  ///< the PDF as DICOM Encapsulated PDF
    /// The planning measurements as a DICOM TID 1500 Structured Report
    /// (ReportJobOptions::measurementGroups; the source series as evidence).
    std::filesystem::path dicomSr;
};

/// Everything one report needs besides the scene.
struct ReportJobOptions {
    /// The view: camera, style (array, colour map, range), VSS, cue, AO, FXAA,
    /// background. width x height is the size of the PNG / Secondary Capture
    /// and the aspect of the report's views (rendered 300 dpi wide). Without a
    /// camera the view is the default orientation fitted to the scene.
    render::OffscreenOptions view;
    /// Caption under the view in the PDF, e.g. "Far view"; empty =
    /// namedViewCaption("") (the default view's).
    std::string viewCaption;
    /// The camera as the settings table names it, e.g. "far"; empty = "default
    /// (fitted)", translated.
    std::string viewDescription;
    /// An optional second view (a preset camera on the scene) and its name.
    std::optional<render::NamedView> secondView;
    std::string secondViewName;
    /// The depth range of the second view; nullopt = view.display.vss.range. Every
    /// legend describes its own image: when `view` pins the first view's
    /// "Visible vessels" range to the screen's (gui::currentViewOptions), the
    /// second view, another camera, takes the range the user chose (its own
    /// visible range, or a fixed range, which then applies to both).
    std::optional<vss::DepthRange> secondViewDepthRange;
    /// An optional slice image (the GUI's slice view with the segmentation
    /// overlay and orientation letters) and its caption: shown in the PDF
    /// under the view(s), scaled to the content width without smoothing
    /// (voxels stay sharp).
    QImage slice;
    std::string sliceCaption;
    /// Centrelines over every view (ViewExportOptions::centerlines): the
    /// PNG, the Secondary Capture and the PDF's views, each with their
    /// legend; nullopt = none.
    std::optional<render::CenterlineOverlay> centerlines;
    bool legends = true;       ///< legends on the PNG / Secondary Capture
    bool transparent = false;  ///< transparent background of the PNG
    /// Print "anonymised" for the patient and leave the identifiers out of the
    /// DICOM exports (only meaningful for DICOM data).
    bool anonymise = false;
    /// The patient and study entered for mesh data (meshes carry none): the
    /// report's patient block and the DICOM exports' patient module. DICOM
    /// data takes its own and ignores this.
    std::optional<ReportPatient> patient;
    std::string title;  ///< empty = defaultReportTitle()
    /// The line under the title; empty = none.
    std::string disclaimer = defaultDisclaimer();
    std::string findings;  ///< free text, may have several lines
    /// The PDF's Measurements section (planning measurements, worded by the
    /// front end); none = left out.
    std::optional<ReportMeasurementSection> measurements;
    /// The same measurements as TID 1500 groups, for outputs.dicomSr.
    std::vector<dicom::SrGroup> measurementGroups;
    /// A PDF report exported before for the same data (File > Export
    /// Report): the PDF outputs are its bytes as they are (its findings,
    /// views and paper), instead of a new layout. Empty = lay out a new one.
    std::filesystem::path existingPdf;
    PaperSize paper = PaperSize::A4;
    /// Thresholds of the area fractions; with neither given and the array
    /// "wss", "below 0.4" (low wall shear stress, Pa).
    StatsThresholds thresholds;
    ReportSource source;
    ReportOutputs outputs;
};

/// One file the job wrote.
struct WrittenOutput {
    std::filesystem::path path;
    std::string description;  ///< e.g. "PDF report, A4", "1600x1200, transparent background"
};

/// Thrown when an output cannot be written: the file and the reason.
class ReportWriteError : public IoError {
  public:
    using IoError::IoError;
};

/// Caption of a named view for the report: "Far view", "Anterior view"
/// (translated); an empty name gives the default view's caption. In a
/// patient's frame "left" / "right" are the lateral views ("Left lateral
/// view"), as the viewer's buttons name them; a mesh's frame keeps "Left view".
[[nodiscard]] std::string namedViewCaption(const std::string& name,
                                           scene::SceneFrame frame = scene::SceneFrame::Unknown);

/// Builds the report of `scene` and writes every requested output: renders
/// the view(s) with `renderer` (which must belong to the calling thread),
/// computes the parameter statistics, lays out the PDF and reads the patient
/// and study from the DICOM source. Everything is computed in memory first;
/// only then are the outputs written, each atomically, in the order PNG,
/// Secondary Capture, PDF, Encapsulated PDF. `progress` is told each step and
/// checked for a stop between steps (a render itself is not interrupted):
/// a cancelled job throws CancelledError before anything is written, so no
/// output file is created or changed. Returns the files written.
/// Throws InvalidArgumentError (size beyond 8K, no outputs, a bad threshold),
/// RenderError (GL), IoError / FormatError reading the DICOM source or
/// `existingPdf` (naming it; not a PDF),
/// ReportWriteError when an output cannot be written (outputs before it stay
/// written), CancelledError.
std::vector<WrittenOutput> runReportJob(render::OffscreenRenderer& renderer,
                                        const scene::Scene& scene, const ReportJobOptions& options,
                                        const Progress& progress = {});

}  // namespace vv::report
