// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QImage>
#include <QWidget>
#include <memory>
#include <optional>

#include "vv/analysis/Sections.h"
#include "vv/scene/Volume.h"
#include "vv/slices/WindowLevel.h"

namespace vv::gui {

class PlanningState;

/// The cross-section perpendicular to the path at the cursor (issue 35): for
/// a scene from a volume the volume resliced in the section's plane (the
/// slice views' window / level), for a mesh a plain background; over it the
/// lumen contour, the minimum and maximum diameter as calipers with their
/// values, and under it the equivalent diameter and the area, all in the UI
/// locale. The plane's axes are the centreline's rotation-minimising frame
/// (analysis::CrossSection::axisU, axisV: right and up), so that stepping
/// along the path does not turn the picture; a 10 mm scale bar says the
/// scale. The wheel and the arrow keys step the cursor along the path.
/// Where no closed contour surrounds the centreline (an end, a junction, a
/// hole) it says so.
class CrossSectionView : public QWidget {
    Q_OBJECT

  public:
    explicit CrossSectionView(PlanningState* state, QWidget* parent = nullptr);

    /// The volume to reslice (nullptr: a mesh scene, the contour alone).
    void setVolume(std::shared_ptr<const scene::Volume> volume);
    void setWindow(const slices::Window& window);
    [[nodiscard]] const slices::Window& window() const noexcept { return window_; }
    [[nodiscard]] const std::shared_ptr<const scene::Volume>& volume() const noexcept {
        return volume_;
    }

    /// The section shown (the profile point nearest the cursor); nullopt
    /// without a path.
    [[nodiscard]] const std::optional<analysis::CrossSection>& section() const noexcept {
        return section_;
    }
    /// The resliced image under it (null for meshes or outside the volume).
    [[nodiscard]] const QImage& image() const noexcept { return image_; }
    /// Its field of view: the square's side, mm.
    [[nodiscard]] double fieldMm() const noexcept { return fieldMm_; }
    /// `volume` resliced in `section`'s plane over a `fieldMm` square centred
    /// on its centreline point (axisU right, axisV up), grey in `window`;
    /// null outside the volume or when it cannot be resampled.
    [[nodiscard]] static QImage resliceImage(const scene::Volume& volume,
                                             const analysis::CrossSection& section, double fieldMm,
                                             const slices::Window& window);
    /// The texts drawn: diameters and area (in the UI locale).
    [[nodiscard]] QStringList texts() const;

    [[nodiscard]] QSize sizeHint() const override { return {220, 260}; }
    [[nodiscard]] QSize minimumSizeHint() const override { return {180, 200}; }

  protected:
    void paintEvent(QPaintEvent* event) override;
    void wheelEvent(QWheelEvent* event) override;
    void keyPressEvent(QKeyEvent* event) override;

  private:
    void follow();
    void reslice();

    PlanningState* state_;
    std::shared_ptr<const scene::Volume> volume_;
    slices::Window window_{300.0, 600.0};  ///< CTA until the slice views say
    std::optional<analysis::CrossSection> section_;
    analysis::FeretCalipers calipers_;
    QImage image_;
    double fieldMm_ = 40.0;
};

}  // namespace vv::gui
