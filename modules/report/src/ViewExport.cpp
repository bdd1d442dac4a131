// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/report/ViewExport.h"

#include <QFile>
#include <QGuiApplication>
#include <QOffscreenSurface>
#include <QOpenGLContext>
#include <QOpenGLFunctions>
#include <QPainter>
#include <QSurfaceFormat>
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "vv/core/AtomicFile.h"
#include "vv/core/Error.h"
#include "vv/core/ImageRange.h"
#include "vv/render/DepthRasterizer.h"
#include "vv/render/GlResources.h"
#include "vv/render/TileProjection.h"
#include "vv/vss/DepthNormalization.h"
#include "vv/vss/Vss.h"

namespace vv::report {

namespace {

/// Legends are laid out for a view of this size; larger images scale them up.
constexpr double kLegendReferenceWidth = 1600.0;
constexpr double kLegendReferenceHeight = 1200.0;

/// The straight-alpha image from two renders over black and over white:
/// alpha = 1 - (white - black), colour = black / alpha.
QImage unmix(const QImage& overBlack, const QImage& overWhite) {
    QImage out(overBlack.size(), QImage::Format_ARGB32);
    for (int y = 0; y < out.height(); ++y) {
        const auto* b = reinterpret_cast<const QRgb*>(overBlack.constScanLine(y));
        const auto* w = reinterpret_cast<const QRgb*>(overWhite.constScanLine(y));
        auto* o = reinterpret_cast<QRgb*>(out.scanLine(y));
        for (int x = 0; x < out.width(); ++x) {
            const int dr = qRed(w[x]) - qRed(b[x]);
            const int dg = qGreen(w[x]) - qGreen(b[x]);
            const int db = qBlue(w[x]) - qBlue(b[x]);
            const int alpha = std::clamp(255 - (dr + dg + db) / 3, 0, 255);
            if (alpha == 0) {
                o[x] = qRgba(0, 0, 0, 0);
                continue;
            }
            const auto channel = [alpha](int premultiplied) {
                return std::clamp((premultiplied * 255 + alpha / 2) / alpha, 0, 255);
            };
            o[x] = qRgba(channel(qRed(b[x])), channel(qGreen(b[x])), channel(qBlue(b[x])), alpha);
        }
    }
    return out;
}

/// Mirrors ssao.frag: the SSAO samples reach at most this many pixels.
constexpr double kSsaoMaxPixels = 96.0;
/// The guard band beyond the SSAO's reach: its normal (1 px) and blur (2 px),
/// the VSS shading's normal fit (5 px) and FXAA (4 px), with room to spare.
constexpr int kFilterReach = 16;

/// A distinct version for the external VSS of every tile of every export.
std::uint64_t nextTileVersion() {
    static std::atomic<std::uint64_t> next{1};
    return next.fetch_add(1);
}

/// The frame without its legends (renderView paints them), over the
/// background or, with a transparent one, unmixed from two renders.
QImage renderFrame(render::OffscreenRenderer& renderer, const scene::Scene& scene,
                   const render::OffscreenOptions& frame, bool transparent) {
    if (!transparent) {
        return renderer.render(scene, frame);
    }
    // Two frames that differ only in the background: the second re-runs the
    // composite, not the solve (the graph caches it).
    render::OffscreenOptions over = frame;
    over.display.background = glm::vec3(0.0F);
    const QImage overBlack = renderer.render(scene, over);
    over.display.background = glm::vec3(1.0F);
    const QImage overWhite = renderer.render(scene, over);
    return unmix(overBlack, overWhite);
}

/// The side tiles may have, or 0 for one piece.
int tileSideFor(const ViewExportOptions& options, int limit) {
    const int width = options.render.width;
    const int height = options.render.height;
    if (options.maxTileSide < 0 ||
        (options.maxTileSide > 0 && options.maxTileSide < kMinTileSide)) {
        throw InvalidArgumentError("the largest tile side must be 0 (automatic) or at least " +
                                   std::to_string(kMinTileSide) + " pixels, got " +
                                   std::to_string(options.maxTileSide));
    }
    if (options.maxTileSide > 0) {
        const int side = std::min(options.maxTileSide, limit);
        return width <= side && height <= side ? 0 : side;
    }
    const bool fits =
        width <= limit && height <= limit &&
        static_cast<long long>(width) * height * kFrameBytesPerPixel <= kAutoTileBudgetBytes;
    return fits ? 0 : std::min(kAutoTileSide, limit);
}

/// A camera for one tile: `full` restricted to `rect`.
render::Camera tileCamera(const render::Camera& full, const render::PixelRect& rect) {
    render::Camera camera = full;
    camera.setWindow(rect);
    return camera;
}

/// The options of one tile: the full frame's, at the tile's size and camera.
render::OffscreenOptions tileOptions(const render::OffscreenOptions& frame,
                                     const render::Camera& full, const render::PixelRect& rect) {
    render::OffscreenOptions options = frame;
    options.width = rect.width;
    options.height = rect.height;
    options.camera = tileCamera(full, rect);
    return options;
}

/// `rect` of `image` (row 0 = top) in GL row order (bottom row first).
Image<float> cutForGl(const Image<float>& image, const render::PixelRect& rect) {
    Image<float> out(rect.width, rect.height);
    for (int y = 0; y < rect.height; ++y) {
        const float* from = image.row(rect.y + y) + rect.x;
        std::copy(from, from + rect.width, out.row(rect.height - 1 - y));
    }
    return out;
}

/// The guard band tiles need so that the screen-space passes see what they
/// see in one piece: the SSAO's reach in pixels at the nearest surface
/// (`nearest`, scene units) plus kFilterReach, at most a quarter of `side`.
int guardBand(const render::OffscreenOptions& frame, const render::Camera& camera, double nearest,
              int side) {
    double reach = 0.0;
    const render::AoSettings& ao = frame.display.ao;
    if (ao.enabled && ao.strength > 0.0F) {
        const double pixelScale =
            2.0 * std::tan(glm::radians(static_cast<double>(camera.fieldOfView())) * 0.5) /
            frame.height;
        reach = nearest > 0.0 && std::isfinite(nearest)
                    ? std::clamp(static_cast<double>(ao.radius) / (nearest * pixelScale), 1.0,
                                 kSsaoMaxPixels)
                    : kSsaoMaxPixels;
    }
    return std::min(static_cast<int>(std::ceil(reach)) + kFilterReach, side / 4);
}

/// Pass 1 of a tiled render: the full image's linear depth (row 0 = top,
/// +Inf on background), read back tile by tile.
Image<float> tiledDepth(render::OffscreenRenderer& renderer, const scene::Scene& scene,
                        const render::OffscreenOptions& frame, const render::Camera& camera,
                        int side, const Progress& progress) {
    Image<float> depth(frame.width, frame.height, std::numeric_limits<float>::infinity());
    const auto tiles = render::splitIntoTiles(frame.width, frame.height, side, 0);
    for (std::size_t i = 0; i < tiles.size(); ++i) {
        progress.report(static_cast<double>(i) / static_cast<double>(tiles.size()), "depth");
        const render::PixelRect& rect = tiles[i].render;
        const Image<float> part = renderer.renderDepth(scene, tileOptions(frame, camera, rect));
        for (int y = 0; y < rect.height; ++y) {
            std::copy(part.row(y), part.row(y) + rect.width, depth.row(rect.y + y) + rect.x);
        }
    }
    return depth;
}

/// The frame-wide VSS of a tiled render, for every tile: solved once on the
/// full depth. Its height is row 0 = top, full size; empty without a VSS.
render::ExternalVss solveWholeFrame(const Image<float>& depth, const render::VssSettings& settings,
                                    const Progress& progress) {
    render::ExternalVss solved;
    if (const auto range = finiteRange(depth.view())) {
        solved.visibleRange =
            std::make_pair(static_cast<double>(range->first), static_cast<double>(range->second));
    }
    if (!settings.enabled) {
        return solved;
    }
    const auto start = std::chrono::steady_clock::now();
    const Image<std::uint8_t> mask = vss::maskFromFiniteDepth(depth.view());
    vss::VssOptions vssOptions;
    vssOptions.solver = render::effectiveSolverOptions(settings);
    vssOptions.range = settings.range;
    vssOptions.stop = progress.stopToken();
    vss::VssResult result = vss::solve(depth.view(), mask.view(), vssOptions);
    solved.height = std::move(result.height);
    solved.dmin = result.dmin;
    solved.dmax = result.dmax;
    solved.errorBound = result.errorBound;
    solved.solveMilliseconds =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    return solved;
}

/// Clears the renderer's external VSS when a tiled render ends, also by an exception.
class ExternalVssScope {
  public:
    explicit ExternalVssScope(render::OffscreenRenderer& renderer) : renderer_(renderer) {}
    ~ExternalVssScope() { renderer_.setExternalVss(std::nullopt); }
    ExternalVssScope(const ExternalVssScope&) = delete;
    ExternalVssScope& operator=(const ExternalVssScope&) = delete;
    ExternalVssScope(ExternalVssScope&&) = delete;
    ExternalVssScope& operator=(ExternalVssScope&&) = delete;

  private:
    render::OffscreenRenderer& renderer_;
};

/// A tiled render of `frame` (no legends) into result.image; sets result.tiles.
/// Returns the whole frame's G-buffer depth, assembled from the tiles.
Image<float> renderTiled(render::OffscreenRenderer& renderer, const scene::Scene& scene,
                         const render::OffscreenOptions& frame, bool transparent, int side,
                         const Progress& progress, RenderedView& result) {
    const render::Camera camera = render::OffscreenRenderer::cameraFor(scene, frame);
    Image<float> depth = tiledDepth(renderer, scene, frame, camera, side, progress.sub(0.0, 0.3));
    progress.report(0.3, "solving the VSS");
    const render::ExternalVss whole = solveWholeFrame(depth, frame.display.vss, progress);
    double nearest = whole.visibleRange ? whole.visibleRange->first : 0.0;
    if (whole.height.width() != 0 && std::isfinite(whole.dmin)) {
        nearest = std::min(nearest, whole.dmin);  // a fixed VSS range may start nearer
    }
    const int guard = guardBand(frame, camera, nearest, side);
    const auto tiles = render::splitIntoTiles(frame.width, frame.height, side, guard);

    result.image = QImage(frame.width, frame.height,
                          transparent ? QImage::Format_ARGB32 : QImage::Format_RGB32);
    if (result.image.isNull()) {
        throw RenderError("cannot allocate the " + std::to_string(frame.width) + "x" +
                          std::to_string(frame.height) + " image");
    }
    const ExternalVssScope scope(renderer);
    const Progress tileProgress = progress.sub(0.4, 1.0);
    for (std::size_t i = 0; i < tiles.size(); ++i) {
        tileProgress.report(static_cast<double>(i) / static_cast<double>(tiles.size()),
                            "rendering tiles");
        const render::PixelRect& rect = tiles[i].render;
        render::ExternalVss part;
        part.version = nextTileVersion();
        if (whole.height.width() != 0) {
            part.height = cutForGl(whole.height, rect);
        }
        part.dmin = whole.dmin;
        part.dmax = whole.dmax;
        part.solveMilliseconds = whole.solveMilliseconds;
        part.errorBound = whole.errorBound;
        part.visibleRange = whole.visibleRange;
        renderer.setExternalVss(std::move(part));
        const QImage piece =
            renderFrame(renderer, scene, tileOptions(frame, camera, rect), transparent);
        const render::PixelRect& core = tiles[i].core;
        for (int y = 0; y < core.height; ++y) {
            const auto* from =
                reinterpret_cast<const QRgb*>(piece.constScanLine(core.y - rect.y + y)) +
                (core.x - rect.x);
            std::copy(from, from + core.width,
                      reinterpret_cast<QRgb*>(result.image.scanLine(core.y + y)) + core.x);
        }
    }
    tileProgress.report(1.0, "rendering tiles");
    result.tiles = static_cast<int>(tiles.size());
    return depth;
}

/// Paints options.centerlines over result.image and adds their legend.
/// `depth`: the whole frame's G-buffer depth when the render has it (tiles).
void paintCenterlines(render::OffscreenRenderer& renderer, const scene::Scene& scene,
                      const ViewExportOptions& options, double scale, Image<float> depth,
                      RenderedView& result) {
    const render::Camera camera = render::OffscreenRenderer::cameraFor(scene, options.render);
    // The tiles' depth, or the depth the VSS solve read for a frame in one
    // piece; else the CPU rasteriser's, with the same convention and camera.
    if (depth.width() == 0 && result.tiles == 1 && result.vss.current) {
        depth = renderer.lastLinearDepth();
    }
    if (depth.width() != options.render.width || depth.height() != options.render.height) {
        depth = render::rasterizeDepth(renderer.lastDrawnScene(scene, options.render), camera);
    }
    render::paintCenterlines(result.image, camera, depth, *options.centerlines, scale);
    render::addCenterlineLegend(result.legends, *options.centerlines);
}

}  // namespace

int maxRenderSide() {
    if (QGuiApplication::instance() == nullptr) {
        throw RenderError("cannot query the OpenGL limits: no QGuiApplication");
    }
    QSurfaceFormat format;
    format.setVersion(4, 1);
    format.setProfile(QSurfaceFormat::CoreProfile);
    QOffscreenSurface surface;
    surface.setFormat(format);
    surface.create();
    QOpenGLContext context;
    context.setFormat(format);
    if (!context.create() || !context.makeCurrent(&surface)) {
        throw RenderError("cannot query the OpenGL limits: no OpenGL context");
    }
    const int side = render::maxRenderSide(*context.functions());
    context.doneCurrent();
    return side;
}

RenderedView renderView(render::OffscreenRenderer& renderer, const scene::Scene& scene,
                        const ViewExportOptions& options, const Progress& progress) {
    if (options.centerlines && options.render.volume) {
        throw InvalidArgumentError(
            "centrelines cannot be drawn over a volume ray cast: they need the surface");
    }
    const int width = options.render.width;
    const int height = options.render.height;
    if (width < 1 || height < 1 || width > kMaxExportSide || height > kMaxExportSide ||
        static_cast<long long>(width) * height > kMaxExportPixels) {
        throw InvalidArgumentError("image size must be within 1x1 and 8K (7680x4320), got " +
                                   std::to_string(width) + "x" + std::to_string(height));
    }
    const int limit = renderer.maxRenderSide();  // its own context: no probe surface
    int side = tileSideFor(options, limit);
    render::OffscreenOptions frame = options.render;
    frame.display.legends = false;  // both painted below
    frame.display.orientationMarker = false;
    frame.display.scaleBar = false;
    RenderedView result;
    progress.throwIfCancelled();
    if (side == 0) {
        try {
            result.image = renderFrame(renderer, scene, frame, options.transparentBackground);
        } catch (const RenderError&) {
            // Out of GPU memory or an incomplete framebuffer at this size:
            // tiles of half the size (or the automatic side) need less.
            side = std::min({kAutoTileSide, limit, (std::max(width, height) + 1) / 2});
            if (options.maxTileSide != 0 || side < kMinTileSide) {
                throw;
            }
            renderer.clearCache();  // free what the failed frame holds
        }
    }
    Image<float> wholeDepth;
    if (side != 0) {
        wholeDepth = renderTiled(renderer, scene, frame, options.transparentBackground, side,
                                 progress, result);
    }
    progress.report(1.0, "rendering");
    result.range = renderer.lastRange();
    result.vss = renderer.vssStatus();

    result.legends = render::legendsFor(&scene, frame.display.style, result.range,
                                        render::frameSettings(frame.display), result.vss,
                                        renderer.lastCueDepthRange());
    const double scale =
        std::max(1.0, std::min(width / kLegendReferenceWidth, height / kLegendReferenceHeight));
    if (options.centerlines) {
        paintCenterlines(renderer, scene, options, scale, std::move(wholeDepth), result);
    }
    if (options.legends && !result.legends.empty()) {
        QPainter painter(&result.image);
        painter.setRenderHint(QPainter::Antialiasing);
        painter.setRenderHint(QPainter::TextAntialiasing);
        painter.scale(scale, scale);
        render::paintLegends(painter, QRectF(0.0, 0.0, width / scale, height / scale),
                             result.legends);
    }
    const render::DisplaySettings& display = options.render.display;
    if (display.orientationMarker || display.scaleBar) {
        QPainter painter(&result.image);  // over the whole image, with its whole camera
        render::paintViewAnnotations(painter, QRectF(result.image.rect()),
                                     render::OffscreenRenderer::cameraFor(scene, options.render),
                                     render::viewAnnotations(display, scene.frame));
    }
    return result;
}

void writePng(const std::filesystem::path& path, const QImage& image) {
    if (image.isNull()) {
        throw InvalidArgumentError(path, "no image to write");
    }
    writeAtomically(path, [&](const std::filesystem::path& temporary) {
        QFile file(QFile::decodeName(temporary.c_str()));
        if (!file.open(QIODevice::WriteOnly) || !image.save(&file, "PNG") || !file.flush()) {
            throw IoError(path, "cannot write the PNG image: " + file.errorString().toStdString());
        }
        file.close();
        if (file.error() != QFileDevice::NoError) {
            throw IoError(path, "cannot write the PNG image: " + file.errorString().toStdString());
        }
    });
}

}  // namespace vv::report
