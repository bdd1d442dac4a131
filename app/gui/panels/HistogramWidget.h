// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QWidget>
#include <span>
#include <vector>

namespace vv::gui::panels {

/// A small histogram of an array's values with the colour map's range marked
/// by two vertical lines (values outside the range are drawn paler). The
/// lines are handles: dragging one emits rangeEdited() continuously.
class HistogramWidget : public QWidget {
    Q_OBJECT

  public:
    static constexpr int kBins = 64;

    explicit HistogramWidget(QWidget* parent = nullptr);

    /// Bins the finite values of `values` (NaN / Inf ignored) into kBins equal
    /// bins over their [min, max]; no values clears the histogram.
    void setValues(std::span<const float> values);
    /// The marked range (lo <= hi, in value units).
    void setRange(double lo, double hi);

    [[nodiscard]] const std::vector<int>& counts() const noexcept { return counts_; }
    [[nodiscard]] double minimum() const noexcept { return min_; }
    [[nodiscard]] double maximum() const noexcept { return max_; }
    [[nodiscard]] double rangeLow() const noexcept { return lo_; }
    [[nodiscard]] double rangeHigh() const noexcept { return hi_; }

    [[nodiscard]] QSize sizeHint() const override;

    /// The horizontal widget position of `value`, and the value at `x`
    /// (both over [minimum(), maximum()] across the drawing area).
    [[nodiscard]] double xOfValue(double value) const noexcept;
    [[nodiscard]] double valueAtX(double x) const noexcept;

  signals:
    /// The user dragged a range handle to (lo, hi), lo <= hi.
    void rangeEdited(double lo, double hi);

  protected:
    void paintEvent(QPaintEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;

  private:
    enum class Handle { None, Low, High };
    [[nodiscard]] Handle handleAt(double x) const noexcept;
    [[nodiscard]] QRectF area() const noexcept;

    Handle dragging_ = Handle::None;
    std::vector<int> counts_;
    double min_ = 0.0;
    double max_ = 1.0;
    double lo_ = 0.0;
    double hi_ = 1.0;
};

}  // namespace vv::gui::panels
