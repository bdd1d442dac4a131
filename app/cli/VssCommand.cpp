// SPDX-License-Identifier: GPL-3.0-or-later
// vesselview-cli vss --depth IN.pfm [--p P] [--solver NAME] [--step K]
//                    [--tolerance T] [--fixed-range A,B] -o OUT.pfm
//                    [--labels OUT.png] [--stats]
#include <QFile>
#include <QImage>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <iomanip>
#include <limits>
#include <optional>
#include <ostream>
#include <sstream>
#include <string>
#include <system_error>
#include <vector>

#include "cli/Cli.h"
#include "vv/core/AtomicFile.h"
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

double parseNumber(const std::string& text, const std::string& what) {
    double value = 0.0;
    const char* begin = text.data();
    const char* end = begin + text.size();
    const auto [ptr, ec] = std::from_chars(begin, end, value);
    if (text.empty() || ec != std::errc() || ptr != end || !std::isfinite(value)) {
        throw UsageError("vss: " + what + " must be a finite number, got '" + text + "'");
    }
    return value;
}

int parseCount(const std::string& text, const std::string& what) {
    int value = 0;
    const char* begin = text.data();
    const char* end = begin + text.size();
    const auto [ptr, ec] = std::from_chars(begin, end, value);
    if (text.empty() || ec != std::errc() || ptr != end) {
        throw UsageError("vss: " + what + " must be a whole number, got '" + text + "'");
    }
    return value;
}

VssArguments parse(const std::vector<std::string>& args) {
    VssArguments parsed;
    bool haveDepth = false;
    bool haveOutput = false;
    for (std::size_t i = 0; i < args.size(); ++i) {
        const std::string& a = args[i];
        const auto value = [&]() -> const std::string& {
            if (i + 1 >= args.size()) {
                throw UsageError("vss: " + a + " needs a value");
            }
            return args[++i];
        };
        if (a == "--depth") {
            parsed.depth = value();
            haveDepth = true;
        } else if (a == "-o" || a == "--output") {
            parsed.output = value();
            haveOutput = true;
        } else if (a == "--labels") {
            parsed.labels = std::filesystem::path(value());
        } else if (a == "--p") {
            parsed.solver.p = parseNumber(value(), "--p");
        } else if (a == "--solver") {
            parsed.solver.kind = vss::parseSolverKind(value());
        } else if (a == "--step") {
            parsed.solver.step = parseCount(value(), "--step");
        } else if (a == "--tolerance") {
            parsed.solver.tolerance = parseNumber(value(), "--tolerance");
        } else if (a == "--fixed-range") {
            const std::string& text = value();
            const auto comma = text.find(',');
            if (comma == std::string::npos) {
                throw UsageError("vss: --fixed-range must be DMIN,DMAX, got '" + text + "'");
            }
            parsed.range.mode = vss::RangeMode::Fixed;
            parsed.range.dmin = parseNumber(text.substr(0, comma), "--fixed-range DMIN");
            parsed.range.dmax = parseNumber(text.substr(comma + 1), "--fixed-range DMAX");
            if (parsed.range.dmin > parsed.range.dmax) {
                throw UsageError("vss: --fixed-range needs DMIN <= DMAX, got '" + text + "'");
            }
        } else if (a == "--stats") {
            parsed.stats = true;
        } else {
            throw UsageError("vss: unknown argument '" + a + "'");
        }
    }
    if (!haveDepth || parsed.depth.empty()) {
        throw UsageError("vss: no input depth image (--depth IN.pfm)");
    }
    if (!haveOutput || parsed.output.empty()) {
        throw UsageError("vss: no output image (-o OUT.pfm)");
    }
    return parsed;
}

/// Throws OutputError when `file` can certainly not be written (no folder, a folder).
void checkWritable(const std::filesystem::path& file) {
    std::error_code ec;
    const std::filesystem::path folder = file.has_parent_path() ? file.parent_path() : ".";
    if (!std::filesystem::is_directory(folder, ec)) {
        throw OutputError(file.string() + ": cannot write: folder '" + folder.string() +
                          "' does not exist");
    }
    if (std::filesystem::is_directory(file, ec)) {
        throw OutputError(file.string() + ": cannot write: it is a folder");
    }
}

/// JSON number, or null when not finite.
std::string json(double v) {
    if (!std::isfinite(v)) {
        return "null";
    }
    std::ostringstream s;
    s << std::setprecision(17) << v;
    return s.str();
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
    try {
        writeAtomically(file, [&](const std::filesystem::path& temporary) {
            if (!image.save(QFile::decodeName(temporary.c_str()), "PNG")) {
                throw IoError(file, "cannot write the PNG image");
            }
        });
    } catch (const IoError& e) {
        throw OutputError(e.what());
    }
}

}  // namespace

int vssCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
    static_cast<void>(err);
    const VssArguments parsed = parse(args);
    const auto solver = vss::makeSolver(parsed.solver);  // bad options: InvalidArgumentError
    checkWritable(parsed.output);
    if (parsed.labels) {
        checkWritable(*parsed.labels);
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
        out << "{\"width\": " << depth.width() << ", \"height\": " << depth.height()
            << ", \"solver\": \"" << vss::toString(parsed.solver.kind) << "\""
            << ", \"p\": " << json(parsed.solver.p) << ", \"regions\": " << s.regionCount
            << ", \"contourPixels\": [";
        for (std::size_t i = 0; i < s.contourPixels.size(); ++i) {
            out << (i == 0 ? "" : ", ") << s.contourPixels[i];
        }
        out << "], \"maxContourPixels\": " << s.maxContourPixels
            << ", \"voidPixels\": " << s.voidPixels << ", \"dmin\": " << json(result.dmin)
            << ", \"dmax\": " << json(result.dmax)
            << ", \"flat\": " << (result.flat ? "true" : "false")
            << ", \"errorBound\": " << json(result.errorBound)
            << ", \"timeMs\": {\"normalize\": " << json(s.normalizeMs)
            << ", \"regions\": " << json(s.regionsMs)
            << ", \"interpolate\": " << json(s.interpolateMs) << "}"
            << ", \"nonFiniteVoidPixels\": " << nonFiniteVoid << "}\n";
    } else {
        out << "wrote " << parsed.output.string() << " (" << depth.width() << "x" << depth.height()
            << ", " << result.stats.regionCount << " void regions, solver "
            << vss::toString(parsed.solver.kind) << ", p " << parsed.solver.p << ")\n";
    }
    return kOk;
}

}  // namespace vv::cli
