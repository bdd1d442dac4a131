// SPDX-License-Identifier: GPL-3.0-or-later
#include "common/SliceReport.h"

#include <QColor>
#include <QCoreApplication>
#include <QFont>
#include <QPainter>
#include <QRectF>
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include "common/SliceTexts.h"
#include "vv/core/Error.h"
#include "vv/slices/OrientationLetters.h"
#include "vv/slices/Reslice.h"
#include "vv/slices/VoxelProbe.h"

namespace vv::app {

/// The translation context of the captions.
class SliceReport {
    Q_DECLARE_TR_FUNCTIONS(vv::app::SliceReport)
};

namespace {

/// What the colours over the slice are.
QString overlaySentence(const std::optional<slices::OverlayStyle>& overlay) {
    if (!overlay || (!overlay->fill && !overlay->outline)) {
        return SliceReport::tr("The segmentation is not drawn.");
    }
    if (overlay->fill && overlay->outline) {
        return SliceReport::tr("Coloured fill and outline: the segmentation.");
    }
    return overlay->fill ? SliceReport::tr("Coloured fill: the segmentation.")
                         : SliceReport::tr("Coloured outline: the segmentation.");
}

}  // namespace

QImage sliceImage(ImageView<const float> values, ImageView<const std::uint8_t> labels,
                  const slices::Window& window, const slices::OverlayStyle& style) {
    const Image<std::uint8_t> gray = slices::applyWindow(values, window);
    const Image<std::uint32_t> rgb = slices::composeSlice(gray.view(), labels, style);
    QImage image(rgb.width(), rgb.height(), QImage::Format_RGB32);
    for (int r = 0; r < rgb.height(); ++r) {
        std::memcpy(image.scanLine(r), rgb.row(r),
                    static_cast<std::size_t>(rgb.width()) * sizeof(std::uint32_t));
    }
    return image;
}

void drawShadowedText(QPainter& painter, const QRectF& rect, int flags, const QString& text) {
    painter.setPen(QColor(0, 0, 0, 200));
    for (const QPointF d : {QPointF(1, 1), QPointF(-1, 1), QPointF(1, -1), QPointF(-1, -1)}) {
        painter.drawText(rect.translated(d), flags, text);
    }
    painter.setPen(QColor(255, 230, 120));
    painter.drawText(rect, flags, text);
}

void drawEdgeLetters(QPainter& painter, const QRectF& area, const slices::SlicePlane& plane) {
    const slices::EdgeLetters letters = slices::edgeLetters(plane);
    drawShadowedText(painter, area, Qt::AlignLeft | Qt::AlignVCenter,
                     QString::fromStdString(letters.left));
    drawShadowedText(painter, area, Qt::AlignRight | Qt::AlignVCenter,
                     QString::fromStdString(letters.right));
    drawShadowedText(painter, area, Qt::AlignHCenter | Qt::AlignTop,
                     QString::fromStdString(letters.top));
    drawShadowedText(painter, area, Qt::AlignHCenter | Qt::AlignBottom,
                     QString::fromStdString(letters.bottom));
}

QImage slicePrintImage(const QImage& slice, const slices::SlicePlane& plane, int width) {
    if (slice.isNull() || width < 1) {
        return {};
    }
    const int height = std::max(1, static_cast<int>(std::lround(static_cast<double>(width) *
                                                                slice.height() / slice.width())));
    QImage out(width, height, QImage::Format_RGB32);
    out.fill(Qt::black);
    QPainter painter(&out);
    painter.drawImage(QRectF(0, 0, width, height), slice);
    QFont font = painter.font();
    font.setPixelSize(std::max(12, width / 40));
    font.setBold(true);
    painter.setFont(font);
    const QRectF area =
        QRectF(out.rect()).adjusted(width / 100.0, width / 100.0, -width / 100.0, -width / 100.0);
    drawEdgeLetters(painter, area, plane);
    return out;
}

QString sliceCaption(const SliceFacts& facts) {
    const QString unit = QString::fromStdString(facts.unit);
    //: %1 plane (Axial), %2 position along its normal (S 12.5 mm), %3 window (W 600 HU  L 300 HU)
    QString caption =
        SliceReport::tr("%1 slice at %2, window %3")
            .arg(orientationName(facts.orientation), slicePositionLabel(facts.axis, facts.position),
                 windowLabel(facts.window, unit));
    if (facts.preset) {
        //: %1 the slice's caption so far, %2 the window preset (CTA)
        caption = SliceReport::tr("%1 (%2 preset)").arg(caption, presetName(*facts.preset));
    }
    return caption + QStringLiteral(". ") + overlaySentence(facts.overlay);
}

PrintedSlice printedSlice(const scene::Volume& volume, const scene::LabelMap* labelMap,
                          slices::SliceOrientation orientation, std::optional<double> position,
                          const std::optional<SliceLook>& look, int width) {
    const slices::SliceStack stack = slices::sliceStack(volume, orientation);
    int index = stack.count / 2;
    if (position) {
        const double lo = std::min(stack.position(0), stack.position(stack.count - 1));
        const double hi = std::max(stack.position(0), stack.position(stack.count - 1));
        const double slack = stack.step / 2.0;
        if (!std::isfinite(*position) || *position < lo - slack || *position > hi + slack) {
            throw InvalidArgumentError("slice position " + std::to_string(*position) +
                                       " mm lies outside the volume (" + std::to_string(lo) +
                                       " to " + std::to_string(hi) + " mm along that axis)");
        }
        index = stack.nearestIndex(*position);
    }
    const slices::SlicePlane plane = stack.planeAt(index);
    const Image<float> values = slices::reslice(volume, plane);
    Image<std::uint8_t> labels;
    if (labelMap != nullptr) {
        labels = slices::resliceLabels(*labelMap, plane);
    }
    SliceLook shown;
    if (look) {
        shown = *look;
    } else {
        const slices::PresetWindow preset = slices::windowPresets(volume).front();
        shown.window = preset.window;
        shown.preset = preset.preset;
    }
    SliceFacts facts;
    facts.orientation = orientation;
    facts.axis = stack.axis;
    facts.position = stack.position(index);
    facts.window = shown.window;
    facts.preset = shown.preset;
    facts.unit = slices::valueUnit(volume);
    if (labelMap != nullptr && (shown.overlay.fill || shown.overlay.outline)) {
        facts.overlay = shown.overlay;
    }
    const QImage image =
        sliceImage(values.view(), facts.overlay ? labels.view() : ImageView<const std::uint8_t>{},
                   facts.window, shown.overlay);
    return {slicePrintImage(image, plane, width), sliceCaption(facts)};
}

std::optional<slices::SliceOrientation> sliceOrientationFromName(std::string_view name) noexcept {
    std::string lower(name);
    std::transform(lower.begin(), lower.end(), lower.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (lower == "axial") {
        return slices::SliceOrientation::Axial;
    }
    if (lower == "coronal") {
        return slices::SliceOrientation::Coronal;
    }
    if (lower == "sagittal") {
        return slices::SliceOrientation::Sagittal;
    }
    return std::nullopt;
}

}  // namespace vv::app
