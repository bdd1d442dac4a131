// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QImage>
#include <QWidget>
#include <memory>
#include <vector>

#include "vv/core/Image.h"
#include "vv/scene/Volume.h"
#include "vv/slices/WindowLevel.h"

class QSlider;
class QLabel;

namespace vv::gui {

class PlanningState;

/// The stretched curved planar reformation along the path (issue 35): the
/// volume resampled on the surface swept by a line across the vessel as it
/// moves along the path, the path straightened along x (the same distances
/// as the diameter profile above it: x is path mm), the line's direction
/// turning about the path by the rotation angle (0-180 degrees, the slider;
/// the frame is rotation-minimising along the path, so a straight vessel
/// does not twist). What a planner reads lumen, thrombus and calcification
/// from. Shown for scenes from a volume; the slice views' window / level.
/// A click moves the cursor there; the cursor is a red line across, each
/// landmark a dashed white one.
class CurvedReformation : public QWidget {
    Q_OBJECT

  public:
    explicit CurvedReformation(PlanningState* state, QWidget* parent = nullptr);

    void setVolume(std::shared_ptr<const scene::Volume> volume);
    void setWindow(const slices::Window& window);
    [[nodiscard]] const slices::Window& window() const noexcept { return window_; }
    /// The rotation about the path, degrees in [0, 180).
    void setRotation(int degrees);
    [[nodiscard]] int rotation() const noexcept { return rotation_; }
    /// The plot's horizontal extent in this widget's x (the profile's plot
    /// area) and the path distances at its sides, so that path distances
    /// line up with the profile's.
    void setHorizontalExtent(double left, double right, double fromMm, double toMm);

    /// The resampled values (rows: across the path, -half .. +half; columns:
    /// the path's points in order), NaN outside the volume. Empty without a
    /// volume or path.
    [[nodiscard]] const Image<float>& values() const noexcept { return values_; }
    /// Half the width across the path, mm, and the row spacing, mm.
    [[nodiscard]] double halfWidthMm() const noexcept { return halfWidthMm_; }
    [[nodiscard]] double rowSpacingMm() const noexcept { return rowSpacingMm_; }
    /// The widget x of path distance `pathMm`.
    [[nodiscard]] double xOf(double pathMm) const;
    [[nodiscard]] QSlider* rotationSlider() const noexcept { return slider_; }

    [[nodiscard]] QSize sizeHint() const override { return {600, 150}; }

  protected:
    void paintEvent(QPaintEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void resizeEvent(QResizeEvent* event) override;

  private:
    void resample();
    void colour();
    [[nodiscard]] QRectF plotRect() const;

    PlanningState* state_;
    std::shared_ptr<const scene::Volume> volume_;
    slices::Window window_{300.0, 600.0};
    int rotation_ = 0;
    Image<float> values_;
    std::vector<double> columnsMm_;  ///< the path distance of each column
    QImage image_;
    double halfWidthMm_ = 20.0;
    double rowSpacingMm_ = 0.5;
    double left_ = -1.0;
    double right_ = -1.0;
    double fromMm_ = 0.0;
    double toMm_ = -1.0;  ///< below fromMm_: the path's length
    QSlider* slider_ = nullptr;
    QLabel* angle_ = nullptr;
};

}  // namespace vv::gui
