// SPDX-License-Identifier: GPL-3.0-or-later
// Error against run time of the VSS solvers (VSS.md, "Error against run time";
// issue 3): depth images of a scene in the paper's views, every solver against
// the reference, Markdown / CSV / PNG plot, at one or several image sizes
// (how the cost grows with the screen, issue 19). Used by `vesselview-cli bench`.
#pragma once

#include <QImage>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <stop_token>
#include <string>
#include <string_view>
#include <vector>

#include "vv/core/Image.h"
#include "vv/render/ViewPresets.h"
#include "vv/scene/Mesh.h"
#include "vv/vss/Solver.h"

namespace vv::evaluation {

/// One solver configuration to measure; options.p is set per case.
struct SolverSetting {
    std::string label;   ///< row name, unique in a run: "reference", "step 3", "fast 2/255"
    std::string series;  ///< plot series (one colour): "reference", "brute", "step 3", "fast"
    vss::SolverOptions options;
};

/// reference, brute, step 3, step 5, fast at 0.5/255 (the default), 2/255 and 8/255.
[[nodiscard]] std::vector<SolverSetting> defaultSolverSettings();

/// A depth image size in pixels.
struct BenchSize {
    int width = 1280;
    int height = 720;
    friend bool operator==(const BenchSize&, const BenchSize&) = default;
};

struct VssBenchmarkOptions {
    /// Depth image sizes, 1..8192 each side, measured one after the other in
    /// this order; the first is the base of the size ratios (sizeRatios()).
    std::vector<BenchSize> sizes{BenchSize{}};
    /// Sizes with more pixels than this compare against the brute solver
    /// (float, every contour pixel; ~1e-6 from the reference) instead of the
    /// reference, whose settings are then not run there (too slow: hours at
    /// 3840x2160); their rows say so in `failure`.
    std::int64_t referenceMaxPixels = 1280LL * 720LL;
    std::vector<render::ViewPreset> views{render::ViewPreset::Far, render::ViewPreset::Medium,
                                          render::ViewPreset::Close};
    std::vector<double> powers{2.0, 4.0, 8.0};  ///< p values, each finite and > 0
    std::vector<SolverSetting> solvers = defaultSolverSettings();
    int runs = 5;           ///< timed runs per setting (median reported), >= 1
    int referenceRuns = 1;  ///< timed runs of the (slow) reference solver, >= 1
    /// When not empty: an existing folder; the depth image of each view is
    /// written there as depth-<view>.pfm (background +Inf), for `vesselview-cli vss`.
    std::filesystem::path depthOut;
    /// Receives one line per step (may be empty).
    std::function<void(std::string_view)> log;
    std::stop_token stop;
};

/// Error of a result against the reference, over the void pixels (label >= 0)
/// where the reference is finite (where a VSS exists). In normalised depth units.
struct ErrorStats {
    double rmse = 0.0;
    double maxAbs = 0.0;         ///< +Inf when the result is not finite where the reference is
    double fractionAbove = 0.0;  ///< fraction of the compared pixels with error > threshold
    std::int64_t compared = 0;   ///< pixels compared
    std::int64_t nonFinite = 0;  ///< compared pixels where the result is NaN / Inf
};

/// Compares `result` with `reference` as described at ErrorStats; a non-finite
/// result counts as an error above any threshold and makes maxAbs +Inf (it is
/// left out of the RMSE). Throws InvalidArgumentError when the sizes differ.
[[nodiscard]] ErrorStats compareToReference(ImageView<const float> result,
                                            ImageView<const float> reference,
                                            ImageView<const std::int32_t> labels,
                                            double threshold = 1.0 / 255.0);

/// One view of the benchmark at one size.
struct ViewSummary {
    BenchSize size;
    render::ViewPreset view = render::ViewPreset::Far;
    float cameraDistance = 0.0F;
    std::int64_t vesselPixels = 0;
    std::int64_t voidPixels = 0;
    std::size_t regions = 0;
    std::int64_t maxContourPixels = 0;
    double dmin = 0.0;  ///< visible depth range, scene units
    double dmax = 0.0;
};

/// One row: a size × view × p × solver setting.
struct VssBenchmarkRow {
    BenchSize size;
    render::ViewPreset view = render::ViewPreset::Far;
    double p = 0.0;
    std::string solver;  ///< SolverSetting::label
    std::string series;
    vss::SolverOptions options;
    /// Empty when measured; else why not (e.g. the solver is not available):
    /// the numbers below are then NaN / 0.
    std::string failure;
    int runs = 0;
    double medianMs = 0.0;  ///< whole vss::solve (normalise, regions, interpolate)
    double minMs = 0.0;
    double medianInterpolateMs = 0.0;  ///< the interpolation stage alone
    /// Process CPU time (all threads) of the whole solve, median over the runs:
    /// unlike wall time, it hardly grows when other processes share the cores.
    double medianCpuMs = 0.0;
    ErrorStats error;                 ///< of the last run against the ground truth (`truth`)
    std::string truth = "reference";  ///< the ground truth: "reference" or "brute"
    std::size_t regions = 0;
    std::int64_t maxContourPixels = 0;
    std::int64_t voidPixels = 0;
    double errorBound = 0.0;  ///< the solver's promise (NaN: none)
};

struct VssBenchmarkResult {
    std::vector<BenchSize> sizes;  ///< as in the options; sizes[0] is the ratios' base
    std::string sceneName;
    std::size_t triangles = 0;
    int threads = 0;  ///< vv::workerCount() during the run
    std::vector<ViewSummary> views;
    std::vector<VssBenchmarkRow> rows;  ///< size-major, then view, p, solver order
};

/// How one solver setting's time grows from the base size (the first of
/// VssBenchmarkResult::sizes) to another size, over the view × p cases
/// measured (without failure) at both sizes.
struct SizeRatio {
    std::string solver;  ///< SolverSetting::label
    BenchSize size;
    int cases = 0;              ///< view × p cases measured at both sizes
    double totalMs = 0.0;       ///< sum of the cases' median wall times at this size
    double baseMs = 0.0;        ///< ... at the base size
    double ratio = 0.0;         ///< totalMs / baseMs (NaN without cases)
    double cpuRatio = 0.0;      ///< the same for the median CPU times
    double maxCaseRatio = 0.0;  ///< the largest ratio of one case's median wall times
};

/// One entry per solver setting (in row order) and size (in sizes order, the
/// base included with ratio 1); rows of unknown sizes are ignored. Throws
/// nothing.
[[nodiscard]] std::vector<SizeRatio> sizeRatios(const VssBenchmarkResult& result);

/// The depth image of `scene` in `view` at width × height, through
/// render::presetCamera (vertex fit) and render::rasterizeDepth: linear depth,
/// +Inf background. Throws as those do.
[[nodiscard]] Image<float> benchmarkDepth(const scene::Scene& scene, render::ViewPreset view,
                                          int width, int height);

/// Runs the benchmark. For every size, view and p the ground truth runs
/// first: the reference solver (its first run), or above referenceMaxPixels
/// the brute solver (untimed); every setting is timed `runs` times
/// (`referenceRuns` for the reference) and its last result is compared.
/// A setting whose solver cannot be made or fails with a vv::Error other than
/// CancelledError gets a row with `failure` set, and the run goes on.
/// Throws InvalidArgumentError for bad options (no size, sizes out of range or
/// given twice, runs < 1, no view / power / solver, duplicate labels, p not
/// finite or <= 0), IoError when a depth PFM cannot be written,
/// CancelledError when stopped. Depth PFMs: depth-<view>.pfm for one size,
/// depth-<view>-<W>x<H>.pfm for several.
[[nodiscard]] VssBenchmarkResult runVssBenchmark(const scene::Scene& scene,
                                                 const VssBenchmarkOptions& options);

/// The rows as a GitHub Markdown table (times in ms, errors in normalised
/// depth units), preceded by a table of the views and, with several sizes,
/// followed by the size ratios (sizeRatios()).
[[nodiscard]] std::string markdownTable(const VssBenchmarkResult& result);

/// The rows as CSV with a header line; numbers in C locale, errors with 9
/// significant digits; `step` only on step rows, `tolerance` only on fast rows;
/// failed rows have empty numbers and the failure text.
[[nodiscard]] std::string csvText(const VssBenchmarkResult& result);

/// Max abs error (log) against median time (log): one colour per series, one
/// marker shape per view, a point per row (failed rows left out; errors of 0
/// are drawn on the bottom axis, marked as such), the 1/255 line and the
/// 16 ms target. Needs a QGuiApplication (fonts; the offscreen platform is
/// fine): throws vv::Error without one. Throws InvalidArgumentError for a size
/// below 320×240 or above 8192×8192.
[[nodiscard]] QImage plotErrorVsTime(const VssBenchmarkResult& result, int width = 1400,
                                     int height = 900);

/// Write the CSV text / the Markdown text (after an SPDX comment line) / the
/// plot PNG (with License and Software text chunks) atomically (vv::writeAtomically). Throw IoError
/// naming the file when it cannot be written; writePlot throws as plotErrorVsTime.
void writeCsv(const std::filesystem::path& file, const VssBenchmarkResult& result);
void writeMarkdown(const std::filesystem::path& file, const VssBenchmarkResult& result);
void writePlot(const std::filesystem::path& file, const VssBenchmarkResult& result,
               int width = 1400, int height = 900);

}  // namespace vv::evaluation
