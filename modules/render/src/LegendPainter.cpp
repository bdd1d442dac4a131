// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/render/LegendPainter.h"

#include <QColor>
#include <QFont>
#include <QFontMetricsF>
#include <QImage>
#include <QPainter>
#include <QPen>
#include <QString>
#include <QStringList>
#include <algorithm>
#include <cmath>
#include <cstdio>

namespace vv::render {

namespace {

/// A value with `decimals` digits after the point ("-0" shown as "0").
std::string fixed(double value, int decimals) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.*f", std::clamp(decimals, 0, 9), value);
    std::string text(buffer);
    if (text.find_first_not_of("-0.") == std::string::npos) {
        return "0";
    }
    return text;
}

/// Decimals a step needs (0.25 -> 2, 5 -> 0).
int decimalsFor(double step) {
    if (!(step > 0.0)) {
        return 0;
    }
    int decimals = 0;
    double scaled = step;
    while (decimals < 9 && std::abs(scaled - std::round(scaled)) > 1e-6 * std::max(1.0, scaled)) {
        scaled *= 10.0;
        ++decimals;
    }
    return decimals;
}

/// An end value: 3 significant digits, plain notation for ordinary magnitudes.
std::string endLabel(double value) {
    const double magnitude = std::abs(value);
    if (magnitude == 0.0) {
        return "0";
    }
    if (magnitude >= 1e6 || magnitude < 1e-3) {
        char buffer[64];
        std::snprintf(buffer, sizeof buffer, "%.3g", value);
        return buffer;
    }
    const int digits = static_cast<int>(std::floor(std::log10(magnitude))) + 1;
    std::string text = fixed(value, std::max(0, 3 - digits));
    if (text.find('.') != std::string::npos) {
        while (text.back() == '0') {
            text.pop_back();
        }
        if (text.back() == '.') {
            text.pop_back();
        }
    }
    return text;
}

double niceStep(double span, int maxTicks) {
    const double raw = span / static_cast<double>(std::max(maxTicks - 1, 1));
    const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
    const double normalized = raw / magnitude;
    double nice = 10.0;
    if (normalized <= 1.0) {
        nice = 1.0;
    } else if (normalized <= 2.0) {
        nice = 2.0;
    } else if (normalized <= 2.5) {
        nice = 2.5;
    } else if (normalized <= 5.0) {
        nice = 5.0;
    }
    return nice * magnitude;
}

struct Metrics {
    double font = 12.0;
    double pad = 6.0;
    double margin = 10.0;
    double bar = 11.0;
    double tick = 3.0;
    double width = 200.0;
    double height = 60.0;
};

Metrics metricsFor(const QRectF& area, int legends) {
    Metrics m;
    m.font = std::clamp(area.height() / 45.0, 11.0, 16.0);
    m.pad = std::round(m.font * 0.5);
    m.margin = std::round(m.font * 0.8);
    m.bar = std::round(m.font * 0.9);
    m.tick = std::max(2.0, std::round(m.font * 0.25));
    const double available = (area.width() - static_cast<double>(legends + 1) * m.margin) /
                             static_cast<double>(std::max(legends, 1));
    m.width = std::min(std::clamp(area.width() * 0.3, 120.0, 340.0), available);
    m.height = m.pad + m.font * 1.3 + m.bar + m.tick + m.font * 1.25 + m.pad;
    return m;
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

/// One legend box: title, colour bar, ticks and labels.
/// `titles`: the title, then shorter forms of it; the first that fits is
/// drawn, else the last one elided.
void paintBox(QPainter& painter, const QRectF& box, const Metrics& m, const QStringList& titles,
              const QImage& bar, const std::vector<LegendTick>& ticks) {
    painter.setPen(Qt::NoPen);
    painter.setBrush(QColor(0, 0, 0, 170));
    painter.drawRoundedRect(box, m.pad * 0.8, m.pad * 0.8);

    QFont font = painter.font();
    font.setPixelSize(static_cast<int>(std::lround(m.font)));
    painter.setFont(font);
    const QFontMetricsF fm(font);
    const QRectF inner = box.adjusted(m.pad, m.pad, -m.pad, -m.pad);
    painter.setPen(QColor(245, 245, 245));
    const QRectF titleRect(inner.left(), inner.top(), inner.width(), m.font * 1.3);
    const QString title = fittingTitle(fm, titles, inner.width());
    painter.drawText(titleRect, Qt::AlignLeft | Qt::AlignVCenter,
                     fm.elidedText(title, Qt::ElideRight, inner.width()));

    const QRectF barRect(inner.left(), titleRect.bottom(), inner.width(), m.bar);
    paintBar(painter, barRect, bar);
    painter.setBrush(Qt::NoBrush);
    painter.setPen(QPen(QColor(235, 235, 235), 1.0));
    painter.drawRect(barRect);

    std::vector<QRectF> drawn;
    const auto drawTick = [&](const LegendTick& tick, bool end) {
        const double x = barRect.left() + tick.position * barRect.width();
        const QString label = QString::fromStdString(tick.label);
        const double w = fm.horizontalAdvance(label) + 2.0;
        double left = x - w / 2.0;
        left = std::clamp(left, inner.left(), inner.right() - w);
        const QRectF labelRect(left, barRect.bottom() + m.tick, w, m.font * 1.25);
        if (!end) {
            for (const QRectF& other : drawn) {
                if (other.adjusted(-3.0, 0.0, 3.0, 0.0).intersects(labelRect)) {
                    return;  // would collide: the ends win
                }
            }
        }
        painter.drawLine(QPointF(x, barRect.bottom()), QPointF(x, barRect.bottom() + m.tick));
        painter.drawText(labelRect, Qt::AlignHCenter | Qt::AlignTop, label);
        drawn.push_back(labelRect);
    };
    if (!ticks.empty()) {
        drawTick(ticks.front(), true);
        if (ticks.size() > 1) {
            drawTick(ticks.back(), true);
        }
        for (std::size_t i = 1; i + 1 < ticks.size(); ++i) {
            drawTick(ticks[i], false);
        }
    }
}

}  // namespace

std::vector<LegendTick> legendTicks(double lo, double hi, int maxTicks) {
    std::vector<LegendTick> ticks;
    if (!std::isfinite(lo) || !std::isfinite(hi) || !(hi > lo)) {
        ticks.push_back(
            {std::isfinite(lo) ? lo : 0.0, 0.0, endLabel(std::isfinite(lo) ? lo : 0.0)});
        return ticks;
    }
    const double span = hi - lo;
    const double step = niceStep(span, std::max(maxTicks, 2));
    const int decimals = decimalsFor(step);
    // An end on the step grid is labelled like the ticks between ("1.0" next to "1.5").
    const auto endText = [&](double value) {
        const double steps = value / step;
        return std::abs(steps - std::round(steps)) < 1e-6 ? fixed(value, decimals)
                                                          : endLabel(value);
    };
    ticks.push_back({lo, 0.0, endText(lo)});
    const double first = std::ceil(lo / step) * step;
    for (int k = 0;; ++k) {
        const double value = first + static_cast<double>(k) * step;
        if (value > hi - 0.35 * step) {
            break;
        }
        if (value < lo + 0.35 * step) {
            continue;
        }
        ticks.push_back({value, (value - lo) / span, fixed(value, decimals)});
    }
    ticks.push_back({hi, 1.0, endText(hi)});
    return ticks;
}

std::vector<LegendTick> depthLegendTicks(double dmin, double dmax, int maxTicks) {
    const double span = (std::isfinite(dmin) && std::isfinite(dmax)) ? dmax - dmin : 0.0;
    return legendTicks(0.0, span, maxTicks);
}

std::string depthLegendTitle(const DepthLegend& legend) {
    return "Depth behind nearest vessel" + (legend.unit.empty() ? "" : " (" + legend.unit + ")");
}

std::vector<std::string> depthLegendTitles(const DepthLegend& legend) {
    const std::string unit = legend.unit.empty() ? "" : " (" + legend.unit + ")";
    return {depthLegendTitle(legend), "Depth behind vessel" + unit, "Depth" + unit};
}

QString fittingTitle(const QFontMetricsF& metrics, const QStringList& titles, double width) {
    for (const QString& candidate : titles) {
        if (metrics.horizontalAdvance(candidate) <= width) {
            return candidate;
        }
    }
    return titles.isEmpty() ? QString() : titles.back();
}

std::string parameterLegendTitle(const ParameterLegend& legend) {
    if (!legend.title.empty()) {
        return legend.title;
    }
    return legend.name + (legend.unit.empty() ? "" : " (" + legend.unit + ")");
}

Legends legendsFor(const scene::Scene* scene, const MeshStyle& style,
                   const std::optional<std::pair<float, float>>& range,
                   const FrameSettings& settings, const VssFrameStatus& status,
                   const std::optional<std::pair<double, double>>& cueRange) {
    Legends legends;
    const auto cueScale = cueDepthScale(settings.cue.cue);
    if (settings.vss.enabled && status.shown) {
        legends.depth = DepthLegend{settings.vss.scale, status.dmin, status.dmax, "mm"};
    } else if (!settings.vss.enabled && cueScale && cueRange) {
        legends.depth = DepthLegend{*cueScale, cueRange->first, cueRange->second, "mm"};
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
    const int count = (legends.depth ? 1 : 0) + (legends.parameter ? 1 : 0);
    const Metrics m = metricsFor(area, count);
    const double top = area.bottom() - m.margin - m.height;
    if (legends.depth) {
        layout.depth = QRectF(area.left() + m.margin, top, m.width, m.height);
    }
    if (legends.parameter) {
        layout.parameter = QRectF(area.right() - m.margin - m.width, top, m.width, m.height);
        for (std::size_t i = 0; i < legends.moreParameters.size(); ++i) {
            layout.moreParameters.push_back(layout.parameter.translated(
                0.0, -static_cast<double>(i + 1) * (m.height + m.margin * 0.5)));
        }
    }
    return layout;
}

void paintLegends(QPainter& painter, const QRectF& area, const Legends& legends) {
    if (legends.empty()) {
        return;
    }
    const int count = (legends.depth ? 1 : 0) + (legends.parameter ? 1 : 0);
    const Metrics m = metricsFor(area, count);
    const LegendLayout layout = legendLayout(area, legends);
    painter.save();
    painter.setRenderHint(QPainter::Antialiasing, true);
    painter.setRenderHint(QPainter::TextAntialiasing, true);
    if (legends.depth) {
        const DepthLegend& d = *legends.depth;
        QStringList titles;
        for (const std::string& t : depthLegendTitles(d)) {
            titles.push_back(QString::fromStdString(t));
        }
        paintBox(painter, layout.depth, m, titles, strip(colormaps::lut(d.scale, 256)),
                 depthLegendTicks(d.dmin, d.dmax));
    }
    const auto paintParameter = [&](const ParameterLegend& p, const QRectF& box) {
        const int entries = p.bins >= 2 ? p.bins : 256;
        auto ticks = legendTicks(static_cast<double>(p.min), static_cast<double>(p.max));
        paintBox(painter, box, m, {QString::fromStdString(parameterLegendTitle(p))},
                 strip(colormaps::lut(p.map, entries)), ticks);
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
