// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QRectF>
#include <QString>
#include <QStringList>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "vv/colormaps/ColorMap.h"
#include "vv/colormaps/DepthScale.h"
#include "vv/render/FrameRenderer.h"
#include "vv/render/MeshStyle.h"
#include "vv/scene/Mesh.h"

class QFontMetricsF;
class QImage;
class QPainter;

namespace vv::render {

/// The depth legend: the depth colour scale labelled in scene units as the
/// distance behind the nearest visible vessel point, 0 at dmin to
/// dmax - dmin at dmax (VSS.md, "Normalised depth").
struct DepthLegend {
    colormaps::DepthScale scale = colormaps::DepthScale::Chromadepth;
    double dmin = 0.0;  ///< linear view depth of t = 0, scene units
    double dmax = 0.0;  ///< ... of t = 1
    std::string unit = "mm";
};

/// The parameter legend: the array's colour map over its shown range.
struct ParameterLegend {
    std::string name;  ///< the point array
    std::string unit;  ///< e.g. "Pa"; empty when unknown
    float min = 0.0F;  ///< value at the map's first colour
    float max = 1.0F;  ///< ... at its last
    colormaps::ColorMap map = colormaps::ColorMap::Viridis;
    int bins = 0;       ///< colormaps bins (0 = continuous)
    std::string title;  ///< replaces "name (unit)" when not empty (MeshStyle::legendTitle)
};

/// The legends a frame shows; each only when its scale is used.
struct Legends {
    std::optional<DepthLegend> depth;
    /// The first array shown (the scene's array when an object shows it).
    std::optional<ParameterLegend> parameter;
    /// One more per further array that objects show (ObjectStyle::array),
    /// stacked above `parameter`; empty when `parameter` is absent.
    std::vector<ParameterLegend> moreParameters;
    [[nodiscard]] bool empty() const noexcept {
        return !depth && !parameter && moreParameters.empty();
    }
};

/// One labelled tick of a legend bar.
struct LegendTick {
    double value = 0.0;     ///< in the legend's units
    double position = 0.0;  ///< 0 = the bar's start (first colour), 1 = its end
    std::string label;
};

/// Ticks over [lo, hi]: both ends always (labelled like the ticks between
/// when on their step grid, else with up to 3 significant digits), and
/// "nice" values (1, 2, 2.5, 5 x 10^k steps) in between, at
/// most about `maxTicks` in all, none closer than 0.35 steps to an end. A
/// range with hi <= lo (or not finite) gives one tick at lo, position 0.
[[nodiscard]] std::vector<LegendTick> legendTicks(double lo, double hi, int maxTicks = 5);

/// The depth legend's ticks: values 0 .. dmax - dmin (distance behind the
/// nearest visible vessel point, scene units), position 0 at dmin.
[[nodiscard]] std::vector<LegendTick> depthLegendTicks(double dmin, double dmax, int maxTicks = 5);

/// "Depth behind nearest vessel (mm)".
[[nodiscard]] std::string depthLegendTitle(const DepthLegend& legend);
/// depthLegendTitle() and shorter forms for narrow legends ("Depth (mm)" last).
[[nodiscard]] std::vector<std::string> depthLegendTitles(const DepthLegend& legend);
/// The first of `titles` no wider than `width` in `metrics`, else the last one
/// (the caller elides it).
[[nodiscard]] QString fittingTitle(const QFontMetricsF& metrics, const QStringList& titles,
                                   double width);
/// "wss (Pa)", or the name alone without a unit; the legend's own title when it has one.
[[nodiscard]] std::string parameterLegendTitle(const ParameterLegend& legend);

/// The legends for a frame: the depth legend when the VSS is on and shown
/// (its scale, status.dmin / dmax), or, with the VSS off, when the vessel cue
/// colours by a depth scale (its scale over `cueRange`); the parameter legend
/// when an array is shown (`range` set) and no cue replaces its colours
/// (vessel chromadepth / pseudo-chromadepth). The unit is the first mesh's
/// that has the array. With a scene, one parameter legend per array that
/// visible objects show (shownArrays(): the scene's array over `range`,
/// others over objectArrayRange()), none when no visible object shows one.
[[nodiscard]] Legends legendsFor(const scene::Scene* scene, const MeshStyle& style,
                                 const std::optional<std::pair<float, float>>& range,
                                 const FrameSettings& settings, const VssFrameStatus& status,
                                 const std::optional<std::pair<double, double>>& cueRange);

/// Where the legends go inside `area` (logical pixels): the depth legend
/// bottom-left, the parameter legend bottom-right, each in a dark box that
/// keeps the text readable; empty rectangles for absent legends.
struct LegendLayout {
    QRectF depth;      ///< null when there is no depth legend
    QRectF parameter;  ///< null when there is no parameter legend
    /// Legends::moreParameters, each above the one before.
    std::vector<QRectF> moreParameters;
};

/// The boxes paintLegends() covers in `area`.
[[nodiscard]] LegendLayout legendLayout(const QRectF& area, const Legends& legends);

/// Paints the legends with `painter` into `area`; the bars come from the same
/// tables as the GL passes (colormaps::lut). Does nothing for empty legends.
void paintLegends(QPainter& painter, const QRectF& area, const Legends& legends);

/// Paints the legends onto `image` (in place, its full rectangle).
void paintLegends(QImage& image, const Legends& legends);

}  // namespace vv::render
