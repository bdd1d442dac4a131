// SPDX-License-Identifier: GPL-3.0-or-later
#include "gui/analysis/CrossSectionView.h"

#include <QKeyEvent>
#include <QPainter>
#include <QPainterPath>
#include <QWheelEvent>
#include <algorithm>
#include <cmath>
#include <exception>

#include "common/MeasurementSection.h"
#include "common/SliceReport.h"
#include "gui/analysis/PlanningState.h"
#include "gui/panels/PanelUtil.h"
#include "vv/colormaps/LabelPalette.h"
#include "vv/report/PdfReport.h"
#include "vv/slices/CurvedReformation.h"
#include "vv/slices/Reslice.h"

namespace vv::gui {

namespace {

/// Pixels of the resliced square (its side).
constexpr int kPixels = 160;

const QColor kContour(255, 214, 0);

QString millimetres(double mm) {
    return QString::fromStdString(report::measurementCellText({mm, 1, "mm", {}}));
}

}  // namespace

CrossSectionView::CrossSectionView(PlanningState* state, QWidget* parent)
    : QWidget(parent), state_(state) {
    setObjectName(QStringLiteral("crossSectionView"));
    setFocusPolicy(Qt::StrongFocus);
    setToolTip(
        tr("The section perpendicular to the path at the cursor; the wheel or the "
           "arrow keys move along the path"));
    for (const auto signal : {&PlanningState::analysisChanged, &PlanningState::pathChanged}) {
        connect(state_, signal, this, &CrossSectionView::follow);
    }
    connect(state_, &PlanningState::cursorMoved, this, &CrossSectionView::follow);
    follow();
}

void CrossSectionView::setVolume(std::shared_ptr<const scene::Volume> volume) {
    volume_ = std::move(volume);
    reslice();
    update();
}

void CrossSectionView::setWindow(const slices::Window& window) {
    window_ = window;
    reslice();
    update();
}

void CrossSectionView::follow() {
    section_.reset();
    const auto point = state_->cursorPoint();
    if (point && state_->hasAnalysis()) {
        const auto& a = *state_->analysis();
        const auto& branch = a.tree.branches[static_cast<std::size_t>(point->location.branch)];
        // The profile point's own section (its abscissa is a centreline point's).
        std::size_t index = 0;
        for (std::size_t i = 0; i < branch.points.size(); ++i) {
            if (std::abs(branch.points[i].abscissaMm - point->location.abscissaMm) <
                std::abs(branch.points[index].abscissaMm - point->location.abscissaMm)) {
                index = i;
            }
        }
        section_ = a.sections[static_cast<std::size_t>(point->location.branch)][index];
        calipers_ = analysis::feretCalipers(section_->contour);
        const double size = section_->status == analysis::CrossSection::Status::Ok
                                ? section_->maxDiameterMm
                                : section_->inscribedDiameterMm;
        fieldMm_ = app::sectionFieldMm(size);
    }
    reslice();
    update();
}

QImage CrossSectionView::resliceImage(const scene::Volume& volume,
                                      const analysis::CrossSection& section, double fieldMm,
                                      const slices::Window& window) {
    try {
        const Image<float> values = slices::reslice(
            volume,
            slices::sectionPlane(section.centre, section.axisU, section.axisV, fieldMm, kPixels));
        return app::sliceImage(values.view(), {}, window, slices::OverlayStyle{});
    } catch (const std::exception&) {
        return {};  // outside or unusable: the contour alone
    }
}

void CrossSectionView::reslice() {
    image_ = QImage();
    if (volume_ && section_) {
        image_ = resliceImage(*volume_, *section_, fieldMm_, window_);
    }
}

QStringList CrossSectionView::texts() const {
    if (!section_) {
        return {};
    }
    if (section_->status != analysis::CrossSection::Status::Ok) {
        return {tr("No closed lumen contour here")};
    }
    QStringList lines{
        tr("Minimum %1, maximum %2")
            .arg(millimetres(section_->minDiameterMm), millimetres(section_->maxDiameterMm)),
        tr("Equivalent %1, area %2")
            .arg(millimetres(section_->equivalentDiameterMm),
                 QString::fromStdString(
                     report::measurementCellText({section_->areaMm2, 0, "mm²", {}})))};
    if (section_->inEndZone) {
        lines << tr("At an end or a junction: not a vessel size");
    }
    return lines;
}

void CrossSectionView::paintEvent(QPaintEvent* event) {
    Q_UNUSED(event);
    QPainter painter(this);
    painter.fillRect(rect(), Qt::black);
    painter.setRenderHint(QPainter::Antialiasing);
    const QFontMetrics metrics(font());
    if (!section_) {
        painter.setPen(Qt::lightGray);
        painter.drawText(rect(), Qt::AlignCenter | Qt::TextWordWrap,
                         tr("Find the centrelines to see the cross-section"));
        return;
    }
    const QStringList lines = texts();
    // The sizes under the square, wrapped to the width (German is long).
    const QRect textBox(2, 0, std::max(10, width() - 4), height());
    int textHeight = metrics.lineSpacing() + 6;
    for (const QString& line : lines) {
        textHeight +=
            metrics.boundingRect(textBox, Qt::AlignCenter | Qt::TextWordWrap, line).height();
    }
    const int side = std::max(10, std::min(width(), height() - textHeight));
    const QRectF square((width() - side) / 2.0, metrics.lineSpacing() + 4.0, side, side);
    if (!image_.isNull()) {
        painter.drawImage(square, image_);
    }
    const double scale = side / fieldMm_;  // px per mm
    const QPointF centre = square.center();
    const auto toWidget = [&](const glm::dvec2& uv) {
        return QPointF(centre.x() + uv.x * scale, centre.y() - uv.y * scale);
    };
    painter.setPen(Qt::white);
    painter.drawText(QRectF(0, 0, width(), metrics.lineSpacing() + 2), Qt::AlignCenter,
                     tr("%1 along the path").arg(millimetres(state_->cursorMm())));
    if (section_->status == analysis::CrossSection::Status::Ok && section_->contour.size() >= 3) {
        QPainterPath contour;
        contour.moveTo(toWidget(section_->contour.front()));
        for (const glm::dvec2& p : section_->contour) {
            contour.lineTo(toWidget(p));
        }
        contour.closeSubpath();
        painter.setPen(QPen(kContour, 2.0));
        painter.drawPath(contour);
        for (const auto& [segment, colour] :
             {std::pair{calipers_.maxSegment,
                        panels::toQColor(colormaps::diameterColors().maximum)},
              std::pair{calipers_.minSegment,
                        panels::toQColor(colormaps::diameterColors().minimum)}}) {
            painter.setPen(QPen(Qt::black, 4.0, Qt::SolidLine, Qt::RoundCap));
            painter.drawLine(toWidget(segment[0]), toWidget(segment[1]));
            painter.setPen(QPen(colour, 2.0, Qt::SolidLine, Qt::RoundCap));
            painter.drawLine(toWidget(segment[0]), toWidget(segment[1]));
        }
    }
    // The centreline point.
    painter.setPen(QPen(Qt::red, 1.5));
    painter.drawLine(centre + QPointF(-5, 0), centre + QPointF(5, 0));
    painter.drawLine(centre + QPointF(0, -5), centre + QPointF(0, 5));
    // A 10 mm scale bar, bottom left of the square.
    const double bar = 10.0 * scale;
    const QPointF barStart = square.bottomLeft() + QPointF(8.0, -10.0);
    painter.setPen(QPen(Qt::white, 2.0));
    painter.drawLine(barStart, barStart + QPointF(bar, 0.0));
    painter.drawText(barStart + QPointF(0.0, -4.0),
                     QString::fromStdString(report::measurementCellText({10.0, 0, "mm", {}})));
    // The sizes under the square, each in its caliper's colour.
    int y = static_cast<int>(square.bottom()) + 4;
    for (qsizetype i = 0; i < lines.size(); ++i) {
        painter.setPen(i == 0 ? QColor(255, 200, 150) : Qt::white);
        const QRect box =
            metrics.boundingRect(textBox, Qt::AlignHCenter | Qt::TextWordWrap, lines[i]);
        painter.drawText(QRect(textBox.left(), y, textBox.width(), box.height()),
                         Qt::AlignHCenter | Qt::TextWordWrap, lines[i]);
        y += box.height();
    }
}

void CrossSectionView::wheelEvent(QWheelEvent* event) {
    const int steps = event->angleDelta().y() / 120;
    if (steps != 0) {
        state_->stepCursor(-steps);
    }
    event->accept();
}

void CrossSectionView::keyPressEvent(QKeyEvent* event) {
    const int step = (event->modifiers() & Qt::ShiftModifier) != 0 ? 10 : 1;
    switch (event->key()) {
        case Qt::Key_Left:
        case Qt::Key_Down:
            state_->stepCursor(-step);
            break;
        case Qt::Key_Right:
        case Qt::Key_Up:
            state_->stepCursor(step);
            break;
        default:
            QWidget::keyPressEvent(event);
            return;
    }
    event->accept();
}

}  // namespace vv::gui
