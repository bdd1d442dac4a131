// SPDX-License-Identifier: GPL-3.0-or-later
#include "cli/RenderOptions.h"

#include <charconv>
#include <cmath>
#include <system_error>
#include <utility>

#include "cli/Cli.h"
#include "vv/colormaps/DepthScale.h"
#include "vv/core/Error.h"
#include "vv/render/MeshRenderer.h"
#include "vv/report/ViewExport.h"
#include "vv/vss/Solver.h"

namespace vv::cli {

namespace {

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

bool parseOnOff(const std::string& option, const std::string& v) {
    if (v != "on" && v != "off") {
        throw UsageError(option + " must be on or off, got '" + v + "'");
    }
    return v == "on";
}

}  // namespace

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

render::LightAngles parseLightAngles(const std::string& text) {
    const auto comma = text.find(',');
    if (comma == std::string::npos) {
        throw UsageError("--light must be AZIMUTH,ELEVATION in degrees (e.g. -30,20), got '" +
                         text + "'");
    }
    render::LightAngles angles;
    angles.azimuth = static_cast<float>(parseDouble(text.substr(0, comma), "--light azimuth"));
    angles.elevation = static_cast<float>(parseDouble(text.substr(comma + 1), "--light elevation"));
    if (std::abs(angles.azimuth) > 180.0F || std::abs(angles.elevation) > 90.0F) {
        throw UsageError(
            "--light needs an azimuth within -180..180 and an elevation within -90..90, got '" +
            text + "'");
    }
    return angles;
}

int parseTileSide(const std::string& text) {
    const int side = parseInt(text, "--tile");
    if (side < report::kMinTileSide) {
        throw UsageError("--tile must be at least " + std::to_string(report::kMinTileSide) +
                         " pixels, got '" + text + "'");
    }
    return side;
}

bool parseRenderOption(const std::vector<std::string>& args, std::size_t& i,
                       RenderOptionValues& parsed, const std::string& command) {
    const std::string& a = args[i];
    const auto value = [&]() -> const std::string& {
        if (i + 1 >= args.size()) {
            throw UsageError(command + ": " + a + " needs a value");
        }
        return args[++i];
    };
    if (a == "--size") {
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
        parsed.legends = parseOnOff(a, value());
    } else if (a == "--background") {
        parsed.background = parseColor(value());
    } else if (a == "--ao" || a == "--aa") {
        (a == "--ao" ? parsed.ao : parsed.aa) = parseOnOff(a, value());
    } else if (a == "--vss") {
        parsed.vss.enabled = parseOnOff(a, value());
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
        parsed.viewName = name;
    } else if (a == "--light") {
        parsed.light = parseLightAngles(value());
    } else {
        return false;
    }
    return true;
}

render::Camera cameraFor(const RenderOptionValues& values, const scene::Scene& scene, int width,
                         int height) {
    render::Camera camera;
    if (values.view) {
        camera =
            render::presetCamera(scene, width, height, values.view->preset, values.view->rotation);
    } else {
        camera.setViewport(width, height);
        camera.fit(scene.bounds());
    }
    return camera;
}

render::OffscreenOptions offscreenOptions(const RenderOptionValues& values,
                                          const scene::Scene& scene,
                                          const std::filesystem::path& input) {
    render::OffscreenOptions options;
    options.width = values.width;
    options.height = values.height;
    options.background = values.background;
    options.style.colorMap = values.colorMap;
    options.style.bins = values.bins;
    options.style.light = values.light;
    options.cue = values.cue;
    options.legends = values.legends;
    options.vss = values.vss;
    options.ao.enabled = values.ao;
    options.antialiasing = values.aa;
    options.style.array = values.array.value_or(render::defaultArrayName(scene));
    if (!options.style.array.empty() && !scene.meshes.empty() &&
        scene.meshes.front().pointArray(options.style.array) == nullptr) {
        std::string known;
        for (const auto& name : render::pointArrayNames(scene)) {
            known += (known.empty() ? "" : ", ") + name;
        }
        throw UsageError("'" + input.string() + "' has no point array '" + options.style.array +
                         "' (it has: " + (known.empty() ? "none" : known) + ")");
    }
    options.camera = cameraFor(values, scene, values.width, values.height);
    return options;
}

void checkOutputPath(const std::filesystem::path& output) {
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

}  // namespace vv::cli
