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
//                            [--centerlines on|off] [--centerline-colour diameter|branch]
//                            [every display setting with an option in SettingsSchema.h]
// vesselview-cli render --session F.vvs -o IMAGE.png [options]
// --session renders what the GUI saved: its files (DICOM: with the stored
// series and segmentation), camera and display settings, through
// report::renderView as File > Export Image does; options after it override it.
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
#include <QGuiApplication>
#include <QImage>
#include <cmath>
#include <filesystem>
#include <memory>
#include <optional>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "cli/Arguments.h"
#include "cli/CenterlineDrawing.h"
#include "cli/Cli.h"
#include "cli/GuiApplication.h"
#include "cli/JsonWriter.h"
#include "cli/OutputFiles.h"
#include "cli/RenderOptions.h"
#include "cli/SegmentSummary.h"
#include "common/SmoothCopy.h"
#include "vv/colormaps/ColorMap.h"
#include "vv/colormaps/DepthScale.h"
#include "vv/core/Error.h"
#include "vv/dicom/Dicom.h"
#include "vv/meshio/MeshLoader.h"
#include "vv/render/DepthRasterizer.h"
#include "vv/render/LegendPainter.h"
#include "vv/render/MeshStyle.h"
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
    std::filesystem::path input;  ///< FILE, or the --session file
    std::filesystem::path output;
    bool timings = false;
    std::filesystem::path depthOutput;  ///< --depth-out; empty = none
    bool raycast = false;               ///< --raycast: the volume as depth source
    std::optional<float> iso;           ///< --iso HU
    int maxTileSide = 0;                ///< --tile N; 0 = one piece
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
    scene.frame = scene::SceneFrame::PatientLps;  // a volume's world is LPS mm
    return scene;
}

RenderArguments parseRenderArguments(const std::vector<std::string>& args) {
    RenderArguments parsed;
    bool haveInput = false;
    bool haveOutput = false;
    for (Arguments a("render", args); a.next();) {
        const std::string& name = a.name();
        if (name == "-o" || name == "--output") {
            parsed.output = a.value();
            haveOutput = true;
        } else if (parseRenderOption(a, parsed)) {
            // a shared render option (RenderOptions.h)
        } else if (name == "--depth-out") {
            parsed.depthOutput = a.path();
        } else if (name == "--timings") {
            parsed.timings = true;
        } else if (name == "--tile") {
            parsed.maxTileSide = parseTileSide(a.value());
        } else if (name == "--raycast") {
            parsed.raycast = true;
        } else if (name == "--iso") {
            parsed.iso = static_cast<float>(parseNumber(a.value(), "--iso"));
        } else {
            a.takeOneInput(parsed.input, haveInput);
        }
    }
    if (parsed.session) {
        if (haveInput) {
            throw UsageError("render: --session names the input files; give no FILE with it");
        }
        if (parsed.raycast) {
            throw UsageError("render: --raycast cannot be combined with --session");
        }
        parsed.input = parsed.sessionFile;
    } else if (!haveInput) {
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
    if (parsed.raycast && parsed.centerlines) {
        throw UsageError("render: --centerlines needs a surface; --raycast has none");
    }
    if (parsed.raycast && !parsed.depthOutput.empty() && !parsed.vss.enabled) {
        // The depth comes from the VSS solve's read-back; the CPU rasteriser has no volumes.
        throw UsageError("render: --depth-out with --raycast needs the VSS on");
    }
    return parsed;
}

/// --timings: the passes of the last frame and their times, as one line of JSON.
void writeTimings(std::ostream& out, render::OffscreenRenderer& renderer, const QImage& image) {
    JsonWriter json(out, JsonWriter::Layout::OneLine);
    json.beginObject();
    json.member("width", image.width());
    json.member("height", image.height());
    json.key("passes");
    json.beginArray();
    const auto timings = renderer.lastTimings();
    for (const auto& pass : renderer.lastPasses()) {
        json.beginObject();
        json.member("name", pass.name);
        json.member("state", render::toString(pass.state));
        for (const auto& t : timings) {
            if (t.pass == pass.name) {
                json.member("cpu_ms", t.cpuMilliseconds);
                json.key("gpu_ms");
                t.gpuMilliseconds ? json.number(*t.gpuMilliseconds) : json.null();
            }
        }
        json.endObject();
    }
    json.endArray();
    double total = 0.0;
    for (const auto& t : timings) {
        total += t.cpuMilliseconds;
    }
    json.member("total_cpu_ms", total);
    const auto& status = renderer.vssStatus();
    json.key("vss");
    json.beginObject();
    json.member("shown", status.shown);
    json.member("solve_ms", status.solveMilliseconds);
    json.endObject();
    json.endObject();
    json.finish();
}

/// The summary's "wrote IMAGE (size, array, VSS, cue, centrelines" (the caller closes it).
void describeImage(std::ostream& summary, const RenderArguments& parsed, const scene::Scene& scene,
                   const render::OffscreenOptions& options,
                   const render::OffscreenRenderer& renderer, const QImage& image, int tiles,
                   const std::optional<render::CenterlineOverlay>& centerlines) {
    summary << "wrote " << parsed.output.string() << " (" << image.width() << "x" << image.height();
    if (tiles > 1) {
        summary << " in " << tiles << " tiles";
    }
    const render::DisplaySettings& display = options.display;
    const auto labels = display.style.array.empty()
                            ? std::nullopt
                            : render::shownLabels(scene, display.style, display.style.array);
    if (display.style.array.empty()) {
        summary << ", no array";
    } else if (labels) {
        summary << ", " << display.style.array << " as " << labels->size() << " labels";
    } else {
        summary << ", " << display.style.array << " through "
                << colormaps::name(display.style.colorMap);
        if (const auto range = renderer.lastRange()) {
            summary << " over [" << range->first << ", " << range->second << "]";
        } else {
            summary << ", no finite values";
        }
    }
    if (display.vss.enabled) {
        summary << ", VSS " << colormaps::name(display.vss.scale) << " p=" << display.vss.solver.p;
    }
    if (display.cue.cue != render::VesselCue::None) {
        summary << ", cue " << render::name(display.cue.cue);
    }
    if (centerlines) {
        summary << ", " << centerlines->lines.size() << " centrelines by "
                << (centerlines->colouring == render::CenterlineColouring::Branch
                        ? "branch"
                        : "inscribed diameter");
    }
}

}  // namespace

int renderCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
    const RenderArguments parsed = parseRenderArguments(args);
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
        scene.frame = scene::SceneFrame::PatientLps;  // no meshes, the volume's frame
    } else if (parsed.session) {
        scene = loadSessionInput(parsed, &source);
    } else {
        scene = segmentation::loadSceneSource(parsed.input, parsed.source, {}, &source);
    }

    render::OffscreenOptions options =
        offscreenOptions(parsed, volume ? cornerScene(*volume) : scene, parsed.input);
    options.volume = volume;
    options.isoValue = iso;
    const render::Camera camera = *options.camera;
    std::optional<render::CenterlineOverlay> centerlines;
    if (parsed.centerlines) {
        centerlines = centerlineOverlay(scene, parsed.input, parsed.centerlineColouring,
                                        options.display.style.colorMap, err);
    }

    ensureGuiApplication();
    render::OffscreenRenderer renderer;
    QImage image;
    int tiles = 1;
    if (parsed.session) {
        // Exactly what the GUI's File > Export Image gives at this size:
        // report::renderView, the legends scaled with the image.
        report::ViewExportOptions exported;
        exported.render = options;
        exported.legends = options.display.legends;
        exported.maxTileSide = parsed.maxTileSide;
        exported.centerlines = centerlines;
        report::RenderedView view = report::renderView(renderer, scene, exported);
        image = std::move(view.image);
        tiles = view.tiles;
    } else if (parsed.maxTileSide > 0 || centerlines) {
        // In tiles, or with the centrelines drawn before the legends.
        report::ViewExportOptions tiled;
        tiled.render = options;
        tiled.legends = false;  // painted below as render() paints them
        tiled.maxTileSide = parsed.maxTileSide;
        tiled.centerlines = centerlines;
        report::RenderedView view = report::renderView(renderer, scene, tiled);
        if (options.display.legends) {
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
            depth = render::rasterizeDepth(renderer.lastDrawnScene(scene, options), camera);
        }
        try {
            vss::writePfm(parsed.depthOutput, std::as_const(depth).view());
        } catch (const IoError& e) {
            throw OutputError(e.what());
        }
    }

    writePngOutput(parsed.output, image);

    // With --timings, stdout carries only the JSON; the summary goes to stderr.
    std::ostream& summary = parsed.timings ? err : out;
    if (parsed.timings) {
        writeTimings(out, renderer, image);
    }
    if (volume) {
        summary << "ray cast series " << source.seriesInstanceUid << " (" << source.volumeDims.x
                << "x" << source.volumeDims.y << "x" << source.volumeDims.z << ") at iso " << iso
                << (volume->unit().empty() ? "" : " " + volume->unit()) << "\n";
    } else {
        printSegmentationSummary(summary, err, source, scene);
    }
    if (parsed.session) {
        summary << "session " << parsed.sessionFile.string() << ": " << parsed.session->files.size()
                << " file(s), " << scene.meshes.size() << " mesh(es), its camera"
                << (parsed.sessionCamera ? "" : " replaced by --view") << "\n";
    }
    describeImage(summary, parsed, scene, options, renderer, image, tiles, centerlines);
    summary << ")\n";
    if (renderer.lastFrameRefined() && options.refined) {
        summary << app::smoothCopyNote(*options.refined) << "\n";
    }
    if (!parsed.depthOutput.empty()) {
        summary << "wrote " << parsed.depthOutput.string() << " (linear depth, background +Inf)\n";
    }
    return kOk;
}

}  // namespace vv::cli
