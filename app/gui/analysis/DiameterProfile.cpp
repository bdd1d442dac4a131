// SPDX-License-Identifier: GPL-3.0-or-later
#include "gui/analysis/DiameterProfile.h"

#include <QChart>
#include <QGraphicsSimpleTextItem>
#include <QKeyEvent>
#include <QLegendMarker>
#include <QLineSeries>
#include <QLocale>
#include <QMouseEvent>
#include <QPen>
#include <QScatterSeries>
#include <QValueAxis>
#include <algorithm>
#include <cmath>
#include <limits>

#include "common/MeasurementSection.h"
#include "gui/analysis/PlanningState.h"
#include "gui/panels/PanelUtil.h"
#include "vv/colormaps/LabelPalette.h"
#include "vv/report/PdfReport.h"

namespace vv::gui {

namespace {

/// A press this close (px) to a landmark's line grabs it.
constexpr double kGrabPixels = 6.0;

// The diameters' colours (told apart with any colour vision), the report's too.
const QColor kEquivalent = panels::toQColor(colormaps::diameterColors().equivalent);
const QColor kArea(120, 120, 120);
const QColor kLandmark(60, 60, 60);
const QColor kCursor(204, 0, 0);

/// 1, 2 or 5 times a power of ten, at least `rough`.
double niceStep(double rough) {
    if (!(rough > 0.0) || !std::isfinite(rough)) {
        return 1.0;
    }
    const double power = std::pow(10.0, std::floor(std::log10(rough)));
    for (const double m : {1.0, 2.0, 5.0}) {
        if (m * power >= rough) {
            return m * power;
        }
    }
    return 10.0 * power;
}

QLineSeries* verticalLine(QChart* chart, const QColor& colour, Qt::PenStyle style, double width,
                          QValueAxis* x, QValueAxis* y) {
    auto* line = new QLineSeries(chart);
    line->setPen(QPen(colour, width, style));
    chart->addSeries(line);
    line->attachAxis(x);
    line->attachAxis(y);
    for (QLegendMarker* marker : chart->legend()->markers(line)) {
        marker->setVisible(false);
    }
    return line;
}

}  // namespace

DiameterProfile::DiameterProfile(PlanningState* state, QWidget* parent)
    : QChartView(new QChart, parent), state_(state) {
    setObjectName(QStringLiteral("diameterProfile"));
    setRenderHint(QPainter::Antialiasing);
    setFocusPolicy(Qt::StrongFocus);
    setMouseTracking(true);
    setMinimumHeight(260);
    chart()->setLocalizeNumbers(true);
    chart()->legend()->setAlignment(Qt::AlignTop);
    // Smaller than the widgets' text: legend and title must fit a narrow dock.
    QFont small = font();
    small.setPointSizeF(small.pointSizeF() * 0.85);
    chart()->legend()->setFont(small);
    chart()->setTitleFont(small);
    chart()->setMargins(QMargins(4, 4, 4, 4));
    connect(state_, &PlanningState::analysisChanged, this, &DiameterProfile::rebuild);
    connect(state_, &PlanningState::pathChanged, this, &DiameterProfile::rebuild);
    connect(state_, &PlanningState::stenosesChanged, this, &DiameterProfile::rebuild);
    connect(state_, &PlanningState::cursorMoved, this, &DiameterProfile::showCursor);
    connect(state_, &PlanningState::landmarksChanged, this, &DiameterProfile::showMarkers);
    connect(state_, &PlanningState::landmarkSelected, this, &DiameterProfile::showMarkers);
    connect(chart(), &QChart::plotAreaChanged, this, &DiameterProfile::placeLabels);
    rebuild();
}

double DiameterProfile::diameterTop() const {
    double top = 1.0;
    for (const ProfilePoint& p : state_->profile()) {
        if (p.measured) {
            top = std::max(top, p.maxMm);
        }
    }
    return top * 1.1;
}

void DiameterProfile::rebuild() {
    QChart* c = chart();
    c->removeAllSeries();
    for (QAbstractAxis* axis : c->axes()) {
        c->removeAxis(axis);
        delete axis;
    }
    cursor_ = nullptr;
    markerLines_.clear();
    markerLandmarks_.clear();
    qDeleteAll(labels_);
    labels_.clear();
    stenoses_ = nullptr;
    qDeleteAll(stenosisLabels_);
    stenosisLabels_.clear();
    const auto& profile = state_->profile();
    if (profile.empty()) {
        c->setTitle(tr("Find the centrelines to see the diameter profile"));
        return;
    }
    c->setTitle(tr("Diameters along the path: %1 \u2192 %2")
                    .arg(state_->endName(state_->pathFrom()), state_->endName(state_->pathTo())));
    along_ = new QValueAxis(c);
    along_->setTitleText(tr("Distance along the path (mm)"));
    along_->setRange(0.0, std::max(1.0, state_->path().lengthMm()));
    along_->setLabelFormat(QStringLiteral("%.0f"));
    diameter_ = new QValueAxis(c);
    diameter_->setTitleText(tr("\u00d8 (mm)"));  // short: the plot is low
    diameter_->setRange(0.0, diameterTop());
    diameter_->setLabelFormat(QStringLiteral("%.0f"));
    area_ = new QValueAxis(c);
    area_->setTitleText(tr("Area (mm²)"));
    area_->setLabelFormat(QStringLiteral("%.0f"));
    double areaTop = 1.0;
    for (const ProfilePoint& p : profile) {
        if (p.measured) {
            areaTop = std::max(areaTop, p.areaMm2);
        }
    }
    area_->setRange(0.0, areaTop * 1.1);
    // Ticks at round values from 0, the range kept: the distance axis ends
    // where the path does (the reformation above lines up with it).
    for (QValueAxis* axis : {along_, diameter_, area_}) {
        axis->setTickType(QValueAxis::TicksDynamic);
        axis->setTickAnchor(0.0);
        axis->setTickInterval(niceStep(axis->max() / 5.0));
    }
    c->addAxis(along_, Qt::AlignBottom);
    c->addAxis(diameter_, Qt::AlignLeft);
    c->addAxis(area_, Qt::AlignRight);
    struct Quantity {
        QString name;
        QColor colour;
        Qt::PenStyle style;
        double width;
        double ProfilePoint::*value;
        QValueAxis* axis;
    };
    const std::array quantities{
        Quantity{tr("Area"), kArea, Qt::DotLine, 1.5, &ProfilePoint::areaMm2, area_},
        Quantity{tr("Minimum"), panels::toQColor(colormaps::diameterColors().minimum), Qt::DashLine,
                 1.5, &ProfilePoint::minMm, diameter_},
        Quantity{tr("Maximum"), panels::toQColor(colormaps::diameterColors().maximum), Qt::DashLine,
                 1.5, &ProfilePoint::maxMm, diameter_},
        Quantity{tr("Equivalent"), kEquivalent, Qt::SolidLine, 2.5, &ProfilePoint::equivalentMm,
                 diameter_},
    };
    for (const Quantity& q : quantities) {
        QLineSeries* run = nullptr;
        bool first = true;
        for (const ProfilePoint& p : profile) {
            if (!p.measured) {
                run = nullptr;  // a gap: the next measured point starts a new run
                continue;
            }
            if (run == nullptr) {
                run = new QLineSeries(c);
                run->setName(q.name);
                run->setPen(QPen(q.colour, q.width, q.style));
                c->addSeries(run);
                run->attachAxis(along_);
                run->attachAxis(q.axis);
                if (!first) {
                    for (QLegendMarker* marker : c->legend()->markers(run)) {
                        marker->setVisible(false);
                    }
                }
                first = false;
            }
            run->append(p.pathMm, p.*q.value);
        }
    }
    stenoses_ = new QScatterSeries(c);
    stenoses_->setName(tr("Stenosis"));
    stenoses_->setColor(kCursor);
    stenoses_->setMarkerSize(9.0);
    stenoses_->setMarkerShape(QScatterSeries::MarkerShapeRectangle);
    c->addSeries(stenoses_);
    stenoses_->attachAxis(along_);
    stenoses_->attachAxis(diameter_);
    for (const PathStenosis& s : state_->pathStenoses()) {
        if (s.diameterPercent < app::kMarkedStenosisPercent) {
            continue;  // within the sections' scatter: not marked (the tables list it)
        }
        const auto& points = state_->profile();
        const auto nearest = std::min_element(
            points.begin(), points.end(), [&s](const ProfilePoint& a, const ProfilePoint& b) {
                return std::abs(a.pathMm - s.pathMm) < std::abs(b.pathMm - s.pathMm);
            });
        const double y = nearest->measured ? nearest->equivalentMm : 0.0;
        stenoses_->append(s.pathMm, y);
        report::MeasurementCell cell{s.diameterPercent, 0, "%", {}};
        auto* label = new QGraphicsSimpleTextItem(
            QString::fromStdString(report::measurementCellText(cell)), c);
        label->setBrush(kCursor);
        label->setData(0, s.pathMm);
        label->setData(1, y);
        stenosisLabels_ << label;
    }
    if (stenoses_->count() == 0) {
        for (QLegendMarker* marker : c->legend()->markers(stenoses_)) {
            marker->setVisible(false);
        }
    }
    cursor_ = verticalLine(c, kCursor, Qt::SolidLine, 1.5, along_, diameter_);
    showMarkers();
    showCursor();
}

void DiameterProfile::showCursor() {
    if (cursor_ == nullptr) {
        return;
    }
    const double x = state_->cursorMm();
    cursor_->replace(QList<QPointF>{{x, 0.0}, {x, diameter_->max()}});
}

void DiameterProfile::showMarkers() {
    if (cursor_ == nullptr) {
        return;
    }
    for (QLineSeries* line : markerLines_) {
        chart()->removeSeries(line);
        delete line;
    }
    markerLines_.clear();
    markerLandmarks_.clear();
    qDeleteAll(labels_);
    labels_.clear();
    const auto& landmarks = state_->landmarks();
    for (std::size_t i = 0; i < landmarks.size(); ++i) {
        const auto along = state_->pathMmOf(landmarks[i].location);
        if (!along) {
            continue;
        }
        const bool selected = static_cast<int>(i) == state_->selectedLandmark();
        QLineSeries* line =
            verticalLine(chart(), kLandmark, Qt::DashLine, selected ? 3.0 : 1.5, along_, diameter_);
        line->append(*along, 0.0);
        line->append(*along, diameter_->max());
        markerLines_ << line;
        markerLandmarks_ << static_cast<int>(i);
        auto* label =
            new QGraphicsSimpleTextItem(PlanningState::landmarkLabel(landmarks[i]), chart());
        QFont font = label->font();
        font.setBold(selected);
        label->setFont(font);
        label->setBrush(kLandmark);
        label->setData(0, *along);
        labels_ << label;
    }
    placeLabels();
}

void DiameterProfile::placeLabels() {
    if (cursor_ == nullptr) {
        return;
    }
    const QRectF plot = chart()->plotArea();
    emit plotExtentChanged(mapFromScene(chart()->mapToScene(plot.topLeft())).x(),
                           mapFromScene(chart()->mapToScene(plot.topRight())).x(), along_->min(),
                           along_->max());
    // Landmark names stand at the top of the plot, stacked where they would overlap.
    QList<QRectF> placed;
    for (QGraphicsSimpleTextItem* label : labels_) {
        const QPointF at = chart()->mapToPosition(QPointF(label->data(0).toDouble(), 0.0), cursor_);
        QRectF box(QPointF(at.x() + 3.0, plot.top() + 2.0), label->boundingRect().size());
        if (box.right() > plot.right()) {
            box.moveRight(at.x() - 3.0);
        }
        if (box.left() < plot.left()) {
            box.moveLeft(plot.left());  // never out of the plot, even over its line
        }
        for (bool moved = true; moved;) {
            moved = false;
            for (const QRectF& other : placed) {
                if (other.intersects(box)) {
                    box.moveTop(other.bottom() + 1.0);
                    moved = true;
                }
            }
        }
        label->setPos(box.topLeft());
        placed << box;
    }
    for (QGraphicsSimpleTextItem* label : stenosisLabels_) {
        const QPointF at = chart()->mapToPosition(
            QPointF(label->data(0).toDouble(), label->data(1).toDouble()), cursor_);
        label->setPos(at + QPointF(6.0, 4.0));
    }
}

std::optional<double> DiameterProfile::pathMmAt(double x) const {
    if (cursor_ == nullptr) {
        return std::nullopt;
    }
    const QRectF plot = chart()->plotArea();
    const QPointF inChart = chart()->mapFromScene(mapToScene(QPoint(static_cast<int>(x), 0)));
    if (inChart.x() < plot.left() - kGrabPixels || inChart.x() > plot.right() + kGrabPixels) {
        return std::nullopt;
    }
    const double s = chart()->mapToValue(QPointF(inChart.x(), plot.center().y()), cursor_).x();
    return std::clamp(s, 0.0, state_->path().lengthMm());
}

double DiameterProfile::xOf(double pathMm) const {
    if (cursor_ == nullptr) {
        return std::numeric_limits<double>::quiet_NaN();
    }
    const QPointF inChart = chart()->mapToPosition(QPointF(pathMm, 0.0), cursor_);
    return mapFromScene(chart()->mapToScene(inChart)).x();
}

QList<QLineSeries*> DiameterProfile::seriesNamed(const QString& name) const {
    QList<QLineSeries*> found;
    for (QAbstractSeries* s : chart()->series()) {
        if (auto* line = qobject_cast<QLineSeries*>(s);
            line != nullptr && line->name() == name &&
            s->type() == QAbstractSeries::SeriesTypeLine) {
            found << line;
        }
    }
    return found;
}

int DiameterProfile::landmarkNear(double x) const {
    int best = -1;
    double bestDistance = kGrabPixels;
    for (qsizetype i = 0; i < markerLines_.size(); ++i) {
        const double d = std::abs(xOf(markerLines_[i]->at(0).x()) - x);
        if (d <= bestDistance) {
            bestDistance = d;
            best = markerLandmarks_[i];
        }
    }
    return best;
}

void DiameterProfile::mousePressEvent(QMouseEvent* event) {
    if (event->button() != Qt::LeftButton || cursor_ == nullptr) {
        QChartView::mousePressEvent(event);
        return;
    }
    setFocus(Qt::MouseFocusReason);
    const int grabbed = landmarkNear(event->position().x());
    if (grabbed >= 0) {
        dragging_ = grabbed;
        state_->selectLandmark(grabbed);
    } else if (const auto s = pathMmAt(event->position().x())) {
        state_->setCursorMm(*s);
    }
    event->accept();
}

void DiameterProfile::mouseMoveEvent(QMouseEvent* event) {
    const auto s = pathMmAt(event->position().x());
    emit hovered(s ? *s : std::numeric_limits<double>::quiet_NaN());
    if (dragging_ >= 0 && s) {
        state_->moveLandmark(dragging_, *s);
    } else if ((event->buttons() & Qt::LeftButton) != 0 && s) {
        state_->setCursorMm(*s);
    }
    if (cursor_ != nullptr) {
        setCursor(dragging_ >= 0 || landmarkNear(event->position().x()) >= 0 ? Qt::SizeHorCursor
                                                                             : Qt::CrossCursor);
    }
    event->accept();
}

void DiameterProfile::mouseReleaseEvent(QMouseEvent* event) {
    dragging_ = -1;
    event->accept();
}

void DiameterProfile::leaveEvent(QEvent* event) {
    emit hovered(std::numeric_limits<double>::quiet_NaN());
    QChartView::leaveEvent(event);
}

void DiameterProfile::keyPressEvent(QKeyEvent* event) {
    const bool shift = (event->modifiers() & Qt::ShiftModifier) != 0;
    const bool control = (event->modifiers() & Qt::ControlModifier) != 0;
    const int step = shift ? 10 : 1;
    switch (event->key()) {
        case Qt::Key_Left:
        case Qt::Key_Right: {
            const int signedStep = event->key() == Qt::Key_Left ? -step : step;
            if (control) {
                state_->stepSelectedLandmark(signedStep);
            } else {
                state_->stepCursor(signedStep);
            }
            break;
        }
        case Qt::Key_Home:
            state_->setCursorMm(0.0);
            break;
        case Qt::Key_End:
            state_->setCursorMm(state_->path().lengthMm());
            break;
        case Qt::Key_Insert:
            emit placeRequested();
            break;
        case Qt::Key_Delete:
            state_->removeLandmark(state_->selectedLandmark());
            break;
        default:
            QChartView::keyPressEvent(event);
            return;
    }
    event->accept();
}

void DiameterProfile::resizeEvent(QResizeEvent* event) {
    QChartView::resizeEvent(event);
    placeLabels();
}

}  // namespace vv::gui
