// SPDX-License-Identifier: GPL-3.0-or-later
// Helpers of the report tests: a QGuiApplication, a per-process folder,
// small scenes, running tools.
#pragma once

#include <QImage>
#include <filesystem>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "GlTestSupport.h"
#include "vv/render/LegendPainter.h"
#include "vv/render/OffscreenRenderer.h"
#include "vv/render/ViewPresets.h"
#include "vv/report/PdfReport.h"
#include "vv/scene/Mesh.h"
#include "vv/vss/DepthNormalization.h"

namespace vv::report::test {

using vv::test::ensureGuiApplication;
/// An offscreen renderer, or null after a test failure saying that there is
/// no OpenGL (run under xvfb-run -a, QT_QPA_PLATFORM=xcb).
inline std::unique_ptr<render::OffscreenRenderer> makeRenderer() {
    return vv::test::makeOffscreenRenderer();
}

/// A fresh folder for this process under VV_TEST_TMP/report/<name>.
std::filesystem::path testDir(const std::string& name);

/// An open tube of radius 1 along x (0 .. 20), axis on the x axis, with point
/// array "wss" (unit Pa) rising linearly from 0 at x = 0 to 10 at x = 20.
scene::Mesh makeTube(const std::string& name);

/// A view-like test image (gradient), width x height, RGB32.
QImage testImage(int width, int height);

/// Runs `command` through the shell; its exit status, its stdout + stderr in `output`.
int runTool(const std::string& command, std::string& output);

/// True when `tool` is on PATH.
bool haveTool(const std::string& tool);

/// Names of the files in `dir`.
std::string listing(const std::filesystem::path& dir);

/// One word of a PDF (pdftotext -bbox): its page (from 1), its box in
/// points from the page's top left, and its text.
struct PdfWord {
    int page = 0;
    double left = 0.0;
    double top = 0.0;
    double right = 0.0;
    double bottom = 0.0;
    std::string text;
};

/// `text` with the font's ligatures (U+FB00 "ff", U+FB01 "fi", ... as
/// pdftotext writes them) as their letters (Unicode NFKC).
std::string withoutLigatures(const std::string& text);

/// The words of `pdf` in the order pdftotext reads them (a test failure when
/// it cannot).
std::vector<PdfWord> pdfWords(const std::filesystem::path& pdf);

/// Every name of render::namedViewNames(), in its order.
std::vector<std::string> namedViews();

/// The depth range (dmin, dmax) of `view` rendered on its own as a report's
/// second view of `base` on `paper`: at the report's size and `base`'s
/// aspect, the preset's camera, the depth range `range`. What that view's
/// legend must describe.
std::pair<double, double> ownDepthRange(render::OffscreenRenderer& renderer,
                                        const scene::Scene& scene,
                                        const render::OffscreenOptions& base,
                                        const render::NamedView& view, const vss::DepthRange& range,
                                        PaperSize paper);

/// What is wrong with the depth legend printed over the view under the first
/// word `heading` (down to the first word `caption` below it, on that
/// page) of `words`: not the title depthLegendTitle(legend), no number
/// there, a number that is not a tick label of depthLegendTicks(legend), or
/// no label of its far end. Empty when it is `legend` (its range and what
/// it measures from). The view must show no parameter legend.
std::string depthLegendProblem(const std::vector<PdfWord>& words, const std::string& heading,
                               const std::string& caption, const render::DepthLegend& legend);

/// Every page of `pdf` rasterised at `dpi` (pdftoppm, poppler-utils) as
/// `dir`/page-N.png, in order (a test failure when it cannot).
std::vector<QImage> pdfPages(const std::filesystem::path& pdf, const std::filesystem::path& dir,
                             int dpi);

/// What lies where nothing of a report page may be, on `page` rasterised at
/// `dpi`: ink (any pixel not white) outside the page's margins (18 mm at the
/// sides, 15 mm at the top and bottom) or in the gap between the content's
/// end and the footer's rule (9 to 6 mm above the bottom margin), which
/// anything running into the footer crosses. One pixel of the boundaries'
/// anti-aliasing is allowed. Empty when the page is clean.
std::vector<std::string> marginProblems(const QImage& page, int dpi);

}  // namespace vv::report::test
