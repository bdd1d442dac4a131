// SPDX-License-Identifier: GPL-3.0-or-later
// vesselview-cli render FILE -o IMAGE.png [--size WxH] [--array NAME|none]
//                            [--colormap NAME] [--bins N] [--background #rrggbb]
//                            [--cue none|vessel-cd|vessel-pcd|fog|fresnel] [--legends on|off]
//                            [--vss on|off] [--scale cd|pcd|dmd] [--p P] [--isolines N]
//                            [--solver NAME] [--tolerance T] [--ao on|off] [--aa on|off]
//                            [--timings]
//                            [--view far|medium|close|anterior|posterior|left|right|
//                                    superior|inferior]
//                            [--depth-out DEPTH.pfm]
// Needs OpenGL 4.1: a display (headless: xvfb-run -a with QT_QPA_PLATFORM=xcb).
#include <QFile>
#include <QGuiApplication>
#include <QImage>
#include <QString>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <optional>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "cli/Cli.h"
#include "cli/GuiApplication.h"
#include "vv/colormaps/ColorMap.h"
#include "vv/colormaps/DepthScale.h"
#include "vv/core/AtomicFile.h"
#include "vv/core/Error.h"
#include "vv/io/MeshLoader.h"
#include "vv/render/DepthRasterizer.h"
#include "vv/render/MeshRenderer.h"
#include "vv/render/OffscreenRenderer.h"
#include "vv/render/RenderGraph.h"
#include "vv/render/ViewPresets.h"
#include "vv/vss/Pfm.h"
#include "vv/vss/Solver.h"

namespace vv::cli {

namespace {

struct RenderArguments {
    std::filesystem::path input;
    std::filesystem::path output;
    int width = 1600;
    int height = 1200;
    std::optional<std::string> array;  ///< nullopt: default (wss when present); "" = none
    colormaps::ColorMap colorMap = colormaps::ColorMap::Viridis;
    int bins = 0;  ///< colour-map bins, 0 = continuous
    render::VesselCueSettings cue;
    bool legends = true;
    glm::vec3 background{0.13F, 0.14F, 0.16F};
    render::VssSettings vss;
    bool ao = true;  ///< ambient occlusion over vessels + VSS
    bool aa = true;  ///< FXAA
    bool timings = false;
    /// --view: nullopt = the default orientation fitted to the bounding box.
    std::optional<render::NamedView> view;
    std::filesystem::path depthOutput;  ///< --depth-out; empty = none
};

double parseDouble(const std::string& text, const std::string& what) {
    double value = 0.0;
    const char* begin = text.data();
    const char* end = begin + text.size();
    const auto [ptr, ec] = std::from_chars(begin, end, value);
    if (ec != std::errc() || ptr != end || !std::isfinite(value)) {
        throw UsageError("invalid " + what + " '" + text + "'");
    }
    return value;
}

/// Compact JSON number: finite values as is, others as null.
std::string jsonNumber(double value) {
    if (!std::isfinite(value)) {
        return "null";
    }
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.3f", value);
    return buffer;
}

int parseInt(const std::string& text, const std::string& what) {
    int value = 0;
    const char* begin = text.data();
    const char* end = begin + text.size();
    const auto [ptr, ec] = std::from_chars(begin, end, value);
    if (ec != std::errc() || ptr != end) {
        throw UsageError("invalid " + what + " '" + text + "'");
    }
    return value;
}

std::pair<int, int> parseSize(const std::string& text) {
    const auto x = text.find_first_of("xX");
    if (x == std::string::npos) {
        throw UsageError("--size must be WIDTHxHEIGHT (e.g. 1600x1200), got '" + text + "'");
    }
    const int w = parseInt(text.substr(0, x), "--size width");
    const int h = parseInt(text.substr(x + 1), "--size height");
    if (w < 1 || h < 1 || w > 16384 || h > 16384) {
        throw UsageError("--size must be within 1x1..16384x16384, got '" + text + "'");
    }
    return {w, h};
}

glm::vec3 parseColor(const std::string& text) {
    const bool ok = text.size() == 7 && text[0] == '#' &&
                    text.find_first_not_of("0123456789abcdefABCDEF", 1) == std::string::npos;
    if (!ok) {
        throw UsageError("--background must be #rrggbb, got '" + text + "'");
    }
    const auto channel = [&](std::size_t at) {
        return static_cast<float>(std::stoi(text.substr(at, 2), nullptr, 16)) / 255.0F;
    };
    return {channel(1), channel(3), channel(5)};
}

RenderArguments parse(const std::vector<std::string>& args) {
    RenderArguments parsed;
    bool haveInput = false;
    bool haveOutput = false;
    for (std::size_t i = 0; i < args.size(); ++i) {
        const std::string& a = args[i];
        const auto value = [&]() -> const std::string& {
            if (i + 1 >= args.size()) {
                throw UsageError("render: " + a + " needs a value");
            }
            return args[++i];
        };
        if (a == "-o" || a == "--output") {
            parsed.output = value();
            haveOutput = true;
        } else if (a == "--size") {
            const auto [w, h] = parseSize(value());
            parsed.width = w;
            parsed.height = h;
        } else if (a == "--array") {
            const std::string& name = value();
            parsed.array = (name == "none" || name == "None" || name.empty()) ? "" : name;
        } else if (a == "--colormap") {
            const std::string& name = value();
            const auto map = colormaps::colorMapFromName(name);
            if (!map) {
                std::string known;
                for (const auto m : colormaps::allColorMaps()) {
                    known += (known.empty() ? "" : ", ") + std::string(colormaps::name(m));
                }
                throw UsageError("unknown colour map '" + name + "' (known: " + known + ")");
            }
            parsed.colorMap = *map;
        } else if (a == "--bins") {
            const int n = parseInt(value(), "--bins");
            if (n != 0 && (n < 2 || n > colormaps::kMaxBins)) {
                throw UsageError("--bins must be 0 (continuous) or within 2.." +
                                 std::to_string(colormaps::kMaxBins) + ", got " + args[i]);
            }
            parsed.bins = n;
        } else if (a == "--cue") {
            const std::string& v = value();
            const auto cue = render::vesselCueFromName(v);
            if (!cue) {
                throw UsageError("unknown vessel cue '" + v +
                                 "' (known: none, vessel-cd, vessel-pcd, fog, fresnel)");
            }
            parsed.cue.cue = *cue;
        } else if (a == "--legends") {
            const std::string& v = value();
            if (v != "on" && v != "off") {
                throw UsageError("--legends must be on or off, got '" + v + "'");
            }
            parsed.legends = v == "on";
        } else if (a == "--background") {
            parsed.background = parseColor(value());
        } else if (a == "--ao" || a == "--aa") {
            const std::string& v = value();
            if (v != "on" && v != "off") {
                throw UsageError(a + " must be on or off, got '" + v + "'");
            }
            (a == "--ao" ? parsed.ao : parsed.aa) = v == "on";
        } else if (a == "--vss") {
            const std::string& v = value();
            if (v != "on" && v != "off") {
                throw UsageError("--vss must be on or off, got '" + v + "'");
            }
            parsed.vss.enabled = v == "on";
        } else if (a == "--scale") {
            const std::string& v = value();
            const auto scale = colormaps::depthScaleFromName(v);
            if (!scale) {
                throw UsageError("unknown depth scale '" + v + "' (known: cd, pcd, dmd)");
            }
            parsed.vss.scale = *scale;
        } else if (a == "--p") {
            const double p = parseDouble(value(), "--p");
            if (!(p > 0.0) || p > 64.0) {
                throw UsageError("--p must be within (0, 64], got " + args[i]);
            }
            parsed.vss.solver.p = p;
        } else if (a == "--isolines") {
            const int n = parseInt(value(), "--isolines");
            if (n < 0 || n > 1000) {
                throw UsageError("--isolines must be within 0..1000, got " + args[i]);
            }
            parsed.vss.isoLines = n;
        } else if (a == "--solver") {
            try {
                parsed.vss.solver.kind = vss::parseSolverKind(value());
            } catch (const InvalidArgumentError&) {
                throw UsageError("unknown solver '" + args[i] +
                                 "' (known: reference, brute, step, fast)");
            }
        } else if (a == "--tolerance") {
            const double t = parseDouble(value(), "--tolerance");
            if (!(t > 0.0)) {
                throw UsageError("--tolerance must be > 0, got " + args[i]);
            }
            parsed.vss.solver.tolerance = t;
        } else if (a == "--view") {
            const std::string& name = value();
            parsed.view = render::namedViewFromName(name);
            if (!parsed.view) {
                throw UsageError("unknown view '" + name + "' (known: " + render::namedViewNames() +
                                 ")");
            }
        } else if (a == "--depth-out") {
            parsed.depthOutput = value();
            if (parsed.depthOutput.empty()) {
                throw UsageError("--depth-out needs a file name");
            }
        } else if (a == "--timings") {
            parsed.timings = true;
        } else if (!a.empty() && a[0] == '-' && a != "-") {
            throw UsageError("render: unknown option '" + a + "'");
        } else if (!haveInput) {
            parsed.input = a;
            haveInput = true;
        } else {
            throw UsageError("render: takes one input file, got a second one '" + a + "'");
        }
    }
    if (!haveInput) {
        throw UsageError("render: no input file");
    }
    if (!haveOutput || parsed.output.empty()) {
        throw UsageError("render: no output image (-o IMAGE.png)");
    }
    return parsed;
}

}  // namespace

int renderCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
    const RenderArguments parsed = parse(args);
    // Fail before the (possibly long) load and render when an output cannot be written.
    for (const std::filesystem::path& output : {parsed.output, parsed.depthOutput}) {
        if (output.empty()) {
            continue;
        }
        std::error_code ec;
        const std::filesystem::path folder = output.has_parent_path() ? output.parent_path() : ".";
        if (!std::filesystem::is_directory(folder, ec)) {
            throw OutputError(output.string() + ": cannot write: folder '" + folder.string() +
                              "' does not exist");
        }
        if (std::filesystem::is_directory(output, ec)) {
            throw OutputError(output.string() + ": cannot write: it is a folder");
        }
    }

    io::Scene scene;
    scene.meshes.push_back(io::loadMesh(parsed.input));

    render::OffscreenOptions options;
    options.width = parsed.width;
    options.height = parsed.height;
    options.background = parsed.background;
    options.style.colorMap = parsed.colorMap;
    options.style.bins = parsed.bins;
    options.cue = parsed.cue;
    options.legends = parsed.legends;
    options.vss = parsed.vss;
    options.ao.enabled = parsed.ao;
    options.antialiasing = parsed.aa;
    options.style.array = parsed.array.value_or(render::defaultArrayName(scene));
    if (!options.style.array.empty() &&
        scene.meshes.front().pointArray(options.style.array) == nullptr) {
        std::string known;
        for (const auto& name : render::pointArrayNames(scene)) {
            known += (known.empty() ? "" : ", ") + name;
        }
        throw UsageError("'" + parsed.input.string() + "' has no point array '" +
                         options.style.array + "' (it has: " + (known.empty() ? "none" : known) +
                         ")");
    }

    // The camera: a named view (presetCamera fits the vertices), or the
    // default orientation fitted to the bounding box as OffscreenRenderer does.
    render::Camera camera;
    if (parsed.view) {
        camera = render::presetCamera(scene, parsed.width, parsed.height, parsed.view->preset,
                                      parsed.view->rotation);
    } else {
        camera.setViewport(parsed.width, parsed.height);
        camera.fit(scene.bounds());
    }
    options.camera = camera;

    ensureGuiApplication();
    render::OffscreenRenderer renderer;
    const QImage image = renderer.render(scene, options);

    if (!parsed.depthOutput.empty()) {
        // The G-buffer's depth when the VSS solve read it for this frame,
        // else the CPU rasteriser with the same camera (same convention:
        // linear view depth in scene units, +Inf on background, row 0 on top).
        Image<float> depth =
            renderer.vssStatus().current ? renderer.lastLinearDepth() : Image<float>();
        if (depth.width() != parsed.width || depth.height() != parsed.height) {
            depth = render::rasterizeDepth(scene, camera);
        }
        try {
            vss::writePfm(parsed.depthOutput, std::as_const(depth).view());
        } catch (const IoError& e) {
            throw OutputError(e.what());
        }
    }

    try {
        writeAtomically(parsed.output, [&](const std::filesystem::path& temporary) {
            // The temporary name has no .png suffix: the format is explicit.
            if (!image.save(QFile::decodeName(temporary.c_str()), "PNG")) {
                throw IoError(parsed.output, "cannot write the PNG image");
            }
        });
    } catch (const IoError& e) {
        throw OutputError(e.what());
    }

    // With --timings, stdout carries only the JSON; the summary goes to stderr.
    std::ostream& summary = parsed.timings ? err : out;
    if (parsed.timings) {
        const auto timings = renderer.lastTimings();
        out << "{\"width\": " << image.width() << ", \"height\": " << image.height()
            << ", \"passes\": [";
        bool first = true;
        for (const auto& pass : renderer.lastPasses()) {
            out << (first ? "" : ", ") << "{\"name\": \"" << pass.name << "\", \"state\": \""
                << render::toString(pass.state) << "\"";
            for (const auto& t : timings) {
                if (t.pass == pass.name) {
                    out << ", \"cpu_ms\": " << jsonNumber(t.cpuMilliseconds) << ", \"gpu_ms\": "
                        << (t.gpuMilliseconds ? jsonNumber(*t.gpuMilliseconds) : "null");
                }
            }
            out << "}";
            first = false;
        }
        double total = 0.0;
        for (const auto& t : timings) {
            total += t.cpuMilliseconds;
        }
        const auto& status = renderer.vssStatus();
        out << "], \"total_cpu_ms\": " << jsonNumber(total)
            << ", \"vss\": {\"shown\": " << (status.shown ? "true" : "false")
            << ", \"solve_ms\": " << jsonNumber(status.solveMilliseconds) << "}}\n";
    }
    summary << "wrote " << parsed.output.string() << " (" << image.width() << "x" << image.height();
    if (options.style.array.empty()) {
        summary << ", no array";
    } else {
        summary << ", " << options.style.array << " through " << colormaps::name(parsed.colorMap);
        if (const auto range = renderer.lastRange()) {
            summary << " over [" << range->first << ", " << range->second << "]";
        } else {
            summary << ", no finite values";
        }
    }
    if (options.vss.enabled) {
        summary << ", VSS " << colormaps::name(options.vss.scale) << " p=" << options.vss.solver.p;
    }
    if (options.cue.cue != render::VesselCue::None) {
        summary << ", cue " << render::name(options.cue.cue);
    }
    summary << ")\n";
    if (!parsed.depthOutput.empty()) {
        summary << "wrote " << parsed.depthOutput.string() << " (linear depth, background +Inf)\n";
    }
    return kOk;
}

}  // namespace vv::cli
