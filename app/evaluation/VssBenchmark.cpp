// SPDX-License-Identifier: GPL-3.0-or-later
#include "evaluation/VssBenchmark.h"

#include <QColor>
#include <QFile>
#include <QFont>
#include <QGuiApplication>
#include <QPainter>
#include <QPainterPath>
#include <QPen>
#include <QPolygonF>
#include <QString>
#include <QStringList>
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <ctime>
#include <fstream>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <sstream>

#include "vv/core/AtomicFile.h"
#include "vv/core/CsvField.h"
#include "vv/core/Error.h"
#include "vv/core/NumberText.h"
#include "vv/core/Parallel.h"
#include "vv/render/DepthRasterizer.h"
#include "vv/vss/DepthNormalization.h"
#include "vv/vss/Pfm.h"
#include "vv/vss/Vss.h"

namespace vv::evaluation {

namespace {

using Clock = std::chrono::steady_clock;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr int kMaxSide = 8192;

void say(const VssBenchmarkOptions& options, const std::string& line) {
    if (options.log) {
        options.log(line);
    }
}

// Numbers go through the C-locale formatters: the CLI is a Qt application,
// whose QCoreApplication sets LC_NUMERIC from the environment, and the CSV
// must read back under any locale.
using vv::fixedText;
using vv::scientificText;
using vv::significantText;

double median(std::vector<double> values) {
    if (values.empty()) {
        return kNaN;
    }
    std::sort(values.begin(), values.end());
    const std::size_t n = values.size();
    return n % 2 == 1 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

std::string tolerance255(double tolerance) {
    return significantText(tolerance * 255.0, 6) + "/255";
}

std::string sizeText(const BenchSize& size) {
    return std::to_string(size.width) + "x" + std::to_string(size.height);
}

std::int64_t pixelsOf(const BenchSize& size) {
    return static_cast<std::int64_t>(size.width) * size.height;
}

void validate(const VssBenchmarkOptions& options) {
    if (options.sizes.empty()) {
        throw InvalidArgumentError("bench: no image size to measure");
    }
    for (std::size_t i = 0; i < options.sizes.size(); ++i) {
        const BenchSize& size = options.sizes[i];
        if (size.width < 1 || size.height < 1 || size.width > kMaxSide || size.height > kMaxSide) {
            throw InvalidArgumentError("bench: the image size must be within 1x1.." +
                                       std::to_string(kMaxSide) + "x" + std::to_string(kMaxSide) +
                                       ", got " + sizeText(size));
        }
        if (std::find(options.sizes.begin(), options.sizes.begin() + static_cast<long>(i), size) !=
            options.sizes.begin() + static_cast<long>(i)) {
            throw InvalidArgumentError("bench: the size " + sizeText(size) + " appears twice");
        }
    }
    if (options.runs < 1 || options.referenceRuns < 1) {
        throw InvalidArgumentError("bench: the number of runs must be at least 1");
    }
    if (options.views.empty()) {
        throw InvalidArgumentError("bench: no view to measure");
    }
    if (options.powers.empty()) {
        throw InvalidArgumentError("bench: no p to measure");
    }
    for (const double p : options.powers) {
        if (!std::isfinite(p) || p <= 0.0) {
            throw InvalidArgumentError("bench: p must be a finite number > 0, got " +
                                       significantText(p, 6));
        }
    }
    if (options.solvers.empty()) {
        throw InvalidArgumentError("bench: no solver to measure");
    }
    std::set<std::string> labels;
    for (const SolverSetting& s : options.solvers) {
        if (!labels.insert(s.label).second) {
            throw InvalidArgumentError("bench: solver label '" + s.label + "' appears twice");
        }
    }
    if (!options.depthOut.empty()) {
        std::error_code ec;
        if (!std::filesystem::is_directory(options.depthOut, ec)) {
            throw IoError(options.depthOut, "not an existing folder");
        }
    }
}

/// CPU time of the whole process (every thread) in ms.
double processCpuMs() {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) * 1e3 + static_cast<double>(t.tv_nsec) * 1e-6;
}

/// One timed series of runs of a solver on a depth image.
struct Measured {
    std::vector<double> totalMs;
    std::vector<double> interpolateMs;
    std::vector<double> cpuMs;
    vss::VssResult first;  ///< kept only when asked for
    vss::VssResult last;
};

Measured measure(const vss::Solver& solver, const Image<float>& depth,
                 const Image<std::uint8_t>& mask, int runs, bool keepFirst,
                 const std::stop_token& stop) {
    Measured m;
    for (int r = 0; r < runs; ++r) {
        const double cpuStart = processCpuMs();
        const auto start = Clock::now();
        vss::VssResult result = vss::solve(depth.view(), mask.view(), solver, {}, stop);
        const double ms = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
        m.cpuMs.push_back(processCpuMs() - cpuStart);
        m.totalMs.push_back(ms);
        m.interpolateMs.push_back(result.stats.interpolateMs);
        if (keepFirst && r == 0) {
            m.first = result;
        }
        m.last = std::move(result);
    }
    return m;
}

void fillRow(VssBenchmarkRow& row, const Measured& m, const vss::VssResult& reference) {
    row.runs = static_cast<int>(m.totalMs.size());
    row.medianMs = median(m.totalMs);
    row.minMs = *std::min_element(m.totalMs.begin(), m.totalMs.end());
    row.medianInterpolateMs = median(m.interpolateMs);
    row.medianCpuMs = median(m.cpuMs);
    row.error =
        compareToReference(m.last.height.view(), reference.height.view(), reference.labels.view());
    row.regions = m.last.stats.regionCount;
    row.maxContourPixels = m.last.stats.maxContourPixels;
    row.voidPixels = m.last.stats.voidPixels;
    row.errorBound = m.last.errorBound;
}

void markFailed(VssBenchmarkRow& row, const std::string& why) {
    row.failure = why;
    row.runs = 0;
    row.medianMs = row.minMs = row.medianInterpolateMs = row.medianCpuMs = kNaN;
    row.error = ErrorStats{kNaN, kNaN, kNaN, 0, 0};
    row.errorBound = kNaN;
}

/// A CSV value: nine significant digits; empty when not measured (NaN).
std::string number(double value) {
    return std::isnan(value) ? std::string() : significantText(value, 9);
}

/// A CSV time in ms: four decimals; empty when not measured (NaN).
std::string msNumber(double ms) {
    return std::isnan(ms) ? std::string() : fixedText(ms, 4);
}

std::string milliseconds(double ms) {
    if (std::isnan(ms)) {
        return "–";
    }
    return fixedText(ms, ms < 10.0 ? 2 : (ms < 1000.0 ? 1 : 0));
}

std::string scientific(double value) {
    if (std::isnan(value)) {
        return "–";
    }
    if (value == 0.0) {
        return "0";
    }
    if (std::isinf(value)) {
        return "inf";
    }
    return scientificText(value, 2);
}

}  // namespace

std::vector<SolverSetting> defaultSolverSettings() {
    std::vector<SolverSetting> settings;
    const auto add = [&](std::string label, std::string series, vss::SolverKind kind, int step,
                         double tolerance) {
        SolverSetting s;
        s.label = std::move(label);
        s.series = std::move(series);
        s.options.kind = kind;
        s.options.step = step;
        s.options.tolerance = tolerance;
        settings.push_back(std::move(s));
    };
    add("reference", "reference", vss::SolverKind::Reference, 1, 0.5 / 255.0);
    add("brute", "brute", vss::SolverKind::Brute, 1, 0.5 / 255.0);
    add("step 3", "step 3", vss::SolverKind::Step, 3, 0.5 / 255.0);
    add("step 5", "step 5", vss::SolverKind::Step, 5, 0.5 / 255.0);
    for (const double t : {0.5, 2.0, 8.0}) {
        add("fast " + tolerance255(t / 255.0), "fast", vss::SolverKind::Fast, 1, t / 255.0);
    }
    return settings;
}

ErrorStats compareToReference(ImageView<const float> result, ImageView<const float> reference,
                              ImageView<const std::int32_t> labels, double threshold) {
    if (result.width() != reference.width() || result.height() != reference.height() ||
        labels.width() != reference.width() || labels.height() != reference.height()) {
        throw InvalidArgumentError("compareToReference: the images differ in size");
    }
    ErrorStats stats;
    double sum2 = 0.0;
    std::int64_t above = 0;
    for (int y = 0; y < reference.height(); ++y) {
        const float* r = result.row(y);
        const float* e = reference.row(y);
        const std::int32_t* l = labels.row(y);
        for (int x = 0; x < reference.width(); ++x) {
            if (l[x] < 0 || !std::isfinite(e[x])) {
                continue;
            }
            ++stats.compared;
            if (!std::isfinite(r[x])) {
                ++stats.nonFinite;
                ++above;
                stats.maxAbs = std::numeric_limits<double>::infinity();
                continue;
            }
            const double d = std::abs(static_cast<double>(r[x]) - static_cast<double>(e[x]));
            sum2 += d * d;
            stats.maxAbs = std::max(stats.maxAbs, d);
            above += d > threshold ? 1 : 0;
        }
    }
    const std::int64_t finite = stats.compared - stats.nonFinite;
    stats.rmse = finite > 0 ? std::sqrt(sum2 / static_cast<double>(finite)) : 0.0;
    stats.fractionAbove =
        stats.compared > 0 ? static_cast<double>(above) / static_cast<double>(stats.compared) : 0.0;
    return stats;
}

Image<float> benchmarkDepth(const scene::Scene& scene, render::ViewPreset view, int width,
                            int height) {
    const render::Camera camera = render::presetCamera(scene, width, height, view);
    return render::rasterizeDepth(scene, camera);
}

namespace {

/// The ground truth of one case: the reference, or the brute solver (untimed).
struct Truth {
    Measured reference;  ///< the reference's runs when it is the truth
    vss::VssResult brute;
    bool isReference = true;
    [[nodiscard]] const vss::VssResult& result() const {
        return isReference ? reference.first : brute;
    }
};

/// Measures every setting for one size, view and p against truth; appends the rows.
void measureCase(const VssBenchmarkOptions& options, const BenchSize& size, render::ViewPreset view,
                 double p, const Image<float>& depth, const Image<std::uint8_t>& mask,
                 const Truth& truth, std::optional<std::size_t> referenceIndex,
                 VssBenchmarkResult& result) {
    const std::string caseName = (options.sizes.size() > 1 ? sizeText(size) + " " : "") +
                                 std::string(render::toString(view)) +
                                 " p=" + significantText(p, 6);
    for (std::size_t si = 0; si < options.solvers.size(); ++si) {
        const SolverSetting& setting = options.solvers[si];
        VssBenchmarkRow row;
        row.size = size;
        row.view = view;
        row.p = p;
        row.solver = setting.label;
        row.series = setting.series;
        row.options = setting.options;
        row.options.p = p;
        row.truth = truth.isReference ? "reference" : "brute";
        const bool isReference = setting.options.kind == vss::SolverKind::Reference;
        if (isReference && !truth.isReference) {
            markFailed(row, "skipped above " + std::to_string(options.referenceMaxPixels) +
                                " pixels (too slow); the brute solver is the ground truth");
        } else if (referenceIndex && si == *referenceIndex) {
            fillRow(row, truth.reference, truth.result());
        } else {
            try {
                const auto solver = vss::makeSolver(row.options);
                const int runs = isReference ? options.referenceRuns : options.runs;
                const Measured m = measure(*solver, depth, mask, runs, false, options.stop);
                fillRow(row, m, truth.result());
            } catch (const CancelledError&) {
                throw;
            } catch (const InvalidArgumentError&) {
                throw;
            } catch (const Error& e) {
                markFailed(row, e.what());
            }
        }
        if (row.failure.empty()) {
            say(options, caseName + " " + row.solver + ": median " + milliseconds(row.medianMs) +
                             " ms (" + std::to_string(row.runs) + " runs), max error " +
                             scientific(row.error.maxAbs));
        } else {
            say(options, caseName + " " + row.solver + ": not measured: " + row.failure);
        }
        result.rows.push_back(std::move(row));
    }
}

}  // namespace

VssBenchmarkResult runVssBenchmark(const scene::Scene& scene, const VssBenchmarkOptions& options) {
    validate(options);
    VssBenchmarkResult result;
    result.sizes = options.sizes;
    result.threads = workerCount();
    for (const scene::Mesh& mesh : scene.meshes) {
        result.triangles += mesh.triangleCount();
        result.sceneName += (result.sceneName.empty() ? "" : " + ") + mesh.name;
    }

    // The ground truth: the first reference setting, or an untimed reference.
    std::optional<std::size_t> referenceIndex;
    for (std::size_t i = 0; i < options.solvers.size(); ++i) {
        if (options.solvers[i].options.kind == vss::SolverKind::Reference) {
            referenceIndex = i;
            break;
        }
    }

    for (const BenchSize& size : options.sizes) {
        const bool referenceTruth = pixelsOf(size) <= options.referenceMaxPixels;
        for (const render::ViewPreset view : options.views) {
            const std::string viewName(render::toString(view));
            const render::Camera camera =
                render::presetCamera(scene, size.width, size.height, view);
            const Image<float> depth = render::rasterizeDepth(scene, camera, options.stop);
            if (!options.depthOut.empty()) {
                const std::string suffix =
                    options.sizes.size() > 1 ? "-" + sizeText(size) : std::string();
                std::string name = "depth-";
                name += viewName;
                name += suffix;
                name += ".pfm";
                const auto file = options.depthOut / name;
                vss::writePfm(file, depth.view());
                say(options, "wrote " + file.string());
            }
            const Image<std::uint8_t> mask = vss::maskFromFiniteDepth(depth.view());

            for (std::size_t pi = 0; pi < options.powers.size(); ++pi) {
                const double p = options.powers[pi];
                const std::string caseName =
                    sizeText(size) + " " + viewName + " p=" + significantText(p, 6);
                Truth truth;
                truth.isReference = referenceTruth;
                if (referenceTruth) {
                    vss::SolverOptions refOptions;
                    refOptions.kind = vss::SolverKind::Reference;
                    refOptions.p = p;
                    const auto referenceSolver = vss::makeSolver(refOptions);
                    const int refRuns = referenceIndex ? options.referenceRuns : 1;
                    say(options, caseName + " reference (" + std::to_string(refRuns) + " run" +
                                     (refRuns == 1 ? "" : "s") + ")...");
                    truth.reference =
                        measure(*referenceSolver, depth, mask, refRuns, true, options.stop);
                } else {
                    vss::SolverOptions bruteOptions;
                    bruteOptions.kind = vss::SolverKind::Brute;
                    bruteOptions.p = p;
                    say(options, caseName + " brute solver as the ground truth...");
                    truth.brute = vss::solve(depth.view(), mask.view(),
                                             *vss::makeSolver(bruteOptions), {}, options.stop);
                }
                const vss::VssResult& t = truth.result();
                if (pi == 0) {
                    ViewSummary summary;
                    summary.size = size;
                    summary.view = view;
                    summary.cameraDistance = camera.distance();
                    summary.voidPixels = t.stats.voidPixels;
                    summary.vesselPixels =
                        static_cast<std::int64_t>(depth.pixelCount()) - t.stats.voidPixels;
                    summary.regions = t.stats.regionCount;
                    summary.maxContourPixels = t.stats.maxContourPixels;
                    summary.dmin = t.dmin;
                    summary.dmax = t.dmax;
                    result.views.push_back(summary);
                    say(options, sizeText(size) + " " + viewName + ": " +
                                     std::to_string(summary.regions) + " regions, " +
                                     std::to_string(summary.maxContourPixels) +
                                     " contour pixels in the largest, " +
                                     std::to_string(summary.voidPixels) + " void pixels");
                }
                measureCase(options, size, view, p, depth, mask, truth,
                            referenceTruth ? referenceIndex : std::nullopt, result);
            }
        }
    }
    return result;
}

std::vector<SizeRatio> sizeRatios(const VssBenchmarkResult& result) {
    std::vector<SizeRatio> ratios;
    if (result.sizes.empty()) {
        return ratios;
    }
    const BenchSize base = result.sizes.front();
    std::vector<std::string> solvers;
    for (const VssBenchmarkRow& r : result.rows) {
        if (std::find(solvers.begin(), solvers.end(), r.solver) == solvers.end()) {
            solvers.push_back(r.solver);
        }
    }
    const auto find = [&](const std::string& solver, const BenchSize& size, render::ViewPreset view,
                          double p) -> const VssBenchmarkRow* {
        for (const VssBenchmarkRow& r : result.rows) {
            if (r.solver == solver && r.size == size && r.view == view && r.p == p &&
                r.failure.empty()) {
                return &r;
            }
        }
        return nullptr;
    };
    for (const std::string& solver : solvers) {
        for (const BenchSize& size : result.sizes) {
            SizeRatio s;
            s.solver = solver;
            s.size = size;
            double cpu = 0.0;
            double baseCpu = 0.0;
            for (const VssBenchmarkRow& r : result.rows) {
                if (r.solver != solver || !(r.size == size) || !r.failure.empty()) {
                    continue;
                }
                const VssBenchmarkRow* b = find(solver, base, r.view, r.p);
                if (b == nullptr) {
                    continue;
                }
                ++s.cases;
                s.totalMs += r.medianMs;
                s.baseMs += b->medianMs;
                cpu += r.medianCpuMs;
                baseCpu += b->medianCpuMs;
                s.maxCaseRatio = std::max(s.maxCaseRatio, r.medianMs / b->medianMs);
            }
            s.ratio = s.cases > 0 ? s.totalMs / s.baseMs : kNaN;
            s.cpuRatio = s.cases > 0 ? cpu / baseCpu : kNaN;
            if (s.cases == 0) {
                s.maxCaseRatio = kNaN;
            }
            ratios.push_back(s);
        }
    }
    return ratios;
}

namespace {

std::string sizesText(const std::vector<BenchSize>& sizes) {
    std::string text;
    for (const BenchSize& size : sizes) {
        text += (text.empty() ? "" : ", ") + std::to_string(size.width) + "×" +
                std::to_string(size.height);
    }
    return text;
}

std::string sizeCell(const BenchSize& size) {
    return std::to_string(size.width) + "×" + std::to_string(size.height);
}

void sizeRatioTable(std::ostringstream& md, const VssBenchmarkResult& result) {
    const std::vector<SizeRatio> ratios = sizeRatios(result);
    md << "\nTime against image size (per solver setting: the sum of the median times of the "
          "view × p cases measured at both sizes, relative to "
       << sizeCell(result.sizes.front()) << "; pixels ×: the pixel count relative to it):\n\n";
    md << "| solver | size | pixels × | cases | Σ median ms | Σ median ms at base | time × | "
          "CPU time × | max case time × |\n";
    md << "|---|---|---:|---:|---:|---:|---:|---:|---:|\n";
    const auto basePixels = static_cast<double>(pixelsOf(result.sizes.front()));
    for (const SizeRatio& r : ratios) {
        md << "| " << r.solver << " | " << sizeCell(r.size) << " | "
           << fixedText(static_cast<double>(pixelsOf(r.size)) / basePixels, 2) << " | " << r.cases
           << " | ";
        if (r.cases == 0) {
            md << "– | – | – | – | – |\n";
            continue;
        }
        md << milliseconds(r.totalMs) << " | " << milliseconds(r.baseMs) << " | "
           << fixedText(r.ratio, 2) << " | " << fixedText(r.cpuRatio, 2) << " | "
           << fixedText(r.maxCaseRatio, 2) << " |\n";
    }
}

}  // namespace

std::string markdownTable(const VssBenchmarkResult& result) {
    std::ostringstream md;
    bool bruteTruth = false;
    for (const VssBenchmarkRow& r : result.rows) {
        bruteTruth = bruteTruth || r.truth == "brute";
    }
    md << "Views (" << sizesText(result.sizes) << ", " << result.sceneName << ", "
       << result.triangles << " triangles):\n\n";
    md << "| size | view | camera distance | vessel px | void px | regions | max contour px | "
          "depth range |\n";
    md << "|---|---|---:|---:|---:|---:|---:|---|\n";
    for (const ViewSummary& v : result.views) {
        md << "| " << sizeCell(v.size) << " | " << render::toString(v.view) << " | "
           << fixedText(v.cameraDistance, 1) << " | " << v.vesselPixels << " | " << v.voidPixels
           << " | " << v.regions << " | " << v.maxContourPixels << " | " << fixedText(v.dmin, 2)
           << " – " << fixedText(v.dmax, 2) << " |\n";
    }
    md << "\nSolvers (" << result.threads
       << " threads. median ms: median wall time of the whole vss::solve (normalise, "
          "regions, interpolate) over `runs` runs; interp. ms: the interpolation stage alone; "
          "CPU ms: process CPU time of the solve, all threads. Errors: the last run against "
          "the ground truth (column truth), in normalised depth units (1 = the visible depth "
          "range), over the void pixels"
       << (bruteTruth ? "; truth brute: sizes too large for the reference, compared against "
                        "the brute solver (float, every contour pixel, ~1e-6 from the reference)"
                      : "")
       << "):\n\n";
    md << "| size | view | p | solver | runs | median ms | interp. ms | CPU ms | RMSE | max err | "
          "max err ×255 | err > 1/255 | truth | regions | max contour px | void px |\n";
    md << "|---|---|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---|---:|---:|---:|\n";
    for (const VssBenchmarkRow& r : result.rows) {
        md << "| " << sizeCell(r.size) << " | " << render::toString(r.view) << " | "
           << significantText(r.p, 6) << " | " << r.solver << " | ";
        if (!r.failure.empty()) {
            md << "– | not measured: " << r.failure << " |";
            for (int k = 0; k < 10; ++k) {
                md << " |";  // the remaining columns, empty
            }
            md << "\n";
            continue;
        }
        md << r.runs << " | " << milliseconds(r.medianMs) << " | "
           << milliseconds(r.medianInterpolateMs) << " | " << milliseconds(r.medianCpuMs) << " | "
           << scientific(r.error.rmse) << " | " << scientific(r.error.maxAbs) << " | "
           << (r.error.maxAbs == 0.0 ? std::string("0")
                                     : significantText(r.error.maxAbs * 255.0, 3))
           << " | " << fixedText(100.0 * r.error.fractionAbove, 3) + " %"
           << " | " << r.truth << " | " << r.regions << " | " << r.maxContourPixels << " | "
           << r.voidPixels << " |\n";
    }
    if (result.sizes.size() > 1) {
        sizeRatioTable(md, result);
    }
    return md.str();
}

std::string csvText(const VssBenchmarkResult& result) {
    std::ostringstream csv;
    csv << "view,width,height,p,solver,series,kind,step,tolerance,threads,runs,median_ms,min_ms,"
           "interpolate_median_ms,cpu_median_ms,rmse,max_abs_error,fraction_above_1_255,compared_"
           "pixels,"
           "non_finite_pixels,regions,max_contour_pixels,void_pixels,error_bound,truth,failure\n";
    for (const VssBenchmarkRow& r : result.rows) {
        const bool ok = r.failure.empty();
        csv << render::toString(r.view) << ',' << r.size.width << ',' << r.size.height << ','
            << significantText(r.p, 6) << ',' << csvField(r.solver) << ',' << csvField(r.series)
            << ',' << vss::toString(r.options.kind) << ','
            << (r.options.kind == vss::SolverKind::Step ? std::to_string(r.options.step) : "")
            << ','
            << (r.options.kind == vss::SolverKind::Fast ? significantText(r.options.tolerance, 9)
                                                        : std::string())
            << ',' << result.threads << ',' << r.runs << ',' << msNumber(r.medianMs) << ','
            << msNumber(r.minMs) << ',' << msNumber(r.medianInterpolateMs) << ','
            << msNumber(r.medianCpuMs) << ',' << number(r.error.rmse) << ','
            << number(r.error.maxAbs) << ',' << number(r.error.fractionAbove) << ','
            << (ok ? std::to_string(r.error.compared) : "") << ','
            << (ok ? std::to_string(r.error.nonFinite) : "") << ','
            << (ok ? std::to_string(r.regions) : "") << ','
            << (ok ? std::to_string(r.maxContourPixels) : "") << ','
            << (ok ? std::to_string(r.voidPixels) : "") << ',' << number(r.errorBound) << ','
            << r.truth << ',' << csvField(r.failure) << '\n';
    }
    return csv.str();
}

void writeCsv(const std::filesystem::path& file, const VssBenchmarkResult& result) {
    writeFileAtomically(file, csvText(result));
}

void writeMarkdown(const std::filesystem::path& file, const VssBenchmarkResult& result) {
    writeFileAtomically(
        file, "<!-- SPDX-License-Identifier: GPL-3.0-or-later -->\n" + markdownTable(result));
}

}  // namespace vv::evaluation
