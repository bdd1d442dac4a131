// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QImage>
#include <QList>
#include <QString>
#include <QWidget>
#include <array>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

#include "common/Session.h"
#include "gui/LatestRun.h"
#include "vv/scene/LabelMap.h"
#include "vv/scene/Volume.h"
#include "vv/slices/SliceOverlay.h"
#include "vv/slices/SlicePlane.h"
#include "vv/slices/WindowLevel.h"

class QAction;
class QActionGroup;
class QGridLayout;
class QMenu;

namespace vv::gui {

class SliceCursor;
class SliceView;
class ViewerWidget;

/// How the window's central area is divided (in app::kSliceLayoutNames' order).
enum class SliceLayout : std::uint8_t {
    ThreeDOnly,       ///< the 3-D view alone
    ThreeDAndSlices,  ///< 3-D, axial / coronal / sagittal in a 2 x 2 grid
    AxialLarge,       ///< one slice view fills the area
    CoronalLarge,
    SagittalLarge,
};

/// The window's central area: the 3-D viewer and, for a scene segmented from
/// a volume (a DICOM image series), the axial, coronal and sagittal
/// SliceViews in the chosen layout. Without a volume only the 3-D viewer is
/// shown and menu() is hidden (mesh scenes show no slice views).
///
/// menu() (View > Slices) chooses the layout, the window preset (the
/// volume's windowPresets(); the first on a new volume) and how the
/// segmentation is drawn (fill, outline). The three views share one window:
/// a drag in one changes all.
class SliceWorkspace : public QWidget {
    Q_OBJECT

  public:
    /// `viewer` (the 3-D view; may be null when OpenGL is unavailable) is
    /// put into this widget.
    explicit SliceWorkspace(ViewerWidget* viewer, QWidget* parent = nullptr);

    /// The volume to slice (null: none, 3-D only) and its segmentation.
    void setVolume(std::shared_ptr<const scene::Volume> volume,
                   const std::shared_ptr<const scene::LabelMap>& labelMap);
    /// A new segmentation of the same volume (the Segmentation panel's
    /// preview or Apply); null removes the overlay.
    void setLabelMap(const std::shared_ptr<const scene::LabelMap>& labelMap);
    [[nodiscard]] const std::shared_ptr<const scene::Volume>& volume() const noexcept {
        return volume_;
    }

    /// The layout chosen in the menu; shown as is when there is a volume,
    /// else the 3-D view alone. Remembered in QSettings (kLayoutKey) and
    /// restored by the next window; View > Reset to Defaults sets the default,
    /// ThreeDAndSlices.
    void setSliceLayout(SliceLayout layout);
    /// The QSettings key of the layout: "3d", "3d+slices", "axial",
    /// "coronal" or "sagittal" (anything else: the default).
    static constexpr const char* kLayoutKey = "slices/layout";
    [[nodiscard]] SliceLayout sliceLayout() const noexcept { return layout_; }
    /// True when slice views are on screen.
    [[nodiscard]] bool showsSlices() const;

    [[nodiscard]] SliceView* sliceView(slices::SliceOrientation orientation) const;
    /// The linked cursor: a click on a slice or on a vessel in the 3-D view
    /// moves the other slices there and marks it in every view; scrolling a
    /// view moves it along with that view's slice (the other views'
    /// crosshairs show the level shown).
    [[nodiscard]] SliceCursor* cursor() const noexcept { return cursor_; }
    /// View > Slices: layouts, window presets, overlay style.
    [[nodiscard]] QMenu* menu() const noexcept { return menu_; }
    /// The window presets of the volume, in menu order.
    [[nodiscard]] const std::vector<slices::PresetWindow>& presets() const noexcept {
        return presets_;
    }
    /// The slice for a report: the large slice view's (else the axial one's)
    /// printImage() and its caption (app::sliceCaption(): plane, position,
    /// window with its preset, what the colours are); nullopt without a volume or before its slice
    /// is shown.
    [[nodiscard]] std::optional<std::pair<QImage, QString>> reportSlice() const;
    void applyPreset(std::size_t index);
    void setWindow(const slices::Window& window);
    [[nodiscard]] const slices::Window& window() const noexcept { return window_; }
    /// The preset checked in the menu while the window is still its window
    /// (nullopt after a drag or without presets).
    [[nodiscard]] std::optional<slices::WindowPreset> chosenPreset() const;

    /// What a session keeps: layout, window and preset, overlay style, each
    /// view's slice position, zoom and pan, the cursor. Nullopt without a
    /// volume (mesh scenes have no slice state).
    [[nodiscard]] std::optional<app::SliceSessionState> sessionState() const;
    /// Shows `state` on the current volume: the layout, the window (its
    /// preset checked when the volume offers it; it stays when the presets
    /// are still being found), the overlay style, the cursor, then each
    /// view's nearest slice to its position, zoom and pan. Without a volume
    /// only the layout applies.
    void applySessionState(const app::SliceSessionState& state);

  signals:
    /// The layout on screen changed.
    void layoutChanged();
    /// The window / level of the slice views changed (the cross-section and
    /// the curved reformation follow it).
    void windowChanged(const vv::slices::Window& window);
    /// A left click without dragging on a slice at `world` (LPS mm): the
    /// cursor moved there; the Segmentation panel takes it as a seed while
    /// it picks one.
    void sliceClicked(const glm::dvec3& world);

  private:
    /// The volume's window presets arrived: the first applies (or the
    /// session's window waiting for them).
    void presetsReady(const std::vector<slices::PresetWindow>& presets);
    /// Shows `window` and checks `preset`'s menu entry (none: no entry).
    void showWindow(const slices::Window& window,
                    const std::optional<slices::WindowPreset>& preset);
    void buildMenu();
    void rebuildPresetMenu();
    void applyLayout();
    void applyOverlayStyle();

    QWidget* viewer_;
    SliceCursor* cursor_ = nullptr;
    std::array<SliceView*, 3> views_{};
    QGridLayout* grid_ = nullptr;
    std::shared_ptr<const scene::Volume> volume_;
    SliceLayout layout_ = SliceLayout::ThreeDAndSlices;
    std::vector<slices::PresetWindow> presets_;
    slices::Window window_;
    /// The presets are being found on a worker (presetsReady() comes).
    bool presetsPending_ = false;
    /// The views are going to the cursor's slices (their changes do not move it).
    bool followingCursor_ = false;
    /// A session's window and preset applied before the presets were found.
    std::optional<std::pair<slices::Window, std::optional<slices::WindowPreset>>> pendingWindow_;
    QMenu* menu_ = nullptr;
    QMenu* presetMenu_ = nullptr;
    QActionGroup* layoutGroup_ = nullptr;
    QActionGroup* presetGroup_ = nullptr;
    QAction* fillAction_ = nullptr;
    QAction* outlineAction_ = nullptr;
    /// The presets of volumes above SliceView::kSynchronousVoxels (a pass
    /// over every voxel) are found on a worker.
    LatestRun<std::vector<slices::PresetWindow>, AtDestruction::Wait> presetRun_{this};
};

}  // namespace vv::gui
