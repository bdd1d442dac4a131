// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QImage>
#include <filesystem>
#include <optional>
#include <utility>

#include "vv/io/Mesh.h"
#include "vv/render/FrameRenderer.h"
#include "vv/render/LegendPainter.h"
#include "vv/render/OffscreenRenderer.h"

namespace vv::report {

/// The largest image export: 8K UHD (7680 x 4320 pixels, in either orientation).
inline constexpr int kMaxExportSide = 7680;
inline constexpr long long kMaxExportPixels = 7680LL * 4320LL;

/// How to export the view as an image.
struct ViewExportOptions {
    /// Size, camera, style, VSS, cue, AO, FXAA, background. `render.legends`
    /// is ignored: the legends are painted by renderView() (`legends` below).
    render::OffscreenOptions render;
    /// Paint the legends of the scales in use (render::paintLegends), scaled
    /// with the image so that they cover the same share of it at any size
    /// (as in a 1600 x 1200 view).
    bool legends = true;
    /// Background pixels transparent (alpha 0) instead of `render.background`;
    /// partly covered pixels (anti-aliased edges, a VSS with opacity < 1, fog)
    /// get the matching partial alpha.
    bool transparentBackground = false;
};

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
};

/// The largest width and height this machine's OpenGL can render offscreen in
/// one piece: min(GL_MAX_TEXTURE_SIZE, GL_MAX_RENDERBUFFER_SIZE,
/// GL_MAX_VIEWPORT_DIMS), from a probe context. Needs a QGuiApplication.
/// Throws RenderError when no OpenGL context can be made.
[[nodiscard]] int maxRenderSide();

/// Renders the view with `renderer` (one frame; the VSS is solved once on the
/// full frame's depth). Sizes up to 8K (kMaxExportSide per side,
/// kMaxExportPixels in all) are accepted.
/// Throws InvalidArgumentError for a size out of that range, RenderError when
/// the size exceeds what this GPU renders in one piece (maxRenderSide(); the
/// message gives the limit) or GL fails.
[[nodiscard]] RenderedView renderView(render::OffscreenRenderer& renderer, const io::Scene& scene,
                                      const ViewExportOptions& options);

/// Writes `image` as PNG to `path` atomically (temporary file in the target
/// folder, then rename): on failure no partial file remains and an existing
/// file is untouched. Throws IoError naming `path` and the reason.
void writePng(const std::filesystem::path& path, const QImage& image);

}  // namespace vv::report
