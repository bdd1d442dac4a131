// SPDX-License-Identifier: GPL-3.0-or-later
#include "gui/analysis/CurvedReformation.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QLocale>
#include <QMouseEvent>
#include <QPainter>
#include <QSlider>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>
#include <exception>
#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>
#include <limits>

#include "common/MeasurementSection.h"
#include "common/SliceReport.h"
#include "gui/analysis/PlanningState.h"
#include "vv/slices/CurvedReformation.h"

namespace vv::gui {

CurvedReformation::CurvedReformation(PlanningState* state, QWidget* parent)
    : QWidget(parent),
      state_(state),
      slider_(new QSlider(Qt::Vertical, this)),
      angle_(new QLabel(this)) {
    setObjectName(QStringLiteral("curvedReformation"));
    setMinimumHeight(120);
    setToolTip(
        tr("The volume along the path, straightened (distances true along it); a click "
           "moves the cursor"));
    slider_->setObjectName(QStringLiteral("cprRotation"));
    slider_->setRange(0, 179);
    slider_->setToolTip(tr("Rotation about the path"));
    angle_->setObjectName(QStringLiteral("cprAngle"));
    angle_->setAlignment(Qt::AlignCenter);
    auto* side = new QVBoxLayout;
    side->addWidget(angle_);
    side->addWidget(slider_, 1);
    auto* layout = new QHBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addStretch(1);
    layout->addLayout(side);
    connect(slider_, &QSlider::valueChanged, this, &CurvedReformation::setRotation);
    for (const auto signal : {&PlanningState::analysisChanged, &PlanningState::pathChanged}) {
        connect(state_, signal, this, &CurvedReformation::resample);
    }
    connect(state_, &PlanningState::cursorMoved, this, [this] { update(); });
    connect(state_, &PlanningState::landmarksChanged, this, [this] { update(); });
    setRotation(0);
}

void CurvedReformation::setVolume(std::shared_ptr<const scene::Volume> volume) {
    volume_ = std::move(volume);
    resample();
}

void CurvedReformation::setWindow(const slices::Window& window) {
    window_ = window;
    colour();
    update();
}

void CurvedReformation::setRotation(int degrees) {
    rotation_ = std::clamp(degrees, 0, 179);
    if (slider_->value() != rotation_) {
        slider_->setValue(rotation_);
    }
    angle_->setText(QStringLiteral("%1°").arg(QLocale().toString(rotation_)));
    resample();
}

void CurvedReformation::setHorizontalExtent(double left, double right, double fromMm, double toMm) {
    left_ = left;
    right_ = right;
    fromMm_ = fromMm;
    toMm_ = toMm;
    update();
}

void CurvedReformation::resample() {
    values_ = Image<float>();
    columnsMm_.clear();
    image_ = QImage();
    const auto& profile = state_->profile();
    if (!volume_ || !state_->hasAnalysis() || profile.size() < 2) {
        update();
        return;
    }
    const auto& tree = state_->analysis()->tree;
    // Wide enough for the widest section on the path, and its surroundings.
    double widest = 0.0;
    for (const ProfilePoint& p : profile) {
        widest = std::max(widest, p.measured ? p.maxMm : 0.0);
    }
    const app::ReformationGrid grid = app::reformationGrid(*volume_, widest);
    halfWidthMm_ = grid.halfWidthMm;
    rowSpacingMm_ = grid.rowSpacingMm;
    std::vector<glm::dvec3> points;
    points.reserve(profile.size());
    for (const ProfilePoint& p : profile) {
        points.push_back(planning::sampleAt(tree, p.location).position);
        columnsMm_.push_back(p.pathMm);
    }
    try {
        values_ =
            slices::curvedReformation(*volume_, points, halfWidthMm_, rowSpacingMm_, rotation_);
    } catch (const std::exception&) {
        values_ = Image<float>();  // a path the volume cannot follow: the message instead
        columnsMm_.clear();
    }
    colour();
    update();
}

void CurvedReformation::colour() {
    image_ = values_.empty() ? QImage()
                             : app::sliceImage(values_.view(), {}, window_, slices::OverlayStyle{});
}

QRectF CurvedReformation::plotRect() const {
    const double sliderWidth = slider_->sizeHint().width() + 8.0;
    const double left = left_ >= 0.0 ? left_ : 4.0;
    const double right = right_ > left ? right_ : width() - sliderWidth;
    return {left, 2.0, std::max(1.0, right - left), std::max(1.0, height() - 4.0)};
}

double CurvedReformation::xOf(double pathMm) const {
    const QRectF plot = plotRect();
    const double to = toMm_ > fromMm_ ? toMm_ : state_->path().lengthMm();
    return plot.left() + plot.width() * (pathMm - fromMm_) / std::max(1e-9, to - fromMm_);
}

void CurvedReformation::paintEvent(QPaintEvent* event) {
    Q_UNUSED(event);
    QPainter painter(this);
    const QRectF plot = plotRect();
    painter.fillRect(plot, Qt::black);
    if (image_.isNull()) {
        painter.setPen(Qt::lightGray);
        painter.drawText(plot, Qt::AlignCenter | Qt::TextWordWrap,
                         volume_ ? tr("Find the centrelines to see the curved reformation")
                                 : tr("The curved reformation needs an image series"));
        return;
    }
    // The columns are 0.5 mm apart along the path: drawn to their distances.
    const double x0 = xOf(columnsMm_.front());
    const double x1 = xOf(columnsMm_.back());
    painter.drawImage(QRectF(x0, plot.top(), std::max(1.0, x1 - x0), plot.height()), image_);
    painter.setRenderHint(QPainter::Antialiasing);
    for (const planning::Landmark& l : state_->landmarks()) {
        if (const auto along = state_->pathMmOf(l.location)) {
            painter.setPen(QPen(Qt::white, 1.0, Qt::DashLine));
            painter.drawLine(QPointF(xOf(*along), plot.top()), QPointF(xOf(*along), plot.bottom()));
        }
    }
    painter.setPen(QPen(QColor(255, 60, 60), 1.5));
    const double cursor = xOf(state_->cursorMm());
    painter.drawLine(QPointF(cursor, plot.top()), QPointF(cursor, plot.bottom()));
}

void CurvedReformation::mousePressEvent(QMouseEvent* event) {
    const QRectF plot = plotRect();
    if (event->button() == Qt::LeftButton && plot.contains(event->position()) &&
        state_->path().lengthMm() > 0.0) {
        const double to = toMm_ > fromMm_ ? toMm_ : state_->path().lengthMm();
        state_->setCursorMm(fromMm_ +
                            (event->position().x() - plot.left()) / plot.width() * (to - fromMm_));
        event->accept();
        return;
    }
    QWidget::mousePressEvent(event);
}

void CurvedReformation::resizeEvent(QResizeEvent* event) {
    QWidget::resizeEvent(event);
    update();
}

}  // namespace vv::gui
