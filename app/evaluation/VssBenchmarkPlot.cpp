// SPDX-License-Identifier: GPL-3.0-or-later
// The plot of `vesselview-cli bench`: max error against median time, one
// colour per solver series, one marker per view (VssBenchmark.h).
#include <QColor>
#include <QFile>
#include <QFont>
#include <QGuiApplication>
#include <QPainter>
#include <QPainterPath>
#include <QPen>
#include <QPolygonF>
#include <QString>
#include <QStringList>
#include <algorithm>
#include <array>
#include <cmath>
#include <set>
#include <string>
#include <vector>

#include "evaluation/VssBenchmark.h"
#include "vv/core/AtomicFile.h"
#include "vv/core/Error.h"

namespace vv::evaluation {

namespace {

const std::array<QColor, 8> kPalette{
    QColor(31, 119, 180),  QColor(255, 127, 14), QColor(44, 160, 44),   QColor(214, 39, 40),
    QColor(148, 103, 189), QColor(140, 86, 75),  QColor(227, 119, 194), QColor(127, 127, 127)};

QColor seriesColor(const std::string& series, std::size_t index) {
    if (series == "reference") {
        return QColor(20, 20, 20);
    }
    if (series == "brute") {
        return kPalette[0];
    }
    if (series == "step 3") {
        return kPalette[1];
    }
    if (series == "step 5") {
        return kPalette[3];
    }
    if (series == "fast") {
        return kPalette[2];
    }
    return kPalette[4 + index % 4];
}

void drawMarker(QPainter& painter, render::ViewPreset view, const QPointF& c, double r) {
    switch (view) {
        case render::ViewPreset::Far:
            painter.drawEllipse(c, r, r);
            return;
        case render::ViewPreset::Medium:
            painter.drawRect(QRectF(c.x() - r, c.y() - r, 2 * r, 2 * r));
            return;
        case render::ViewPreset::Close: {
            QPolygonF triangle;
            triangle << QPointF(c.x(), c.y() - 1.2 * r) << QPointF(c.x() + 1.1 * r, c.y() + 0.8 * r)
                     << QPointF(c.x() - 1.1 * r, c.y() + 0.8 * r);
            painter.drawPolygon(triangle);
            return;
        }
    }
    QPolygonF diamond;
    diamond << QPointF(c.x(), c.y() - r) << QPointF(c.x() + r, c.y()) << QPointF(c.x(), c.y() + r)
            << QPointF(c.x() - r, c.y());
    painter.drawPolygon(diamond);
}

QString sizesLabel(const std::vector<BenchSize>& sizes) {
    QStringList parts;
    for (const BenchSize& size : sizes) {
        parts << QStringLiteral("%1×%2").arg(size.width).arg(size.height);
    }
    return parts.join(QStringLiteral(", "));
}

QString decadeLabel(int exponent) {
    if (exponent >= 0 && exponent <= 4) {
        return QString::number(std::pow(10.0, exponent), 'f', 0);
    }
    if (exponent >= -3 && exponent < 0) {
        return QString::number(std::pow(10.0, exponent), 'f', -exponent);
    }
    return QStringLiteral("1e%1").arg(exponent);
}

}  // namespace

QImage plotErrorVsTime(const VssBenchmarkResult& result, int width, int height) {
    if (width < 320 || height < 240 || width > 8192 || height > 8192) {
        throw InvalidArgumentError("plot: the size must be within 320x240..8192x8192");
    }
    if (qobject_cast<QGuiApplication*>(QCoreApplication::instance()) == nullptr) {
        throw Error("plot: drawing text needs a QGuiApplication");
    }
    constexpr double kTargetMs = 16.0;
    constexpr double kVisible = 1.0 / 255.0;

    // Ranges, in decades.
    double tLo = kTargetMs;
    double tHi = kTargetMs;
    double eLo = kVisible;
    double eHi = kVisible;
    bool anyZero = false;
    bool anyInf = false;
    for (const VssBenchmarkRow& r : result.rows) {
        if (!r.failure.empty() || !(r.medianMs > 0.0)) {
            continue;
        }
        tLo = std::min(tLo, r.medianMs);
        tHi = std::max(tHi, r.medianMs);
        if (r.error.maxAbs == 0.0) {
            anyZero = true;
        } else if (std::isinf(r.error.maxAbs)) {
            anyInf = true;
        } else if (r.error.maxAbs > 0.0) {
            eLo = std::min(eLo, r.error.maxAbs);
            eHi = std::max(eHi, r.error.maxAbs);
        }
    }
    const int xd0 = static_cast<int>(std::floor(std::log10(tLo)));
    const int xd1 = std::max(xd0 + 1, static_cast<int>(std::ceil(std::log10(tHi))));
    // One extra decade at the bottom holds the exact (zero error) points.
    const int yd0 = static_cast<int>(std::floor(std::log10(eLo))) - (anyZero ? 1 : 0);
    const int yd1 = std::max(yd0 + 1, static_cast<int>(std::ceil(std::log10(eHi))));

    QImage image(width, height, QImage::Format_RGB32);
    image.fill(Qt::white);
    QPainter painter(&image);
    painter.setRenderHint(QPainter::Antialiasing, true);
    painter.setRenderHint(QPainter::TextAntialiasing, true);
    const double scale = std::min(width / 1400.0, height / 900.0);
    const auto px = [&](double v) { return std::max(1, static_cast<int>(std::lround(v * scale))); };
    QFont font(QStringLiteral("DejaVu Sans"));
    font.setPixelSize(px(15));
    QFont small = font;
    small.setPixelSize(px(13));
    QFont title = font;
    title.setPixelSize(px(19));
    title.setBold(true);

    const QRectF plot(px(100), px(70), width - px(100) - px(330), height - px(70) - px(90));
    const auto mapX = [&](double ms) {
        const double t = (std::log10(ms) - xd0) / (xd1 - xd0);
        return plot.left() + t * plot.width();
    };
    const auto mapY = [&](double error) {
        double e = 0.0;
        if (error == 0.0) {
            e = yd0;
        } else if (std::isinf(error)) {
            e = yd1;
        } else {
            e = std::log10(error);
        }
        const double t = (e - yd0) / (yd1 - yd0);
        return plot.bottom() - t * plot.height();
    };

    // Grid and ticks.
    painter.setFont(small);
    for (int d = xd0; d <= xd1; ++d) {
        const double x = mapX(std::pow(10.0, d));
        painter.setPen(QPen(QColor(200, 200, 200), 1.0));
        painter.drawLine(QPointF(x, plot.top()), QPointF(x, plot.bottom()));
        painter.setPen(Qt::black);
        painter.drawText(QRectF(x - px(50), plot.bottom() + px(6), px(100), px(20)),
                         Qt::AlignHCenter | Qt::AlignTop, decadeLabel(d));
        if (d < xd1) {
            painter.setPen(QPen(QColor(235, 235, 235), 1.0));
            for (int m = 2; m <= 9; ++m) {
                const double xm = mapX(m * std::pow(10.0, d));
                painter.drawLine(QPointF(xm, plot.top()), QPointF(xm, plot.bottom()));
            }
        }
    }
    for (int d = yd0; d <= yd1; ++d) {
        const double y = mapY(std::pow(10.0, d));
        painter.setPen(QPen(QColor(200, 200, 200), 1.0));
        painter.drawLine(QPointF(plot.left(), y), QPointF(plot.right(), y));
        painter.setPen(Qt::black);
        const QString label = (anyZero && d == yd0) ? QStringLiteral("0") : decadeLabel(d);
        painter.drawText(QRectF(plot.left() - px(95), y - px(10), px(88), px(20)),
                         Qt::AlignRight | Qt::AlignVCenter, label);
        if (d < yd1 && !(anyZero && d == yd0)) {
            painter.setPen(QPen(QColor(235, 235, 235), 1.0));
            for (int m = 2; m <= 9; ++m) {
                const double ym = mapY(m * std::pow(10.0, d));
                painter.drawLine(QPointF(plot.left(), ym), QPointF(plot.right(), ym));
            }
        }
    }
    if (anyZero) {
        // The bottom decade is a break: exact results sit on its lower line.
        painter.setPen(QPen(QColor(120, 120, 120), 1.0, Qt::DotLine));
        const double y = mapY(std::pow(10.0, yd0 + 1));
        painter.drawLine(QPointF(plot.left(), y), QPointF(plot.right(), y));
    }

    // The 1/255 line and the 16 ms target.
    painter.setPen(QPen(QColor(200, 30, 30), 1.5, Qt::DashLine));
    const double yVisible = mapY(kVisible);
    painter.drawLine(QPointF(plot.left(), yVisible), QPointF(plot.right(), yVisible));
    painter.drawText(QRectF(plot.left() + px(6), yVisible - px(20), px(400), px(18)),
                     Qt::AlignLeft | Qt::AlignBottom, QStringLiteral("1/255: one 8-bit step"));
    // The tolerances the fast settings promise, as thin dotted lines.
    std::set<double> tolerances;
    for (const VssBenchmarkRow& r : result.rows) {
        if (r.failure.empty() && r.options.kind == vss::SolverKind::Fast &&
            std::isfinite(r.errorBound) && r.errorBound > 0.0) {
            tolerances.insert(r.errorBound);
        }
    }
    for (const double t : tolerances) {
        const double y = mapY(t);
        if (y < plot.top() || y > plot.bottom()) {
            continue;
        }
        painter.setPen(QPen(seriesColor("fast", 0), 1.0, Qt::DotLine));
        painter.drawLine(QPointF(plot.left(), y), QPointF(plot.right(), y));
        painter.drawText(QRectF(plot.right() - px(306), y - px(18), px(300), px(16)),
                         Qt::AlignRight | Qt::AlignBottom,
                         QStringLiteral("fast tolerance %1/255").arg(t * 255.0, 0, 'g', 3));
    }
    painter.setPen(QPen(QColor(30, 120, 30), 1.5, Qt::DashLine));
    const double xTarget = mapX(kTargetMs);
    painter.drawLine(QPointF(xTarget, plot.top()), QPointF(xTarget, plot.bottom()));
    painter.save();
    painter.translate(xTarget - px(4), plot.top() + px(6));
    painter.rotate(90.0);
    painter.drawText(QRectF(0, -px(2), px(300), px(18)), Qt::AlignLeft | Qt::AlignBottom,
                     QStringLiteral("16 ms target"));
    painter.restore();

    painter.setPen(QPen(Qt::black, 1.2));
    painter.setBrush(Qt::NoBrush);
    painter.drawRect(plot);

    // Points.
    std::vector<std::string> series;
    for (const VssBenchmarkRow& r : result.rows) {
        if (std::find(series.begin(), series.end(), r.series) == series.end()) {
            series.push_back(r.series);
        }
    }
    const auto colorOf = [&](const std::string& s) {
        const auto it = std::find(series.begin(), series.end(), s);
        return seriesColor(s, static_cast<std::size_t>(it - series.begin()));
    };
    painter.setClipRect(plot.adjusted(-px(8), -px(8), px(8), px(8)));
    for (const VssBenchmarkRow& r : result.rows) {
        if (!r.failure.empty() || !(r.medianMs > 0.0) || std::isnan(r.error.maxAbs)) {
            continue;
        }
        // the first size filled, larger sizes hollow and larger
        const auto sizeIndex = static_cast<int>(
            std::find(result.sizes.begin(), result.sizes.end(), r.size) - result.sizes.begin());
        QColor fill = colorOf(r.series);
        fill.setAlpha(190);
        painter.setPen(QPen(colorOf(r.series).darker(140), sizeIndex > 0 ? 2.0 : 1.0));
        if (sizeIndex > 0) {
            painter.setBrush(Qt::NoBrush);
        } else {
            painter.setBrush(fill);
        }
        drawMarker(painter, r.view, QPointF(mapX(r.medianMs), mapY(r.error.maxAbs)),
                   px(6 + 2 * sizeIndex));
    }
    painter.setClipping(false);

    // Axis titles and title.
    painter.setPen(Qt::black);
    painter.setFont(font);
    painter.drawText(QRectF(plot.left(), plot.bottom() + px(32), plot.width(), px(24)),
                     Qt::AlignHCenter | Qt::AlignTop,
                     QStringLiteral("median wall time per frame [ms], log scale (whole VSS "
                                    "solve, %1 threads)")
                         .arg(result.threads));
    painter.save();
    painter.translate(px(22), plot.center().y());
    painter.rotate(-90.0);
    painter.drawText(QRectF(-plot.height() / 2, -px(12), plot.height(), px(24)), Qt::AlignCenter,
                     QStringLiteral("max abs error [normalised depth], log scale"));
    painter.restore();
    painter.setFont(title);
    painter.drawText(QRectF(plot.left(), px(18), width - plot.left() - px(10), px(30)),
                     Qt::AlignLeft | Qt::AlignVCenter,
                     QStringLiteral("VSS solvers: error against run time — %1, %2")
                         .arg(sizesLabel(result.sizes))
                         .arg(QString::fromStdString(result.sceneName)));

    // Legend.
    double ly = plot.top();
    const double lx = plot.right() + px(24);
    painter.setFont(font);
    painter.drawText(QPointF(lx, ly + px(14)), QStringLiteral("solver"));
    ly += px(28);
    painter.setFont(small);
    for (const std::string& s : series) {
        painter.setPen(QPen(colorOf(s).darker(140), 1.0));
        painter.setBrush(colorOf(s));
        painter.drawRect(QRectF(lx, ly - px(10), px(22), px(12)));
        painter.setPen(Qt::black);
        painter.drawText(QPointF(lx + px(32), ly), QString::fromStdString(s));
        ly += px(22);
    }
    ly += px(14);
    painter.setFont(font);
    painter.drawText(QPointF(lx, ly + px(14)), QStringLiteral("view (marker)"));
    ly += px(28);
    painter.setFont(small);
    std::vector<render::ViewPreset> views;
    for (const VssBenchmarkRow& r : result.rows) {
        if (std::find(views.begin(), views.end(), r.view) == views.end()) {
            views.push_back(r.view);
        }
    }
    for (const render::ViewPreset v : views) {
        painter.setPen(QPen(Qt::black, 1.0));
        painter.setBrush(QColor(160, 160, 160));
        drawMarker(painter, v, QPointF(lx + px(11), ly - px(4)), px(6));
        painter.drawText(QPointF(lx + px(32), ly),
                         QString::fromStdString(std::string(render::toString(v))));
        ly += px(22);
    }
    ly += px(14);
    painter.setPen(QColor(60, 60, 60));
    QStringList notes{QStringLiteral("one point per view × p × setting"),
                      QStringLiteral("(p and fast tolerances: see the CSV)")};
    if (result.sizes.size() > 1) {
        notes
            << QStringLiteral("filled: %1; hollow, larger:").arg(sizesLabel({result.sizes.front()}))
            << QStringLiteral("  the larger sizes, in order");
    }
    if (anyZero) {
        notes << QStringLiteral("bottom line: error exactly 0");
    }
    if (anyInf) {
        notes << QStringLiteral("top line: non-finite output");
    }
    for (const QString& note : notes) {
        painter.drawText(QPointF(lx, ly), note);
        ly += px(20);
    }
    painter.end();
    return image;
}

void writePlot(const std::filesystem::path& file, const VssBenchmarkResult& result, int width,
               int height) {
    QImage image = plotErrorVsTime(result, width, height);
    image.setText(QStringLiteral("License"),
                  QStringLiteral("SPDX-License-Identifier: GPL-3.0-or-later"));
    image.setText(QStringLiteral("Software"), QStringLiteral("VesselView (vesselview-cli bench)"));
    writeAtomically(file, [&](const std::filesystem::path& temporary) {
        if (!image.save(QFile::decodeName(temporary.c_str()), "PNG")) {
            throw IoError(file, "cannot write the PNG image");
        }
    });
}

}  // namespace vv::evaluation
