// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QImage>
#include <filesystem>
#include <optional>
#include <utility>

#include "vv/core/Progress.h"
#include "vv/render/CenterlineOverlay.h"
#include "vv/render/FrameSettings.h"
#include "vv/render/LegendPainter.h"
#include "vv/render/OffscreenRenderer.h"
#include "vv/scene/Mesh.h"

namespace vv::report {

/// The largest image export: 8K UHD (7680 x 4320 pixels, in either orientation).
inline constexpr int kMaxExportSide = 7680;
inline constexpr long long kMaxExportPixels = 7680LL * 4320LL;

/// How to export the view as an image.
struct ViewExportOptions {
    /// Size, camera and display settings. `render.display.legends` is
    /// ignored: the legends are painted by renderView() (`legends` below).
    render::OffscreenOptions render;
    /// Paint the legends of the scales in use (render::paintLegends), scaled
    /// with the image so that they cover the same share of it at any size
    /// (as in a 1600 x 1200 view).
    bool legends = true;
    /// Background pixels transparent (alpha 0) instead of `render.display.background`;
    /// partly covered pixels (anti-aliased edges, a VSS with opacity < 1, fog)
    /// get the matching partial alpha.
    bool transparentBackground = false;
    /// The largest side, in pixels, of one rendered piece. Larger images are
    /// rendered in tiles (see renderView()). 0 = automatic: in one piece when
    /// the frame fits maxRenderSide() and kAutoTileBudgetBytes of GPU memory,
    /// else in tiles of kAutoTileSide. Else at least kMinTileSide.
    int maxTileSide = 0;
    /// Centrelines drawn over the view (render::paintCenterlines, widths
    /// scaled with the image as the legends are) before the legends, whose
    /// list gains the overlay's (render::addCenterlineLegend); nullopt =
    /// none. Their visibility is judged against the G-buffer depth the VSS
    /// solve read, or the CPU rasteriser's (render::rasterizeDepth) when
    /// there was none: meshes only, so not with a volume ray cast.
    std::optional<render::CenterlineOverlay> centerlines;
};

/// Automatic tiling: the GPU memory one piece may take (the frame's textures,
/// about kFrameBytesPerPixel per pixel), and the tile side beyond it.
inline constexpr long long kAutoTileBudgetBytes = 1LL << 30;
inline constexpr long long kFrameBytesPerPixel = 56;
inline constexpr int kAutoTileSide = 4096;
/// The smallest maxTileSide accepted.
inline constexpr int kMinTileSide = 64;

/// A rendered view and what it shows.
struct RenderedView {
    /// Format_RGB32, or Format_ARGB32 with a transparent background.
    QImage image;
    /// The legends of the frame (painted onto `image` when asked).
    render::Legends legends;
    /// The parameter range the colour map spanned; nullopt without an array.
    std::optional<std::pair<float, float>> range;
    /// The VSS of the frame (shown, dmin / dmax, solve time).
    render::VssFrameStatus vss;
    /// How many pieces the image was rendered in (1 = one piece).
    int tiles = 1;
};

/// The largest width and height this machine's OpenGL can render offscreen in
/// one piece: min(GL_MAX_TEXTURE_SIZE, GL_MAX_RENDERBUFFER_SIZE,
/// GL_MAX_VIEWPORT_DIMS), from a probe context made on the calling thread (a
/// QOffscreenSurface: call it on the GUI thread; renderView() asks its
/// renderer instead, OffscreenRenderer::maxRenderSide()). Needs a QGuiApplication.
/// Throws RenderError when no OpenGL context can be made.
[[nodiscard]] int maxRenderSide();

/// Renders the view with `renderer`. Sizes up to 8K (kMaxExportSide per side,
/// kMaxExportPixels in all) are accepted.
///
/// In one piece when it fits (ViewExportOptions::maxTileSide,
/// OffscreenRenderer::maxRenderSide());
/// else, or when the automatic one-piece render fails with a RenderError (out
/// of GPU memory, incomplete framebuffer), in tiles that give the same image:
///  1. every tile's G-buffer depth (an off-axis sub-frustum of the same
///     camera, render::tileProjection) is read back into the full image's
///     depth;
///  2. the VSS is solved once on that full depth (its depth range, the
///     vessel cue's and the legends' come from the full frame);
///  3. every tile is drawn with its cut of that solve (render::ExternalVss)
///     and a guard band as wide as the screen-space passes reach (SSAO, its
///     blur, VSS normals, FXAA; at most a quarter of the tile side), which is
///     cropped away.
/// The centrelines, then the legends are painted on the whole image afterwards.
/// `progress` gets the fraction done per tile and stops between tiles and
/// inside the solve (CancelledError).
/// Throws InvalidArgumentError for a size out of range or maxTileSide in
/// 1..kMinTileSide-1 or negative, or centrelines with a volume,
/// RenderError when GL fails, CancelledError.
[[nodiscard]] RenderedView renderView(render::OffscreenRenderer& renderer,
                                      const scene::Scene& scene, const ViewExportOptions& options,
                                      const Progress& progress = {});

/// Writes `image` as PNG to `path` atomically (temporary file in the target
/// folder, then rename): on failure no partial file remains and an existing
/// file is untouched. Throws IoError naming `path` and the reason.
void writePng(const std::filesystem::path& path, const QImage& image);

}  // namespace vv::report
