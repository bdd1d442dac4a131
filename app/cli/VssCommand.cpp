// SPDX-License-Identifier: GPL-3.0-or-later
// vesselview-cli vss --depth IN.pfm [--p P] [--solver NAME] [--step K]
//                    [--tolerance T] [--fixed-range A,B] -o OUT.pfm
//                    [--labels OUT.png] [--stats]
#include <QImage>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "cli/Arguments.h"
#include "cli/Cli.h"
#include "cli/JsonWriter.h"
#include "cli/OutputFiles.h"
#include "cli/RenderOptions.h"
#include "common/DisplaySettings.h"
#include "vv/core/Error.h"
#include "vv/vss/DepthNormalization.h"
#include "vv/vss/Pfm.h"
#include "vv/vss/Solver.h"
#include "vv/vss/Vss.h"

namespace vv::cli {

namespace {

struct VssArguments {
    std::filesystem::path depth;
    std::filesystem::path output;
    std::optional<std::filesystem::path> labels;
    vss::SolverOptions solver;
    vss::DepthRange range;
    bool stats = false;
};

VssArguments parseVssArguments(const std::vector<std::string>& args) {
    VssArguments parsed;
    bool haveDepth = false;
    bool haveOutput = false;
    // p, solver, step and tolerance are the display settings' (SettingsSchema.h).
    app::DisplaySettings settings;
    for (Arguments a("vss", args); a.next();) {
        const std::string& name = a.name();
        if (name == "--depth") {
            parsed.depth = a.value();
            haveDepth = true;
        } else if (name == "-o" || name == "--output") {
            parsed.output = a.value();
            haveOutput = true;
        } else if (name == "--labels") {
            parsed.labels = a.path();
        } else if (name == "--p") {
            parseSettingValue(a, "vss.p", settings);
        } else if (name == "--solver") {
            parseSettingValue(a, "vss.solver", settings);
        } else if (name == "--step") {
            parseSettingValue(a, "vss.step", settings);
        } else if (name == "--tolerance") {
            parseSettingValue(a, "vss.tolerance", settings);
        } else if (name == "--fixed-range") {
            const std::string& text = a.value();
            const auto comma = text.find(',');
            if (comma == std::string::npos) {
                a.fail("--fixed-range must be DMIN,DMAX, got '" + text + "'");
            }
            parsed.range.mode = vss::RangeMode::Fixed;
            parsed.range.dmin = parseNumber(text.substr(0, comma), "vss: --fixed-range DMIN");
            parsed.range.dmax = parseNumber(text.substr(comma + 1), "vss: --fixed-range DMAX");
            if (parsed.range.dmin > parsed.range.dmax) {
                a.fail("--fixed-range needs DMIN <= DMAX, got '" + text + "'");
            }
        } else if (name == "--stats") {
            parsed.stats = true;
        } else {
            a.fail("unknown argument '" + a.current() + "'");
        }
    }
    parsed.solver = settings.vss.solver;
    if (!haveDepth || parsed.depth.empty()) {
        throw UsageError("vss: no input depth image (--depth IN.pfm)");
    }
    if (!haveOutput || parsed.output.empty()) {
        throw UsageError("vss: no output image (-o OUT.pfm)");
    }
    return parsed;
}

void writeLabels(const std::filesystem::path& file, const vss::VssResult& result) {
    const auto& labels = result.labels;
    const bool wide = result.regions.size() + 1 > 255;
    if (result.regions.size() + 1 > 65535) {
        throw OutputError(file.string() + ": cannot write " +
                          std::to_string(result.regions.size()) +
                          " region labels into a 16-bit PNG");
    }
    QImage image(labels.width(), labels.height(),
                 wide ? QImage::Format_Grayscale16 : QImage::Format_Grayscale8);
    if (image.isNull()) {
        throw OutputError(file.string() + ": cannot allocate the label image");
    }
    for (int y = 0; y < labels.height(); ++y) {
        const std::int32_t* l = labels.row(y);
        if (wide) {
            auto* row = reinterpret_cast<std::uint16_t*>(image.scanLine(y));
            for (int x = 0; x < labels.width(); ++x) {
                row[x] = static_cast<std::uint16_t>(l[x] + 1);
            }
        } else {
            auto* row = image.scanLine(y);
            for (int x = 0; x < labels.width(); ++x) {
                row[x] = static_cast<std::uint8_t>(l[x] + 1);
            }
        }
    }
    writePngOutput(file, image);
}

}  // namespace

int vssCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
    static_cast<void>(err);
    const VssArguments parsed = parseVssArguments(args);
    const auto solver = vss::makeSolver(parsed.solver);  // bad options: InvalidArgumentError
    checkOutputPath(parsed.output);
    if (parsed.labels) {
        checkOutputPath(*parsed.labels);
    }

    const Image<float> depth = vss::readPfm(parsed.depth);  // IoError / FormatError: exit 3
    const Image<std::uint8_t> mask = vss::maskFromFiniteDepth(depth.view());
    const vss::VssResult result = vss::solve(depth.view(), mask.view(), *solver, parsed.range);

    try {
        vss::writePfm(parsed.output, result.height.view());
    } catch (const IoError& e) {
        throw OutputError(e.what());
    }
    if (parsed.labels) {
        writeLabels(*parsed.labels, result);
    }

    std::int64_t nonFiniteVoid = 0;
    for (int y = 0; y < result.labels.height(); ++y) {
        const std::int32_t* l = result.labels.row(y);
        const float* h = result.height.row(y);
        for (int x = 0; x < result.labels.width(); ++x) {
            if (l[x] != vss::kVesselLabel && !std::isfinite(h[x])) {
                ++nonFiniteVoid;
            }
        }
    }

    if (parsed.stats) {
        const auto& s = result.stats;
        JsonWriter json(out, JsonWriter::Layout::OneLine);
        json.beginObject();
        json.member("width", depth.width());
        json.member("height", depth.height());
        json.member("solver", vss::toString(parsed.solver.kind));
        json.member("p", parsed.solver.p);
        json.member("regions", s.regionCount);
        json.key("contourPixels");
        json.beginArray();
        for (const std::int64_t n : s.contourPixels) {
            json.integer(n);
        }
        json.endArray();
        json.member("maxContourPixels", s.maxContourPixels);
        json.member("voidPixels", s.voidPixels);
        json.member("dmin", result.dmin);
        json.member("dmax", result.dmax);
        json.member("flat", result.flat);
        json.member("errorBound", result.errorBound);
        json.key("timeMs");
        json.beginObject();
        json.member("normalize", s.normalizeMs);
        json.member("regions", s.regionsMs);
        json.member("interpolate", s.interpolateMs);
        json.endObject();
        json.member("nonFiniteVoidPixels", nonFiniteVoid);
        json.endObject();
        json.finish();
    } else {
        out << "wrote " << parsed.output.string() << " (" << depth.width() << "x" << depth.height()
            << ", " << result.stats.regionCount << " void regions, solver "
            << vss::toString(parsed.solver.kind) << ", p " << parsed.solver.p << ")\n";
    }
    return kOk;
}

}  // namespace vv::cli
