// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QPointF>
#include <QPointer>
#include <QString>
#include <QWidget>
#include <glm/glm.hpp>
#include <memory>
#include <optional>
#include <vector>

#include "gui/EngineTexts.h"
#include "gui/LatestRun.h"
#include "gui/panels/PanelUtil.h"
#include "vv/scene/Mesh.h"
#include "vv/scene/Volume.h"
#include "vv/segmentation/SegmentationPipeline.h"
#include "vv/segmentation/VolumeSegmentation.h"
#include "vv/segmentation/VolumeSurface.h"

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QFormLayout;
class QLabel;
class QProgressBar;
class QPushButton;
class QSpinBox;
class QTimer;
class QVBoxLayout;

namespace vv::segmentation {
struct SegmentationOutcome;
}  // namespace vv::segmentation

namespace vv::gui {

class SegmentationTask;
class ViewerWidget;

namespace panels {

/// The "Segmentation" panel: re-segments the volume a DICOM scene came from,
/// without reading the files again. Disabled (with a tooltip saying why)
/// unless setVolume() gave it a volume.
///
/// Controls: how to show the volume (a surface mesh, or the ray-cast
/// iso-surface at an iso value that follows the lower threshold until it is
/// edited), the threshold range (with the modality's default and a Default
/// button), keep the largest components (how many) or the component under a
/// seed, bone removal, the MR intensity correction (on for MR, unavailable
/// for CT; its gain field is estimated once per volume on a worker, with
/// the default range, which then applies to the corrected values — a range
/// still at the default follows the new default when it is toggled), the
/// surface's triangle target, "Pick seed", live Preview (on by default) and
/// Apply. Under the message a warning (cutOffLabel()) says when a bright
/// tube continues past the segmentation (segmentation::findCutOffVessels):
/// after each preview and Apply, and for the segmentation the scene was
/// loaded with (showCutOff()).
///
/// Preview: 300 ms after the last change, a worker (SegmentationTask)
/// segments every previewStep()-th voxel and extracts a coarse surface;
/// sceneReady() hands it over, marked as a preview. A newer change cancels a
/// running preview. Apply segments at full resolution on a worker with
/// progress and Cancel; a failed or cancelled Apply leaves the scene alone.
/// Seed: with "Pick seed" on, a click on the viewer (press and release
/// without moving) probes it (ViewerWidget::probeAt; the mesh or the ray-cast
/// iso-surface) and pickSeed() takes the point.
class SegmentationPanel : public QWidget {
    Q_OBJECT

  public:
    /// How the volume is shown (displayChooser()'s item data).
    enum class Display { SurfaceMesh = 0, RaycastIsoSurface = 1 };
    /// Which components are kept (modeChooser()'s item data).
    enum class Mode { Largest = 0, Seed = 1 };

    /// The tasks are children: deleting the panel cancels and waits for them.
    explicit SegmentationPanel(ViewerWidget* viewer, QWidget* parent = nullptr);

    /// The volume the shown scene was segmented from with `options` (the
    /// range actually used: `range`) and `surface`; nullptr: the scene did not
    /// come from a volume, and the panel is disabled. Cancels running work and
    /// goes back to the surface mesh display (without emitting sceneReady).
    void setVolume(std::shared_ptr<const scene::Volume> volume,
                   const segmentation::SegmentationOptions& options = {},
                   const segmentation::ThresholdRange& range = {},
                   const segmentation::SurfaceOptions& surface = {});
    [[nodiscard]] const std::shared_ptr<const scene::Volume>& volume() const noexcept {
        return volume_;
    }

    /// The options the controls hold (full-resolution voxel indices).
    [[nodiscard]] segmentation::SegmentationOptions segmentationOptions() const;
    [[nodiscard]] segmentation::SurfaceOptions surfaceOptions() const;

    /// Takes the seed from a world point (mm; e.g. a click's
    /// ProbeResult::worldPosition): the voxel nearest to it within the
    /// threshold range, at most two voxels away (a point on a surface lies
    /// between the inside and the outside). Shows i, j, k and its value and
    /// switches to "component under seed". When no such voxel exists (the
    /// point is outside the volume or in the background) the message says so
    /// and nothing else changes; returns false then.
    bool pickSeed(const glm::vec3& world);
    [[nodiscard]] const std::optional<glm::ivec3>& seed() const noexcept { return seed_; }

    /// Shows (or, when empty, hides) the cut-off warning for `vessels`, found
    /// on a segmentation with the intensity correction on or off (`corrected`:
    /// the advice differs).
    void showCutOff(const std::vector<segmentation::CutOffVessel>& vessels, bool corrected);
    /// True when the scene on screen is this volume's segmentation at full
    /// resolution with the current controls (as loaded, or after Apply): not
    /// a preview, not the ray-cast display, no control changed since.
    [[nodiscard]] bool showsFullResolution() const;
    /// What the controls would segment: every `step`-th voxel, the surface
    /// decimated to at most `maxTriangles` (0: the control's target), the
    /// gain field when the correction is on and it is known. Needs a volume.
    [[nodiscard]] segmentation::SegmentationRequest segmentationRequest(int step,
                                                                        int maxTriangles) const;

    /// Starts a preview of the current controls at once (what the debounce
    /// timer does); nothing when there is no volume, Apply is running, the
    /// volume is ray cast, or the seed mode has no seed yet.
    void startPreview();
    /// Apply: the full-resolution segmentation on a worker.
    void apply();
    /// Stops a running Apply; the scene stays.
    void cancelApply();
    [[nodiscard]] bool isApplying() const;
    /// A preview is waiting for its debounce or running.
    [[nodiscard]] bool isPreviewing() const;
    /// Shows the volume as a surface mesh or as its ray-cast iso-surface.
    void setDisplay(Display display);
    [[nodiscard]] Display display() const noexcept { return display_; }

    /// What the last preview / Apply produced (null before the first).
    [[nodiscard]] const std::shared_ptr<const segmentation::SegmentationOutcome>& lastOutcome()
        const noexcept {
        return lastOutcome_;
    }
    /// True when the last segmentation handed over (sceneReady) is a preview
    /// that was not applied (until Apply or setVolume(); the ray-cast display
    /// keeps it, its mesh returns with the surface display).
    [[nodiscard]] bool showsPreview() const noexcept { return previewShown_; }
    /// Previews shown since construction.
    [[nodiscard]] int previewsShown() const noexcept { return previewsShown_; }

    [[nodiscard]] QComboBox* displayChooser() const noexcept { return displayBox_; }
    [[nodiscard]] QDoubleSpinBox* isoBox() const noexcept { return iso_; }
    [[nodiscard]] QDoubleSpinBox* lowerBox() const noexcept { return lower_; }
    [[nodiscard]] QDoubleSpinBox* upperBox() const noexcept { return upper_; }
    [[nodiscard]] QPushButton* defaultButton() const noexcept { return default_; }
    [[nodiscard]] QLabel* defaultLabel() const noexcept { return defaultLabel_; }
    [[nodiscard]] QComboBox* modeChooser() const noexcept { return mode_; }
    [[nodiscard]] QSpinBox* componentsBox() const noexcept { return components_; }
    [[nodiscard]] QCheckBox* boneRemovalBox() const noexcept { return bone_; }
    [[nodiscard]] QCheckBox* correctionBox() const noexcept { return correction_; }
    /// The gain field of the intensity correction (null: off, or not known yet).
    [[nodiscard]] const std::shared_ptr<const segmentation::GainField>& gainField() const noexcept {
        return gain_;
    }
    [[nodiscard]] QSpinBox* trianglesBox() const noexcept { return triangles_; }
    [[nodiscard]] QPushButton* pickSeedButton() const noexcept { return pickSeed_; }
    [[nodiscard]] QLabel* seedLabel() const noexcept { return seedLabel_; }
    [[nodiscard]] QCheckBox* previewBox() const noexcept { return preview_; }
    [[nodiscard]] QPushButton* applyButton() const noexcept { return apply_; }
    [[nodiscard]] QPushButton* cancelButton() const noexcept { return cancel_; }
    [[nodiscard]] QProgressBar* progressBar() const noexcept { return progress_; }
    /// Results, seed problems and errors.
    [[nodiscard]] QLabel* messageLabel() const noexcept { return message_; }
    /// The cut-off warning (hidden when there is none).
    [[nodiscard]] QLabel* cutOffLabel() const noexcept { return cutOff_; }

  signals:
    /// Show `scene` instead of the current one, keeping the camera; `status`
    /// is for the status bar (a preview says "Preview"). The ray-cast
    /// display hands over an empty scene (the volume is on the viewer).
    void sceneReady(std::shared_ptr<const vv::scene::Scene> scene, const QString& status);
    /// The label map of a preview or Apply (the slice views' overlay);
    /// emitted before its sceneReady().
    void labelMapReady(std::shared_ptr<const vv::scene::LabelMap> labelMap);
    /// A message for the status bar (errors, seed problems, cancelled).
    void statusMessage(const QString& message);
    /// An Apply segmented `request` at full resolution into `outcome`:
    /// emitted before its labelMapReady() and sceneReady().
    void applied(std::shared_ptr<const vv::segmentation::SegmentationOutcome> outcome,
                 const vv::segmentation::SegmentationRequest& request);
    /// An Apply ended (true: its scene was handed over).
    void applyFinished(bool applied);

  protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

  private:
    /// Builds the controls top to bottom (creation order is tab order), each
    /// group with its connections.
    void buildControls();
    /// What is loaded, how the volume is shown, the iso value.
    void addVolumeRows(QFormLayout* top);
    /// The threshold range and its default.
    void addThresholdRows(QFormLayout* form);
    /// Which components are kept: mode, count, seed, bone removal.
    void addComponentRows(QFormLayout* form);
    /// The MR fall-off correction and the surface's triangle budget.
    void addSurfaceRows(QFormLayout* form);
    void addSeedAndPreviewRow(QVBoxLayout* outer);
    /// Apply, its progress and Cancel, the message and the cut-off warning.
    void addApplyRows(QVBoxLayout* outer);
    /// A control changed the options: preview after the debounce delay.
    void optionsChanged();
    void updateApplicability();
    void showMessage(const QString& text);
    /// showMessage(text), the problem's details in the message's tooltip.
    void showProblemMessage(const QString& text, const ProblemText& problem);
    void startDefaultRange();
    /// Sets the threshold boxes to `range` (one preview); `isDefault`: the
    /// range follows the default from now on.
    void setRange(const segmentation::ThresholdRange& range, bool isDefault);
    /// The intensity correction applies to volume_ (not CT) and is ticked.
    [[nodiscard]] bool correcting() const;
    /// A voxel's value as the threshold sees it (corrected when correcting).
    [[nodiscard]] double thresholdedValue(const glm::ivec3& voxel) const;
    [[nodiscard]] QString valueText(double value) const;
    [[nodiscard]] SegmentationTask* makeTask(int step, int maxTriangles);
    void previewDone(const std::shared_ptr<const segmentation::SegmentationOutcome>& outcome);
    void applyDone(const std::shared_ptr<const segmentation::SegmentationOutcome>& outcome);
    void stopPreview();
    /// Cancels `task` without waiting; its result is dropped. Sets it to null.
    void abandon(QPointer<SegmentationTask>& task);
    void pickAt(const QPointF& position);

    ViewerWidget* viewer_;
    std::shared_ptr<const scene::Volume> volume_;
    std::optional<segmentation::ThresholdRange> defaultRange_;
    /// The default range and the correction's gain field of one volume.
    struct Defaults {
        std::optional<segmentation::ThresholdRange> range;
        std::shared_ptr<const segmentation::GainField> gain;
    };
    /// Computes the default range of volume_ (and the gain field, when
    /// correcting) on a worker.
    LatestRun<Defaults, AtDestruction::Wait> defaultRangeRun_{this};
    std::shared_ptr<const segmentation::GainField> gain_;
    bool rangeIsDefault_ = false;  ///< the threshold boxes follow the default
    bool settingRange_ = false;    ///< setRange() is filling the threshold boxes
    std::optional<glm::ivec3> seed_;
    Display display_ = Display::SurfaceMesh;
    /// The mesh scene shown before switching to the ray-cast display.
    std::shared_ptr<const scene::Scene> meshScene_;
    std::shared_ptr<const segmentation::SegmentationOutcome> lastOutcome_;
    QPointer<SegmentationTask> previewTask_;
    QPointer<SegmentationTask> applyTask_;
    QTimer* debounce_ = nullptr;
    bool dirty_ = false;  ///< the controls differ from the shown segmentation
    bool isoFollowsLower_ = true;
    bool filling_ = false;  ///< setVolume() is filling the controls
    int previewsShown_ = 0;
    ClickDetector click_;  ///< clicks on the viewer while picking a seed

    QComboBox* displayBox_ = nullptr;
    QDoubleSpinBox* iso_ = nullptr;
    QWidget* segmentation_ = nullptr;  ///< the segmentation controls (disabled when ray cast)
    QDoubleSpinBox* lower_ = nullptr;
    QDoubleSpinBox* upper_ = nullptr;
    QPushButton* default_ = nullptr;
    QLabel* defaultLabel_ = nullptr;
    QComboBox* mode_ = nullptr;
    QSpinBox* components_ = nullptr;
    QCheckBox* bone_ = nullptr;
    QCheckBox* correction_ = nullptr;
    QSpinBox* triangles_ = nullptr;
    QPushButton* pickSeed_ = nullptr;
    QLabel* seedLabel_ = nullptr;
    QCheckBox* preview_ = nullptr;
    QPushButton* apply_ = nullptr;
    QPushButton* cancel_ = nullptr;
    QProgressBar* progress_ = nullptr;
    QLabel* message_ = nullptr;
    QWidget* cutOffBox_ = nullptr;  ///< the warning's icon and text
    QLabel* cutOff_ = nullptr;
    bool previewShown_ = false;  ///< showsPreview()
    /// What the running (or last) Apply segments.
    std::optional<segmentation::SegmentationRequest> applyRequest_;
    QLabel* volumeLabel_ = nullptr;
};

}  // namespace panels
}  // namespace vv::gui
