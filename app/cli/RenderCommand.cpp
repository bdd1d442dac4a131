// SPDX-License-Identifier: GPL-3.0-or-later
// vesselview-cli render FILE -o IMAGE.png [--size WxH] [--array NAME|none]
//                            [--colormap NAME] [--bins N] [--background #rrggbb]
//                            [--cue none|vessel-cd|vessel-pcd|fog|fresnel] [--legends on|off]
//                            [--vss on|off] [--scale cd|pcd|dmd] [--p P] [--isolines N]
//                            [--solver NAME] [--tolerance T] [--ao on|off] [--aa on|off]
//                            [--timings]
//                            [--view far|medium|close|anterior|posterior|left|right|
//                                    superior|inferior]
//                            [--depth-out DEPTH.pfm] [--tile N]
// --tile N renders in tiles of at most N pixels per side (small GPUs; the
// image is the same, report::renderView); not with --timings / --depth-out.
// FILE may be a mesh file or DICOM (a folder, a DICOMDIR, a file): the series is
// segmented into vessel surfaces, see segmentation::setSceneSourceOption:
//                            [--series UID] [--threshold LO:HI] [--components N]
//                            [--seed I,J,K] [--bone-removal on|off] [--triangles N]
// or, with --raycast [--iso HU], ray cast directly as an iso-surface (volume
// depth source; no segmentation, no mesh): the iso value defaults to the lower
// threshold (--threshold, else the modality's default range).
// Needs OpenGL 4.1: a display (headless: xvfb-run -a with QT_QPA_PLATFORM=xcb).
#include <QFile>
#include <QGuiApplication>
#include <QImage>
#include <QString>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <optional>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "cli/Cli.h"
#include "cli/GuiApplication.h"
#include "cli/RenderOptions.h"
#include "vv/colormaps/ColorMap.h"
#include "vv/colormaps/DepthScale.h"
#include "vv/core/AtomicFile.h"
#include "vv/core/Error.h"
#include "vv/dicom/Dicom.h"
#include "vv/meshio/MeshLoader.h"
#include "vv/render/DepthRasterizer.h"
#include "vv/render/LegendPainter.h"
#include "vv/render/MeshRenderer.h"
#include "vv/render/OffscreenRenderer.h"
#include "vv/render/RenderGraph.h"
#include "vv/render/ViewPresets.h"
#include "vv/report/ViewExport.h"
#include "vv/segmentation/SceneSource.h"
#include "vv/segmentation/VolumeSegmentation.h"
#include "vv/vss/Pfm.h"
#include "vv/vss/Solver.h"

namespace vv::cli {

namespace {

struct RenderArguments : RenderOptionValues {
    std::filesystem::path input;
    std::filesystem::path output;
    bool timings = false;
    std::filesystem::path depthOutput;        ///< --depth-out; empty = none
    segmentation::SceneSourceOptions source;  ///< DICOM: series, segmentation, surface
    bool raycast = false;                     ///< --raycast: the volume as depth source
    std::optional<float> iso;                 ///< --iso HU
    int maxTileSide = 0;                      ///< --tile N; 0 = one piece
};

/// --raycast: a scene of the volume's eight corners, only for fitting the camera.
scene::Scene cornerScene(const scene::Volume& volume) {
    scene::Mesh corners;
    const glm::dvec3 last = glm::dvec3(volume.dims() - 1);
    for (int c = 0; c < 8; ++c) {
        const glm::dvec3 ijk((c & 1) != 0 ? last.x : 0.0, (c & 2) != 0 ? last.y : 0.0,
                             (c & 4) != 0 ? last.z : 0.0);
        corners.positions.emplace_back(volume.worldPosition(ijk));
    }
    scene::Scene scene;
    scene.meshes.push_back(std::move(corners));
    return scene;
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
        } else if (parseRenderOption(args, i, parsed, "render")) {
            // a shared render option (RenderOptions.h)
        } else if (a == "--depth-out") {
            parsed.depthOutput = value();
            if (parsed.depthOutput.empty()) {
                throw UsageError("--depth-out needs a file name");
            }
        } else if (a == "--timings") {
            parsed.timings = true;
        } else if (a == "--tile") {
            parsed.maxTileSide = parseTileSide(value());
        } else if (a == "--raycast") {
            parsed.raycast = true;
        } else if (a == "--iso") {
            parsed.iso = static_cast<float>(parseDouble(value(), "--iso"));
        } else if (segmentation::setSceneSourceOption(
                       a, i + 1 < args.size() ? args[i + 1] : std::string(), parsed.source)) {
            ++i;  // a DICOM option and its value
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
    if (parsed.iso && !parsed.raycast) {
        throw UsageError("render: --iso needs --raycast");
    }
    if (parsed.maxTileSide > 0 && (parsed.timings || !parsed.depthOutput.empty())) {
        // Both describe one frame's G-buffer and passes; tiles have many.
        throw UsageError("render: --tile cannot be combined with --timings or --depth-out");
    }
    if (parsed.raycast && !parsed.depthOutput.empty() && !parsed.vss.enabled) {
        // The depth comes from the VSS solve's read-back; the CPU rasteriser has no volumes.
        throw UsageError("render: --depth-out with --raycast needs the VSS on");
    }
    return parsed;
}

}  // namespace

int renderCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
    const RenderArguments parsed = parse(args);
    // Fail before the (possibly long) load and render when an output cannot be written.
    for (const std::filesystem::path& output : {parsed.output, parsed.depthOutput}) {
        if (!output.empty()) {
            checkOutputPath(output);
        }
    }

    // A mesh file, or DICOM segmented into vessel surfaces.
    segmentation::SceneSourceReport source;
    scene::Scene scene;
    std::shared_ptr<const scene::Volume> volume;  // --raycast
    float iso = 0.0F;
    if (parsed.raycast) {
        if (!segmentation::isDicomSource(parsed.input)) {
            throw UsageError(
                "render: --raycast needs DICOM (a folder, a DICOMDIR or a file), got '" +
                parsed.input.string() + "'");
        }
        dicom::DicomVolume loaded = dicom::loadDicomVolume(
            parsed.input, parsed.source.seriesInstanceUid, parsed.source.dicom);
        source.seriesInstanceUid = loaded.seriesInstanceUid;
        source.volumeDims = loaded.volume.dims();
        volume = std::make_shared<const scene::Volume>(std::move(loaded.volume));
        iso = parsed.iso.value_or(parsed.source.segmentation.range
                                      ? parsed.source.segmentation.range->lower
                                      : segmentation::defaultThresholdRange(*volume).lower);
    } else {
        scene = segmentation::loadSceneSource(parsed.input, parsed.source, {}, &source);
    }

    render::OffscreenOptions options =
        offscreenOptions(parsed, volume ? cornerScene(*volume) : scene, parsed.input);
    options.volume = volume;
    options.isoValue = iso;
    const render::Camera camera = *options.camera;

    ensureGuiApplication();
    render::OffscreenRenderer renderer;
    QImage image;
    int tiles = 1;
    if (parsed.maxTileSide > 0) {
        report::ViewExportOptions tiled;
        tiled.render = options;
        tiled.legends = false;  // painted below as render() paints them
        tiled.maxTileSide = parsed.maxTileSide;
        report::RenderedView view = report::renderView(renderer, scene, tiled);
        if (options.legends) {
            render::paintLegends(view.image, view.legends);
        }
        image = std::move(view.image);
        tiles = view.tiles;
    } else {
        image = renderer.render(scene, options);
    }

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
    if (volume) {
        summary << "ray cast series " << source.seriesInstanceUid << " (" << source.volumeDims.x
                << "x" << source.volumeDims.y << "x" << source.volumeDims.z << ") at iso " << iso
                << (volume->unit().empty() ? "" : " " + volume->unit()) << "\n";
    } else if (source.fromVolume) {
        summary << "segmented series " << source.seriesInstanceUid << " (" << source.volumeDims.x
                << "x" << source.volumeDims.y << "x" << source.volumeDims.z
                << "): " << source.range.rule << ", kept " << source.componentsKept << " of "
                << source.componentsFound << " components, " << source.boneComponents
                << " bone-like removed, " << scene.meshes.front().triangleCount() << " triangles\n";
    } else if (source.fromSegmentationObject) {
        summary << "read " << scene.meshes.size() << " segment(s) from the DICOM SEG:";
        for (const scene::Mesh& mesh : scene.meshes) {
            summary << " '" << mesh.name << "'";
        }
        summary << "\n";
    }
    summary << "wrote " << parsed.output.string() << " (" << image.width() << "x" << image.height();
    if (tiles > 1) {
        summary << " in " << tiles << " tiles";
    }
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
