// SPDX-License-Identifier: GPL-3.0-or-later
// vesselview-cli bench [--mesh FILE] [--size WxH | --sizes WxH,WxH...]
//                      [--views far,medium,close]
//                      [--p 2,4,8] [--runs N] [--reference-runs N]
//                      [--solvers LIST] [--tolerances LIST] [--out DIR]
//                      [--depth-out DIR] [--quick]
// Error against run time of the VSS solvers (app/evaluation/VssBenchmark.h).
#include <QCoreApplication>
#include <QGuiApplication>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <optional>
#include <ostream>
#include <string>
#include <variant>
#include <vector>

#include "cli/Arguments.h"
#include "cli/BenchSizes.h"
#include "cli/Cli.h"
#include "cli/GuiApplication.h"
#include "cli/OutputFiles.h"
#include "cli/RenderOptions.h"
#include "evaluation/VssBenchmark.h"
#include "vv/core/Error.h"
#include "vv/core/NumberText.h"
#include "vv/demo/DemoTree.h"
#include "vv/meshio/MeshLoader.h"
#include "vv/render/ViewPresets.h"

namespace vv::cli {

namespace {

constexpr int kQuickWidth = 256;
constexpr int kQuickHeight = 144;

struct BenchArguments {
    std::optional<std::filesystem::path> mesh;
    std::vector<evaluation::BenchSize> sizes;  ///< empty: the default (or --quick) size
    std::vector<render::ViewPreset> views{render::ViewPreset::Far, render::ViewPreset::Medium,
                                          render::ViewPreset::Close};
    std::vector<double> powers{2.0, 4.0, 8.0};
    std::optional<int> runs;
    std::optional<int> referenceRuns;
    std::vector<std::string> solvers{"reference", "brute", "step3", "step5", "fast"};
    std::vector<double> tolerances255{0.5, 2.0, 8.0};  ///< fast tolerances in units of 1/255
    std::filesystem::path out = ".";
    std::optional<std::filesystem::path> depthOut;
    bool quick = false;
};

double parsePositive(const std::string& text, const std::string& what) {
    const double value = parseNumber(text, "bench: " + what);
    if (!(value > 0.0)) {
        throw UsageError("bench: " + what + " must be > 0, got '" + text + "'");
    }
    return value;
}

BenchArguments parseBenchArguments(const std::vector<std::string>& args) {
    BenchArguments parsed;
    for (Arguments arg("bench", args); arg.next();) {
        const std::string& a = arg.name();
        if (a == "--mesh") {
            parsed.mesh = arg.path();
        } else if (a == "--size" || a == "--sizes") {
            if (!parsed.sizes.empty()) {
                throw UsageError("bench: give the image size once (--size or --sizes)");
            }
            parsed.sizes = a == "--size" ? std::vector<evaluation::BenchSize>{parseBenchSize(
                                               arg.value(), "bench: --size")}
                                         : parseBenchSizes(arg.value());
        } else if (a == "--views") {
            parsed.views.clear();
            for (const std::string& name : splitList(arg.value(), "bench: --views")) {
                const auto view = render::viewPresetFromName(name);
                if (!view) {
                    throw UsageError("bench: unknown view '" + name +
                                     "' (known: far, medium, close)");
                }
                parsed.views.push_back(*view);
            }
        } else if (a == "--p") {
            parsed.powers.clear();
            for (const std::string& p : splitList(arg.value(), "bench: --p")) {
                // The VSS exponent's range and message, as `render --p` checks them.
                parsed.powers.push_back(
                    std::get<double>(parseSettingOption("vss.p", p, "bench: --p")));
            }
        } else if (a == "--runs") {
            parsed.runs = parseWholeNumber(arg.value(), "bench: --runs", 1, 1000);
        } else if (a == "--reference-runs") {
            parsed.referenceRuns =
                parseWholeNumber(arg.value(), "bench: --reference-runs", 1, 1000);
        } else if (a == "--solvers") {
            parsed.solvers = splitList(arg.value(), "bench: --solvers");
        } else if (a == "--tolerances") {
            parsed.tolerances255.clear();
            for (const std::string& t : splitList(arg.value(), "bench: --tolerances")) {
                parsed.tolerances255.push_back(parsePositive(t, "--tolerances"));
            }
        } else if (a == "--out") {
            parsed.out = arg.path();
        } else if (a == "--depth-out") {
            parsed.depthOut = arg.path();
        } else if (a == "--quick") {
            parsed.quick = true;
        } else {
            arg.fail("unknown argument '" + arg.current() + "'");
        }
    }
    return parsed;
}

/// The solver settings named on the command line: reference, brute, stepK
/// (K >= 1), fast (one setting per tolerance).
std::vector<evaluation::SolverSetting> solverSettings(const BenchArguments& parsed) {
    std::vector<evaluation::SolverSetting> settings;
    const std::vector<evaluation::SolverSetting> defaults = evaluation::defaultSolverSettings();
    const auto byLabel = [&](const std::string& label) {
        for (const auto& s : defaults) {
            if (s.label == label) {
                return s;
            }
        }
        throw UsageError("bench: no default solver setting '" + label + "'");
    };
    for (const std::string& name : parsed.solvers) {
        if (name == "reference" || name == "brute") {
            settings.push_back(byLabel(name));
        } else if (name.rfind("step", 0) == 0) {
            const int k =
                parseWholeNumber(name.substr(4), "bench: the step of '" + name + "'", 1, 1000000);
            evaluation::SolverSetting s;
            s.label = "step " + std::to_string(k);
            s.series = s.label;
            s.options.kind = vss::SolverKind::Step;
            s.options.step = k;
            settings.push_back(s);
        } else if (name == "fast") {
            for (const double t : parsed.tolerances255) {
                evaluation::SolverSetting s;
                s.label = "fast " + vv::significantText(t, 6) + "/255";
                s.series = "fast";
                s.options.kind = vss::SolverKind::Fast;
                s.options.tolerance = t / 255.0;
                settings.push_back(s);
            }
        } else {
            throw UsageError("bench: unknown solver '" + name +
                             "' (known: reference, brute, stepK, fast)");
        }
    }
    for (std::size_t i = 0; i < settings.size(); ++i) {
        for (std::size_t j = 0; j < i; ++j) {
            if (settings[i].label == settings[j].label) {
                throw UsageError("bench: solver '" + settings[i].label + "' given twice");
            }
        }
    }
    return settings;
}

}  // namespace

int benchCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
    const BenchArguments parsed = parseBenchArguments(args);

    evaluation::VssBenchmarkOptions options;
    options.sizes = parsed.sizes;
    if (options.sizes.empty()) {
        options.sizes = {parsed.quick ? evaluation::BenchSize{kQuickWidth, kQuickHeight}
                                      : evaluation::BenchSize{}};
    }
    options.views = parsed.views;
    options.powers = parsed.powers;
    options.solvers = solverSettings(parsed);
    options.runs = parsed.runs.value_or(parsed.quick ? 1 : 5);
    options.referenceRuns = parsed.referenceRuns.value_or(1);
    options.log = [&err](std::string_view line) { err << "bench: " << line << "\n" << std::flush; };

    // Fail before the long run when the outputs cannot be written.
    ensureOutputFolder(parsed.out);
    if (parsed.depthOut) {
        ensureOutputFolder(*parsed.depthOut);
        options.depthOut = *parsed.depthOut;
    }
    ensureGuiApplication();

    scene::Scene scene;
    if (parsed.mesh) {
        scene.meshes.push_back(meshio::loadMesh(*parsed.mesh));
    } else {
        err << "bench: generating the demo vessel tree\n" << std::flush;
        scene.meshes.push_back(demo::generateDemoMesh());
    }

    evaluation::VssBenchmarkResult result;
    try {
        result = evaluation::runVssBenchmark(scene, options);
    } catch (const IoError& e) {
        throw OutputError(e.what());  // only the depth PFMs are written during the run
    }

    const std::filesystem::path csv = parsed.out / "vss.csv";
    const std::filesystem::path table = parsed.out / "vss-table.md";
    const std::filesystem::path plot = parsed.out / "vss-error-vs-time.png";
    try {
        evaluation::writeCsv(csv, result);
        evaluation::writeMarkdown(table, result);
        evaluation::writePlot(plot, result);
    } catch (const IoError& e) {
        throw OutputError(e.what());
    }

    out << evaluation::markdownTable(result);
    // A solver that promises a bound and misses it is a bug worth shouting about.
    int failed = 0;
    for (const evaluation::VssBenchmarkRow& row : result.rows) {
        if (!row.failure.empty()) {
            ++failed;
            continue;
        }
        if (std::isfinite(row.errorBound) && row.errorBound > 0.0 &&
            !(row.error.maxAbs <= row.errorBound)) {
            err << "bench: warning: " << row.size.width << "x" << row.size.height << " "
                << render::toString(row.view) << " p=" << row.p << " " << row.solver
                << ": max error " << row.error.maxAbs << " exceeds its bound " << row.errorBound
                << "\n";
        }
    }
    if (failed > 0) {
        err << "bench: warning: " << failed
            << " setting(s) could not be measured (see the table)\n";
    }
    out << "\nwrote " << csv.string() << ", " << table.string() << ", " << plot.string() << "\n";
    return kOk;
}

}  // namespace vv::cli
