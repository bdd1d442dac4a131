// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QColor>
#include <QPointF>
#include <QString>
#include <QVariant>
#include <QWidget>
#include <glm/glm.hpp>
#include <optional>
#include <string>
#include <string_view>

class QComboBox;
class QDoubleSpinBox;
class QSlider;
class QSpinBox;

namespace vv::scene {
struct Scene;
}

namespace vv::gui::panels {

/// Tells a click (a left press and release within a few pixels) from a drag
/// in a widget's mouse events: for the panels that pick a point on the
/// viewer while its drags still turn the view.
class ClickDetector {
  public:
    /// Feeds `event` (any type); the release's position when it ends a click.
    [[nodiscard]] std::optional<QPointF> clicked(const QEvent* event);

  private:
    bool pressed_ = false;
    QPointF at_;
};

/// A QString of UTF-8 text (the modules' names and labels).
inline QString fromUtf8(std::string_view text) {
    return QString::fromUtf8(text.data(), static_cast<qsizetype>(text.size()));
}

/// A name the modules define in English (colour maps, depth scales, vessel
/// cues: their displayName()), translated for the user (context
/// "vv::gui::panels::EngineNames"); unknown names come back unchanged.
[[nodiscard]] QString engineName(std::string_view name);

/// Enables `widget` and shows `toolTip`, or disables it and shows `whyNot`
/// as its tooltip, so that a control that does not apply says why.
inline void setApplicable(QWidget* widget, bool applicable, const QString& toolTip,
                          const QString& whyNot) {
    widget->setEnabled(applicable);
    widget->setToolTip(applicable ? toolTip : whyNot);
}

/// An sRGB colour with components in [0, 1] as a QColor.
inline QColor toQColor(const glm::vec3& srgb) {
    return QColor::fromRgbF(srgb.r, srgb.g, srgb.b);
}

/// A QColor as sRGB components in [0, 1].
inline glm::vec3 toVec(const QColor& color) {
    return {static_cast<float>(color.redF()), static_cast<float>(color.greenF()),
            static_cast<float>(color.blueF())};
}

/// "wss (Pa)" (scene::quantityTitle()) for a point array with a unit on some
/// mesh of `scene`, else "wss".
[[nodiscard]] QString arrayLabel(const scene::Scene& scene, const std::string& name);

// --- Controls of the settings schema (common/SettingsSchema.h) --------------
// Their ranges, decimals, steps, suffixes and labels come from the setting
// `key` ("vss.p"); a control shows the value times the setting's widget scale
// (percent: 100, tolerance in 1/255: 255).

/// The setting's label, translated ("Power p").
[[nodiscard]] QString settingLabel(std::string_view key);
/// As a form row's label ("Power p:").
[[nodiscard]] QString settingFormLabel(std::string_view key);
/// Range, decimals, step and suffix of a spin box for the setting `key`.
void setUpForSetting(QDoubleSpinBox* box, std::string_view key);
void setUpForSetting(QSpinBox* box, std::string_view key);
/// The range of a slider for the setting `key` (whole steps of the scaled value).
void setUpForSetting(QSlider* slider, std::string_view key);
/// A value of the setting `key` as its control shows it, and back.
[[nodiscard]] double toControl(std::string_view key, double value);
[[nodiscard]] double fromControl(std::string_view key, double shown);

/// Makes `combo` at least as wide as its widest item needs to be read in
/// full (the style's own size hint can fall a few pixels short). Call again
/// after its items change.
void fitToItems(QComboBox* combo);

/// Lets a panel fit the side panel's width without cutting any text: every
/// form row puts its field under its label when side by side they would not
/// fit, combo boxes are as wide as their widest item and spin boxes never
/// narrower than their longest value with its suffix.
void makeNarrow(QWidget* panel);

}  // namespace vv::gui::panels
