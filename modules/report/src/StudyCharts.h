// SPDX-License-Identifier: GPL-3.0-or-later
// The study report's charts, painted with QPainter at the report's 300 dpi:
// an error-bar chart (a dot at the mean, a bar over its confidence
// interval, per condition) and box plots (per condition). Private to
// vv::report; tests map values to pixels through plotRect() and yOf().
#pragma once

#include <QPainter>
#include <QRectF>
#include <QString>
#include <QStringList>
#include <functional>
#include <optional>
#include <vector>

#include "vv/study/Statistics.h"

namespace vv::report::charts {

/// A value axis: its range, its ticks, how a tick reads, its title.
struct Axis {
    double min = 0.0;
    double max = 1.0;
    std::vector<double> ticks;
    std::function<QString(double)> label;
    QString title;
};

/// An axis from 0 over `high` with "nice" ticks (1, 2 or 5 times a power
/// of ten, about five of them), labelled by `label`.
[[nodiscard]] Axis axisFromZero(double high, std::function<QString(double)> label, QString title);

/// The plotting area inside a chart's `area`: room left of it for the tick
/// labels and the axis title, below it for the categories.
[[nodiscard]] QRectF plotRect(const QRectF& area);

/// The vertical pixel of `value` in `plot` (max at the top).
[[nodiscard]] double yOf(const QRectF& plot, const Axis& axis, double value);

/// The horizontal centre of category `index` of `count` in `plot`.
[[nodiscard]] double xOf(const QRectF& plot, std::size_t index, std::size_t count);

struct Interval {
    double low = 0.0;
    double centre = 0.0;
    double high = 0.0;
};

/// Per category a dot at `centre` and a bar from `low` to `high` with end
/// caps; an optional dashed reference line (chance level) with its label.
void errorBarChart(QPainter& painter, const QRectF& area, const QStringList& categories,
                   const std::vector<Interval>& values, const Axis& axis,
                   std::optional<double> reference, const QString& referenceLabel);

/// Per category a box from the lower to the upper quartile with the median
/// across it, whiskers with caps, and the outliers as rings.
void boxPlotChart(QPainter& painter, const QRectF& area, const QStringList& categories,
                  const std::vector<study::BoxStatistics>& boxes, const Axis& axis);

}  // namespace vv::report::charts
