// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QObject>
#include <QString>
#include <memory>
#include <optional>

#include "gui/analysis/PlanningReport.h"
#include "vv/scene/Volume.h"

class QDockWidget;
class QMainWindow;

namespace vv::gui {

class CrossSectionView;
class CurvedReformation;
class DiameterProfile;
class PlanningOverlay;
class PlanningState;
class SliceWorkspace;
class ViewerWidget;

namespace panels {
class AnalysisPanel;
}

/// The planning views of the main window (issue 35), apart from the side
/// panel's Analysis section: under the views the "Along the Path" dock
/// ("diameterProfileDock": the curved reformation over the diameter
/// profile, sharing its distances, and the cross-section at the cursor
/// beside them) and the "Measurements" dock ("measurementsDock", right of
/// it: the panel's measurement tables), both shown while there is an
/// analysis; the planning marks over the 3-D view; and their links: the
/// slice views' window and cursor (following the path's cursor and the
/// mouse over the profile), a click on a slice while Pick on Vessel is on,
/// Insert in the profile, the lines' colouring.
class PlanningDocks : public QObject {
    Q_OBJECT

  public:
    /// Adds the docks to `window` (hidden) and the overlay to `viewer`.
    PlanningDocks(QMainWindow* window, ViewerWidget* viewer, SliceWorkspace* slices,
                  PlanningState* state, panels::AnalysisPanel* panel);

    /// The volume the scene came from (nullptr: a mesh): the reformation
    /// shows only with one.
    void setVolume(const std::shared_ptr<const scene::Volume>& volume);
    /// Shows the docks while there is an analysis (after Reset Layout).
    void showForAnalysis();
    /// The planning work for a report or a PACS (planningReport()); nullopt
    /// without an analysis, or when it cannot be put together (statusMessage()
    /// says why).
    [[nodiscard]] std::optional<PlanningReport> plannedReport();

    [[nodiscard]] DiameterProfile* profile() const noexcept { return profile_; }
    [[nodiscard]] CurvedReformation* reformation() const noexcept { return reformation_; }
    [[nodiscard]] CrossSectionView* crossSection() const noexcept { return crossSection_; }
    [[nodiscard]] PlanningOverlay* overlay() const noexcept { return overlay_; }
    [[nodiscard]] QDockWidget* profileDock() const noexcept { return profileDock_; }
    [[nodiscard]] QDockWidget* measurementsDock() const noexcept { return measurementsDock_; }

  signals:
    /// A one-line message for the status bar.
    void statusMessage(const QString& message);

  private:
    void linkSlices(SliceWorkspace* slices);

    QMainWindow* window_;
    PlanningState* state_;
    panels::AnalysisPanel* panel_;
    DiameterProfile* profile_ = nullptr;
    CurvedReformation* reformation_ = nullptr;
    CrossSectionView* crossSection_ = nullptr;
    PlanningOverlay* overlay_ = nullptr;
    QDockWidget* profileDock_ = nullptr;
    QDockWidget* measurementsDock_ = nullptr;
};

}  // namespace vv::gui
