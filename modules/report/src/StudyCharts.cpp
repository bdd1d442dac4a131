// SPDX-License-Identifier: GPL-3.0-or-later
#include "StudyCharts.h"

#include <QPainterPath>
#include <algorithm>
#include <cmath>

#include "PdfFlow.h"

namespace vv::report::charts {
namespace {

using pdf::mm;

const QColor kMark = pdf::kAccent;
const QColor kBoxFill(214, 226, 238);

/// Grid lines, tick labels, the axis title (rotated) and the frame.
void drawAxis(QPainter& painter, const QRectF& area, const QRectF& plot, const Axis& axis) {
    painter.setFont(pdf::font(7.5));
    for (const double tick : axis.ticks) {
        const double y = yOf(plot, axis, tick);
        painter.setPen(QPen(pdf::kRule, mm(0.15)));
        painter.drawLine(QPointF(plot.left(), y), QPointF(plot.right(), y));
        painter.setPen(pdf::kMuted);
        painter.drawText(QRectF(area.left() + mm(9.0), y - mm(2.0),
                                plot.left() - area.left() - mm(10.0), mm(4.0)),
                         Qt::AlignRight | Qt::AlignVCenter, axis.label(tick));
    }
    // The title turned along the axis, in up to two lines over the plot's
    // height, between the area's edge and the tick labels (0.5 to 8.5 mm).
    painter.save();
    painter.translate(area.left() + mm(4.5), plot.center().y());
    painter.rotate(-90.0);
    painter.setFont(pdf::font(8.0, true));
    painter.setPen(pdf::kInk);
    painter.drawText(QRectF(-plot.height() / 2.0, -mm(4.0), plot.height(), mm(8.0)),
                     Qt::AlignCenter | Qt::TextWordWrap, axis.title);
    painter.restore();
    painter.setPen(QPen(pdf::kInk, mm(0.25)));
    painter.setBrush(Qt::NoBrush);
    painter.drawLine(plot.bottomLeft(), plot.bottomRight());
    painter.drawLine(plot.bottomLeft(), plot.topLeft());
}

void drawCategories(QPainter& painter, const QRectF& area, const QRectF& plot,
                    const QStringList& categories) {
    painter.setFont(pdf::font(7.5));
    painter.setPen(pdf::kInk);
    const auto count = static_cast<std::size_t>(categories.size());
    const double slot = plot.width() / static_cast<double>(std::max<std::size_t>(count, 1));
    for (std::size_t i = 0; i < count; ++i) {
        painter.drawText(QRectF(xOf(plot, i, count) - slot / 2.0, plot.bottom() + mm(1.0), slot,
                                area.bottom() - plot.bottom() - mm(1.0)),
                         Qt::AlignHCenter | Qt::AlignTop | Qt::TextWordWrap,
                         categories[static_cast<qsizetype>(i)]);
    }
}

}  // namespace

Axis axisFromZero(double high, std::function<QString(double)> label, QString title) {
    Axis axis;
    axis.label = std::move(label);
    axis.title = std::move(title);
    const double top = high > 0.0 && std::isfinite(high) ? high : 1.0;
    const double rough = top / 5.0;
    const double power = std::pow(10.0, std::floor(std::log10(rough)));
    double step = power;
    for (const double m : {1.0, 2.0, 5.0, 10.0}) {
        step = m * power;
        if (step >= rough) {
            break;
        }
    }
    axis.max = std::ceil(top / step - 1e-9) * step;
    for (double t = 0.0; t <= axis.max + step * 1e-6; t += step) {
        axis.ticks.push_back(t);
    }
    return axis;
}

QRectF plotRect(const QRectF& area) {
    return {area.left() + mm(20.0), area.top() + mm(3.0), area.width() - mm(23.0),
            area.height() - mm(13.0)};
}

double yOf(const QRectF& plot, const Axis& axis, double value) {
    return plot.bottom() - (value - axis.min) / (axis.max - axis.min) * plot.height();
}

double xOf(const QRectF& plot, std::size_t index, std::size_t count) {
    const double slot = plot.width() / static_cast<double>(std::max<std::size_t>(count, 1));
    return plot.left() + (static_cast<double>(index) + 0.5) * slot;
}

void errorBarChart(QPainter& painter, const QRectF& area, const QStringList& categories,
                   const std::vector<Interval>& values, const Axis& axis,
                   std::optional<double> reference, const QString& referenceLabel) {
    const QRectF plot = plotRect(area);
    drawAxis(painter, area, plot, axis);
    if (reference) {
        const double y = yOf(plot, axis, *reference);
        painter.setPen(QPen(pdf::kMuted, mm(0.3), Qt::DashLine));
        painter.drawLine(QPointF(plot.left(), y), QPointF(plot.right(), y));
        painter.setFont(pdf::font(7.0, false, true));
        painter.drawText(
            QRectF(plot.left() + mm(1.0), y + mm(0.5), plot.width() - mm(2.0), mm(3.5)),
            Qt::AlignRight | Qt::AlignTop, referenceLabel);
    }
    const std::size_t count = values.size();
    const double cap = mm(2.0);
    for (std::size_t i = 0; i < count; ++i) {
        const double x = xOf(plot, i, count);
        const double low = yOf(plot, axis, values[i].low);
        const double high = yOf(plot, axis, values[i].high);
        painter.setPen(QPen(kMark, mm(0.4), Qt::SolidLine, Qt::FlatCap));
        painter.drawLine(QPointF(x, low), QPointF(x, high));
        painter.drawLine(QPointF(x - cap, low), QPointF(x + cap, low));
        painter.drawLine(QPointF(x - cap, high), QPointF(x + cap, high));
        painter.setPen(Qt::NoPen);
        painter.setBrush(kMark);
        painter.drawEllipse(QPointF(x, yOf(plot, axis, values[i].centre)), mm(1.1), mm(1.1));
        painter.setBrush(Qt::NoBrush);
    }
    drawCategories(painter, area, plot, categories);
}

void boxPlotChart(QPainter& painter, const QRectF& area, const QStringList& categories,
                  const std::vector<study::BoxStatistics>& boxes, const Axis& axis) {
    const QRectF plot = plotRect(area);
    drawAxis(painter, area, plot, axis);
    const std::size_t count = boxes.size();
    const double half = std::min(mm(7.0), plot.width() / static_cast<double>(count) * 0.3);
    for (std::size_t i = 0; i < count; ++i) {
        const study::BoxStatistics& b = boxes[i];
        const double x = xOf(plot, i, count);
        const double q1 = yOf(plot, axis, b.lowerQuartile);
        const double q3 = yOf(plot, axis, b.upperQuartile);
        painter.setPen(QPen(kMark, mm(0.3), Qt::SolidLine, Qt::FlatCap));
        painter.drawLine(QPointF(x, q3), QPointF(x, yOf(plot, axis, b.upperWhisker)));
        painter.drawLine(QPointF(x, q1), QPointF(x, yOf(plot, axis, b.lowerWhisker)));
        for (const double whisker : {b.lowerWhisker, b.upperWhisker}) {
            const double y = yOf(plot, axis, whisker);
            painter.drawLine(QPointF(x - half / 2.0, y), QPointF(x + half / 2.0, y));
        }
        painter.setBrush(kBoxFill);
        painter.drawRect(QRectF(QPointF(x - half, q3), QPointF(x + half, q1)));
        painter.setPen(QPen(kMark, mm(0.6), Qt::SolidLine, Qt::FlatCap));
        const double median = yOf(plot, axis, b.median);
        painter.drawLine(QPointF(x - half, median), QPointF(x + half, median));
        painter.setPen(QPen(kMark, mm(0.25)));
        painter.setBrush(Qt::NoBrush);
        for (const double outlier : b.outliers) {
            painter.drawEllipse(QPointF(x, yOf(plot, axis, outlier)), mm(0.8), mm(0.8));
        }
    }
    drawCategories(painter, area, plot, categories);
}

}  // namespace vv::report::charts
