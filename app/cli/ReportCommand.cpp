// SPDX-License-Identifier: GPL-3.0-or-later
// vesselview-cli report INPUT -o OUT.pdf [render options] [--png OUT.png]
//                       [--dicom-sc OUT.dcm] [--dicom-pdf OUT.dcm] [--transparent]
//                       [--measurements MEAS.json [--dicom-sr SR.dcm]]
//                       [--anonymise] [--note TEXT] [--title TEXT] [--second-view VIEW]
//                       [--paper a4|letter] [--below V] [--above V]
//                       [--slice axial|coronal|sagittal[@MM]] (DICOM image series)
//                       [--lang en|de] [--disclaimer TEXT] [patient options for meshes:
//                       --patient-name PN --patient-id ID --birth-date YYYYMMDD
//                       --sex F|M|O --study-date YYYYMMDD --accession A --referring-physician PN]
//                       [DICOM options as for render: --series UID, --threshold LO:HI, ...]
// vesselview-cli report --session F.vvs -o OUT.pdf [the same options]: the
//                       session's files, camera and display settings (as render --session)
// vesselview-cli report --batch LIST.txt --out-dir DIR [--formats pdf,png,dicom-sc,dicom-pdf]
//                       [the same options]
#include "cli/ReportCommand.h"

#include <QCoreApplication>
#include <QDate>
#include <QFile>
#include <QLocale>
#include <QString>
#include <algorithm>
#include <array>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <optional>
#include <ostream>
#include <set>
#include <string>
#include <vector>

#include "cli/Arguments.h"
#include "cli/CenterlineDrawing.h"
#include "cli/Cli.h"
#include "cli/GuiApplication.h"
#include "cli/OutputFiles.h"
#include "cli/RenderOptions.h"
#include "cli/SegmentSummary.h"
#include "common/MeasurementSection.h"
#include "common/ResourcePaths.h"
#include "common/SegmentationText.h"
#include "common/SliceReport.h"
#include "vv/core/Error.h"
#include "vv/render/OffscreenRenderer.h"
#include "vv/report/PdfReport.h"
#include "vv/report/ReportJob.h"
#include "vv/report/ViewExport.h"
#include "vv/segmentation/SceneSource.h"
#include "vv/slices/WindowLevel.h"

namespace vv::cli {

namespace {

namespace fs = std::filesystem;

using Outputs = report::ReportOutputs;

struct ReportArguments : RenderOptionValues {
    fs::path input;
    Outputs outputs;
    /// A measurement file (centerline --json): the PDF's Measurements
    /// section and the --dicom-sr report.
    fs::path measurements;
    fs::path batch;
    fs::path outDir;
    std::set<std::string> formats{"pdf"};
    bool transparent = false;
    bool anonymise = false;
    std::string note;
    std::string title;  ///< empty = the translated default
    std::string language = "en";
    std::optional<std::string> disclaimer;  ///< nullopt = the translated default
    std::optional<report::ReportPatient> patient;
    std::optional<render::NamedView> secondView;
    std::string secondViewName;
    /// --slice: the plane and, when given, the position (mm, LPS).
    std::optional<slices::SliceOrientation> slice;
    std::optional<double> slicePosition;
    report::PaperSize paper = report::PaperSize::A4;
    report::StatsThresholds thresholds;
};

/// --birth-date / --study-date: a valid date as YYYYMMDD (DICOM DA).
std::string dicomDate(const std::string& value, const std::string& option) {
    const QDate date = QDate::fromString(QString::fromStdString(value), QStringLiteral("yyyyMMdd"));
    if (value.size() != 8 || !date.isValid()) {
        throw UsageError(option + " must be a date as YYYYMMDD, got '" + value + "'");
    }
    return value;
}

/// --slice PLANE[@MM]: the plane and its position along the plane's world
/// axis, as a signed LPS coordinate ("axial@-120") or as the slice views
/// write it, the patient side first ("axial@I120", "coronal@A12.5").
void parseSlice(const std::string& value, ReportArguments& parsed) {
    const auto at = value.find('@');
    const std::string plane = value.substr(0, at);
    parsed.slice = app::sliceOrientationFromName(plane);
    if (!parsed.slice) {
        throw UsageError("--slice must be axial, coronal or sagittal (optionally @MM), got '" +
                         value + "'");
    }
    if (at == std::string::npos) {
        return;
    }
    std::string position = value.substr(at + 1);
    // The letters of the plane's axis: positive (L, P, S) and negative (R, A, I) side.
    static constexpr std::array<std::pair<char, char>, 3> kSides{
        {{'L', 'R'}, {'P', 'A'}, {'S', 'I'}}};
    const auto [positive, negative] =
        kSides.at(static_cast<std::size_t>(slices::sliceAxis(*parsed.slice)));
    double sign = 1.0;
    if (!position.empty() && std::isalpha(static_cast<unsigned char>(position.front())) != 0) {
        const char side = static_cast<char>(std::toupper(static_cast<unsigned char>(position[0])));
        if (side != positive && side != negative) {
            throw UsageError("--slice " + plane + "@" + position + ": a " + plane +
                             " position lies along " + positive + "/" + negative + ", not " +
                             position.front());
        }
        sign = side == positive ? 1.0 : -1.0;
        position.erase(0, 1);
    }
    parsed.slicePosition = sign * parseNumber(position, "--slice position (mm)");
}

/// A patient / study option for meshes; false when `name` is none of them.
bool parsePatientOption(Arguments& a, ReportArguments& parsed) {
    static const std::vector<std::string> names = {
        "--patient-name", "--patient-id", "--birth-date",         "--sex",
        "--study-date",   "--accession",  "--referring-physician"};
    const std::string& name = a.name();
    if (std::find(names.begin(), names.end(), name) == names.end()) {
        return false;
    }
    report::ReportPatient& p = parsed.patient ? *parsed.patient : parsed.patient.emplace();
    const std::string& value = a.value();
    if (name == "--patient-name") {
        p.name = value;
    } else if (name == "--patient-id") {
        p.id = value;
    } else if (name == "--birth-date") {
        p.birthDate = dicomDate(value, name);
    } else if (name == "--sex") {
        if (value != "F" && value != "M" && value != "O") {
            throw UsageError("--sex must be F, M or O, got '" + value + "'");
        }
        p.sex = value;
    } else if (name == "--study-date") {
        p.studyDate = dicomDate(value, name);
    } else if (name == "--accession") {
        p.accession = value;
    } else {
        p.referringPhysician = value;
    }
    return true;
}

ReportArguments parseReportArguments(const std::vector<std::string>& args) {
    ReportArguments parsed;
    bool haveInput = false;
    bool haveFormats = false;
    for (Arguments a("report", args); a.next();) {
        const std::string& name = a.name();
        if (name == "-o" || name == "--output") {
            parsed.outputs.pdf = a.path();
        } else if (name == "--png") {
            parsed.outputs.png = a.path();
        } else if (name == "--dicom-sc") {
            parsed.outputs.dicomSc = a.path();
        } else if (name == "--dicom-pdf") {
            parsed.outputs.dicomPdf = a.path();
        } else if (name == "--dicom-sr") {
            parsed.outputs.dicomSr = a.path();
        } else if (name == "--measurements") {
            parsed.measurements = a.path();
        } else if (name == "--batch") {
            parsed.batch = a.path();
        } else if (name == "--out-dir") {
            parsed.outDir = a.path();
        } else if (name == "--formats") {
            parsed.formats.clear();
            for (const std::string& f : splitList(a.value(), "report: --formats")) {
                if (f != "pdf" && f != "png" && f != "dicom-sc" && f != "dicom-pdf") {
                    throw UsageError("unknown report format '" + f +
                                     "' (known: pdf, png, dicom-sc, dicom-pdf)");
                }
                parsed.formats.insert(f);
            }
            haveFormats = true;
        } else if (name == "--transparent") {
            parsed.transparent = true;
        } else if (name == "--anonymise" || name == "--anonymize") {
            parsed.anonymise = true;
        } else if (name == "--note") {
            parsed.note = a.value();
        } else if (name == "--title") {
            parsed.title = a.value();
        } else if (name == "--disclaimer") {
            parsed.disclaimer = a.value();
        } else if (name == "--lang") {
            parsed.language = a.value();
            checkLanguage("report", parsed.language);
        } else if (name == "--second-view") {
            parsed.secondViewName = a.value();
            parsed.secondView = render::namedViewFromName(parsed.secondViewName);
            if (!parsed.secondView) {
                throw UsageError("unknown view '" + parsed.secondViewName +
                                 "' (known: " + render::namedViewNames() + ")");
            }
        } else if (name == "--slice") {
            parseSlice(a.value(), parsed);
        } else if (name == "--paper") {
            const std::string& paperName = a.value();
            const auto paper = report::paperSizeFromName(paperName);
            if (!paper) {
                throw UsageError("--paper must be a4 or letter, got '" + paperName + "'");
            }
            parsed.paper = *paper;
        } else if (name == "--below") {
            parsed.thresholds.below = parseNumber(a.value(), "--below");
        } else if (name == "--above") {
            parsed.thresholds.above = parseNumber(a.value(), "--above");
        } else if (parseRenderOption(a, parsed) || parsePatientOption(a, parsed)) {
            // a shared render option (RenderOptions.h), the patient of mesh data
        } else {
            a.takeOneInput(parsed.input, haveInput);
        }
    }
    if (parsed.session) {
        if (haveInput || !parsed.batch.empty()) {
            throw UsageError("report: --session names the input files; give no FILE or --batch");
        }
        parsed.input = parsed.sessionFile;
        haveInput = true;
    }
    if (parsed.width > report::kMaxExportSide || parsed.height > report::kMaxExportSide ||
        static_cast<long long>(parsed.width) * parsed.height > report::kMaxExportPixels) {
        throw UsageError("report: --size must be at most 8K (7680x4320)");
    }
    if (!parsed.batch.empty()) {
        if (haveInput || !parsed.outputs.pdf.empty() || !parsed.outputs.png.empty() ||
            !parsed.outputs.dicomSc.empty() || !parsed.outputs.dicomPdf.empty() ||
            !parsed.outputs.dicomSr.empty() || !parsed.measurements.empty()) {
            throw UsageError(
                "report: --batch takes no INPUT, -o, --png, --dicom-* or --measurements; "
                "choose the outputs with --formats");
        }
        if (parsed.outDir.empty()) {
            throw UsageError("report: --batch needs --out-dir DIR");
        }
        return parsed;
    }
    if (haveFormats || !parsed.outDir.empty()) {
        throw UsageError("report: --formats and --out-dir go with --batch");
    }
    if (!haveInput) {
        throw UsageError("report: no input file");
    }
    if (parsed.outputs.pdf.empty()) {
        throw UsageError("report: no output report (-o REPORT.pdf)");
    }
    if (!parsed.outputs.dicomSr.empty() && parsed.measurements.empty()) {
        throw UsageError(
            "report: --dicom-sr writes the measurements: give --measurements MEAS.json");
    }
    return parsed;
}

bool samePath(const fs::path& a, const fs::path& b) {
    std::error_code ec;
    return fs::weakly_canonical(fs::absolute(a), ec) == fs::weakly_canonical(fs::absolute(b), ec);
}

/// Refuses outputs that are the input or each other.
void checkOutputs(const fs::path& input, const Outputs& outputs) {
    std::vector<fs::path> all;
    for (const fs::path* p :
         {&outputs.pdf, &outputs.png, &outputs.dicomSc, &outputs.dicomPdf, &outputs.dicomSr}) {
        if (p->empty()) {
            continue;
        }
        if (samePath(*p, input)) {
            throw UsageError("report: output '" + p->string() + "' would overwrite the input");
        }
        for (const fs::path& other : all) {
            if (samePath(*p, other)) {
                throw UsageError("report: '" + p->string() + "' is given as two outputs");
            }
        }
        all.push_back(*p);
    }
    for (const fs::path& p : all) {
        checkOutputPath(p);
    }
}

std::vector<fs::path> sessionFiles(const app::Session& session) {
    std::vector<fs::path> files;
    for (const QString& file : session.files) {
        files.emplace_back(QFile::encodeName(file).toStdString());
    }
    return files;
}

/// The DICOM source of a session's files: the last one (as loadSessionScene reports it).
fs::path lastDicomSource(const std::vector<fs::path>& files) {
    const auto found = std::find_if(files.rbegin(), files.rend(), [](const fs::path& f) {
        return segmentation::isDicomSource(f);
    });
    return found != files.rend() ? *found : fs::path();
}

/// Loads `input`, renders and writes every requested output (report::runReportJob).
void produce(const ReportArguments& a, const fs::path& input, const Outputs& outputs,
             render::OffscreenRenderer& renderer, std::ostream& out, std::ostream& err) {
    // A mesh file, DICOM segmented into vessel surfaces, or a session's files.
    segmentation::SceneSourceReport loaded;
    const scene::Scene scene = a.session
                                   ? loadSessionInput(a, &loaded)
                                   : segmentation::loadSceneSource(input, a.source, {}, &loaded);
    report::ReportJobOptions job;
    job.view = offscreenOptions(a, scene, input);
    job.viewCaption = report::namedViewCaption(a.viewName, scene.frame);
    job.viewDescription = !a.viewName.empty() ? report::namedViewCaption(a.viewName, scene.frame)
                          : a.sessionCamera ? QCoreApplication::translate("vv::report::ReportText",
                                                                          "as saved in the session")
                                                  .toStdString()
                                            : std::string();  // the default view's description
    job.secondView = a.secondView;
    job.secondViewName = a.secondViewName;
    job.legends = a.legends;
    if (a.centerlines) {
        job.centerlines = centerlineOverlay(scene, input, a.centerlineColouring,
                                            job.view.display.style.colorMap, err);
    }
    job.transparent = a.transparent;
    job.anonymise = a.anonymise;
    job.title = a.title;
    if (a.disclaimer) {
        job.disclaimer = *a.disclaimer;
    }
    job.patient = a.patient;
    job.findings = a.note;
    job.paper = a.paper;
    job.thresholds = a.thresholds;
    job.source.files = a.session ? sessionFiles(*a.session) : std::vector<fs::path>{input};
    if (loaded.fromVolume || loaded.fromSegmentationObject) {
        // The exports join the source study (and its patient).
        job.source.dicomPath = a.session ? lastDicomSource(job.source.files) : input;
        job.source.seriesInstanceUid = loaded.seriesInstanceUid;
        // Listed by its description (as the GUI names it) when it has one.
        job.source.seriesName =
            QString::fromStdString(loaded.seriesDescription).simplified().toStdString();
    }
    if (loaded.fromVolume) {
        // A vessel that may be cut off is said on stderr too, as render and segment say it.
        printCutOffWarnings(err, loaded);
        // How the series was segmented, and whether a vessel may be cut off.
        job.source.segmentation = app::reportSegmentation(app::provenanceOf(
            loaded, a.session && a.session->dicom ? *a.session->dicom : a.source));
    }
    job.source.syntheticDemo =
        !job.source.files.empty() &&
        std::all_of(job.source.files.begin(), job.source.files.end(),
                    [](const fs::path& file) { return app::isDemoFile(file); });
    if (a.slice) {
        if (!loaded.volume) {
            throw UsageError("report: --slice needs a DICOM image series; '" + input.string() +
                             "' is " +
                             (loaded.fromSegmentationObject ? "a DICOM Segmentation object"
                                                            : "not from an image series"));
        }
        // A session's slice views: their window, overlay and the plane's position.
        std::optional<double> position = a.slicePosition;
        std::optional<app::SliceLook> look;
        if (a.session && a.session->slices) {
            const app::SliceSessionState& saved = *a.session->slices;
            if (!position) {
                position = saved.views.at(static_cast<std::size_t>(*a.slice)).position;
            }
            look = app::SliceLook{saved.window, saved.preset, {}};
            look->overlay.fill = saved.fill;
            look->overlay.outline = saved.outline;
        }
        try {
            const app::PrintedSlice slice =
                app::printedSlice(*loaded.volume, loaded.labelMap.get(), *a.slice, position, look);
            job.slice = slice.image;
            job.sliceCaption = slice.caption.toStdString();
        } catch (const InvalidArgumentError& e) {
            throw UsageError("report: --slice: " + input.string() + ": " + e.what());
        }
    }
    if (!a.measurements.empty()) {
        for (const fs::path* p :
             {&outputs.pdf, &outputs.png, &outputs.dicomSc, &outputs.dicomPdf, &outputs.dicomSr}) {
            if (!p->empty() && samePath(*p, a.measurements)) {
                throw UsageError("report: output '" + p->string() +
                                 "' would overwrite the measurements");
            }
        }
        const app::ReportMeasurements measured = app::readMeasurements(a.measurements);
        job.measurements = app::measurementSection(measured);
        job.measurementGroups = app::measurementGroups(measured);
        if (loaded.volume) {
            // An image series: the reformation and the sections over the
            // volume, in its default window (the slice views' first).
            const auto presets = slices::windowPresets(*loaded.volume);
            app::addVolumePictures(
                *job.measurements, measured, *loaded.volume,
                presets.empty() ? slices::Window{300.0, 600.0} : presets.front().window);
        }
    }
    job.outputs = outputs;
    std::vector<report::WrittenOutput> written;
    try {
        written = report::runReportJob(renderer, scene, job);
    } catch (const report::ReportWriteError& e) {
        throw OutputError(e.what());  // exit code 4
    }
    for (const report::WrittenOutput& file : written) {
        out << "wrote " << file.path.string() << " (" << file.description << ")\n";
    }
}

/// The inputs listed in `list`: one path a line, relative to the list's folder;
/// blank lines and lines starting with # are skipped.
std::vector<fs::path> readList(const fs::path& list) {
    std::ifstream in(list);
    if (!in) {
        throw IoError(list, "cannot read the batch list");
    }
    std::vector<fs::path> inputs;
    std::string line;
    while (std::getline(in, line)) {
        const auto first = line.find_first_not_of(" \t\r");
        if (first == std::string::npos || line[first] == '#') {
            continue;
        }
        const auto last = line.find_last_not_of(" \t\r");
        fs::path p = line.substr(first, last - first + 1);
        if (p.is_relative()) {
            p = list.parent_path() / p;
        }
        inputs.push_back(p.lexically_normal());
    }
    if (inputs.empty()) {
        throw FormatError(list, "the batch list names no input");
    }
    return inputs;
}

/// The exit code run() gives `error` (Cli.h).
int exitCode(const std::exception_ptr& error) {
    try {
        std::rethrow_exception(error);
    } catch (const UsageError&) {
        return kUsage;
    } catch (const OutputError&) {
        return kCannotWrite;
    } catch (const RenderError&) {
        return kInternalError;
    } catch (const InvalidArgumentError&) {
        return kUsage;
    } catch (const Error&) {
        return kInvalidInput;
    } catch (...) {
        return kInternalError;
    }
}

int runBatch(const ReportArguments& a, std::ostream& out, std::ostream& err) {
    const std::vector<fs::path> inputs = readList(a.batch);
    std::error_code ec;
    if (!fs::is_directory(a.outDir, ec)) {
        throw OutputError(a.outDir.string() + ": cannot write: the output folder does not exist");
    }
    for (const fs::path& input : inputs) {
        if (samePath(input.parent_path().empty() ? fs::path(".") : input.parent_path(), a.outDir)) {
            throw UsageError("report: --out-dir '" + a.outDir.string() + "' holds input '" +
                             input.string() + "': write the reports into another folder");
        }
    }
    ensureGuiApplication();
    useLanguage(a.language);
    render::OffscreenRenderer renderer;
    std::set<std::string> stems;
    int firstFailure = kOk;
    std::size_t failed = 0;
    for (const fs::path& input : inputs) {
        std::string stem = input.stem().string();
        for (int n = 2; !stems.insert(stem).second; ++n) {
            stem = input.stem().string() + "-" + std::to_string(n);
        }
        Outputs outputs;
        const auto name = [&](const std::string& format, const std::string& suffix) {
            return a.formats.contains(format) ? a.outDir / (stem + suffix) : fs::path();
        };
        outputs.pdf = name("pdf", ".pdf");
        outputs.png = name("png", ".png");
        outputs.dicomSc = name("dicom-sc", "-sc.dcm");
        outputs.dicomPdf = name("dicom-pdf", "-report.dcm");
        try {
            checkOutputs(input, outputs);
            produce(a, input, outputs, renderer, out, err);
        } catch (const std::exception& e) {
            const int code = exitCode(std::current_exception());
            err << "vesselview-cli: report: " << input.string() << ": " << e.what() << "\n";
            if (firstFailure == kOk) {
                firstFailure = code;
            }
            ++failed;
        }
    }
    out << "report: " << inputs.size() - failed << " of " << inputs.size() << " inputs done";
    if (failed > 0) {
        out << ", " << failed << " failed";
    }
    out << " (" << a.outDir.string() << ")\n";
    return firstFailure;
}

}  // namespace

int reportCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
    const ReportArguments parsed = parseReportArguments(args);
    if (!parsed.batch.empty()) {
        return runBatch(parsed, out, err);
    }
    checkOutputs(parsed.input, parsed.outputs);
    ensureGuiApplication();
    useLanguage(parsed.language);
    render::OffscreenRenderer renderer;
    produce(parsed, parsed.input, parsed.outputs, renderer, out, err);
    return kOk;
}

}  // namespace vv::cli
