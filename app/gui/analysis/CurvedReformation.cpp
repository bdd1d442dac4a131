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

#include "gui/analysis/PlanningState.h"
#include "vv/slices/Reslice.h"

namespace vv::gui {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// Any unit vector perpendicular to `t`.
glm::dvec3 perpendicular(const glm::dvec3& t) {
    const glm::dvec3 axis = std::abs(t.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
    return glm::normalize(glm::cross(t, axis));
}

}  // namespace

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
    halfWidthMm_ = std::max(10.0, 1.5 * widest);
    const double spacing =
        std::min(volume_->spacing().x, std::min(volume_->spacing().y, volume_->spacing().z));
    rowSpacingMm_ = std::clamp(spacing, 0.25, 1.0);
    const int rows =
        std::clamp(static_cast<int>(std::lround(2.0 * halfWidthMm_ / rowSpacingMm_)) + 1, 3, 2048);
    values_ = Image<float>(static_cast<int>(profile.size()), rows);
    // A rotation-minimising frame along the path: the previous across
    // direction projected off each new tangent.
    std::vector<glm::dvec3> points;
    points.reserve(profile.size());
    for (const ProfilePoint& p : profile) {
        points.push_back(planning::sampleAt(tree, p.location).position);
    }
    const auto tangentAt = [&points](std::size_t i) {
        const std::size_t a = i == 0 ? 0 : i - 1;
        const std::size_t b = std::min(points.size() - 1, i + 1);
        const glm::dvec3 d = points[b] - points[a];
        return glm::length(d) > 0.0 ? glm::normalize(d) : glm::dvec3(0, 0, 1);
    };
    glm::dvec3 across = perpendicular(tangentAt(0));
    const double angle = rotation_ * glm::pi<double>() / 180.0;
    for (std::size_t i = 0; i < points.size(); ++i) {
        const glm::dvec3 t = tangentAt(i);
        const glm::dvec3 projected = across - glm::dot(across, t) * t;
        across = glm::length(projected) > 1e-9 ? glm::normalize(projected) : perpendicular(t);
        const glm::dvec3 binormal = glm::cross(t, across);
        const glm::dvec3 d = std::cos(angle) * across + std::sin(angle) * binormal;
        slices::SlicePlane column;
        column.width = 1;
        column.height = rows;
        column.pixelSpacing = rowSpacingMm_;
        column.right = t;
        column.down = -d;
        column.origin = points[i] + halfWidthMm_ * d;
        try {
            const Image<float> line = slices::reslice(*volume_, column);
            for (int r = 0; r < rows; ++r) {
                values_(static_cast<int>(i), r) = line(0, r);
            }
        } catch (const std::exception&) {
            for (int r = 0; r < rows; ++r) {
                values_(static_cast<int>(i), r) = static_cast<float>(kNaN);
            }
        }
        columnsMm_.push_back(profile[i].pathMm);
    }
    colour();
    update();
}

void CurvedReformation::colour() {
    if (values_.empty()) {
        image_ = QImage();
        return;
    }
    const Image<std::uint8_t> gray = slices::applyWindow(values_.view(), window_);
    image_ = QImage(gray.width(), gray.height(), QImage::Format_Grayscale8);
    for (int y = 0; y < gray.height(); ++y) {
        std::copy_n(gray.row(y), gray.width(), image_.scanLine(y));
    }
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
