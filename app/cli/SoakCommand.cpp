// SPDX-License-Identifier: GPL-3.0-or-later
// `vesselview-cli soak FRAMES [--mesh FILE] [--size WxH] [--every N]`
// (hidden; scripts/soak runs it): renders FRAMES frames in one process with
// the camera and the settings changing every frame, and checks that resident
// memory does not grow (issue 9, docs/reliability.md).
#include <QGuiApplication>
#include <QImage>
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <limits>
#include <optional>
#include <ostream>
#include <string>
#include <tuple>
#include <vector>

#include "cli/Arguments.h"
#include "cli/Cli.h"
#include "cli/GuiApplication.h"
#include "vv/colormaps/ColorMap.h"
#include "vv/colormaps/DepthScale.h"
#include "vv/core/Error.h"
#include "vv/core/NumberText.h"
#include "vv/core/ProcessMemory.h"
#include "vv/demo/DemoTree.h"
#include "vv/meshio/MeshLoader.h"
#include "vv/render/Camera.h"
#include "vv/render/DisplaySettings.h"
#include "vv/render/OffscreenRenderer.h"

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace vv::cli {

namespace {

constexpr const char* kSoakUsage =
    "usage: vesselview-cli soak FRAMES [--mesh FILE] [--size WxH] [--every N]\n"
    "                               [--resize-every N] [--trim]\n"
    "  Renders FRAMES frames (>= 101) offscreen in one process, changing the camera\n"
    "  and the settings (VSS, scale, p, iso-lines, colour map, array, AO, FXAA,\n"
    "  cue, legends, size) every frame; OpenGL errors are checked after every\n"
    "  frame (a GL error fails the frame). Reads resident memory (VmRSS) after\n"
    "  every frame and prints it every N frames (default 1000). Readings swing by\n"
    "  tens of MiB from frame to frame (transient buffers, GL objects the driver\n"
    "  frees late), so the memory in use is the floor (lowest reading) over a\n"
    "  window of 100 frames: a leak raises it, a transient does not. Exit 1 when\n"
    "  the floor of the last 100 frames is more than 5% above that of frames\n"
    "  1..100; the peaks of both windows are printed too.\n"
    "  --mesh FILE  the scene (default: the demo tree, generated in memory)\n"
    "  --size WxH   the base image size (default 640x480)\n"
    "  --resize-every N  switch between the base size and 3/4 of it every N\n"
    "               frames (default 500; 0 = never)\n"
    "  --trim       return freed heap to the system (malloc_trim) before each\n"
    "               reading: tells a leak from allocator high-water marks\n";

/// VmRSS of this process in KiB, from /proc/self/status; 0 when unknown.
/// With `trim`, first returns the free heap to the system.
std::uint64_t residentAfterTrimKiB(bool trim) {
#if defined(__GLIBC__)
    if (trim) {
        malloc_trim(0);
    }
#else
    (void)trim;
#endif
    return vv::residentKiB().value_or(0);
}

std::string mib(std::uint64_t kib) {
    return vv::fixedText(static_cast<double>(kib) / 1024.0, 1) + " MiB";
}

/// The display settings of soak frame `f` (1..): every setting changes now
/// and then, each on its own period; `arrays` are the scene's ("" = none).
/// No orientation marker or scale bar, as in OffscreenOptions{}.
render::DisplaySettings frameDisplay(long f, const std::vector<std::string>& arrays) {
    constexpr std::array<colormaps::DepthScale, 3> kScales = {
        colormaps::DepthScale::Chromadepth, colormaps::DepthScale::PseudoChromadepth,
        colormaps::DepthScale::DarkMeansDeep};
    constexpr std::array<colormaps::ColorMap, 4> kMaps = {
        colormaps::ColorMap::Viridis, colormaps::ColorMap::Cividis, colormaps::ColorMap::Inferno,
        colormaps::ColorMap::BlueWhiteRed};
    constexpr std::array<render::VesselCue, 5> kCues = {
        render::VesselCue::None, render::VesselCue::Chromadepth,
        render::VesselCue::PseudoChromadepth, render::VesselCue::Fog, render::VesselCue::Fresnel};
    constexpr std::array<double, 4> kPowers = {2.0, 4.0, 1.0, 8.0};

    const auto k = static_cast<std::size_t>(f);
    render::DisplaySettings display = render::OffscreenOptions{}.display;
    display.style.array = arrays[(k / 3) % arrays.size()];
    display.style.colorMap = kMaps[(k / 5) % kMaps.size()];
    display.style.bins = (f / 7) % 3 == 0 ? 0 : static_cast<int>(2 + (k / 7) % 9);
    display.vss.enabled = f % 11 != 0;
    display.vss.scale = kScales[(k / 4) % kScales.size()];
    display.vss.solver.p = kPowers[(k / 9) % kPowers.size()];
    display.vss.isoLines = static_cast<int>((k / 2) % 13);
    display.vss.preview = f % 6 == 0;
    display.cue.cue = kCues[(k / 13) % kCues.size()];
    display.ao.enabled = f % 5 != 0;
    display.antialiasing = f % 3 != 0;
    display.legends = f % 17 == 0;
    display.background = glm::vec3(0.1F + 0.05F * static_cast<float>(f % 4), 0.14F, 0.16F);
    return display;
}

/// printf's "%+.2f%%".
std::string signedPercent(double percent) {
    return (std::signbit(percent) ? "" : "+") + vv::fixedText(percent, 2) + "%";
}

struct SoakOptions {
    long frames = 0;
    std::filesystem::path meshFile;
    int width = 640;
    int height = 480;
    long every = 1000;
    long resizeEvery = 500;
    bool trim = false;
};

/// The soak's arguments; nullopt after --help (the usage is printed to `out`).
/// Throws UsageError on a bad or missing argument.
std::optional<SoakOptions> parseSoakArguments(const std::vector<std::string>& args,
                                              std::ostream& out) {
    SoakOptions soak;
    for (Arguments arg("soak", args); arg.next();) {
        const std::string& a = arg.name();
        if (a == "--help" || a == "-h") {
            out << kSoakUsage;
            return std::nullopt;
        }
        if (a == "--mesh") {
            soak.meshFile = arg.path();
        } else if (a == "--size") {
            std::tie(soak.width, soak.height) = parseSize(arg.value(), "soak: --size", 16, 4096);
        } else if (a == "--resize-every") {
            soak.resizeEvery = std::max(0, parseWholeNumber(arg.value(), "soak: --resize-every"));
        } else if (a == "--trim") {
            soak.trim = true;
        } else if (a == "--every") {
            soak.every = std::max(1, parseWholeNumber(arg.value(), "soak: --every"));
        } else if (!arg.isOption() && soak.frames == 0) {
            soak.frames = parseWholeNumber(a, "soak: FRAMES");
        } else {
            arg.fail("unexpected argument '" + arg.current() + "'");
        }
    }
    if (soak.frames < 101) {
        throw UsageError("soak: FRAMES must be at least 101");
    }
    return soak;
}

/// What frame `f` (1-based) renders: the size, the camera and the settings
/// (frameDisplay()), each cycling with its own period so that the frames go
/// through their combinations. `arrays` are the mesh's point arrays, "" (none)
/// first.
render::OffscreenOptions frameOptions(long f, const SoakOptions& soak, const Aabb& bounds,
                                      const std::vector<std::string>& arrays) {
    render::OffscreenOptions options;
    const bool small = soak.resizeEvery > 0 && (f / soak.resizeEvery) % 2 == 1;
    options.width = small ? soak.width * 3 / 4 : soak.width;
    options.height = small ? soak.height * 3 / 4 : soak.height;
    render::Camera camera;
    camera.setViewport(options.width, options.height);
    camera.fit(bounds);
    camera.rotateView(static_cast<float>(f) * 0.037F, glm::vec3(0.0F, 0.0F, 1.0F));
    camera.rotateView(static_cast<float>(f % 97) * 0.011F, glm::vec3(1.0F, 0.0F, 0.0F));
    camera.pan(glm::vec2(static_cast<float>(f % 13) - 6.0F, static_cast<float>(f % 7) - 3.0F));
    options.camera = camera;
    options.display = frameDisplay(f, arrays);
    return options;
}

/// Resident memory over the first 100 frames and the last 100: peak and
/// floor (lowest reading) of each window.
struct MemoryWindows {
    std::uint64_t after100 = 0;  // peak over frames 1..100
    std::uint64_t end = 0;       // peak over the last 100 frames
    std::uint64_t floor100 = std::numeric_limits<std::uint64_t>::max();  // lowest, frames 1..100
    std::uint64_t floorEnd = std::numeric_limits<std::uint64_t>::max();  // lowest, last 100

    /// Counts frame `f`'s reading `rss` (KiB) in the windows it belongs to.
    void record(long f, long frames, std::uint64_t rss) {
        if (f <= 100) {
            after100 = std::max(after100, rss);
            floor100 = std::min(floor100, rss);
        }
        if (f > frames - 100) {
            end = std::max(end, rss);
            floorEnd = std::min(floorEnd, rss);
        }
    }
};

/// Prints the run's line and judges it: kOk, or kInternalError (with the
/// reason on `err`) when VmRSS could not be read or the floor grew by more than 5%.
int soakVerdict(const SoakOptions& soak, const MemoryWindows& memory, double seconds,
                std::ostream& out, std::ostream& err) {
    const auto percent = [](std::uint64_t before, std::uint64_t after) {
        return before > 0 ? 100.0 * (static_cast<double>(after) / static_cast<double>(before) - 1.0)
                          : 0.0;
    };
    const double growth = percent(memory.floor100, memory.floorEnd);
    out << "soak: " << soak.frames << " frames in " << vv::fixedText(seconds, 0) << " s ("
        << vv::fixedText(1000.0 * seconds / static_cast<double>(soak.frames), 1)
        << " ms/frame); resident in use (floor) over frames 1-100 " << mib(memory.floor100)
        << ", over the last 100 " << mib(memory.floorEnd) << " (" << signedPercent(growth)
        << "); peaks " << mib(memory.after100) << " and " << mib(memory.end) << " ("
        << signedPercent(percent(memory.after100, memory.end)) << ")\n";
    if (memory.floor100 == 0 || memory.floorEnd == 0) {
        err << "vesselview-cli: soak: cannot read VmRSS from /proc/self/status\n";
        return kInternalError;
    }
    if (growth > 5.0) {
        err << "vesselview-cli: soak: resident memory grew by more than 5% after frame 100\n";
        return kInternalError;
    }
    return kOk;
}

}  // namespace

int soakCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
    const std::optional<SoakOptions> parsed = parseSoakArguments(args, out);
    if (!parsed) {
        return kOk;
    }
    const SoakOptions& soak = *parsed;

    scene::Scene scene;
    scene.meshes.push_back(soak.meshFile.empty() ? demo::generateDemoMesh()
                                                 : meshio::loadMesh(soak.meshFile));
    std::vector<std::string> arrays = {""};
    for (const auto& a : scene.meshes.front().pointArrays) {
        arrays.push_back(a.name);
    }
    const Aabb bounds = scene.bounds();

    ensureGuiApplication();
    render::OffscreenRenderer renderer;
    out << "soak: " << soak.frames << " frames of " << scene.meshes.front().triangleCount()
        << " triangles at " << soak.width << "x" << soak.height << " (3/4 of it every "
        << soak.resizeEvery << " frames), " << renderer.glDescription() << "\n";
    out.flush();

    MemoryWindows memory;
    std::uint64_t lapPeak = 0;  // peak since the last progress line
    const auto start = std::chrono::steady_clock::now();
    auto lapStart = start;
    for (long f = 1; f <= soak.frames; ++f) {
        const render::OffscreenOptions options = frameOptions(f, soak, bounds, arrays);
        try {
            const QImage image = renderer.render(scene, options);
            if (image.width() != options.width || image.height() != options.height) {
                err << "vesselview-cli: soak: frame " << f << " has the wrong size\n";
                return kInternalError;
            }
        } catch (const RenderError& e) {
            // OffscreenRenderer::render reads glGetError after the frame (GL
            // errors are sticky, so one raised anywhere in the frame shows).
            err << "vesselview-cli: soak: frame " << f << ": " << e.what() << "\n";
            return kInternalError;
        }
        const std::uint64_t rss = residentAfterTrimKiB(soak.trim);
        lapPeak = std::max(lapPeak, rss);
        memory.record(f, soak.frames, rss);
        if (f == 100) {
            out << "frames 1-100: resident " << mib(memory.floor100) << " .. "
                << mib(memory.after100) << "\n";
        }
        if (f % soak.every == 0 || f == soak.frames) {
            const auto now = std::chrono::steady_clock::now();
            const double lap = std::chrono::duration<double>(now - lapStart).count();
            const long lapFrames = f % soak.every == 0 ? soak.every : f % soak.every;
            lapStart = now;
            out << "frame " << f << ": resident " << mib(rss) << " (peak since last "
                << mib(lapPeak) << "), "
                << vv::fixedText(1000.0 * lap / static_cast<double>(lapFrames), 1) << " ms/frame\n";
            lapPeak = 0;
            out.flush();
        }
    }
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return soakVerdict(soak, memory, seconds, out, err);
}

}  // namespace vv::cli
