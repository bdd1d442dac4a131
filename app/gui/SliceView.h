// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QImage>
#include <QPointF>
#include <QString>
#include <QWidget>
#include <algorithm>
#include <glm/glm.hpp>
#include <memory>
#include <optional>

#include "gui/LatestRun.h"
#include "vv/core/Image.h"
#include "vv/scene/LabelMap.h"
#include "vv/scene/Volume.h"
#include "vv/slices/SliceOverlay.h"
#include "vv/slices/SlicePlane.h"
#include "vv/slices/WindowLevel.h"

namespace vv::gui {

/// One slice view (axial, coronal or sagittal) of a volume, painted with Qt:
/// the resliced values through the window, the segmentation overlay over
/// them, the orientation letters on the four edges, the view's name, the
/// slice position in mm and the slice number, the window, and the voxel under
/// the mouse (position in mm and value with unit).
///
/// Mouse: the wheel scrolls through the slices (Ctrl + wheel zooms), a left
/// drag changes the window (right: wider, down: higher level), a middle drag
/// or Shift + left drag pans, a right drag zooms, a double click fits the
/// slice again; a left click without dragging is clickedAt(). Keys: Up /
/// Page Up the next slice, Down / Page Down the previous one.
///
/// Slices of volumes up to kSynchronousVoxels voxels are resliced at once;
/// larger ones on a worker (only the newest request counts; the previous
/// slice stays on screen until the new one is ready).
class SliceView : public QWidget {
    Q_OBJECT

  public:
    /// Volumes with more voxels are resliced on a worker thread.
    static constexpr std::size_t kSynchronousVoxels = std::size_t{8} * 1024U * 1024U;

    explicit SliceView(slices::SliceOrientation orientation, QWidget* parent = nullptr);

    [[nodiscard]] slices::SliceOrientation orientation() const noexcept { return orientation_; }
    /// The volume to show (null: none); the middle slice, fitted. Throws
    /// nothing: a volume that cannot be sliced shows its problem as text.
    void setVolume(std::shared_ptr<const scene::Volume> volume);
    /// The segmentation to draw over the slices (null: none); its own grid.
    void setLabelMap(std::shared_ptr<const scene::LabelMap> labelMap);
    /// The segmentation drawn over the slice; null when none.
    [[nodiscard]] const std::shared_ptr<const scene::LabelMap>& labelMap() const noexcept {
        return labelMap_;
    }
    void setWindow(const slices::Window& window);
    [[nodiscard]] const slices::Window& window() const noexcept { return window_; }
    /// The span of the volume's values (max - min), which scales window drags.
    void setValueSpan(double span) noexcept { valueSpan_ = std::max(span, 1e-6); }
    void setOverlayStyle(const slices::OverlayStyle& style);

    [[nodiscard]] int sliceCount() const noexcept { return stack_ ? stack_->count : 0; }
    [[nodiscard]] int sliceIndex() const noexcept { return index_; }
    /// Shows slice `index` (clamped); sliceChanged() when it changed.
    void setSliceIndex(int index);
    /// Shows the slice nearest to the world point's slice position.
    void showSliceThrough(const glm::dvec3& world);
    /// Shows the slice nearest to slice position `mm` (clamped to the stack).
    void setSlicePosition(double mm);
    /// The slice position of the shown slice (mm along the view's world axis).
    [[nodiscard]] double slicePosition() const noexcept;
    [[nodiscard]] const std::optional<slices::SliceStack>& stack() const noexcept { return stack_; }

    /// Texts as painted: the position line ("S 12.5 mm  41 / 80") and the
    /// read-out of the point under the mouse (empty when none).
    [[nodiscard]] QString positionText() const;
    [[nodiscard]] const QString& readoutText() const noexcept { return readout_; }
    /// The slice image as composed (window and overlay), one pixel per
    /// slice pixel; null before the first slice is ready.
    [[nodiscard]] const QImage& sliceImage() const noexcept { return image_; }
    /// The slice whose values sliceImage() shows (-1: none yet).
    [[nodiscard]] int shownSliceIndex() const noexcept { return shownIndex_; }
    /// The shown slice for print: `width` pixels wide (the slice's aspect),
    /// the slice without zoom or pan (voxels sharp), the orientation letters
    /// on its edges; null before a slice is shown.
    [[nodiscard]] QImage printImage(int width) const;
    /// Blocks until a pending reslice has finished and is shown (tests).
    void waitForSlice();

    /// Zoom factor over the fitted size (1 = the slice fits the view),
    /// clamped to [app::kMinSliceZoom, app::kMaxSliceZoom].
    [[nodiscard]] double zoom() const noexcept { return zoom_; }
    void setZoom(double zoom);
    /// Where the slice's centre lies from the view's centre, in mm along the
    /// view's right and down (0, 0: centred; kept in mm, so that it stays on
    /// the same anatomy when the view is resized).
    [[nodiscard]] glm::dvec2 pan() const noexcept { return pan_; }
    void setPan(const glm::dvec2& mm);
    /// The world point (LPS mm) under widget position `position`, on the
    /// shown slice's plane; nullopt without a slice.
    [[nodiscard]] std::optional<glm::dvec3> worldAt(const QPointF& position) const;
    /// The widget position of `world` projected onto the shown slice.
    [[nodiscard]] std::optional<QPointF> widgetPointOf(const glm::dvec3& world) const;
    /// The linked cursor (LPS mm; nullopt: none): a crosshair where it lies
    /// on the shown slice (within half a slice step).
    void setCrosshair(const std::optional<glm::dvec3>& world);
    [[nodiscard]] const std::optional<glm::dvec3>& crosshair() const noexcept { return crosshair_; }
    /// The read-out for the point under widget position `position` (what
    /// hovering shows).
    void hoverAt(const QPointF& position);

  signals:
    void sliceChanged(int index);
    /// A left drag changed the window (the other views follow).
    void windowDragged(const vv::slices::Window& window);
    /// A left click without dragging at world point `world` (LPS mm).
    void clickedAt(const glm::dvec3& world);

  protected:
    /// The mouse help (tooltip) only off the image, so that it never covers
    /// the values being read.
    bool event(QEvent* event) override;
    void paintEvent(QPaintEvent* event) override;
    void wheelEvent(QWheelEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void mouseDoubleClickEvent(QMouseEvent* event) override;
    void keyPressEvent(QKeyEvent* event) override;
    void leaveEvent(QEvent* event) override;

  private:
    /// The resliced values and labels of one slice.
    struct Resliced {
        int index = -1;
        std::shared_ptr<const Image<float>> values;
        std::shared_ptr<const Image<std::uint8_t>> labels;
        QString error;
    };
    void requestSlice();
    void showResliced(const Resliced& resliced);
    /// Window + overlay of the shown values into image_.
    void compose();
    /// The widget rectangle the slice image is drawn into.
    [[nodiscard]] QRectF imageRect() const;
    /// Widget pixels per mm on the slice as drawn (0 without a slice).
    [[nodiscard]] double pixelsPerMm() const;
    void paintTexts(class QPainter& painter) const;
    void paintCrosshair(class QPainter& painter) const;

    slices::SliceOrientation orientation_;
    std::shared_ptr<const scene::Volume> volume_;
    std::shared_ptr<const scene::LabelMap> labelMap_;
    std::optional<slices::SliceStack> stack_;
    int index_ = 0;
    slices::Window window_;
    slices::OverlayStyle overlay_;
    double valueSpan_ = 1.0;
    Resliced shown_;
    int shownIndex_ = -1;
    QImage image_;
    QString problem_;
    QString readout_;
    std::optional<glm::dvec3> crosshair_;
    double zoom_ = 1.0;
    glm::dvec2 pan_{0.0};  // mm
    // Mouse drag state.
    Qt::MouseButton dragButton_ = Qt::NoButton;
    bool dragPans_ = false;
    bool dragged_ = false;
    QPointF pressAt_;
    QPointF lastAt_;
    slices::Window pressWindow_;
    double pressZoom_ = 1.0;
    LatestRun<Resliced, AtDestruction::Wait> run_{this};
};

}  // namespace vv::gui
