// SPDX-License-Identifier: GPL-3.0-or-later
#include "VssBenchmark.h"

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
#include "vv/core/Error.h"
#include "vv/core/NumberText.h"
#include "vv/core/Parallel.h"
#include "vv/render/DepthRasterizer.h"
#include "vv/vss/DepthNormalization.h"
#include "vv/vss/Pfm.h"
#include "vv/vss/Vss.h"

namespace vv::bench {

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

void validate(const VssBenchmarkOptions& options) {
    if (options.width < 1 || options.height < 1 || options.width > kMaxSide ||
        options.height > kMaxSide) {
        throw InvalidArgumentError("bench: the image size must be within 1x1.." +
                                   std::to_string(kMaxSide) + "x" + std::to_string(kMaxSide));
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

std::string csvField(const std::string& text) {
    if (text.find_first_of(",\"\n") == std::string::npos) {
        return text;
    }
    std::string quoted = "\"";
    for (const char c : text) {
        quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
    }
    return quoted + "\"";
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

void writeText(const std::filesystem::path& file, const std::string& text) {
    writeAtomically(file, [&](const std::filesystem::path& temporary) {
        std::ofstream stream(temporary, std::ios::binary | std::ios::trunc);
        stream << text;
        stream.flush();
        if (!stream) {
            throw IoError(file, "cannot write the file");
        }
    });
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

VssBenchmarkResult runVssBenchmark(const scene::Scene& scene, const VssBenchmarkOptions& options) {
    validate(options);
    VssBenchmarkResult result;
    result.width = options.width;
    result.height = options.height;
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

    for (const render::ViewPreset view : options.views) {
        const std::string viewName(render::toString(view));
        const render::Camera camera =
            render::presetCamera(scene, options.width, options.height, view);
        const Image<float> depth = render::rasterizeDepth(scene, camera, options.stop);
        if (!options.depthOut.empty()) {
            const auto file = options.depthOut / ("depth-" + viewName + ".pfm");
            vss::writePfm(file, depth.view());
            say(options, "wrote " + file.string());
        }
        const Image<std::uint8_t> mask = vss::maskFromFiniteDepth(depth.view());

        for (std::size_t pi = 0; pi < options.powers.size(); ++pi) {
            const double p = options.powers[pi];
            const std::string caseName = viewName + " p=" + significantText(p, 6);
            vss::SolverOptions refOptions;
            refOptions.kind = vss::SolverKind::Reference;
            refOptions.p = p;
            const auto referenceSolver = vss::makeSolver(refOptions);
            const int refRuns = referenceIndex ? options.referenceRuns : 1;
            say(options, caseName + " reference (" + std::to_string(refRuns) + " run" +
                             (refRuns == 1 ? "" : "s") + ")...");
            const Measured reference =
                measure(*referenceSolver, depth, mask, refRuns, true, options.stop);
            // The first run is the ground truth; the last one is compared with it.
            const vss::VssResult& truth = reference.first;

            if (pi == 0) {
                ViewSummary summary;
                summary.view = view;
                summary.cameraDistance = camera.distance();
                summary.voidPixels = truth.stats.voidPixels;
                summary.vesselPixels =
                    static_cast<std::int64_t>(depth.pixelCount()) - truth.stats.voidPixels;
                summary.regions = truth.stats.regionCount;
                summary.maxContourPixels = truth.stats.maxContourPixels;
                summary.dmin = truth.dmin;
                summary.dmax = truth.dmax;
                result.views.push_back(summary);
                say(options, viewName + ": " + std::to_string(summary.regions) + " regions, " +
                                 std::to_string(summary.maxContourPixels) +
                                 " contour pixels in the largest, " +
                                 std::to_string(summary.voidPixels) + " void pixels");
            }

            for (std::size_t si = 0; si < options.solvers.size(); ++si) {
                const SolverSetting& setting = options.solvers[si];
                VssBenchmarkRow row;
                row.view = view;
                row.p = p;
                row.solver = setting.label;
                row.series = setting.series;
                row.options = setting.options;
                row.options.p = p;
                if (referenceIndex && si == *referenceIndex) {
                    fillRow(row, reference, truth);
                } else {
                    try {
                        const auto solver = vss::makeSolver(row.options);
                        const int runs = setting.options.kind == vss::SolverKind::Reference
                                             ? options.referenceRuns
                                             : options.runs;
                        const Measured m = measure(*solver, depth, mask, runs, false, options.stop);
                        fillRow(row, m, truth);
                    } catch (const CancelledError&) {
                        throw;
                    } catch (const InvalidArgumentError&) {
                        throw;
                    } catch (const Error& e) {
                        markFailed(row, e.what());
                    }
                }
                if (row.failure.empty()) {
                    say(options, caseName + " " + row.solver + ": median " +
                                     milliseconds(row.medianMs) + " ms (" +
                                     std::to_string(row.runs) + " runs), max error " +
                                     scientific(row.error.maxAbs));
                } else {
                    say(options, caseName + " " + row.solver + ": not measured: " + row.failure);
                }
                result.rows.push_back(std::move(row));
            }
        }
    }
    return result;
}

std::string markdownTable(const VssBenchmarkResult& result) {
    std::ostringstream md;
    md << "Views (" << result.width << "×" << result.height << ", " << result.sceneName << ", "
       << result.triangles << " triangles):\n\n";
    md << "| view | camera distance | vessel px | void px | regions | max contour px | "
          "depth range |\n";
    md << "|---|---:|---:|---:|---:|---:|---|\n";
    for (const ViewSummary& v : result.views) {
        md << "| " << render::toString(v.view) << " | " << fixedText(v.cameraDistance, 1) << " | "
           << v.vesselPixels << " | " << v.voidPixels << " | " << v.regions << " | "
           << v.maxContourPixels << " | " << fixedText(v.dmin, 2) << " – " << fixedText(v.dmax, 2)
           << " |\n";
    }
    md << "\nSolvers (" << result.threads
       << " threads. median ms: median wall time of the whole vss::solve (normalise, "
          "regions, interpolate) over `runs` runs; interp. ms: the interpolation stage alone; "
          "CPU ms: process CPU time of the solve, all threads. Errors: the last run against "
          "the reference, in normalised depth units (1 = the visible depth range), over the "
          "void pixels):\n\n";
    md << "| view | p | solver | runs | median ms | interp. ms | CPU ms | RMSE | max err | max "
          "err ×255 | err > 1/255 | regions | max contour px | void px |\n";
    md << "|---|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
    for (const VssBenchmarkRow& r : result.rows) {
        md << "| " << render::toString(r.view) << " | " << significantText(r.p, 6) << " | "
           << r.solver << " | ";
        if (!r.failure.empty()) {
            md << "– | not measured: " << r.failure << " |";
            for (int k = 0; k < 9; ++k) {
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
           << " | " << r.regions << " | " << r.maxContourPixels << " | " << r.voidPixels << " |\n";
    }
    return md.str();
}

std::string csvText(const VssBenchmarkResult& result) {
    std::ostringstream csv;
    csv << "view,width,height,p,solver,series,kind,step,tolerance,threads,runs,median_ms,min_ms,"
           "interpolate_median_ms,cpu_median_ms,rmse,max_abs_error,fraction_above_1_255,compared_"
           "pixels,"
           "non_finite_pixels,regions,max_contour_pixels,void_pixels,error_bound,failure\n";
    for (const VssBenchmarkRow& r : result.rows) {
        const bool ok = r.failure.empty();
        csv << render::toString(r.view) << ',' << result.width << ',' << result.height << ','
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
            << csvField(r.failure) << '\n';
    }
    return csv.str();
}

// ---------------------------------------------------------------------------
// The plot.

namespace {

const std::array<QColor, 8> kPalette{
    QColor(31, 119, 180),  QColor(255, 127, 14), QColor(44, 160, 44),   QColor(214, 39, 40),
    QColor(148, 103, 189), QColor(140, 86, 75),  QColor(227, 119, 194), QColor(127, 127, 127)};

QColor seriesColor(const std::string& series, std::size_t index) {
    if (series == "reference") {
        return QColor(20, 20, 20);
    }
    if (series == "brute") {
        return kPalette[0];
    }
    if (series == "step 3") {
        return kPalette[1];
    }
    if (series == "step 5") {
        return kPalette[3];
    }
    if (series == "fast") {
        return kPalette[2];
    }
    return kPalette[4 + index % 4];
}

void drawMarker(QPainter& painter, render::ViewPreset view, const QPointF& c, double r) {
    switch (view) {
        case render::ViewPreset::Far:
            painter.drawEllipse(c, r, r);
            return;
        case render::ViewPreset::Medium:
            painter.drawRect(QRectF(c.x() - r, c.y() - r, 2 * r, 2 * r));
            return;
        case render::ViewPreset::Close: {
            QPolygonF triangle;
            triangle << QPointF(c.x(), c.y() - 1.2 * r) << QPointF(c.x() + 1.1 * r, c.y() + 0.8 * r)
                     << QPointF(c.x() - 1.1 * r, c.y() + 0.8 * r);
            painter.drawPolygon(triangle);
            return;
        }
    }
    QPolygonF diamond;
    diamond << QPointF(c.x(), c.y() - r) << QPointF(c.x() + r, c.y()) << QPointF(c.x(), c.y() + r)
            << QPointF(c.x() - r, c.y());
    painter.drawPolygon(diamond);
}

QString decadeLabel(int exponent) {
    if (exponent >= 0 && exponent <= 4) {
        return QString::number(std::pow(10.0, exponent), 'f', 0);
    }
    if (exponent >= -3 && exponent < 0) {
        return QString::number(std::pow(10.0, exponent), 'f', -exponent);
    }
    return QStringLiteral("1e%1").arg(exponent);
}

}  // namespace

QImage plotErrorVsTime(const VssBenchmarkResult& result, int width, int height) {
    if (width < 320 || height < 240 || width > 8192 || height > 8192) {
        throw InvalidArgumentError("plot: the size must be within 320x240..8192x8192");
    }
    if (qobject_cast<QGuiApplication*>(QCoreApplication::instance()) == nullptr) {
        throw Error("plot: drawing text needs a QGuiApplication");
    }
    constexpr double kTargetMs = 16.0;
    constexpr double kVisible = 1.0 / 255.0;

    // Ranges, in decades.
    double tLo = kTargetMs;
    double tHi = kTargetMs;
    double eLo = kVisible;
    double eHi = kVisible;
    bool anyZero = false;
    bool anyInf = false;
    for (const VssBenchmarkRow& r : result.rows) {
        if (!r.failure.empty() || !(r.medianMs > 0.0)) {
            continue;
        }
        tLo = std::min(tLo, r.medianMs);
        tHi = std::max(tHi, r.medianMs);
        if (r.error.maxAbs == 0.0) {
            anyZero = true;
        } else if (std::isinf(r.error.maxAbs)) {
            anyInf = true;
        } else if (r.error.maxAbs > 0.0) {
            eLo = std::min(eLo, r.error.maxAbs);
            eHi = std::max(eHi, r.error.maxAbs);
        }
    }
    const int xd0 = static_cast<int>(std::floor(std::log10(tLo)));
    const int xd1 = std::max(xd0 + 1, static_cast<int>(std::ceil(std::log10(tHi))));
    // One extra decade at the bottom holds the exact (zero error) points.
    const int yd0 = static_cast<int>(std::floor(std::log10(eLo))) - (anyZero ? 1 : 0);
    const int yd1 = std::max(yd0 + 1, static_cast<int>(std::ceil(std::log10(eHi))));

    QImage image(width, height, QImage::Format_RGB32);
    image.fill(Qt::white);
    QPainter painter(&image);
    painter.setRenderHint(QPainter::Antialiasing, true);
    painter.setRenderHint(QPainter::TextAntialiasing, true);
    const double scale = std::min(width / 1400.0, height / 900.0);
    const auto px = [&](double v) { return std::max(1, static_cast<int>(std::lround(v * scale))); };
    QFont font(QStringLiteral("DejaVu Sans"));
    font.setPixelSize(px(15));
    QFont small = font;
    small.setPixelSize(px(13));
    QFont title = font;
    title.setPixelSize(px(19));
    title.setBold(true);

    const QRectF plot(px(100), px(70), width - px(100) - px(330), height - px(70) - px(90));
    const auto mapX = [&](double ms) {
        const double t = (std::log10(ms) - xd0) / (xd1 - xd0);
        return plot.left() + t * plot.width();
    };
    const auto mapY = [&](double error) {
        double e = 0.0;
        if (error == 0.0) {
            e = yd0;
        } else if (std::isinf(error)) {
            e = yd1;
        } else {
            e = std::log10(error);
        }
        const double t = (e - yd0) / (yd1 - yd0);
        return plot.bottom() - t * plot.height();
    };

    // Grid and ticks.
    painter.setFont(small);
    for (int d = xd0; d <= xd1; ++d) {
        const double x = mapX(std::pow(10.0, d));
        painter.setPen(QPen(QColor(200, 200, 200), 1.0));
        painter.drawLine(QPointF(x, plot.top()), QPointF(x, plot.bottom()));
        painter.setPen(Qt::black);
        painter.drawText(QRectF(x - px(50), plot.bottom() + px(6), px(100), px(20)),
                         Qt::AlignHCenter | Qt::AlignTop, decadeLabel(d));
        if (d < xd1) {
            painter.setPen(QPen(QColor(235, 235, 235), 1.0));
            for (int m = 2; m <= 9; ++m) {
                const double xm = mapX(m * std::pow(10.0, d));
                painter.drawLine(QPointF(xm, plot.top()), QPointF(xm, plot.bottom()));
            }
        }
    }
    for (int d = yd0; d <= yd1; ++d) {
        const double y = mapY(std::pow(10.0, d));
        painter.setPen(QPen(QColor(200, 200, 200), 1.0));
        painter.drawLine(QPointF(plot.left(), y), QPointF(plot.right(), y));
        painter.setPen(Qt::black);
        const QString label = (anyZero && d == yd0) ? QStringLiteral("0") : decadeLabel(d);
        painter.drawText(QRectF(plot.left() - px(95), y - px(10), px(88), px(20)),
                         Qt::AlignRight | Qt::AlignVCenter, label);
        if (d < yd1 && !(anyZero && d == yd0)) {
            painter.setPen(QPen(QColor(235, 235, 235), 1.0));
            for (int m = 2; m <= 9; ++m) {
                const double ym = mapY(m * std::pow(10.0, d));
                painter.drawLine(QPointF(plot.left(), ym), QPointF(plot.right(), ym));
            }
        }
    }
    if (anyZero) {
        // The bottom decade is a break: exact results sit on its lower line.
        painter.setPen(QPen(QColor(120, 120, 120), 1.0, Qt::DotLine));
        const double y = mapY(std::pow(10.0, yd0 + 1));
        painter.drawLine(QPointF(plot.left(), y), QPointF(plot.right(), y));
    }

    // The 1/255 line and the 16 ms target.
    painter.setPen(QPen(QColor(200, 30, 30), 1.5, Qt::DashLine));
    const double yVisible = mapY(kVisible);
    painter.drawLine(QPointF(plot.left(), yVisible), QPointF(plot.right(), yVisible));
    painter.drawText(QRectF(plot.left() + px(6), yVisible - px(20), px(400), px(18)),
                     Qt::AlignLeft | Qt::AlignBottom, QStringLiteral("1/255: one 8-bit step"));
    // The tolerances the fast settings promise, as thin dotted lines.
    std::set<double> tolerances;
    for (const VssBenchmarkRow& r : result.rows) {
        if (r.failure.empty() && r.options.kind == vss::SolverKind::Fast &&
            std::isfinite(r.errorBound) && r.errorBound > 0.0) {
            tolerances.insert(r.errorBound);
        }
    }
    for (const double t : tolerances) {
        const double y = mapY(t);
        if (y < plot.top() || y > plot.bottom()) {
            continue;
        }
        painter.setPen(QPen(seriesColor("fast", 0), 1.0, Qt::DotLine));
        painter.drawLine(QPointF(plot.left(), y), QPointF(plot.right(), y));
        painter.drawText(QRectF(plot.right() - px(306), y - px(18), px(300), px(16)),
                         Qt::AlignRight | Qt::AlignBottom,
                         QStringLiteral("fast tolerance %1/255").arg(t * 255.0, 0, 'g', 3));
    }
    painter.setPen(QPen(QColor(30, 120, 30), 1.5, Qt::DashLine));
    const double xTarget = mapX(kTargetMs);
    painter.drawLine(QPointF(xTarget, plot.top()), QPointF(xTarget, plot.bottom()));
    painter.save();
    painter.translate(xTarget - px(4), plot.top() + px(6));
    painter.rotate(90.0);
    painter.drawText(QRectF(0, -px(2), px(300), px(18)), Qt::AlignLeft | Qt::AlignBottom,
                     QStringLiteral("16 ms target"));
    painter.restore();

    painter.setPen(QPen(Qt::black, 1.2));
    painter.setBrush(Qt::NoBrush);
    painter.drawRect(plot);

    // Points.
    std::vector<std::string> series;
    for (const VssBenchmarkRow& r : result.rows) {
        if (std::find(series.begin(), series.end(), r.series) == series.end()) {
            series.push_back(r.series);
        }
    }
    const auto colorOf = [&](const std::string& s) {
        const auto it = std::find(series.begin(), series.end(), s);
        return seriesColor(s, static_cast<std::size_t>(it - series.begin()));
    };
    painter.setClipRect(plot.adjusted(-px(8), -px(8), px(8), px(8)));
    for (const VssBenchmarkRow& r : result.rows) {
        if (!r.failure.empty() || !(r.medianMs > 0.0) || std::isnan(r.error.maxAbs)) {
            continue;
        }
        QColor fill = colorOf(r.series);
        fill.setAlpha(190);
        painter.setPen(QPen(colorOf(r.series).darker(140), 1.0));
        painter.setBrush(fill);
        drawMarker(painter, r.view, QPointF(mapX(r.medianMs), mapY(r.error.maxAbs)), px(6));
    }
    painter.setClipping(false);

    // Axis titles and title.
    painter.setPen(Qt::black);
    painter.setFont(font);
    painter.drawText(QRectF(plot.left(), plot.bottom() + px(32), plot.width(), px(24)),
                     Qt::AlignHCenter | Qt::AlignTop,
                     QStringLiteral("median wall time per frame [ms], log scale (whole VSS "
                                    "solve, %1 threads)")
                         .arg(result.threads));
    painter.save();
    painter.translate(px(22), plot.center().y());
    painter.rotate(-90.0);
    painter.drawText(QRectF(-plot.height() / 2, -px(12), plot.height(), px(24)), Qt::AlignCenter,
                     QStringLiteral("max abs error [normalised depth], log scale"));
    painter.restore();
    painter.setFont(title);
    painter.drawText(QRectF(plot.left(), px(18), plot.width(), px(30)),
                     Qt::AlignLeft | Qt::AlignVCenter,
                     QStringLiteral("VSS solvers: error against run time — %1×%2, %3")
                         .arg(result.width)
                         .arg(result.height)
                         .arg(QString::fromStdString(result.sceneName)));

    // Legend.
    double ly = plot.top();
    const double lx = plot.right() + px(24);
    painter.setFont(font);
    painter.drawText(QPointF(lx, ly + px(14)), QStringLiteral("solver"));
    ly += px(28);
    painter.setFont(small);
    for (const std::string& s : series) {
        painter.setPen(QPen(colorOf(s).darker(140), 1.0));
        painter.setBrush(colorOf(s));
        painter.drawRect(QRectF(lx, ly - px(10), px(22), px(12)));
        painter.setPen(Qt::black);
        painter.drawText(QPointF(lx + px(32), ly), QString::fromStdString(s));
        ly += px(22);
    }
    ly += px(14);
    painter.setFont(font);
    painter.drawText(QPointF(lx, ly + px(14)), QStringLiteral("view (marker)"));
    ly += px(28);
    painter.setFont(small);
    std::vector<render::ViewPreset> views;
    for (const VssBenchmarkRow& r : result.rows) {
        if (std::find(views.begin(), views.end(), r.view) == views.end()) {
            views.push_back(r.view);
        }
    }
    for (const render::ViewPreset v : views) {
        painter.setPen(QPen(Qt::black, 1.0));
        painter.setBrush(QColor(160, 160, 160));
        drawMarker(painter, v, QPointF(lx + px(11), ly - px(4)), px(6));
        painter.drawText(QPointF(lx + px(32), ly),
                         QString::fromStdString(std::string(render::toString(v))));
        ly += px(22);
    }
    ly += px(14);
    painter.setPen(QColor(60, 60, 60));
    QStringList notes{QStringLiteral("one point per view × p × setting"),
                      QStringLiteral("(p and fast tolerances: see the CSV)")};
    if (anyZero) {
        notes << QStringLiteral("bottom line: error exactly 0");
    }
    if (anyInf) {
        notes << QStringLiteral("top line: non-finite output");
    }
    for (const QString& note : notes) {
        painter.drawText(QPointF(lx, ly), note);
        ly += px(20);
    }
    painter.end();
    return image;
}

void writeCsv(const std::filesystem::path& file, const VssBenchmarkResult& result) {
    writeText(file, csvText(result));
}

void writeMarkdown(const std::filesystem::path& file, const VssBenchmarkResult& result) {
    writeText(file, "<!-- SPDX-License-Identifier: GPL-3.0-or-later -->\n" + markdownTable(result));
}

void writePlot(const std::filesystem::path& file, const VssBenchmarkResult& result, int width,
               int height) {
    QImage image = plotErrorVsTime(result, width, height);
    image.setText(QStringLiteral("License"),
                  QStringLiteral("SPDX-License-Identifier: GPL-3.0-or-later"));
    image.setText(QStringLiteral("Software"), QStringLiteral("VesselView (vesselview-cli bench)"));
    writeAtomically(file, [&](const std::filesystem::path& temporary) {
        if (!image.save(QFile::decodeName(temporary.c_str()), "PNG")) {
            throw IoError(file, "cannot write the PNG image");
        }
    });
}

}  // namespace vv::bench
