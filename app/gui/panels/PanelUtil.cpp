// SPDX-License-Identifier: GPL-3.0-or-later
#include "gui/panels/PanelUtil.h"

#include <QAbstractSpinBox>
#include <QComboBox>
#include <QCoreApplication>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QMouseEvent>
#include <QSlider>
#include <QSpinBox>
#include <QStyle>
#include <QStyleOptionComboBox>
#include <QtGlobal>
#include <algorithm>
#include <cmath>

#include "common/SettingsSchema.h"
#include "vv/scene/Mesh.h"
#include "vv/scene/QuantityTitle.h"

namespace vv::gui::panels {

namespace {

// The modules' display names, for lupdate (translated by engineName()).
[[maybe_unused]] const char* const kEngineNames[] = {
    // colormaps::displayName(ColorMap)
    QT_TRANSLATE_NOOP("vv::gui::panels::EngineNames", "Viridis"),
    QT_TRANSLATE_NOOP("vv::gui::panels::EngineNames", "Cividis"),
    QT_TRANSLATE_NOOP("vv::gui::panels::EngineNames", "Inferno"),
    QT_TRANSLATE_NOOP("vv::gui::panels::EngineNames", "Blue-white-red (diverging)"),
    // colormaps::displayName(DepthScale)
    QT_TRANSLATE_NOOP("vv::gui::panels::EngineNames", "Chromadepth"),
    QT_TRANSLATE_NOOP("vv::gui::panels::EngineNames", "Pseudo-chromadepth"),
    QT_TRANSLATE_NOOP("vv::gui::panels::EngineNames", "Dark means deep"),
    // render::displayName(VesselCue)
    QT_TRANSLATE_NOOP("vv::gui::panels::EngineNames", "None"),
    QT_TRANSLATE_NOOP("vv::gui::panels::EngineNames", "Vessel chromadepth"),
    QT_TRANSLATE_NOOP("vv::gui::panels::EngineNames", "Vessel pseudo-chromadepth"),
    QT_TRANSLATE_NOOP("vv::gui::panels::EngineNames", "Depth fog"),
    QT_TRANSLATE_NOOP("vv::gui::panels::EngineNames", "Fresnel-edge pseudo-chromadepth"),
};

}  // namespace

QString engineName(std::string_view name) {
    const QByteArray utf8(name.data(), static_cast<qsizetype>(name.size()));
    return QCoreApplication::translate("vv::gui::panels::EngineNames", utf8.constData());
}

QString settingLabel(std::string_view key) {
    return QCoreApplication::translate(app::kSettingsContext, app::setting(key).label);
}

QString settingFormLabel(std::string_view key) {
    return settingLabel(key) + QLatin1Char(':');
}

void setUpForSetting(QDoubleSpinBox* box, std::string_view key) {
    const app::Setting& s = app::setting(key);
    box->setDecimals(s.widget.decimals);
    box->setRange(s.min * s.widget.scale, s.max * s.widget.scale);
    box->setSingleStep(s.widget.step);
    box->setSuffix(fromUtf8(s.widget.suffix));
}

void setUpForSetting(QSpinBox* box, std::string_view key) {
    const app::Setting& s = app::setting(key);
    box->setRange(static_cast<int>(std::lround(s.min * s.widget.scale)),
                  static_cast<int>(std::lround(s.max * s.widget.scale)));
    box->setSingleStep(static_cast<int>(std::lround(s.widget.step)));
    box->setSuffix(fromUtf8(s.widget.suffix));
}

void setUpForSetting(QSlider* slider, std::string_view key) {
    const app::Setting& s = app::setting(key);
    slider->setRange(static_cast<int>(std::lround(s.min * s.widget.scale)),
                     static_cast<int>(std::lround(s.max * s.widget.scale)));
}

double toControl(std::string_view key, double value) {
    return value * app::setting(key).widget.scale;
}

double fromControl(std::string_view key, double shown) {
    return shown / app::setting(key).widget.scale;
}

QString arrayLabel(const scene::Scene& scene, const std::string& name) {
    for (const auto& mesh : scene.meshes) {
        const scene::DataArray* array = mesh.pointArray(name);
        if (array != nullptr && !array->unit.empty()) {
            return QString::fromStdString(scene::quantityTitle(name, array->unit));
        }
    }
    return QString::fromStdString(name);
}

void fitToItems(QComboBox* combo) {
    // The room the style leaves for the text at the hinted width, less the
    // pixel each side it draws the text in from the field's edges.
    combo->setMinimumWidth(0);
    const int hinted = combo->sizeHint().width();
    QStyleOptionComboBox option;
    option.initFrom(combo);
    option.rect = QRect(0, 0, hinted, combo->sizeHint().height());
    const int field =
        combo->style()
            ->subControlRect(QStyle::CC_ComboBox, &option, QStyle::SC_ComboBoxEditField, combo)
            .width() -
        2;
    int widest = 0;
    for (int i = 0; i < combo->count(); ++i) {
        int width = combo->fontMetrics().horizontalAdvance(combo->itemText(i));
        if (!combo->itemIcon(i).isNull()) {
            width += combo->iconSize().width() + 4;
        }
        widest = std::max(widest, width);
    }
    combo->setMinimumWidth(hinted + std::max(0, widest - field));
}

void makeNarrow(QWidget* panel) {
    // Never narrower than their size hint (the widest item; the longest
    // value with its suffix), also when items or ranges change later.
    for (auto* combo : panel->findChildren<QComboBox*>()) {
        combo->setSizeAdjustPolicy(QComboBox::AdjustToContents);
        combo->setSizePolicy(QSizePolicy::Minimum, combo->sizePolicy().verticalPolicy());
        fitToItems(combo);
    }
    for (auto* spin : panel->findChildren<QAbstractSpinBox*>()) {
        spin->setSizePolicy(QSizePolicy::Minimum, spin->sizePolicy().verticalPolicy());
    }
    for (auto* form : panel->findChildren<QFormLayout*>()) {
        form->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
        form->setRowWrapPolicy(QFormLayout::WrapLongRows);
    }
}

std::optional<QPointF> ClickDetector::clicked(const QEvent* event) {
    /// A press and release closer than this (px) is a click, not a drag.
    constexpr int kClickSlop = 4;
    const auto* mouse = dynamic_cast<const QMouseEvent*>(event);
    if (mouse == nullptr) {
        return std::nullopt;
    }
    if (event->type() == QEvent::MouseButtonPress) {
        pressed_ = mouse->button() == Qt::LeftButton;
        at_ = mouse->position();
    } else if (event->type() == QEvent::MouseButtonRelease && pressed_) {
        pressed_ = false;
        if (mouse->button() == Qt::LeftButton &&
            (mouse->position() - at_).manhattanLength() < kClickSlop) {
            return mouse->position();
        }
    }
    return std::nullopt;
}

}  // namespace vv::gui::panels
