// SPDX-License-Identifier: GPL-3.0-or-later
#include "common/SliceTexts.h"

#include <QCoreApplication>
#include <QLocale>
#include <cmath>

#include "vv/slices/OrientationLetters.h"

namespace vv::app {

namespace {

QString withUnit(const QString& number, const QString& unit) {
    return unit.isEmpty() ? number : number + QChar(0x00A0) + unit;
}

QString valueNumber(double v) {
    if (std::abs(v - std::round(v)) < 1e-6 && std::abs(v) < 1e9) {
        return QLocale().toString(static_cast<qlonglong>(std::llround(v)));
    }
    return QLocale().toString(v, 'g', 4);
}

}  // namespace

QString orientationName(slices::SliceOrientation orientation) {
    switch (orientation) {
        case slices::SliceOrientation::Coronal:
            return QCoreApplication::translate("vv::gui::SliceTexts", "Coronal");
        case slices::SliceOrientation::Sagittal:
            return QCoreApplication::translate("vv::gui::SliceTexts", "Sagittal");
        case slices::SliceOrientation::Axial:
            break;
    }
    return QCoreApplication::translate("vv::gui::SliceTexts", "Axial");
}

QString presetName(slices::WindowPreset preset) {
    switch (preset) {
        case slices::WindowPreset::Cta:
            return QCoreApplication::translate("vv::gui::SliceTexts", "CTA");
        case slices::WindowPreset::Mra:
            return QCoreApplication::translate("vv::gui::SliceTexts", "MRA");
        case slices::WindowPreset::SoftTissue:
            return QCoreApplication::translate("vv::gui::SliceTexts", "Soft tissue");
        case slices::WindowPreset::Bone:
            return QCoreApplication::translate("vv::gui::SliceTexts", "Bone");
        case slices::WindowPreset::FullRange:
            break;
    }
    return QCoreApplication::translate("vv::gui::SliceTexts", "Full range");
}

QString millimetres(double mm) {
    return withUnit(QLocale().toString(mm, 'f', 1),
                    QCoreApplication::translate("vv::gui::SliceTexts", "mm"));
}

QString slicePositionLabel(int axis, double mm) {
    const slices::PositionText p = slices::slicePositionText(axis, mm);
    return QString(QLatin1Char(p.letter)) + QLatin1Char(' ') + millimetres(p.distance);
}

QString worldPointLabel(const glm::dvec3& world) {
    QStringList parts;
    for (int a = 0; a < 3; ++a) {
        const slices::PositionText p = slices::slicePositionText(a, world[a]);
        parts << QString(QLatin1Char(p.letter)) + QLatin1Char(' ') +
                     QLocale().toString(p.distance, 'f', 1);
    }
    return withUnit(parts.join(QStringLiteral("  ")),
                    QCoreApplication::translate("vv::gui::SliceTexts", "mm"));
}

QString voxelValueLabel(const slices::VoxelSample& sample) {
    return withUnit(valueNumber(sample.value), QString::fromStdString(sample.unit));
}

QString windowLabel(const slices::Window& window, const QString& unit) {
    //: W and L: the width and level (centre) of the grey-value window
    return QCoreApplication::translate("vv::gui::SliceTexts", "W %1  L %2")
        .arg(withUnit(valueNumber(window.width), unit), withUnit(valueNumber(window.center), unit));
}

}  // namespace vv::app
