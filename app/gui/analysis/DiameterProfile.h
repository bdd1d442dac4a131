// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QChartView>
#include <QList>
#include <optional>

class QGraphicsSimpleTextItem;
class QLineSeries;
class QScatterSeries;
class QValueAxis;

namespace vv::gui {

class PlanningState;

/// The diameter profile along the chosen path (issue 35), drawn with Qt
/// Charts: the equivalent, minimum and maximum diameter (left axis, mm) and
/// the area (right axis, mm²) against the distance along the path (mm); gaps
/// where no section measures the vessel (ends, junctions, no contour), never
/// a line across them. Landmarks on the path are dashed vertical lines with
/// their names, graded stenoses a marker with their diameter percent, the
/// cursor a red line. Numbers in the UI locale.
///
/// Mouse: a click moves the cursor; a press on a landmark's line selects it
/// and dragging moves it along the path; hovering says where (hovered()).
/// Keys: Left / Right move the cursor by one section (Shift: ten), Home /
/// End to the path's ends; Ctrl+Left / Ctrl+Right move the selected
/// landmark by one section; Insert asks to place a landmark at the cursor
/// (placeRequested()), Delete removes the selected landmark.
class DiameterProfile : public QChartView {
    Q_OBJECT

  public:
    explicit DiameterProfile(PlanningState* state, QWidget* parent = nullptr);

    /// The path distance (mm) at widget position `x`; nullopt outside the plot.
    [[nodiscard]] std::optional<double> pathMmAt(double x) const;
    /// The widget x of path distance `pathMm`.
    [[nodiscard]] double xOf(double pathMm) const;
    /// The series of one quantity (its runs between gaps), for tests.
    [[nodiscard]] QList<QLineSeries*> seriesNamed(const QString& name) const;
    /// The cursor's line, and the landmarks' lines and labels (in the
    /// state's landmark order; those not on the path are left out).
    [[nodiscard]] QLineSeries* cursorLine() const noexcept { return cursor_; }
    [[nodiscard]] const QList<QGraphicsSimpleTextItem*>& landmarkLabels() const noexcept {
        return labels_;
    }

  signals:
    /// The mouse is over the plot at `pathMm` along the path; NaN when it left.
    void hovered(double pathMm);
    /// Insert: place the chosen landmark at the cursor.
    void placeRequested();
    /// The plot area's horizontal extent in this widget's x, and the path
    /// distances (mm) at its two sides (for views that line up with it: the
    /// curved reformation above it).
    void plotExtentChanged(double left, double right, double fromMm, double toMm);

  protected:
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void leaveEvent(QEvent* event) override;
    void keyPressEvent(QKeyEvent* event) override;
    void resizeEvent(QResizeEvent* event) override;

  private:
    void rebuild();
    void showCursor();
    void showMarkers();
    void placeLabels();
    [[nodiscard]] int landmarkNear(double x) const;
    [[nodiscard]] double diameterTop() const;

    PlanningState* state_;
    QValueAxis* along_ = nullptr;
    QValueAxis* diameter_ = nullptr;
    QValueAxis* area_ = nullptr;
    QLineSeries* cursor_ = nullptr;
    QList<QLineSeries*> markerLines_;  ///< one per landmark on the path
    QList<int> markerLandmarks_;       ///< their indices in the state
    QList<QGraphicsSimpleTextItem*> labels_;
    QScatterSeries* stenoses_ = nullptr;
    QList<QGraphicsSimpleTextItem*> stenosisLabels_;
    int dragging_ = -1;  ///< the landmark being dragged
};

}  // namespace vv::gui
