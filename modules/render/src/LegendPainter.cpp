// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/render/LegendPainter.h"

#include <QColor>
#include <QCoreApplication>
#include <QFont>
#include <QFontMetricsF>
#include <QImage>
#include <QLocale>
#include <QPainter>
#include <QPen>
#include <QString>
#include <QStringList>
#include <algorithm>
#include <cmath>

#include "vv/colormaps/LabelPalette.h"
#include "vv/scene/QuantityTitle.h"

namespace vv::render {

namespace {

QString translated(const char* text) {
    return QCoreApplication::translate("vv::render::Legend", text);
}

struct Metrics {
    double font = 12.0;
    double pad = 6.0;
    double margin = 10.0;
    double bar = 11.0;
    double tick = 3.0;
    double width = 200.0;
    double height = 60.0;
    double available = 200.0;  ///< the widest a legend may be beside the others
    bool interactive = false;  ///< Legends::interactive
};

Metrics metricsFor(const QRectF& area, const Legends& shown) {
    const int legends = (shown.depth ? 1 : 0) + (shown.parameter ? 1 : 0);
    Metrics m;
    m.interactive = shown.interactive;
    m.font = std::clamp(area.height() / 45.0, 11.0, 16.0);
    m.pad = std::round(m.font * 0.5);
    m.margin = std::round(m.font * 0.8);
    m.bar = std::round(m.font * 0.9);
    m.tick = std::max(2.0, std::round(m.font * 0.25));
    const double available = (area.width() - static_cast<double>(legends + 1) * m.margin) /
                             static_cast<double>(std::max(legends, 1));
    m.width = std::min(std::clamp(area.width() * 0.3, 120.0, 340.0), available);
    m.available = std::max(m.width, available);
    m.height = m.pad + m.font * 1.3 + m.bar + m.tick + m.font * 1.25 + m.pad;
    return m;
}

QFont legendFont(const Metrics& m) {
    QFont font;
    font.setPixelSize(static_cast<int>(std::lround(m.font)));
    return font;
}

/// The least room between two tick labels: 1.25 times the font's pixel size,
/// about two digits (closer, "100 128" reads as crowded).
double labelGap(const Metrics& m) {
    return std::round(m.font * 1.25);
}

/// The room of a title line.
double titleLineHeight(const Metrics& m) {
    return m.font * 1.3;
}

/// `title` in the lines it takes inside a legend `m` wide: one, or more
/// where it is wider, broken between words (a single word wider than the
/// legend, which no title has, is elided): the title is never shortened.
QStringList titleLines(const Metrics& m, const QString& title, double boxWidth) {
    const QFontMetricsF fm(legendFont(m));
    const double width = boxWidth - 2.0 * m.pad;
    QStringList lines;
    QString line;
    for (const QString& word : title.split(QLatin1Char(' '), Qt::SkipEmptyParts)) {
        const QString longer = line.isEmpty() ? word : line + QLatin1Char(' ') + word;
        if (!line.isEmpty() && fm.horizontalAdvance(longer) > width) {
            lines << line;
            line = word;
        } else {
            line = longer;
        }
    }
    lines << line;
    for (QString& l : lines) {
        l = fm.elidedText(l, Qt::ElideRight, width);
    }
    return lines;
}

/// A colour bar legend's box height with its title.
double barLegendHeight(const Metrics& m, const QString& title, double boxWidth) {
    return m.height +
           static_cast<double>(titleLines(m, title, boxWidth).size() - 1) * titleLineHeight(m);
}

QImage strip(const std::vector<glm::u8vec4>& table) {
    QImage image(static_cast<int>(table.size()), 1, QImage::Format_RGB32);
    for (std::size_t i = 0; i < table.size(); ++i) {
        image.setPixel(static_cast<int>(i), 0, qRgb(table[i].r, table[i].g, table[i].b));
    }
    return image;
}

/// The colour bar: one opaque rectangle per entry of `table` (a 1-pixel-high
/// strip), each reaching to the bar's end so that no seam shows. Not an image:
/// a PDF paints images with the brush's alpha (the box's, dimming them), may
/// store them as JPEG, and viewers smooth them when enlarged; rectangles keep
/// the colour map's exact colours in every output.
void paintBar(QPainter& painter, const QRectF& rect, const QImage& table) {
    painter.save();
    painter.setPen(Qt::NoPen);
    painter.setRenderHint(QPainter::Antialiasing, false);
    const int entries = table.width();
    for (int i = 0; i < entries; ++i) {
        const double x = rect.left() + rect.width() * static_cast<double>(i) / entries;
        painter.fillRect(QRectF(x, rect.top(), rect.right() - x, rect.height()),
                         QColor::fromRgb(table.pixel(i, 0)));
    }
    painter.restore();
}

/// One legend box: title (titleLines()), colour bar, ticks and labels.
void paintBox(QPainter& painter, const QRectF& box, const Metrics& m, const QString& title,
              const QImage& bar, const std::vector<LegendTick>& ticks) {
    painter.setPen(Qt::NoPen);
    painter.setBrush(QColor(0, 0, 0, 170));
    painter.drawRoundedRect(box, m.pad * 0.8, m.pad * 0.8);

    const QFont font = legendFont(m);
    painter.setFont(font);
    const QFontMetricsF fm(font);
    const QRectF inner = box.adjusted(m.pad, m.pad, -m.pad, -m.pad);
    painter.setPen(QColor(245, 245, 245));
    double top = inner.top();
    for (const QString& line : titleLines(m, title, box.width())) {
        painter.drawText(QRectF(inner.left(), top, inner.width(), titleLineHeight(m)),
                         Qt::AlignLeft | Qt::AlignVCenter, line);
        top += titleLineHeight(m);
    }

    const QRectF barRect(inner.left(), top, inner.width(), m.bar);
    paintBar(painter, barRect, bar);
    painter.setBrush(Qt::NoBrush);
    painter.setPen(QPen(QColor(235, 235, 235), 1.0));
    painter.drawRect(barRect);

    // Every tick gets its mark; labels where they fit (labelledTicks()).
    std::vector<double> centres;
    std::vector<double> widths;
    for (const LegendTick& tick : ticks) {
        const double x = barRect.left() + tick.position * barRect.width();
        const double w = fm.horizontalAdvance(tick.label) + 2.0;
        centres.push_back(std::clamp(x, inner.left() + w / 2.0, inner.right() - w / 2.0));
        widths.push_back(w);
        painter.drawLine(QPointF(x, barRect.bottom()), QPointF(x, barRect.bottom() + m.tick));
    }
    for (const std::size_t i : labelledTicks(centres, widths, labelGap(m))) {
        const QRectF labelRect(centres[i] - widths[i] / 2.0, barRect.bottom() + m.tick, widths[i],
                               m.font * 1.25);
        painter.drawText(labelRect, Qt::AlignHCenter | Qt::AlignTop, ticks[i].label);
    }
}

/// Where a label legend's swatches go: `columns` side by side, rows below.
struct SwatchGrid {
    int columns = 1;
    int rows = 0;
    double rowHeight = 0.0;
};

constexpr std::size_t kMaxSwatches = 16;  ///< more labels: the rest summed up in one line

/// More labels than the palette has colours: some share a colour.
bool labelColoursRepeat(const ParameterLegend& p) {
    return p.labels.size() > colormaps::labelPalette().size();
}

/// The texts of a label legend's rows: one per label, at most kMaxSwatches
/// (the last then says how many more there are).
QStringList swatchTexts(const ParameterLegend& p, const Metrics& m) {
    QStringList texts;
    if (labelColoursRepeat(p)) {
        // A key where two rows share a colour would mislead: a summary
        // instead, broken into lines as wide as the legend, never elided;
        // over the live view, how to tell the labels apart.
        texts << titleLines(
            m,
            translated(QT_TRANSLATE_NOOP("vv::render::Legend", "%1 labels, colours repeat"))
                .arg(QLocale().toString(static_cast<qulonglong>(p.labels.size()))),
            m.width);
        if (m.interactive) {
            texts << titleLines(
                m, translated(QT_TRANSLATE_NOOP("vv::render::Legend", "hover names a label")),
                m.width);
        }
        return texts;
    }
    const std::size_t shown = p.labels.size() > kMaxSwatches ? kMaxSwatches - 1 : p.labels.size();
    for (std::size_t i = 0; i < shown; ++i) {
        texts.push_back(labelName(p.labels[i]));
    }
    if (shown < p.labels.size()) {
        texts.push_back(
            translated(QT_TRANSLATE_NOOP("vv::render::Legend", "… %1 more"))
                .arg(QLocale().toString(static_cast<qulonglong>(p.labels.size() - shown))));
    }
    return texts;
}

SwatchGrid swatchGrid(const ParameterLegend& p, const Metrics& m) {
    const QFontMetricsF fm(legendFont(m));
    const QStringList texts = swatchTexts(p, m);
    double widest = 0.0;
    for (const QString& text : texts) {
        widest = std::max(widest, fm.horizontalAdvance(text));
    }
    const double column = m.bar + m.pad * 0.6 + widest + m.pad * 1.5;
    const double inner = m.width - 2.0 * m.pad;
    SwatchGrid grid;
    grid.columns = labelColoursRepeat(p)
                       ? 1  // the two lines of text, one under the other
                       : std::clamp(static_cast<int>(inner / std::max(column, 1.0)), 1, 4);
    grid.rows = (static_cast<int>(texts.size()) + grid.columns - 1) / grid.columns;
    grid.rowHeight = std::max(m.bar + 3.0, m.font * 1.35);
    return grid;
}

/// The ticks of a parameter legend's bar.
std::vector<LegendTick> parameterTicks(const ParameterLegend& p) {
    const auto lo = static_cast<double>(p.min);
    const auto hi = static_cast<double>(p.max);
    return p.bins >= 2 ? binEdgeTicks(lo, hi, p.bins) : legendTicks(lo, hi);
}

/// A parameter legend's width: a binned bar as wide as labels at all its
/// edges need (as far as the room beside the other legends allows), else
/// the usual width.
double legendWidth(const ParameterLegend& p, const Metrics& m) {
    if (p.bins < 2 || !p.labels.empty()) {
        return m.width;
    }
    const QFontMetricsF fm(legendFont(m));
    double widest = 0.0;
    for (const LegendTick& tick : parameterTicks(p)) {
        widest = std::max(widest, fm.horizontalAdvance(tick.label) + 2.0);
    }
    // Neighbouring edges a label and a gap apart; an end label is held inside
    // the bar, half a label in from its edge: the end bins need half a label more.
    const double bar = static_cast<double>(p.bins) * (1.5 * widest + labelGap(m));
    return std::clamp(bar + 2.0 * m.pad, m.width, m.available);
}

double legendHeight(const ParameterLegend& p, const Metrics& m) {
    const QString title = QString::fromStdString(parameterLegendTitle(p));
    if (p.labels.empty()) {
        return barLegendHeight(m, title, legendWidth(p, m));
    }
    const SwatchGrid grid = swatchGrid(p, m);
    return m.pad + static_cast<double>(titleLines(m, title, m.width).size()) * titleLineHeight(m) +
           static_cast<double>(grid.rows) * grid.rowHeight + m.pad;
}

/// A label legend: the title, then per label a swatch of its colour and its name.
void paintLabelBox(QPainter& painter, const QRectF& box, const Metrics& m,
                   const ParameterLegend& p) {
    painter.setPen(Qt::NoPen);
    painter.setBrush(QColor(0, 0, 0, 170));
    painter.drawRoundedRect(box, m.pad * 0.8, m.pad * 0.8);
    const QFont font = legendFont(m);
    painter.setFont(font);
    const QFontMetricsF fm(font);
    const QRectF inner = box.adjusted(m.pad, m.pad, -m.pad, -m.pad);
    painter.setPen(QColor(245, 245, 245));
    double titleBottom = inner.top();
    for (const QString& line :
         titleLines(m, QString::fromStdString(parameterLegendTitle(p)), box.width())) {
        painter.drawText(QRectF(inner.left(), titleBottom, inner.width(), titleLineHeight(m)),
                         Qt::AlignLeft | Qt::AlignVCenter, line);
        titleBottom += titleLineHeight(m);
    }
    const SwatchGrid grid = swatchGrid(p, m);
    const QStringList texts = swatchTexts(p, m);
    const double columnWidth = inner.width() / static_cast<double>(grid.columns);
    for (int i = 0; i < texts.size(); ++i) {
        const int column = i / grid.rows;
        const int row = i % grid.rows;
        const double left = inner.left() + static_cast<double>(column) * columnWidth;
        const double top = titleBottom + static_cast<double>(row) * grid.rowHeight;
        const QRectF swatch(left, top + (grid.rowHeight - m.bar) / 2.0, m.bar, m.bar);
        const bool summary = labelColoursRepeat(p) ||
                             static_cast<std::size_t>(i) >= p.labels.size() ||
                             (p.labels.size() > kMaxSwatches && i + 1 == texts.size());
        if (!summary) {
            const glm::u8vec4 c =
                colormaps::toRgba8(colormaps::labelColor(static_cast<std::size_t>(i)));
            painter.setPen(QPen(QColor(235, 235, 235), 1.0));
            painter.setBrush(QColor(c.r, c.g, c.b));
            painter.drawRect(swatch);
        }
        painter.setPen(QColor(245, 245, 245));
        const double textLeft = labelColoursRepeat(p) ? left : swatch.right() + m.pad * 0.6;
        const QRectF textRect(textLeft, top, left + columnWidth - textLeft, grid.rowHeight);
        painter.drawText(textRect, Qt::AlignLeft | Qt::AlignVCenter,
                         fm.elidedText(texts[i], Qt::ElideRight, textRect.width()));
    }
}

}  // namespace

QString depthQuantityName(DepthReference reference) {
    return reference == DepthReference::Camera
               ? translated(QT_TRANSLATE_NOOP("vv::render::Legend", "Viewing distance"))
               : translated(
                     QT_TRANSLATE_NOOP("vv::render::Legend", "Depth behind the frontmost vessel"));
}

std::string depthLegendTitle(const DepthLegend& legend) {
    return scene::quantityTitle(depthQuantityName(legend.reference).toStdString(), legend.unit);
}

QString labelName(const scene::Label& label) {
    return label.name.empty() ? translated(QT_TRANSLATE_NOOP("vv::render::Legend", "Label %1"))
                                    .arg(QLocale().toString(static_cast<qlonglong>(label.value)))
                              : QString::fromStdString(label.name);
}

std::string parameterLegendTitle(const ParameterLegend& legend) {
    if (!legend.title.empty()) {
        return legend.title;
    }
    // A label legend lists names: the values have no unit.
    return scene::quantityTitle(legend.name, legend.labels.empty() ? legend.unit : std::string());
}

Legends legendsFor(const scene::Scene* scene, const MeshStyle& style,
                   const std::optional<std::pair<float, float>>& range,
                   const FrameSettings& settings, const VssFrameStatus& status,
                   const std::optional<std::pair<double, double>>& cueRange,
                   const ShownLabels* labels) {
    Legends legends;
    const auto cueScale = cueDepthScale(settings.cue.cue);
    if (settings.vss.enabled && status.shown) {
        legends.depth = DepthLegend{settings.vss.scale, status.dmin, status.dmax, "mm",
                                    depthReference(settings.vss)};
    } else if (!settings.vss.enabled && cueScale && cueRange) {
        legends.depth = DepthLegend{*cueScale, cueRange->first, cueRange->second, "mm",
                                    DepthReference::FrontmostVessel};
    }
    const bool cueReplacesColors = settings.cue.cue == VesselCue::Chromadepth ||
                                   settings.cue.cue == VesselCue::PseudoChromadepth;
    if (cueReplacesColors) {
        return legends;
    }
    // Without a scene, the scene's array alone (nothing tells what objects show).
    const std::vector<std::string> arrays =
        scene != nullptr ? shownArrays(*scene, style)
                         : (style.array.empty() ? std::vector<std::string>{}
                                                : std::vector<std::string>{style.array});
    for (const std::string& name : arrays) {
        const bool sceneArray = name == style.array;
        const auto shown = sceneArray ? range : objectArrayRange(*scene, style, name);
        if (!shown) {
            continue;
        }
        ParameterLegend parameter;
        parameter.name = name;
        parameter.min = shown->first;
        parameter.max = shown->second;
        parameter.map = style.colorMap;
        parameter.bins = style.bins;
        parameter.title = sceneArray ? style.legendTitle : std::string();
        if (labels != nullptr) {
            if (const std::vector<scene::Label>* listed = labelsOf(*labels, name)) {
                parameter.labels = *listed;
            }
        } else if (scene != nullptr) {
            parameter.labels =
                shownLabels(*scene, style, name).value_or(std::vector<scene::Label>{});
        }
        if (scene != nullptr) {
            for (const auto& mesh : scene->meshes) {
                if (const scene::DataArray* array = mesh.pointArray(name)) {
                    parameter.unit = array->unit;
                    break;
                }
            }
        }
        if (!legends.parameter) {
            legends.parameter = std::move(parameter);
        } else {
            legends.moreParameters.push_back(std::move(parameter));
        }
    }
    return legends;
}

LegendLayout legendLayout(const QRectF& area, const Legends& legends) {
    LegendLayout layout;
    if (legends.empty()) {
        return layout;
    }
    const Metrics m = metricsFor(area, legends);
    if (legends.depth) {
        const double height =
            barLegendHeight(m, QString::fromStdString(depthLegendTitle(*legends.depth)), m.width);
        layout.depth =
            QRectF(area.left() + m.margin, area.bottom() - m.margin - height, m.width, height);
    }
    if (legends.parameter) {
        double bottom = area.bottom() - m.margin;
        const auto place = [&](const ParameterLegend& p) {
            const double height = legendHeight(p, m);
            const double width = legendWidth(p, m);
            const QRectF box(area.right() - m.margin - width, bottom - height, width, height);
            bottom = box.top() - m.margin * 0.5;
            return box;
        };
        layout.parameter = place(*legends.parameter);
        for (const ParameterLegend& more : legends.moreParameters) {
            layout.moreParameters.push_back(place(more));
        }
    }
    return layout;
}

void paintLegends(QPainter& painter, const QRectF& area, const Legends& legends) {
    if (legends.empty()) {
        return;
    }
    const Metrics m = metricsFor(area, legends);
    const LegendLayout layout = legendLayout(area, legends);
    painter.save();
    painter.setRenderHint(QPainter::Antialiasing, true);
    painter.setRenderHint(QPainter::TextAntialiasing, true);
    if (legends.depth) {
        const DepthLegend& d = *legends.depth;
        paintBox(painter, layout.depth, m, QString::fromStdString(depthLegendTitle(d)),
                 strip(colormaps::lut(d.scale, 256)), depthLegendTicks(d));
    }
    const auto paintParameter = [&](const ParameterLegend& p, const QRectF& box) {
        if (!p.labels.empty()) {
            paintLabelBox(painter, box, m, p);
            return;
        }
        const int entries = p.bins >= 2 ? p.bins : 256;
        paintBox(painter, box, m, QString::fromStdString(parameterLegendTitle(p)),
                 strip(colormaps::lut(p.map, entries)), parameterTicks(p));
    };
    if (legends.parameter) {
        paintParameter(*legends.parameter, layout.parameter);
        for (std::size_t i = 0; i < legends.moreParameters.size(); ++i) {
            paintParameter(legends.moreParameters[i], layout.moreParameters[i]);
        }
    }
    painter.restore();
}

void paintLegends(QImage& image, const Legends& legends) {
    if (legends.empty() || image.isNull()) {
        return;
    }
    QPainter painter(&image);
    paintLegends(painter, QRectF(0.0, 0.0, image.width(), image.height()), legends);
}

}  // namespace vv::render
