// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/report/ReportJob.h"

#include <QFile>
#include <QString>
#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <functional>
#include <utility>

#include "ReportText.h"
#include "vv/dicom/Dicom.h"
#include "vv/render/MeshStyle.h"
#include "vv/report/DicomExport.h"
#include "vv/report/DicomSource.h"
#include "vv/report/ViewExport.h"
#include "vv/vss/Solver.h"

namespace vv::report {

namespace {

namespace fs = std::filesystem;

/// The job's steps as shares of the whole, in the order they run.
class Steps {
  public:
    explicit Steps(const Progress& progress, double total)
        : progress_(progress), total_(std::max(total, 1.0)) {}

    /// The next step of `weight`: checks for a stop, reports its start and
    /// returns the sub-progress for it.
    Progress next(double weight, const QString& stage) {
        const double begin = done_ / total_;
        done_ += weight;
        const double end = std::min(1.0, done_ / total_);
        progress_.report(begin, stage.toStdString());
        progress_.throwIfCancelled();  // also a stop asked for while reporting
        return progress_.sub(begin, end);
    }

  private:
    const Progress& progress_;
    double total_;
    double done_ = 0.0;
};

constexpr double kRenderWeight = 4.0;
constexpr double kScanWeight = 1.0;
constexpr double kPdfWeight = 1.0;
constexpr double kWriteWeight = 0.5;

/// The study the DICOM exports go into, and the series the data came from.
struct ExportSource {
    DicomStudy study;
    std::string modality;   ///< of the source series; empty for meshes
    std::string seriesUid;  ///< the source series; empty for meshes
    std::vector<std::filesystem::path> files;
};

/// The study the DICOM exports go into: the source's (with its patient) for
/// DICOM data, else a new one.
ExportSource studyOf(const ReportSource& source, bool anonymise, const Progress& progress) {
    ExportSource exports{newStudy(), {}, {}, {}};
    DicomStudy& study = exports.study;
    if (source.dicomPath.empty()) {
        return exports;
    }
    const dicom::DicomScanResult scan = dicom::scanDicom(source.dicomPath, progress);
    std::string uid = source.seriesInstanceUid;
    if (scan.findSeries(uid) == nullptr) {
        // The only image series under the path, as loadSceneSource() takes it.
        const auto all = scan.allSeries();
        uid = all.size() == 1 ? all.front()->seriesInstanceUid : std::string();
    }
    if (const auto found = sourceStudy(scan, uid)) {
        study = found->study;
    }
    if (anonymise && study.patient) {
        study.patient->anonymise = true;
    }
    if (const dicom::DicomSeries* series = scan.findSeries(uid)) {
        exports.modality = series->modality;
        exports.seriesUid = series->seriesInstanceUid;
        exports.files = series->files;
    }
    return exports;
}

/// The exports of mesh data: a new study, with the patient entered for it.
ExportSource meshSource(const ReportJobOptions& options) {
    ExportSource source{newStudy(), {}, {}, {}};
    if (options.patient) {
        source.study.patient = options.patient;
        source.study.patient->anonymise = options.anonymise;
    }
    return source;
}

/// The measurement SR's content: the groups, and the source series'
/// instances as evidence (pseudonyms when anonymising, as the study's UID).
dicom::MeasurementReportContent srContent(const ReportJobOptions& options,
                                          const ExportSource& source, bool anonymise) {
    dicom::MeasurementReportContent content;
    content.groups = options.measurementGroups;
    content.sourceModality = source.modality;
    if (!source.seriesUid.empty()) {
        content.sourceSeriesUid = anonymise ? anonymisedUid(source.seriesUid) : source.seriesUid;
        content.sourceInstances = dicom::readSourceInstances(source.files);
        if (anonymise) {
            for (auto& instance : content.sourceInstances) {
                instance.sopInstanceUid = anonymisedUid(instance.sopInstanceUid);
            }
        }
    }
    return content;
}

/// Writes the measurement SR in a new series of `study`; what was written.
WrittenOutput writeSrOutput(const std::filesystem::path& path,
                            const dicom::MeasurementReportContent& content,
                            const DicomStudy& study) {
    DicomSeries series;
    series.description = "VesselView measurements";
    series.seriesNumber = 902;
    static_cast<void>(writeMeasurementSr(path, content, study, series));
    return {path, "DICOM Structured Report (TID 1500 measurements)"};
}

/// Throws InvalidArgumentError when no output is asked for, or a measurement
/// SR without measurements.
void requireOutputs(const ReportJobOptions& options) {
    const ReportOutputs& out = options.outputs;
    if (out.pdf.empty() && out.png.empty() && out.dicomSc.empty() && out.dicomPdf.empty() &&
        out.dicomSr.empty()) {
        throw InvalidArgumentError("report: no output file given");
    }
    if (!out.dicomSr.empty() && options.measurementGroups.empty()) {
        throw InvalidArgumentError("report: a measurement SR needs measurements");
    }
}

/// The parameter section: only when an array is shown and had a range.
std::optional<ReportParameter> parameterOf(const scene::Scene& scene,
                                           const render::OffscreenOptions& view,
                                           const std::optional<std::pair<float, float>>& range,
                                           const StatsThresholds& thresholds) {
    if (view.display.style.array.empty() || !range) {
        return std::nullopt;
    }
    ReportParameter parameter;
    parameter.name = view.display.style.array;
    parameter.unit = arrayUnit(scene, parameter.name);
    parameter.range = *range;
    parameter.map = view.display.style.colorMap;
    parameter.bins = view.display.style.bins;
    parameter.thresholds = thresholds;
    if (!thresholds.below && !thresholds.above && parameter.name == "wss") {
        parameter.thresholds.below = 0.4;  // low wall shear stress, Pa
    }
    parameter.stats = parameterStats(scene, parameter.name, parameter.thresholds);
    return parameter;
}

/// The bytes of the PDF report at `path`. Throws IoError naming it when it
/// cannot be read, FormatError when it is no PDF.
QByteArray readPdf(const fs::path& path) {
    QFile file(QFile::decodeName(path.c_str()));
    if (!file.open(QIODevice::ReadOnly)) {
        throw IoError(path, "cannot read the exported report: " + file.errorString().toStdString());
    }
    QByteArray bytes = file.readAll();
    if (!bytes.startsWith("%PDF-")) {
        throw FormatError(path, "the exported report is not a PDF file");
    }
    return bytes;
}

/// Runs `write`; an IoError becomes a ReportWriteError (same file, same problem).
void writing(const std::function<void()>& write) {
    try {
        write();
    } catch (const ReportWriteError&) {
        throw;
    } catch (const IoError& e) {
        throw ReportWriteError(e.file(), e.problem());
    }
}

}  // namespace

std::string namedViewCaption(const std::string& name, scene::SceneFrame frame) {
    // In a patient's frame "left" is the patient's left side: the lateral view.
    if (frame == scene::SceneFrame::PatientLps && (name == "left" || name == "right")) {
        return ReportText::tr(
                   name == "left"
                       ? QT_TRANSLATE_NOOP("vv::report::ReportText", "Left lateral view")
                       : QT_TRANSLATE_NOOP("vv::report::ReportText", "Right lateral view"))
            .toStdString();
    }
    static const std::array<std::pair<const char*, const char*>, 9> captions{{
        {"far", QT_TRANSLATE_NOOP("vv::report::ReportText", "Far view")},
        {"medium", QT_TRANSLATE_NOOP("vv::report::ReportText", "Medium view")},
        {"close", QT_TRANSLATE_NOOP("vv::report::ReportText", "Close view")},
        {"anterior", QT_TRANSLATE_NOOP("vv::report::ReportText", "Anterior view")},
        {"posterior", QT_TRANSLATE_NOOP("vv::report::ReportText", "Posterior view")},
        {"left", QT_TRANSLATE_NOOP("vv::report::ReportText", "Left view")},
        {"right", QT_TRANSLATE_NOOP("vv::report::ReportText", "Right view")},
        {"superior", QT_TRANSLATE_NOOP("vv::report::ReportText", "Superior view")},
        {"inferior", QT_TRANSLATE_NOOP("vv::report::ReportText", "Inferior view")},
    }};
    if (name.empty()) {
        return QCoreApplication::translate("vv::report::ReportText",
                                           "Default view, the whole tree fitted")
            .toStdString();
    }
    for (const auto& [key, caption] : captions) {
        if (name == key) {
            return ReportText::tr(caption).toStdString();
        }
    }
    std::string caption = name;
    caption[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(caption[0])));
    return QCoreApplication::translate("vv::report::ReportText", "%1 view")
        .arg(QString::fromStdString(caption))
        .toStdString();
}

std::vector<WrittenOutput> runReportJob(render::OffscreenRenderer& renderer,
                                        const scene::Scene& scene, const ReportJobOptions& options,
                                        const Progress& progress) {
    requireOutputs(options);
    const ReportOutputs& out = options.outputs;
    const bool image = !out.png.empty() || !out.dicomSc.empty();
    const bool report = !out.pdf.empty() || !out.dicomPdf.empty();
    // A report laid out now, or one exported before and sent as it is.
    const bool layout = report && options.existingPdf.empty();
    const render::OffscreenOptions& base = options.view;
    double total = (image ? kRenderWeight * (options.transparent ? 1.5 : 1.0) : 0.0) +
                   (layout ? kRenderWeight * (options.secondView ? 2.0 : 1.0) : 0.0) +
                   (report ? kPdfWeight : 0.0) + kWriteWeight;
    total += options.source.dicomPath.empty() ? 0.0 : kScanWeight;
    Steps steps(progress, total);

    // The study of the DICOM exports and the patient block.
    ExportSource source =
        options.source.dicomPath.empty()
            ? meshSource(options)
            : studyOf(options.source, options.anonymise,
                      steps.next(kScanWeight, ReportText::tr("Reading the patient and study")));
    DicomStudy& study = source.study;

    std::optional<RenderedView> shown;
    if (image) {
        const Progress rendering = steps.next(kRenderWeight * (options.transparent ? 1.5 : 1.0),
                                              ReportText::tr("Rendering the image"));
        ViewExportOptions view;
        view.render = base;
        view.legends = options.legends;
        view.transparentBackground = options.transparent;
        view.centerlines = options.centerlines;
        shown = renderView(renderer, scene, view, rendering);
    }

    QByteArray pdf;
    if (report && !layout) {
        steps.next(kPdfWeight, ReportText::tr("Reading the exported report"));
        pdf = readPdf(options.existingPdf);
    }
    if (layout) {
        // The report's views: 300 dpi across the content width, the view's aspect.
        const int width = reportImageWidth(options.paper);
        const int height = std::max(
            1,
            static_cast<int>(std::lround(width * static_cast<double>(base.height) / base.width)));
        bool smoothed = false;  // a view drew the smooth copy of a coarse scene
        const auto reportView = [&](const std::optional<render::Camera>& camera,
                                    const vss::DepthRange& depthRange, const std::string& caption,
                                    const Progress& rendering) {
            ViewExportOptions view;
            view.render = base;
            view.render.width = width;
            view.render.height = height;
            view.render.camera = camera;
            view.render.display.vss.range = depthRange;
            view.legends = false;  // painted by the report as vectors
            view.centerlines = options.centerlines;
            RenderedView rendered = renderView(renderer, scene, view, rendering);
            smoothed = smoothed || renderer.lastFrameRefined();
            return std::pair{ReportView{rendered.image, caption, rendered.legends}, rendered.range};
        };
        ReportContent content;
        content.title = options.title;
        content.disclaimer = options.disclaimer;
        content.sources = options.source.files;
        if (!options.source.seriesName.empty()) {
            // The series by its name, not by the folder (or file) it was read from.
            content.series = options.source.seriesName;
            std::erase(content.sources, options.source.dicomPath);
        }
        content.syntheticDemo = options.source.syntheticDemo;
        content.segmentation = options.source.segmentation;
        auto [view, range] = reportView(
            base.camera, base.display.vss.range,
            options.viewCaption.empty() ? namedViewCaption({}, scene.frame) : options.viewCaption,
            steps.next(kRenderWeight, ReportText::tr("Rendering the report's view")));
        content.view = std::move(view);
        if (options.secondView) {
            const Progress rendering =
                steps.next(kRenderWeight, ReportText::tr("Rendering the second view"));
            content.secondView =
                reportView(render::presetCamera(scene, width, height, options.secondView->preset,
                                                options.secondView->rotation),
                           options.secondViewDepthRange.value_or(base.display.vss.range),
                           namedViewCaption(options.secondViewName, scene.frame), rendering)
                    .first;
        }
        if (!options.slice.isNull()) {
            const QImage scaled = options.slice.width() >= width
                                      ? options.slice
                                      : options.slice.scaledToWidth(width, Qt::FastTransformation);
            content.slice = ReportView{scaled, options.sliceCaption, {}};
        }
        steps.next(kPdfWeight, ReportText::tr("Laying out the PDF"));
        content.parameter = parameterOf(scene, base, range, options.thresholds);
        content.settings.vss = base.display.vss;
        content.settings.errorBound = vss::makeSolver(base.display.vss.solver)->errorBound();
        content.settings.cue = base.display.cue;
        content.settings.ambientOcclusion = base.display.ao.enabled;
        content.settings.antialiasing = base.display.antialiasing;
        if (smoothed && base.refined) {
            content.settings.smoothedWallMm = base.refined->largestDeviationMm;
        }
        content.settings.view = options.viewDescription.empty()
                                    ? ReportText::tr("default (fitted)").toStdString()
                                    : options.viewDescription;
        content.findings = options.findings;
        content.measurements = options.measurements;
        content.patient = study.patient;
        pdf = renderPdf(content, options.paper);
    }

    // The SR's evidence is read before anything is written.
    const std::optional<dicom::MeasurementReportContent> sr =
        out.dicomSr.empty()
            ? std::nullopt
            : std::optional(srContent(options, source, options.anonymise && study.patient));

    // Last chance to stop: from here on the outputs are written.
    steps.next(kWriteWeight, ReportText::tr("Writing the files"));
    std::vector<WrittenOutput> written;
    if (!out.png.empty()) {
        writing([&] { writePng(out.png, shown->image); });
        written.push_back({out.png, std::to_string(shown->image.width()) + "x" +
                                        std::to_string(shown->image.height()) +
                                        (options.transparent ? ", transparent background" : "")});
    }
    if (!out.dicomSc.empty()) {
        writing([&] { (void)writeSecondaryCapture(out.dicomSc, shown->image, study); });
        written.push_back({out.dicomSc, "DICOM Secondary Capture"});
    }
    if (!out.pdf.empty()) {
        writing([&] { writePdfBytes(out.pdf, pdf); });
        written.push_back({out.pdf, std::string("PDF report, ") +
                                        (options.paper == PaperSize::A4 ? "A4" : "Letter")});
    }
    if (!out.dicomPdf.empty()) {
        writing([&] {
            (void)writeEncapsulatedPdf(out.dicomPdf, pdf,
                                       options.title.empty() ? defaultReportTitle() : options.title,
                                       study);
        });
        written.push_back({out.dicomPdf, "DICOM Encapsulated PDF"});
    }
    if (sr) {
        writing([&] { written.push_back(writeSrOutput(out.dicomSr, *sr, study)); });
    }
    return written;
}

}  // namespace vv::report
