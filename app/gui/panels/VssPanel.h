// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QWidget>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QFormLayout;
class QLabel;
class QSlider;
class QSpinBox;

namespace vv::gui {

class ViewerWidget;

namespace panels {

class CollapsibleSection;

/// The "Void Space Surface" panel: on/off, depth colour scale, the IDW power p (logarithmic slider
/// over the setting's range, 0.25-64, and a spin box), iso-lines, lighting, ambient
/// occlusion, the depth range (the visible vessels', or a fixed one in mm that keeps colours across
/// views; choosing "fixed" starts from the range on screen), and, in a folded "Advanced" section
/// (advancedSection()), the solver (fast with tolerance, exact, the paper's
/// every-k-th-contour-pixel step) and the last solve's time and error bound. Every control writes
/// the viewer at once and then emits changed(). Ranges, steps and labels come from the settings
/// schema (common/SettingsSchema.h).
class VssPanel : public QWidget {
    Q_OBJECT

  public:
    /// Slider positions of the logarithmic p slider: 0 = the setting's
    /// minimum, kSliderSteps = its maximum (SettingsSchema.h, "vss.p").
    static constexpr int kSliderSteps = 1000;

    explicit VssPanel(ViewerWidget* viewer, QWidget* parent = nullptr);

    /// p of a slider position, and the nearest position of p (clamped).
    [[nodiscard]] static double powerFromSlider(int position) noexcept;
    [[nodiscard]] static int sliderFromPower(double power) noexcept;

    [[nodiscard]] QCheckBox* enabledBox() const noexcept { return enabled_; }
    [[nodiscard]] QSlider* powerSlider() const noexcept { return powerSlider_; }
    [[nodiscard]] QDoubleSpinBox* powerBox() const noexcept { return powerBox_; }
    [[nodiscard]] QComboBox* solverChooser() const noexcept { return solver_; }
    [[nodiscard]] QComboBox* scaleChooser() const noexcept { return scale_; }
    [[nodiscard]] QLabel* statusLabel() const noexcept { return status_; }
    [[nodiscard]] QComboBox* rangeChooser() const noexcept { return rangeMode_; }
    [[nodiscard]] QDoubleSpinBox* rangeMinBox() const noexcept { return rangeMin_; }
    [[nodiscard]] QDoubleSpinBox* rangeMaxBox() const noexcept { return rangeMax_; }
    /// The folded part with the solver's settings and status ("vssAdvancedSection").
    [[nodiscard]] CollapsibleSection* advancedSection() const noexcept { return advanced_; }

  public slots:
    /// Shows the viewer's current settings (without writing them back).
    void syncFromViewer();
    /// Updates the solve time / error bound read-out from the last frame.
    void updateStatus();

  signals:
    /// The panel changed the viewer's settings.
    void changed();

  private:
    // The constructor's steps, top to bottom as the panel shows them (and as
    // the widgets are created: their tab order).
    /// On / off, the depth colour scale and p.
    void addFirstRows(QFormLayout* form);
    /// Iso-lines, lighting and ambient occlusion.
    void addLookRows(QFormLayout* form);
    /// The depth range: visible vessels or fixed, near / far.
    void addRangeRows(QFormLayout* form);
    /// The folded solver settings and status.
    CollapsibleSection* buildAdvancedSection();
    void connectControls();
    /// The range mode was chosen: fixing starts from the range on screen.
    void rangeModeChosen();

    void apply();
    void updateApplicability();
    void updateBound();

    ViewerWidget* viewer_;
    QCheckBox* enabled_ = nullptr;
    QSlider* powerSlider_ = nullptr;
    QDoubleSpinBox* powerBox_ = nullptr;
    QComboBox* solver_ = nullptr;
    QDoubleSpinBox* tolerance_ = nullptr;
    QSpinBox* step_ = nullptr;
    QComboBox* scale_ = nullptr;
    QSpinBox* isoLines_ = nullptr;
    QSlider* isoStrength_ = nullptr;
    QSlider* lighting_ = nullptr;
    QCheckBox* ao_ = nullptr;
    QDoubleSpinBox* aoRadius_ = nullptr;
    QComboBox* rangeMode_ = nullptr;  ///< visible vessels / fixed
    QDoubleSpinBox* rangeMin_ = nullptr;
    QDoubleSpinBox* rangeMax_ = nullptr;
    QLabel* status_ = nullptr;
    CollapsibleSection* advanced_ = nullptr;
    QString bound_;  ///< the error bound of the current settings, as shown
    bool syncing_ = false;
};

}  // namespace panels
}  // namespace vv::gui
