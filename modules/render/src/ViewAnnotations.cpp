// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/render/ViewAnnotations.h"

#include <QCoreApplication>
#include <QFont>
#include <QFontMetricsF>
#include <QLocale>
#include <QPainter>
#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace vv::render {

namespace {

/// The positive and negative names of world axis `axis` in `frame`.
std::pair<QString, QString> axisNames(int axis, SceneFrame frame) {
    if (frame == SceneFrame::PatientLps) {
        static const std::array<std::pair<const char*, const char*>, 3> patient{
            {{"L", "R"}, {"P", "A"}, {"S", "I"}}};
        return {QString::fromLatin1(patient[static_cast<std::size_t>(axis)].first),
                QString::fromLatin1(patient[static_cast<std::size_t>(axis)].second)};
    }
    const QChar name(QLatin1Char(static_cast<char>('x' + axis)));
    return {QStringLiteral("+") + name, QStringLiteral("-") + name};
}

/// The marker's letter at the positive end of world axis `axis`.
QString axisLetter(int axis, SceneFrame frame) {
    return frame == SceneFrame::PatientLps ? axisNames(axis, frame).first
                                           : QString(QLatin1Char(static_cast<char>('x' + axis)));
}

const QColor kInk(245, 245, 245);
const QColor kBox(0, 0, 0, 150);

/// Text with a dark halo (the text drawn dark around it), readable over
/// any background, centred on `at`.
void haloText(QPainter& painter, const QPointF& at, const QString& text, const QColor& ink) {
    const QFontMetricsF fm(painter.font());
    const QPointF origin(std::round(at.x() - fm.horizontalAdvance(text) / 2.0),
                         std::round(at.y() + (fm.ascent() - fm.descent()) / 2.0));
    painter.setPen(QColor(0, 0, 0, 220));
    for (const QPointF offset : {QPointF(-1, -1), QPointF(0, -1), QPointF(1, -1), QPointF(-1, 0),
                                 QPointF(1, 0), QPointF(-1, 1), QPointF(0, 1), QPointF(1, 1)}) {
        painter.drawText(origin + offset, text);
    }
    painter.setPen(ink);
    painter.drawText(origin, text);
}

/// `p` on a grid of 1/8 pixel.
QPointF snapped(const QPointF& p) {
    return {std::round(p.x() * 8.0) / 8.0, std::round(p.y() * 8.0) / 8.0};
}

/// The font size of the annotations for a view of `area`.
int fontPixels(const QRectF& area) {
    return static_cast<int>(std::clamp(std::lround(area.height() / 48.0), 11L, 40L));
}

/// The marker's disc: its centre, the axes' length and the letters' size.
struct MarkerGeometry {
    double font = 0.0;
    double radius = 0.0;
    double outer = 0.0;  ///< the disc behind the axes
    QPointF centre;
};

MarkerGeometry markerGeometry(const QRectF& area) {
    MarkerGeometry g;
    g.font = fontPixels(area);
    g.radius = g.font * 2.6;
    g.outer = g.radius + g.font * 1.1;
    g.centre = QPointF(area.left() + g.font * 0.8 + g.outer, area.top() + g.font * 0.8 + g.outer);
    return g;
}

/// The tip of world axis `axis` in the marker seen with `camera`.
QPointF axisTip(const MarkerGeometry& g, const Camera& camera, int axis) {
    glm::vec3 e(0.0F);
    e[axis] = 1.0F;
    // On a 1/8-pixel grid: cameras equal up to float noise paint the same pixels.
    return snapped(g.centre + QPointF(glm::dot(e, camera.right()) * g.radius,
                                      -glm::dot(e, camera.up()) * g.radius));
}

void paintMarker(QPainter& painter, const QRectF& area, const Camera& camera, SceneFrame frame) {
    const MarkerGeometry g = markerGeometry(area);
    painter.setPen(Qt::NoPen);
    painter.setBrush(kBox);
    painter.drawEllipse(g.centre, g.outer, g.outer);
    // The axes farthest from the viewer first, so that nearer ones cover them.
    std::array<int, 3> order{0, 1, 2};
    const auto towards = [&](int axis) {
        glm::vec3 e(0.0F);
        e[axis] = 1.0F;
        return glm::dot(e, camera.forward());
    };
    std::sort(order.begin(), order.end(), [&](int a, int b) { return towards(a) > towards(b); });
    static const std::array<QColor, 3> colours{QColor(240, 90, 80), QColor(110, 210, 110),
                                               QColor(110, 160, 255)};
    const std::array<QPointF, 3> letters = markerLetterPositions(camera, area);
    for (const int axis : order) {
        painter.setPen(QPen(colours[static_cast<std::size_t>(axis)], std::max(2.0, g.font / 6.0),
                            Qt::SolidLine, Qt::RoundCap));
        painter.drawLine(g.centre, axisTip(g, camera, axis));
    }
    for (const int axis : order) {
        haloText(painter, letters[static_cast<std::size_t>(axis)], axisLetter(axis, frame),
                 colours[static_cast<std::size_t>(axis)]);
    }
    if (frame != SceneFrame::PatientLps) {
        return;
    }
    // The patient directions at the middle of each edge of the view.
    const EdgeLabels edges = edgeLabels(camera, frame);
    const QFontMetricsF fm(painter.font());
    const double inset = g.font * 0.9;
    haloText(
        painter,
        QPointF(area.left() + inset + fm.horizontalAdvance(edges.left) / 2.0, area.center().y()),
        edges.left, kInk);
    haloText(
        painter,
        QPointF(area.right() - inset - fm.horizontalAdvance(edges.right) / 2.0, area.center().y()),
        edges.right, kInk);
    haloText(painter, QPointF(area.center().x(), area.top() + inset), edges.top, kInk);
    haloText(painter, QPointF(area.center().x(), area.bottom() - inset), edges.bottom, kInk);
}

void paintScaleBar(QPainter& painter, const QRectF& area, const Camera& camera) {
    const std::optional<ScaleBar> bar = scaleBarFor(camera, area.size());
    if (!bar) {
        return;
    }
    const double font = fontPixels(area);
    const QString length = QCoreApplication::translate("vv::render::ViewAnnotations", "%1 mm")
                               .arg(QLocale().toString(bar->millimetres, 'g', 6));
    const QString where =
        QCoreApplication::translate("vv::render::ViewAnnotations", "at the focal plane");
    const QFontMetricsF fm(painter.font());
    const double pad = font * 0.6;
    const double width =
        std::max({bar->pixels, fm.horizontalAdvance(length), fm.horizontalAdvance(where)}) +
        2.0 * pad;
    const double height = pad + font * 2.6 + pad + font * 0.5;
    const QRectF box(area.right() - font * 1.2 - width, area.top() + font * 1.2, width, height);
    painter.setPen(Qt::NoPen);
    painter.setBrush(kBox);
    painter.drawRoundedRect(box, pad, pad);
    // The bar itself on whole pixels: exactly bar->pixels long.
    const double left = std::round(box.right() - pad - bar->pixels);
    const double top = std::round(box.top() + pad + font * 0.2);
    const double thick = std::max(3.0, std::round(font / 4.0));
    painter.save();
    painter.setRenderHint(QPainter::Antialiasing, false);
    painter.fillRect(QRectF(left, top, std::round(bar->pixels), thick), kInk);
    painter.fillRect(QRectF(left, top - thick, thick, 3.0 * thick), kInk);
    painter.fillRect(
        QRectF(left + std::round(bar->pixels) - thick, top - thick, thick, 3.0 * thick), kInk);
    painter.restore();
    painter.setPen(kInk);
    const QRectF text(box.left() + pad, top + 2.0 * thick, box.width() - 2.0 * pad, font * 2.6);
    painter.drawText(text, Qt::AlignRight | Qt::AlignTop, length + QLatin1Char('\n') + where);
}

}  // namespace

QString directionName(const glm::vec3& world, SceneFrame frame) {
    const float length = glm::length(world);
    if (!(length > 0.0F)) {
        return {};
    }
    const glm::vec3 unit = world / length;
    std::array<int, 3> order{0, 1, 2};
    std::sort(order.begin(), order.end(),
              [&](int a, int b) { return std::abs(unit[a]) > std::abs(unit[b]); });
    QStringList parts;
    for (const int axis : order) {
        if (std::abs(unit[axis]) >= kDirectionShare) {
            const auto names = axisNames(axis, frame);
            parts << (unit[axis] > 0.0F ? names.first : names.second);
        }
    }
    return parts.join(frame == SceneFrame::PatientLps ? QString() : QStringLiteral(" "));
}

EdgeLabels edgeLabels(const Camera& camera, SceneFrame frame) {
    return EdgeLabels{directionName(-camera.right(), frame), directionName(camera.right(), frame),
                      directionName(camera.up(), frame), directionName(-camera.up(), frame)};
}

double focalPlanePixelsPerMillimetre(const Camera& camera, double heightPixels) {
    const double halfAngle =
        static_cast<double>(camera.fieldOfView()) * std::numbers::pi / 360.0;  // degrees / 2
    const double visible = 2.0 * static_cast<double>(camera.distance()) * std::tan(halfAngle);
    return heightPixels / visible;
}

std::optional<ScaleBar> scaleBarFor(const Camera& camera, const QSizeF& area) {
    if (area.width() < 1.0 || area.height() < 1.0) {
        return std::nullopt;
    }
    const double perMm = focalPlanePixelsPerMillimetre(camera, area.height());
    const double longest = kScaleBarMaxShare * area.width() / perMm;  // mm
    if (!std::isfinite(longest) || longest <= 0.0) {
        return std::nullopt;
    }
    double decade = std::pow(10.0, std::floor(std::log10(longest)));
    double mm = decade;
    for (const double step : {2.0, 5.0, 10.0}) {
        if (decade * step <= longest) {
            mm = decade * step;
        }
    }
    return ScaleBar{mm, mm * perMm};
}

void paintViewAnnotations(QPainter& painter, const QRectF& area, const Camera& camera,
                          const ViewAnnotations& annotations) {
    if (!annotations.orientationMarker && !annotations.scaleBar) {
        return;
    }
    painter.save();
    painter.setRenderHint(QPainter::Antialiasing);
    painter.setRenderHint(QPainter::TextAntialiasing);
    QFont font = painter.font();
    font.setPixelSize(fontPixels(area));
    font.setBold(true);
    painter.setFont(font);
    if (annotations.orientationMarker) {
        paintMarker(painter, area, camera, annotations.frame);
    }
    if (annotations.scaleBar) {
        paintScaleBar(painter, area, camera);
    }
    painter.restore();
}

std::array<QPointF, 3> markerLetterPositions(const Camera& camera, const QRectF& area) {
    const MarkerGeometry g = markerGeometry(area);
    std::array<QPointF, 3> letters;
    for (int axis = 0; axis < 3; ++axis) {
        const QPointF tip = axisTip(g, camera, axis);
        const QPointF away = tip - g.centre;
        const double length = std::hypot(away.x(), away.y());
        // An axis along the view direction has no length: its letter beside the centre.
        letters[static_cast<std::size_t>(axis)] = length > g.font * 0.8
                                                      ? tip + away / length * (g.font * 0.7)
                                                      : g.centre + QPointF(g.font, g.font) * 0.75;
    }
    // Two axes can project onto one direction (looking along a diagonal of
    // their plane), or both nearly onto the centre: their letters are pushed
    // apart until none covers another.
    const double gap = g.font * kMarkerLetterGap;
    for (int pass = 0; pass < 4; ++pass) {
        for (std::size_t a = 0; a < 3; ++a) {
            for (std::size_t b = a + 1; b < 3; ++b) {
                QPointF apart = letters[b] - letters[a];
                double distance = std::hypot(apart.x(), apart.y());
                if (distance >= gap) {
                    continue;
                }
                if (distance < 1e-6) {
                    // Coincident: apart across the first one's axis.
                    const QPointF along = letters[a] - g.centre;
                    const double l = std::hypot(along.x(), along.y());
                    apart = l > 1e-6 ? QPointF(-along.y(), along.x()) / l : QPointF(1.0, 0.0);
                    distance = 0.0;
                } else {
                    apart /= distance;
                }
                const QPointF push = apart * ((gap - distance) / 2.0);
                letters[a] -= push;
                letters[b] += push;
            }
        }
    }
    for (QPointF& letter : letters) {
        letter = snapped(letter);
    }
    return letters;
}

}  // namespace vv::render
