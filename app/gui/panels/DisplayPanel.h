// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QWidget>
#include <array>
#include <glm/glm.hpp>

#include "vv/render/ViewAnnotations.h"
#include "vv/render/ViewPresets.h"

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QFormLayout;
class QSlider;
class QLabel;
class QToolButton;

namespace vv::gui {

class ViewerWidget;

namespace panels {

/// The "Display" panel: the comparison cue on the vessels (none, vessel
/// chromadepth / pseudo-chromadepth, fog, Fresnel edge), the vessels'
/// material colour (used when no array colours them), the background,
/// the key light's direction (azimuth, elevation; shared by the vessels, the
/// VSS and translucent objects), camera presets (Far, Medium, Close in the
/// scene's home orientation, and the six anatomical views, named as
/// radiology names them for a scene in the patient frame), the legends, and a performance overlay
/// over the viewer (the last frame's passes with their CPU milliseconds).
class DisplayPanel : public QWidget {
    Q_OBJECT

  public:
    explicit DisplayPanel(ViewerWidget* viewer, QWidget* parent = nullptr);

    [[nodiscard]] QComboBox* vesselCueChooser() const noexcept { return cue_; }
    [[nodiscard]] QComboBox* backgroundChooser() const noexcept { return background_; }
    /// Opens a colour dialog (objectName "vesselColorDialog", window-modal,
    /// not blocking) for the vessels' material colour.
    [[nodiscard]] QToolButton* vesselColorButton() const noexcept { return vesselColor_; }
    [[nodiscard]] QCheckBox* legendsBox() const noexcept { return legends_; }
    /// The light's azimuth (-180..180 degrees, 0 = from the eye, > 0 = from the right).
    [[nodiscard]] QDoubleSpinBox* lightAzimuthBox() const noexcept { return lightAzimuth_; }
    /// The light's elevation (-90..90 degrees, > 0 = from above).
    [[nodiscard]] QDoubleSpinBox* lightElevationBox() const noexcept { return lightElevation_; }
    /// Puts the light back to its default direction.
    [[nodiscard]] QToolButton* lightResetButton() const noexcept { return lightReset_; }
    [[nodiscard]] QCheckBox* performanceBox() const noexcept { return performance_; }
    /// The overlay label over the viewer (hidden unless performanceBox() is checked).
    [[nodiscard]] QLabel* performanceOverlay() const noexcept { return overlay_; }
    // The camera buttons have objectName "viewFar", "viewMedium", "viewClose",
    // "viewAnterior", … (findChild).

  public slots:
    /// Shows the viewer's current settings (without writing them back).
    void syncFromViewer();
    /// Refreshes the performance overlay from the last frame.
    void frameRendered();

  signals:
    void changed();

  public:
    /// The camera preset buttons' names ("Far", translated); the report's
    /// second view is offered under the same names.
    [[nodiscard]] static QString presetLabel(render::ViewPreset preset);
    /// The anatomical buttons' names: radiology's for a scene in the patient
    /// frame ("Left lateral"), the former short ones otherwise.
    [[nodiscard]] static QString anatomicalLabel(render::AnatomicalView view,
                                                 render::SceneFrame frame);

  private:
    // The constructor's steps, top to bottom as the panel shows them (and as
    // the widgets are created: their tab order).
    /// The vessels' depth cue, fog strength, Fresnel exponent.
    void addCueRows(QFormLayout* form);
    /// Background and vessel colour.
    void addColourRows(QFormLayout* form);
    /// The key light's azimuth and elevation, and Reset.
    void addLightRow(QFormLayout* form);
    /// The distance presets and the anatomical views.
    void addCameraButtons(QFormLayout* form);
    /// Legends, the performance overlay's check box and the overlay itself.
    void addOverlayRows(QFormLayout* form);
    void connectControls();
    /// Where the camera looks from and what is up, and for meshes the axes.
    [[nodiscard]] static QString anatomicalToolTip(render::AnatomicalView view,
                                                   render::SceneFrame frame);
    /// Names the anatomical buttons for the viewer's scene's frame (their
    /// tooltips: updateApplicability()).
    void labelCameraButtons();
    void applyCue();
    void applyBackground();
    void chooseVesselColor();
    void applyLight();
    void updateApplicability();

    ViewerWidget* viewer_;
    QComboBox* cue_ = nullptr;
    QSlider* fogStrength_ = nullptr;
    QDoubleSpinBox* fresnelExponent_ = nullptr;
    QComboBox* background_ = nullptr;
    QToolButton* vesselColor_ = nullptr;
    QDoubleSpinBox* lightAzimuth_ = nullptr;
    QDoubleSpinBox* lightElevation_ = nullptr;
    QToolButton* lightReset_ = nullptr;
    QCheckBox* legends_ = nullptr;
    QCheckBox* performance_ = nullptr;
    QLabel* overlay_ = nullptr;
    QWidget* cameraButtons_ = nullptr;
    std::array<QToolButton*, 6> anatomicalButtons_{};  ///< allAnatomicalViews()' order
    bool syncing_ = false;
};

}  // namespace panels
}  // namespace vv::gui
