// SPDX-License-Identifier: GPL-3.0-or-later
#include "gui/panels/HistogramWidget.h"

#include <QMouseEvent>
#include <QPainter>
#include <algorithm>
#include <cmath>
#include <limits>

namespace vv::gui::panels {

HistogramWidget::HistogramWidget(QWidget* parent) : QWidget(parent) {
    setObjectName(QStringLiteral("functionalHistogram"));
    setMinimumHeight(60);
    setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);
    setMouseTracking(true);  // the cursor shows where a handle can be grabbed
}

QRectF HistogramWidget::area() const noexcept {
    return QRectF(rect()).adjusted(1, 1, -1, -1);
}

double HistogramWidget::xOfValue(double value) const noexcept {
    const QRectF a = area();
    const double span = max_ > min_ ? max_ - min_ : 1.0;
    return a.left() + (value - min_) / span * a.width();
}

double HistogramWidget::valueAtX(double x) const noexcept {
    const QRectF a = area();
    const double t = a.width() > 0.0 ? (x - a.left()) / a.width() : 0.0;
    return min_ + std::clamp(t, 0.0, 1.0) * (max_ > min_ ? max_ - min_ : 0.0);
}

HistogramWidget::Handle HistogramWidget::handleAt(double x) const noexcept {
    constexpr double kGrab = 6.0;  // pixels either side of a line
    if (counts_.empty()) {
        return Handle::None;
    }
    const double low = std::abs(x - xOfValue(lo_));
    const double high = std::abs(x - xOfValue(hi_));
    if (std::min(low, high) > kGrab) {
        return Handle::None;
    }
    return low < high || (low == high && x < xOfValue(lo_)) ? Handle::Low : Handle::High;
}

void HistogramWidget::mousePressEvent(QMouseEvent* event) {
    dragging_ = event->button() == Qt::LeftButton && isEnabled() ? handleAt(event->position().x())
                                                                 : Handle::None;
    event->accept();
}

void HistogramWidget::mouseMoveEvent(QMouseEvent* event) {
    const double x = event->position().x();
    if (dragging_ == Handle::None) {
        setCursor(handleAt(x) == Handle::None ? Qt::ArrowCursor : Qt::SizeHorCursor);
        return;
    }
    const double value = valueAtX(x);
    if (dragging_ == Handle::Low) {
        lo_ = std::min(value, hi_);
    } else {
        hi_ = std::max(value, lo_);
    }
    update();
    emit rangeEdited(lo_, hi_);
}

void HistogramWidget::mouseReleaseEvent(QMouseEvent* event) {
    dragging_ = Handle::None;
    event->accept();
}

QSize HistogramWidget::sizeHint() const {
    return {200, 70};
}

void HistogramWidget::setValues(std::span<const float> values) {
    counts_.clear();
    double lo = std::numeric_limits<double>::infinity();
    double hi = -lo;
    for (const float v : values) {
        if (std::isfinite(v)) {
            lo = std::min(lo, static_cast<double>(v));
            hi = std::max(hi, static_cast<double>(v));
        }
    }
    if (lo <= hi) {
        counts_.assign(kBins, 0);
        min_ = lo;
        max_ = hi;
        const double width = hi > lo ? hi - lo : 1.0;
        for (const float v : values) {
            if (std::isfinite(v)) {
                const auto bin = static_cast<int>((static_cast<double>(v) - lo) / width * kBins);
                ++counts_[static_cast<std::size_t>(std::clamp(bin, 0, kBins - 1))];
            }
        }
    }
    update();
}

void HistogramWidget::setRange(double lo, double hi) {
    lo_ = lo;
    hi_ = hi;
    update();
}

void HistogramWidget::paintEvent(QPaintEvent* /*event*/) {
    QPainter painter(this);
    const QRectF area = this->area();
    painter.fillRect(area, palette().base());
    if (counts_.empty()) {
        painter.setPen(palette().color(QPalette::Disabled, QPalette::Text));
        painter.drawText(area, Qt::AlignCenter, tr("No values"));
        return;
    }
    const int peak = std::max(1, *std::max_element(counts_.begin(), counts_.end()));
    const double span = max_ > min_ ? max_ - min_ : 1.0;
    const double barWidth = area.width() / kBins;
    const QColor inside = palette().color(QPalette::Highlight);
    QColor outside = palette().color(QPalette::Mid);
    for (int i = 0; i < kBins; ++i) {
        const double height = area.height() * counts_[static_cast<std::size_t>(i)] / peak;
        const double centre = min_ + (i + 0.5) * span / kBins;
        const QRectF bar(area.left() + i * barWidth, area.bottom() - height, barWidth, height);
        painter.fillRect(bar, centre >= lo_ && centre <= hi_ ? inside : outside);
    }
    painter.setPen(QPen(palette().color(QPalette::Text), 2));
    for (const double mark : {lo_, hi_}) {
        const double x = std::clamp(xOfValue(mark), area.left(), area.right());
        painter.drawLine(QPointF(x, area.top()), QPointF(x, area.bottom()));
    }
}

}  // namespace vv::gui::panels
