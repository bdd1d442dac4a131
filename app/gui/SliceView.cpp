// SPDX-License-Identifier: GPL-3.0-or-later
#include "gui/SliceView.h"

#include <QCoreApplication>
#include <QEventLoop>
#include <QFontMetricsF>
#include <QHelpEvent>
#include <QKeyEvent>
#include <QLocale>
#include <QMouseEvent>
#include <QPainter>
#include <QToolTip>
#include <QWheelEvent>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <utility>

#include "common/Session.h"
#include "common/SliceReport.h"
#include "common/SliceTexts.h"
#include "vv/core/Error.h"
#include "vv/slices/OrientationLetters.h"
#include "vv/slices/Reslice.h"
#include "vv/slices/VoxelProbe.h"

namespace vv::gui {

using app::drawEdgeLetters;
using app::drawShadowedText;
using app::orientationName;
using app::slicePositionLabel;
using app::slicePrintImage;
using app::voxelValueLabel;
using app::windowLabel;
using app::worldPointLabel;

namespace {

constexpr double kClickSlack = 4.0;  // px a click may move
constexpr int kTextMargin = 6;

// The values and labels of `plane` (on the calling thread).
template <typename Result>
Result resliceAt(const std::shared_ptr<const scene::Volume>& volume,
                 const std::shared_ptr<const scene::LabelMap>& labelMap,
                 const slices::SlicePlane& plane, int index, const std::stop_token& stop) {
    Result r;
    r.index = index;
    try {
        r.values = std::make_shared<const Image<float>>(
            slices::reslice(*volume, plane, slices::Interpolation::Linear, stop));
        if (labelMap) {
            r.labels = std::make_shared<const Image<std::uint8_t>>(
                slices::resliceLabels(*labelMap, plane, stop));
        }
    } catch (const CancelledError&) {
        r.index = -1;
    } catch (const Error& e) {
        r.error = QString::fromStdString(e.problem());
    }
    return r;
}

}  // namespace

SliceView::SliceView(slices::SliceOrientation orientation, QWidget* parent)
    : QWidget(parent), orientation_(orientation) {
    static constexpr std::array<const char*, 3> kNames{"axialSliceView", "coronalSliceView",
                                                       "sagittalSliceView"};
    setObjectName(QLatin1String(kNames.at(static_cast<std::size_t>(orientation))));
    setMouseTracking(true);
    setFocusPolicy(Qt::WheelFocus);
    setMinimumSize(120, 120);
    setToolTip(
        tr("Wheel or Up/Down: slices · Ctrl+wheel or right-drag: zoom · Double-click: fit\n"
           "Left-drag: window (right: wider, down: darker) · "
           "Middle or Shift+left-drag: pan\n"
           "Click: show this point in every view"));
    setAttribute(Qt::WA_OpaquePaintEvent);
}

void SliceView::setVolume(std::shared_ptr<const scene::Volume> volume) {
    run_.cancel();
    volume_ = std::move(volume);
    stack_.reset();
    shown_ = {};
    shownIndex_ = -1;
    image_ = {};
    problem_.clear();
    readout_.clear();
    crosshair_.reset();
    zoom_ = 1.0;
    pan_ = glm::dvec2(0.0);
    if (volume_ && !volume_->empty()) {
        try {
            stack_ = slices::sliceStack(*volume_, orientation_);
            index_ = stack_->count / 2;
            requestSlice();
        } catch (const Error& e) {
            problem_ = QString::fromStdString(e.problem());
        }
    }
    update();
}

void SliceView::setLabelMap(std::shared_ptr<const scene::LabelMap> labelMap) {
    labelMap_ = std::move(labelMap);
    if (stack_) {
        requestSlice();
    }
}

void SliceView::setWindow(const slices::Window& window) {
    window_ = window;
    compose();
    update();
}

void SliceView::setOverlayStyle(const slices::OverlayStyle& style) {
    overlay_ = style;
    compose();
    update();
}

void SliceView::setSliceIndex(int index) {
    if (!stack_) {
        return;
    }
    const int k = std::clamp(index, 0, stack_->count - 1);
    if (k == index_) {
        return;
    }
    index_ = k;
    requestSlice();
    emit sliceChanged(index_);
}

void SliceView::showSliceThrough(const glm::dvec3& world) {
    if (stack_) {
        setSliceIndex(stack_->nearestIndex(world[stack_->axis]));
    }
}

void SliceView::setSlicePosition(double mm) {
    if (stack_) {
        setSliceIndex(stack_->nearestIndex(mm));
    }
}

double SliceView::slicePosition() const noexcept {
    return stack_ ? stack_->position(index_) : 0.0;
}

void SliceView::requestSlice() {
    if (!stack_ || !volume_) {
        return;
    }
    const slices::SlicePlane plane = stack_->planeAt(index_);
    if (volume_->voxelCount() <= kSynchronousVoxels) {
        run_.cancel();
        showResliced(resliceAt<Resliced>(volume_, labelMap_, plane, index_, {}));
        return;
    }
    run_.start(
        [volume = volume_, labels = labelMap_, plane, index = index_](const std::stop_token& stop) {
            return resliceAt<Resliced>(volume, labels, plane, index, stop);
        },
        [this](const Resliced& r) {
            if (r.index >= 0) {
                showResliced(r);
            }
        });
}

void SliceView::showResliced(const Resliced& resliced) {
    if (resliced.index < 0) {
        return;
    }
    shown_ = resliced;
    shownIndex_ = resliced.index;
    problem_ = resliced.error;
    compose();
    update();
}

void SliceView::waitForSlice() {
    while (run_.isRunning() || (stack_ && shownIndex_ != index_ && problem_.isEmpty())) {
        run_.waitForFinished();
        QCoreApplication::processEvents(QEventLoop::AllEvents, 20);
    }
}

void SliceView::compose() {
    if (!shown_.values) {
        image_ = {};
        return;
    }
    image_ = app::sliceImage(
        shown_.values->view(),
        shown_.labels ? shown_.labels->view() : ImageView<const std::uint8_t>{}, window_, overlay_);
}

QRectF SliceView::imageRect() const {
    if (image_.isNull()) {
        return {};
    }
    const double fit = std::min(width() / static_cast<double>(image_.width()),
                                height() / static_cast<double>(image_.height()));
    const double scale = fit * zoom_;
    const QSizeF size(image_.width() * scale, image_.height() * scale);
    const double perMm = scale / stack_->plane.pixelSpacing;
    const QPointF centre = QPointF(width() / 2.0 + pan_.x * perMm, height() / 2.0 + pan_.y * perMm);
    return {centre - QPointF(size.width() / 2.0, size.height() / 2.0), size};
}

double SliceView::pixelsPerMm() const {
    const QRectF rect = imageRect();
    return rect.isEmpty() ? 0.0 : rect.width() / (image_.width() * stack_->plane.pixelSpacing);
}

void SliceView::setZoom(double zoom) {
    zoom_ = std::clamp(zoom, app::kMinSliceZoom, app::kMaxSliceZoom);
    update();
}

void SliceView::setPan(const glm::dvec2& mm) {
    pan_ = mm;
    update();
}

std::optional<glm::dvec3> SliceView::worldAt(const QPointF& position) const {
    const QRectF rect = imageRect();
    if (!stack_ || rect.isEmpty()) {
        return std::nullopt;
    }
    const double column = (position.x() - rect.left()) / rect.width() * image_.width() - 0.5;
    const double row = (position.y() - rect.top()) / rect.height() * image_.height() - 0.5;
    return stack_->planeAt(index_).worldAt(column, row);
}

std::optional<QPointF> SliceView::widgetPointOf(const glm::dvec3& world) const {
    const QRectF rect = imageRect();
    if (!stack_ || rect.isEmpty()) {
        return std::nullopt;
    }
    const glm::dvec2 p = stack_->planeAt(index_).pixelAt(world);
    return QPointF(rect.left() + (p.x + 0.5) / image_.width() * rect.width(),
                   rect.top() + (p.y + 0.5) / image_.height() * rect.height());
}

QString SliceView::positionText() const {
    if (!stack_) {
        return {};
    }
    return slicePositionLabel(stack_->axis, slicePosition()) + QStringLiteral("   ") +
           tr("%1 / %2").arg(QLocale().toString(index_ + 1), QLocale().toString(stack_->count));
}

void SliceView::hoverAt(const QPointF& position) {
    QString text;
    if (const auto world = worldAt(position); world && volume_) {
        if (const auto sample = slices::voxelAt(*volume_, *world)) {
            text = worldPointLabel(*world) + QStringLiteral("   ") + voxelValueLabel(*sample);
        }
    }
    if (text != readout_) {
        readout_ = text;
        update();
    }
}

bool SliceView::event(QEvent* event) {
    if (event->type() == QEvent::ToolTip) {
        const auto* help = static_cast<QHelpEvent*>(event);
        if (imageRect().contains(help->pos())) {
            QToolTip::hideText();
            event->ignore();
            return true;
        }
    }
    return QWidget::event(event);
}

void SliceView::paintEvent(QPaintEvent* /*event*/) {
    QPainter painter(this);
    painter.fillRect(rect(), Qt::black);
    if (!image_.isNull()) {
        const QRectF target = imageRect();
        painter.setRenderHint(QPainter::SmoothPixmapTransform,
                              target.width() < 2.0 * image_.width());
        painter.drawImage(target, image_);
    }
    paintCrosshair(painter);
    paintTexts(painter);
}

void SliceView::setCrosshair(const std::optional<glm::dvec3>& world) {
    crosshair_ = world;
    update();
}

void SliceView::paintCrosshair(QPainter& painter) const {
    if (!crosshair_ || !stack_) {
        return;
    }
    const slices::SlicePlane plane = stack_->planeAt(index_);
    if (std::abs(glm::dot(*crosshair_ - plane.origin, plane.normal())) >
        0.5 * stack_->step + 1e-6) {
        return;
    }
    const auto at = widgetPointOf(*crosshair_);
    if (!at) {
        return;
    }
    constexpr double kGap = 6.0;
    painter.setPen(QPen(QColor(120, 255, 120, 170), 1.0));
    painter.drawLine(QPointF(0, at->y()), QPointF(at->x() - kGap, at->y()));
    painter.drawLine(QPointF(at->x() + kGap, at->y()), QPointF(width(), at->y()));
    painter.drawLine(QPointF(at->x(), 0), QPointF(at->x(), at->y() - kGap));
    painter.drawLine(QPointF(at->x(), at->y() + kGap), QPointF(at->x(), height()));
}

QImage SliceView::printImage(int width) const {
    return stack_ ? slicePrintImage(image_, stack_->plane, width) : QImage();
}

void SliceView::paintTexts(QPainter& painter) const {
    QFont font = painter.font();
    font.setPointSizeF(std::max(7.0, font.pointSizeF() * 0.9));
    painter.setFont(font);
    const QRectF area =
        QRectF(rect()).adjusted(kTextMargin, kTextMargin, -kTextMargin, -kTextMargin);
    drawShadowedText(painter, area, Qt::AlignLeft | Qt::AlignTop, orientationName(orientation_));
    if (!problem_.isEmpty()) {
        drawShadowedText(painter, area, Qt::AlignCenter | Qt::TextWordWrap, problem_);
    }
    if (!stack_) {
        return;
    }
    QFont bold = font;
    bold.setBold(true);
    painter.setFont(bold);
    drawEdgeLetters(painter, area, stack_->plane);
    painter.setFont(font);
    const double line = QFontMetricsF(font).height();
    const QRectF lower = area.adjusted(0, 0, 0, -line);
    drawShadowedText(painter, area, Qt::AlignRight | Qt::AlignTop,
                     windowLabel(window_, QString::fromStdString(slices::valueUnit(*volume_))));
    drawShadowedText(painter, lower, Qt::AlignLeft | Qt::AlignBottom, positionText());
    if (!readout_.isEmpty()) {
        drawShadowedText(painter, area, Qt::AlignLeft | Qt::AlignBottom, readout_);
    }
}

void SliceView::wheelEvent(QWheelEvent* event) {
    const int steps = event->angleDelta().y() / 120;
    if (steps == 0) {
        event->ignore();
        return;
    }
    if ((event->modifiers() & Qt::ControlModifier) != 0) {
        setZoom(zoom_ * std::pow(1.25, steps));
    } else {
        setSliceIndex(index_ + steps);
    }
    hoverAt(event->position());
    event->accept();
}

void SliceView::mousePressEvent(QMouseEvent* event) {
    dragButton_ = event->button();
    dragPans_ =
        event->button() == Qt::MiddleButton ||
        (event->button() == Qt::LeftButton && (event->modifiers() & Qt::ShiftModifier) != 0);
    dragged_ = false;
    pressAt_ = event->position();
    lastAt_ = event->position();
    pressWindow_ = window_;
    pressZoom_ = zoom_;
    event->accept();
}

void SliceView::mouseMoveEvent(QMouseEvent* event) {
    const QPointF at = event->position();
    if (dragButton_ != Qt::NoButton) {
        const QPointF moved = at - pressAt_;
        dragged_ = dragged_ || std::hypot(moved.x(), moved.y()) > kClickSlack;
        if (dragged_) {
            if (dragPans_) {
                // The pan is kept in mm (pixelsPerMm() is 0 before a slice is shown).
                if (const double perMm = pixelsPerMm(); perMm > 0.0) {
                    const QPointF step = at - lastAt_;
                    pan_ += glm::dvec2(step.x(), step.y()) / perMm;
                    update();
                }
            } else if (dragButton_ == Qt::LeftButton) {
                window_ = slices::dragWindow(pressWindow_, moved.x(), moved.y(), valueSpan_);
                compose();
                update();
                emit windowDragged(window_);
            } else if (dragButton_ == Qt::RightButton) {
                setZoom(pressZoom_ * std::pow(1.01, -moved.y()));
            }
        }
        lastAt_ = at;
    }
    hoverAt(at);
}

void SliceView::mouseReleaseEvent(QMouseEvent* event) {
    if (event->button() == dragButton_) {
        if (!dragged_ && dragButton_ == Qt::LeftButton && !dragPans_) {
            if (const auto world = worldAt(event->position())) {
                emit clickedAt(*world);
            }
        }
        dragButton_ = Qt::NoButton;
    }
    event->accept();
}

void SliceView::mouseDoubleClickEvent(QMouseEvent* event) {
    zoom_ = 1.0;
    pan_ = glm::dvec2(0.0);
    update();
    event->accept();
}

void SliceView::keyPressEvent(QKeyEvent* event) {
    switch (event->key()) {
        case Qt::Key_Up:
        case Qt::Key_PageUp:
            setSliceIndex(index_ + 1);
            break;
        case Qt::Key_Down:
        case Qt::Key_PageDown:
            setSliceIndex(index_ - 1);
            break;
        default:
            QWidget::keyPressEvent(event);
            return;
    }
    event->accept();
}

void SliceView::leaveEvent(QEvent* event) {
    if (!readout_.isEmpty()) {
        readout_.clear();
        update();
    }
    QWidget::leaveEvent(event);
}

}  // namespace vv::gui
