// SPDX-License-Identifier: GPL-3.0-or-later
#include "MeasurementFigures.h"

#include <QLocale>
#include <QPainterPath>
#include <algorithm>
#include <cmath>

#include "ReportText.h"
#include "StudyCharts.h"
#include "vv/colormaps/LabelPalette.h"

namespace vv::report::figures {

namespace {

using pdf::font;
using pdf::mm;

QString qs(const std::string& text) {
    return QString::fromStdString(text);
}

QString tickLabel(double value) {
    return fixed(value, 0);
}

/// The ticks of an axis from 0 over `high` (nice steps).
charts::Axis axis(double high, const std::string& title) {
    return charts::axisFromZero(high, tickLabel, qs(title));
}

double xOf(const QRectF& plot, const charts::Axis& x, double value) {
    return plot.left() + plot.width() * (value - x.min) / std::max(1e-9, x.max - x.min);
}

/// The profile's plot inside its `area`: room left for the y ticks and
/// title, below for the x ticks and title, above for the legend. The
/// reformation below it lines up with its x.
QRectF profilePlot(const QRectF& area) {
    return {area.left() + mm(16.0), area.top() + mm(6.0), area.width() - mm(18.0),
            area.height() - mm(16.0)};
}

void paintProfile(QPainter& p, const QRectF& area, const ProfileFigure& f) {
    double top = 1.0;
    for (const auto& series : f.series) {
        for (const double v : series.values) {
            if (std::isfinite(v)) {
                top = std::max(top, v);
            }
        }
    }
    const charts::Axis y = axis(top * 1.05, f.yTitle);
    const charts::Axis x = axis(f.lengthMm, f.xTitle);
    const QRectF plot = profilePlot(area);
    p.save();
    p.setRenderHint(QPainter::Antialiasing);
    p.setFont(font(7.5));
    for (const double tick : y.ticks) {
        const double py = charts::yOf(plot, y, tick);
        p.setPen(QPen(pdf::kRule, mm(0.15)));
        p.drawLine(QPointF(plot.left(), py), QPointF(plot.right(), py));
        p.setPen(pdf::kMuted);
        p.drawText(QRectF(area.left() + mm(6.0), py - mm(2.0), mm(9.0), mm(4.0)),
                   Qt::AlignRight | Qt::AlignVCenter, y.label(tick));
    }
    for (const double tick : x.ticks) {
        const double px = xOf(plot, x, tick);
        p.setPen(QPen(pdf::kRule, mm(0.15)));
        p.drawLine(QPointF(px, plot.top()), QPointF(px, plot.bottom()));
        p.setPen(pdf::kMuted);
        p.drawText(QRectF(px - mm(8.0), plot.bottom() + mm(0.8), mm(16.0), mm(3.5)),
                   Qt::AlignHCenter | Qt::AlignTop, x.label(tick));
    }
    p.setPen(pdf::kInk);
    p.setFont(font(8.0, true));
    p.drawText(QRectF(plot.left(), plot.bottom() + mm(4.5), plot.width(), mm(4.0)),
               Qt::AlignHCenter | Qt::AlignTop, x.title);
    p.save();
    p.translate(area.left() + mm(2.5), plot.center().y());
    p.rotate(-90.0);
    p.drawText(QRectF(-plot.height() / 2.0, -mm(2.5), plot.height(), mm(5.0)), Qt::AlignCenter,
               y.title);
    p.restore();
    // The series, broken at gaps; the first (equivalent) last, on top.
    const auto& colours = seriesColours();
    for (std::size_t s = f.series.size(); s-- > 0;) {
        const auto& values = f.series[s].values;
        QPainterPath path;
        bool open = false;
        for (std::size_t i = 0; i < values.size() && i < f.pathMm.size(); ++i) {
            if (!std::isfinite(values[i])) {
                open = false;
                continue;
            }
            const QPointF at(xOf(plot, x, f.pathMm[i]), charts::yOf(plot, y, values[i]));
            if (open) {
                path.lineTo(at);
            } else {
                path.moveTo(at);
                open = true;
            }
        }
        p.setPen(QPen(colours[s % colours.size()], mm(s == 0 ? 0.5 : 0.3),
                      s == 0 ? Qt::SolidLine : Qt::DashLine, Qt::RoundCap, Qt::RoundJoin));
        p.setBrush(Qt::NoBrush);
        p.drawPath(path);
    }
    // Landmarks: dashed lines with their names at the top, stacked apart.
    p.setFont(font(6.5));
    const QFontMetricsF metrics(p.font(), p.device());
    std::vector<QRectF> placed;
    for (const PathMark& mark : f.landmarks) {
        const double px = xOf(plot, x, mark.pathMm);
        p.setPen(QPen(pdf::kInk, mm(0.2), Qt::DashLine));
        p.drawLine(QPointF(px, plot.top()), QPointF(px, plot.bottom()));
        QRectF box(QPointF(px + mm(0.6), plot.top() + mm(0.5)),
                   QSizeF(metrics.horizontalAdvance(qs(mark.label)) + mm(0.4), metrics.height()));
        if (box.right() > plot.right()) {
            box.moveRight(px - mm(0.6));
        }
        for (bool moved = true; moved;) {
            moved = false;
            for (const QRectF& other : placed) {
                if (other.intersects(box)) {
                    box.moveTop(other.bottom());
                    moved = true;
                }
            }
        }
        placed.push_back(box);
        p.fillRect(box, QColor(255, 255, 255, 210));
        p.setPen(pdf::kInk);
        p.drawText(box, Qt::AlignLeft | Qt::AlignVCenter, qs(mark.label));
    }
    for (const PathMark& mark : f.stenoses) {
        const double px = xOf(plot, x, mark.pathMm);
        p.setPen(Qt::NoPen);
        p.setBrush(pdf::kWarning);
        p.drawRect(QRectF(px - mm(0.8), plot.bottom() - mm(2.4), mm(1.6), mm(1.6)));
        p.setPen(pdf::kWarning);
        p.drawText(QRectF(px + mm(1.2), plot.bottom() - mm(3.4), mm(20.0), mm(3.0)),
                   Qt::AlignLeft | Qt::AlignVCenter, qs(mark.label));
    }
    // The legend above the plot.
    p.setFont(font(7.5));
    double lx = plot.left();
    for (std::size_t s = 0; s < f.series.size(); ++s) {
        p.setPen(QPen(colours[s % colours.size()], mm(s == 0 ? 0.5 : 0.3),
                      s == 0 ? Qt::SolidLine : Qt::DashLine));
        const double ly = area.top() + mm(2.5);
        p.drawLine(QPointF(lx, ly), QPointF(lx + mm(6.0), ly));
        p.setPen(pdf::kInk);
        const QString name = qs(f.series[s].name);
        p.drawText(QRectF(lx + mm(7.0), ly - mm(2.0), mm(40.0), mm(4.0)),
                   Qt::AlignLeft | Qt::AlignVCenter, name);
        lx += mm(9.0) + QFontMetricsF(p.font(), p.device()).horizontalAdvance(name);
    }
    p.setPen(QPen(pdf::kInk, mm(0.25)));
    p.drawLine(plot.bottomLeft(), plot.bottomRight());
    p.drawLine(plot.bottomLeft(), plot.topLeft());
    p.restore();
}

void paintSection(QPainter& p, const QRectF& square, const SectionFigure& f) {
    p.save();
    p.setRenderHint(QPainter::Antialiasing);
    p.setRenderHint(QPainter::SmoothPixmapTransform);
    if (!f.image.isNull()) {
        p.drawImage(square, f.image);
    } else {
        p.fillRect(square, pdf::kZebra);
    }
    const double scale = square.width() / std::max(1e-9, f.fieldMm);
    const QPointF centre = square.center();
    const auto at = [&](const glm::dvec2& uv) {
        return QPointF(centre.x() + uv.x * scale, centre.y() - uv.y * scale);
    };
    p.setClipRect(square);
    if (f.contour.size() >= 3) {
        QPainterPath contour;
        contour.moveTo(at(f.contour.front()));
        for (const glm::dvec2& q : f.contour) {
            contour.lineTo(at(q));
        }
        contour.closeSubpath();
        p.setPen(QPen(kContour, mm(0.4)));
        p.setBrush(Qt::NoBrush);
        p.drawPath(contour);
    }
    const auto& colours = seriesColours();
    for (const auto& [caliper, colour] :
         {std::pair{f.maxCaliper, colours[2]}, std::pair{f.minCaliper, colours[1]}}) {
        if (caliper) {
            p.setPen(QPen(colour, mm(0.35), Qt::SolidLine, Qt::RoundCap));
            p.drawLine(at((*caliper)[0]), at((*caliper)[1]));
        }
    }
    // The centreline point, and a 10 mm scale bar.
    p.setPen(QPen(pdf::kWarning, mm(0.25)));
    p.drawLine(centre - QPointF(mm(1.2), 0), centre + QPointF(mm(1.2), 0));
    p.drawLine(centre - QPointF(0, mm(1.2)), centre + QPointF(0, mm(1.2)));
    const QPointF bar = square.bottomLeft() + QPointF(mm(2.0), -mm(2.5));
    const QColor ink = f.image.isNull() ? pdf::kInk : QColor(Qt::white);
    p.setPen(QPen(ink, mm(0.4)));
    p.drawLine(bar, bar + QPointF(10.0 * scale, 0.0));
    p.setFont(font(6.5));
    p.drawText(QRectF(bar.x(), bar.y() - mm(3.5), mm(15.0), mm(3.0)), Qt::AlignLeft,
               withUnit(fixed(10.0, 0), "mm"));
    p.setClipping(false);
    p.setPen(QPen(pdf::kRule, mm(0.2)));
    p.setBrush(Qt::NoBrush);
    p.drawRect(square);
    p.restore();
}

}  // namespace

const std::vector<QColor>& seriesColours() {
    static const std::vector<QColor> colours = [] {
        const auto c = colormaps::diameterColors();
        const auto q = [](const glm::vec3& v) { return QColor::fromRgbF(v.r, v.g, v.b); };
        return std::vector<QColor>{q(c.equivalent), q(c.minimum), q(c.maximum)};
    }();
    return colours;
}

void profileFigure(pdf::Flow& flow, const ProfileFigure& figure) {
    const QFont titleFont = font(9.5, true);
    const QFont noteFont = font(8.0, false, true);
    const double chart = mm(62.0);
    const double titleHeight = flow.paragraphHeight(qs(figure.title), titleFont);
    const double noteHeight =
        figure.note.empty() ? 0.0 : flow.paragraphHeight(qs(figure.note), noteFont);
    flow.ensure(mm(3.0) + titleHeight + mm(1.5) + chart + noteHeight);
    flow.advance(mm(3.0));
    flow.paragraph(qs(figure.title), titleFont, pdf::kInk, mm(1.5));
    if (flow.drawing()) {
        paintProfile(flow.painter(), QRectF(flow.left(), flow.y(), flow.width(), chart), figure);
    }
    flow.advance(chart);
    if (!figure.note.empty()) {
        flow.paragraph(qs(figure.note), noteFont, pdf::kMuted);
    }
}

void reformationFigure(pdf::Flow& flow, const ReformationFigure& figure) {
    if (figure.image.isNull() || figure.lengthMm <= 0.0) {
        return;
    }
    const double trueHeight =
        (flow.width() - mm(18.0)) * 2.0 * figure.halfWidthMm / figure.lengthMm;
    const double height = std::clamp(trueHeight, mm(18.0), mm(60.0));
    QString caption = qs(figure.caption);
    if (std::abs(height - trueHeight) > mm(0.5)) {
        caption +=
            QStringLiteral(" ") + ReportText::tr("Drawn %1 times as high as long, to be read.")
                                      .arg(fixed(height / trueHeight, 1));
    }
    const QFont captionFont = font(8.0, false, true);
    const double captionHeight = flow.paragraphHeight(caption, captionFont);
    flow.ensure(mm(3.0) + height + mm(1.0) + captionHeight);
    flow.advance(mm(3.0));
    // Under the profile's plot, at its scale: the same distance, the same x.
    const QRectF plot = profilePlot(QRectF(flow.left(), flow.y(), flow.width(), height));
    const charts::Axis distance = axis(figure.lengthMm, {});
    const QRectF box(plot.left(), flow.y(), plot.width() * figure.lengthMm / distance.max, height);
    if (flow.drawing()) {
        QPainter& p = flow.painter();
        p.save();
        p.setRenderHint(QPainter::SmoothPixmapTransform);
        p.drawImage(box, figure.image);
        p.setRenderHint(QPainter::Antialiasing);
        p.setFont(font(6.5));
        for (const PathMark& mark : figure.landmarks) {
            const double x = box.left() + box.width() * mark.pathMm / figure.lengthMm;
            p.setPen(QPen(Qt::white, mm(0.2), Qt::DashLine));
            p.drawLine(QPointF(x, box.top()), QPointF(x, box.bottom()));
            p.drawText(QRectF(x + mm(0.6), box.top() + mm(0.5), mm(30.0), mm(3.0)),
                       Qt::AlignLeft | Qt::AlignTop, qs(mark.label));
        }
        p.setPen(QPen(pdf::kRule, mm(0.2)));
        p.setBrush(Qt::NoBrush);
        p.drawRect(box);
        p.restore();
    }
    flow.advance(height + mm(1.0));
    flow.paragraph(caption, captionFont, pdf::kMuted);
}

void sectionFigures(pdf::Flow& flow, const std::vector<SectionFigure>& figures) {
    constexpr int kPerRow = 3;
    const double gap = mm(5.0);
    const double side = (flow.width() - (kPerRow - 1) * gap) / kPerRow;
    const QFont titleFont = font(8.5, true);
    const QFont captionFont = font(7.5);
    for (std::size_t first = 0; first < figures.size(); first += kPerRow) {
        const std::size_t last = std::min(figures.size(), first + kPerRow);
        double titleHeight = 0.0;
        double captionHeight = 0.0;
        for (std::size_t i = first; i < last; ++i) {
            titleHeight =
                std::max(titleHeight, flow.textHeight(qs(figures[i].title), titleFont, side));
            captionHeight =
                std::max(captionHeight, flow.textHeight(qs(figures[i].caption), captionFont, side));
        }
        flow.ensure(mm(3.0) + titleHeight + mm(1.0) + side + mm(1.0) + captionHeight);
        flow.advance(mm(3.0));
        for (std::size_t i = first; i < last; ++i) {
            const double x = flow.left() + static_cast<double>(i - first) * (side + gap);
            flow.text(QRectF(x, flow.y(), side, titleHeight), qs(figures[i].title), titleFont,
                      pdf::kInk, Qt::AlignLeft | Qt::TextWordWrap);
            const QRectF square(x, flow.y() + titleHeight + mm(1.0), side, side);
            if (flow.drawing()) {
                paintSection(flow.painter(), square, figures[i]);
            }
            flow.text(QRectF(x, square.bottom() + mm(1.0), side, captionHeight),
                      qs(figures[i].caption), captionFont, pdf::kMuted,
                      Qt::AlignLeft | Qt::TextWordWrap);
        }
        flow.advance(titleHeight + mm(1.0) + side + mm(1.0) + captionHeight);
    }
}

}  // namespace vv::report::figures
