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
#include <string>

#include "vv/core/AtomicFile.h"
#include "vv/core/Error.h"

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
    QOpenGLFunctions* gl = context.functions();
    GLint texture = 0;
    GLint renderbuffer = 0;
    GLint viewport[2] = {0, 0};
    gl->glGetIntegerv(GL_MAX_TEXTURE_SIZE, &texture);
    gl->glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &renderbuffer);
    gl->glGetIntegerv(GL_MAX_VIEWPORT_DIMS, viewport);
    context.doneCurrent();
    return std::min({texture, renderbuffer, viewport[0], viewport[1]});
}

RenderedView renderView(render::OffscreenRenderer& renderer, const io::Scene& scene,
                        const ViewExportOptions& options) {
    const int width = options.render.width;
    const int height = options.render.height;
    if (width < 1 || height < 1 || width > kMaxExportSide || height > kMaxExportSide ||
        static_cast<long long>(width) * height > kMaxExportPixels) {
        throw InvalidArgumentError("image size must be within 1x1 and 8K (7680x4320), got " +
                                   std::to_string(width) + "x" + std::to_string(height));
    }
    // Tiling is not done: the VSS is interpolated over whole void regions, so
    // tiles would each need the full frame's depth. Every GL 4.1 driver we
    // know of renders 8K in one piece (llvmpipe: 16384).
    const int limit = maxRenderSide();
    if (width > limit || height > limit) {
        throw RenderError("cannot render " + std::to_string(width) + "x" + std::to_string(height) +
                          ": this OpenGL renders at most " + std::to_string(limit) +
                          " pixels per side in one piece");
    }

    render::OffscreenOptions frame = options.render;
    frame.legends = false;
    RenderedView result;
    if (options.transparentBackground) {
        // Two frames that differ only in the background: the second re-runs
        // the composite, not the solve (the graph caches it).
        frame.background = glm::vec3(0.0F);
        const QImage overBlack = renderer.render(scene, frame);
        frame.background = glm::vec3(1.0F);
        const QImage overWhite = renderer.render(scene, frame);
        result.image = unmix(overBlack, overWhite);
    } else {
        result.image = renderer.render(scene, frame);
    }
    result.range = renderer.lastRange();
    result.vss = renderer.vssStatus();

    render::FrameSettings settings;
    settings.background = frame.background;
    settings.vss = frame.vss;
    settings.cue = frame.cue;
    settings.ao = frame.ao;
    settings.antialiasing = frame.antialiasing;
    result.legends = render::legendsFor(&scene, frame.style, result.range, settings, result.vss,
                                        renderer.lastCueDepthRange());
    if (options.legends && !result.legends.empty()) {
        const double scale =
            std::max(1.0, std::min(width / kLegendReferenceWidth, height / kLegendReferenceHeight));
        QPainter painter(&result.image);
        painter.setRenderHint(QPainter::Antialiasing);
        painter.setRenderHint(QPainter::TextAntialiasing);
        painter.scale(scale, scale);
        render::paintLegends(painter, QRectF(0.0, 0.0, width / scale, height / scale),
                             result.legends);
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
