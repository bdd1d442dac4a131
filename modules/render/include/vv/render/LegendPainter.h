// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QRectF>
#include <QString>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "vv/colormaps/ColorMap.h"
#include "vv/colormaps/DepthScale.h"
#include "vv/render/FrameSettings.h"
#include "vv/render/MeshStyle.h"
#include "vv/scene/ArrayLabels.h"
#include "vv/scene/Mesh.h"

class QImage;
class QPainter;

namespace vv::render {

/// The depth legend: the depth colour scale labelled in scene units along
/// the viewing direction (VSS.md, "Normalised depth"), measured from
/// `reference`: FrontmostVessel, the depth behind the frontmost visible
/// vessel point, 0 at dmin to dmax - dmin at dmax; Camera (a fixed range the
/// user chose), the viewing distance, dmin to dmax.
struct DepthLegend {
    colormaps::DepthScale scale = colormaps::DepthScale::Chromadepth;
    double dmin = 0.0;  ///< linear view depth of t = 0, scene units
    double dmax = 0.0;  ///< ... of t = 1
    std::string unit = "mm";
    DepthReference reference = DepthReference::FrontmostVessel;
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
    /// Not empty: the array holds labels (shownLabels()); the legend lists
    /// one swatch per label, label i in colormaps::labelColor(i), instead
    /// of a colour bar (min, max, map and bins are then unused).
    std::vector<scene::Label> labels;
};

/// The legends a frame shows; each only when its scale is used.
struct Legends {
    std::optional<DepthLegend> depth;
    /// The first array shown (the scene's array when an object shows it).
    std::optional<ParameterLegend> parameter;
    /// One more per further array that objects show (ObjectStyle::array),
    /// stacked above `parameter`; empty when `parameter` is absent.
    std::vector<ParameterLegend> moreParameters;
    /// Painted over the live view, where hovering a vessel names its label:
    /// a label legend whose colours repeat then says so. Off in exported
    /// images and reports, which no one can hover.
    bool interactive = false;
    [[nodiscard]] bool empty() const noexcept {
        return !depth && !parameter && moreParameters.empty();
    }
};

/// One labelled tick of a legend bar.
struct LegendTick {
    double value = 0.0;     ///< in the legend's units
    double position = 0.0;  ///< 0 = the bar's start (first colour), 1 = its end
    QString label;          ///< in the UI locale (legendNumber())
};

/// `value` with `decimals` digits after the separator in the UI locale
/// (QLocale(): "0,45" in German), "0" rather than "-0"; magnitudes of 1e9
/// and more or below 1e-6 in 3 significant digits with an exponent.
[[nodiscard]] QString legendNumber(double value, int decimals);

/// Ticks over [lo, hi]: both ends always and "nice" values (1, 2, 2.5,
/// 5 x 10^k steps) in between, at most about `maxTicks` in all, none closer
/// than 0.35 steps to an end. All labels of a legend have one precision: the
/// step's decimals, or more when the ends need them to show 3 significant
/// digits of the larger magnitude (0.45 .. 1.31: "0.45", "0.50", ...,
/// "1.31"). A range with hi <= lo (or not finite) gives one tick at lo,
/// position 0.
[[nodiscard]] std::vector<LegendTick> legendTicks(double lo, double hi, int maxTicks = 5);

/// The ticks of a binned legend: every bin edge, bins + 1 ticks from lo to
/// hi, all with one precision: the ends' (as legendTicks()) or more until
/// neighbouring edges read differently. bins < 2 or an empty range:
/// legendTicks(lo, hi).
[[nodiscard]] std::vector<LegendTick> binEdgeTicks(double lo, double hi, int bins);

/// Which tick labels to draw, given each label's centre and width along the
/// bar (pixels) and the least `gap` between two labels: as many as fit with
/// no two closer than `gap`, always the first and the last; among the ways
/// to label that many, the one whose closest neighbours are farthest apart.
/// Indices ascending; {0, n - 1} when even the ends alone collide.
[[nodiscard]] std::vector<std::size_t> labelledTicks(const std::vector<double>& centres,
                                                     const std::vector<double>& widths, double gap);

/// The depth legend's ticks, position 0 at dmin: values 0 .. dmax - dmin
/// (the depth behind the frontmost visible vessel point, scene units) for
/// DepthReference::FrontmostVessel, dmin .. dmax (the viewing distance) for
/// Camera.
[[nodiscard]] std::vector<LegendTick> depthLegendTicks(const DepthLegend& legend, int maxTicks = 5);

/// The one name of the depth quantity that the depth legend, the probe and
/// the reports use, in the UI language (translation context
/// "vv::render::Legend", as every legend text): "Depth behind the frontmost
/// vessel" (the frontmost vessel point in view; the distance is along the
/// viewing direction) for FrontmostVessel, "Viewing distance" (from the
/// camera, as the VSS panel's fixed near / far) for Camera.
[[nodiscard]] QString depthQuantityName(DepthReference reference);
/// The depth legend's title: its quantity and unit, "Depth behind the
/// frontmost vessel (mm)" or "Viewing distance (mm)" (scene::quantityTitle());
/// a legend too narrow for it in one line shows it in more (never shortened).
[[nodiscard]] std::string depthLegendTitle(const DepthLegend& legend);
/// A label's legend text: its name from the file, else "Label <value>"
/// (translated, the value in the UI locale).
[[nodiscard]] QString labelName(const scene::Label& label);
/// "wss (Pa)" (scene::quantityTitle()), or the name alone without a unit (or
/// for labels); the legend's own title when it has one.
[[nodiscard]] std::string parameterLegendTitle(const ParameterLegend& legend);

/// The legends for a frame: the depth legend when the VSS is on and shown
/// (its scale, status.dmin / dmax, measured from depthReference(settings.vss)),
/// or, with the VSS off, when the vessel cue colours by a depth scale (its
/// scale over `cueRange`, from the frontmost vessel); the parameter legend
/// when an array is shown (`range` set) and no cue replaces its colours
/// (vessel chromadepth / pseudo-chromadepth). The unit is the first mesh's
/// that has the array. An array shown as labels (shownLabels()) gets their
/// list (ParameterLegend::labels). With a scene, one parameter legend per array that
/// visible objects show (shownArrays(): the scene's array over `range`,
/// others over objectArrayRange()), none when no visible object shows one.
/// `labels`: the scene's ShownLabels when the caller keeps them (a view, per
/// frame: a ShownLabelsCache); null computes them here.
[[nodiscard]] Legends legendsFor(const scene::Scene* scene, const MeshStyle& style,
                                 const std::optional<std::pair<float, float>>& range,
                                 const FrameSettings& settings, const VssFrameStatus& status,
                                 const std::optional<std::pair<double, double>>& cueRange,
                                 const ShownLabels* labels = nullptr);

/// Where the legends go inside `area` (logical pixels): the depth legend
/// bottom-left, the parameter legend bottom-right, each in a dark box that
/// keeps the text readable; empty rectangles for absent legends. A label
/// legend is as tall as its swatches need (in columns when they fit); a
/// binned one as wide as labels at all its bin edges need, as far as the
/// room beside the other legend allows.
struct LegendLayout {
    QRectF depth;      ///< null when there is no depth legend
    QRectF parameter;  ///< null when there is no parameter legend
    /// Legends::moreParameters, each above the one before.
    std::vector<QRectF> moreParameters;
};

/// The boxes paintLegends() covers in `area`.
[[nodiscard]] LegendLayout legendLayout(const QRectF& area, const Legends& legends);

/// Paints the legends with `painter` into `area`; the bars come from the same
/// tables as the GL passes (colormaps::lut). A title too long for one line
/// takes more (the box grows). A binned bar has a tick at every bin edge
/// (binEdgeTicks(), labels chosen by labelledTicks() with a gap of 1.25 times
/// the font's pixel size, about two digits, between two labels); a
/// label legend one swatch per label with its name (from the file) or
/// "Label <value>". Text is in the UI language and locale. Does nothing for
/// empty legends.
void paintLegends(QPainter& painter, const QRectF& area, const Legends& legends);

/// Paints the legends onto `image` (in place, its full rectangle).
void paintLegends(QImage& image, const Legends& legends);

}  // namespace vv::render
