// SPDX-License-Identifier: GPL-3.0-or-later
#include "gui/analysis/PlanningDocks.h"

#include <QDockWidget>
#include <QHBoxLayout>
#include <QMainWindow>
#include <QPushButton>
#include <QVBoxLayout>
#include <cmath>

#include "gui/EngineTexts.h"
#include "gui/SliceCursor.h"
#include "gui/SliceWorkspace.h"
#include "gui/ViewerWidget.h"
#include "gui/analysis/CrossSectionView.h"
#include "gui/analysis/CurvedReformation.h"
#include "gui/analysis/DiameterProfile.h"
#include "gui/analysis/MeasurementTables.h"
#include "gui/analysis/PlanningOverlay.h"
#include "gui/analysis/PlanningState.h"
#include "gui/panels/AnalysisPanel.h"
#include "vv/core/Error.h"

namespace vv::gui {

PlanningDocks::PlanningDocks(QMainWindow* window, ViewerWidget* viewer, SliceWorkspace* slices,
                             PlanningState* state, panels::AnalysisPanel* panel)
    : QObject(window),
      window_(window),
      state_(state),
      panel_(panel),
      overlay_(new PlanningOverlay(viewer, state)) {
    // Under the views, along the path: the curved reformation (image series
    // only) over the diameter profile, sharing its distances, and the
    // cross-section at the cursor beside them. Not in the window's own dock
    // list: Reset Layout does not show them without an analysis.
    auto* along = new QWidget(window);
    profile_ = new DiameterProfile(state_, along);
    reformation_ = new CurvedReformation(state_, along);
    reformation_->hide();
    crossSection_ = new CrossSectionView(state_, along);
    auto* column = new QVBoxLayout;
    column->addWidget(reformation_, 2);
    column->addWidget(profile_, 3);
    auto* row = new QHBoxLayout(along);
    row->setContentsMargins(2, 2, 2, 2);
    row->addLayout(column, 1);
    row->addWidget(crossSection_);
    profileDock_ = new QDockWidget(tr("Along the Path"), window);
    profileDock_->setObjectName(QStringLiteral("diameterProfileDock"));
    profileDock_->setWidget(along);
    window->addDockWidget(Qt::BottomDockWidgetArea, profileDock_);
    profileDock_->hide();
    measurementsDock_ = new QDockWidget(tr("Measurements"), window);
    measurementsDock_->setObjectName(QStringLiteral("measurementsDock"));
    measurementsDock_->setWidget(panel_->measurementTables());
    panel_->measurementTables()->show();
    // Right of the views along the path.
    window->addDockWidget(Qt::BottomDockWidgetArea, measurementsDock_);
    window->splitDockWidget(profileDock_, measurementsDock_, Qt::Horizontal);
    measurementsDock_->hide();

    connect(profile_, &DiameterProfile::plotExtentChanged, reformation_,
            &CurvedReformation::setHorizontalExtent);
    connect(state_, &PlanningState::analysisChanged, this, [this] {
        const bool first = state_->hasAnalysis() && profileDock_->isHidden();
        showForAnalysis();
        if (first) {
            // The views along the path take most of the width.
            const int width = window_->width();
            window_->resizeDocks({profileDock_, measurementsDock_}, {width * 3 / 5, width * 2 / 5},
                                 Qt::Horizontal);
        }
    });
    connect(profile_, &DiameterProfile::hovered, overlay_, &PlanningOverlay::setHoverMm);
    connect(panel_, &panels::AnalysisPanel::linesColouringChosen, overlay_, [this](int colouring) {
        overlay_->setColouring(static_cast<PlanningOverlay::Colouring>(colouring));
    });
    connect(profile_, &DiameterProfile::placeRequested, panel_->placeButton(), &QPushButton::click);
    linkSlices(slices);
}

void PlanningDocks::linkSlices(SliceWorkspace* slices) {
    connect(slices, &SliceWorkspace::windowChanged, this, [this](const slices::Window& window) {
        reformation_->setWindow(window);
        crossSection_->setWindow(window);
    });
    // The cursor in the slice views follows the path's cursor, and the
    // mouse while it hovers the profile (back to the cursor when it leaves).
    const auto showInSlices = [this, slices](double pathMm) {
        if (state_->hasAnalysis() && slices->volume() != nullptr && !state_->profile().empty()) {
            const double at = std::isfinite(pathMm) ? pathMm : state_->cursorMm();
            slices->cursor()->setPoint(
                planning::sampleAt(state_->analysis()->tree, state_->path().locationAt(at))
                    .position);
        }
    };
    connect(state_, &PlanningState::cursorMoved, this, showInSlices);
    connect(profile_, &DiameterProfile::hovered, this, showInSlices);
    // A click on a slice moves the cursor while "Pick on Vessel" is on.
    connect(slices, &SliceWorkspace::sliceClicked, this, [this](const glm::dvec3& world) {
        if (panel_->pickButton()->isChecked()) {
            state_->moveCursorNear(world);
        }
    });
}

void PlanningDocks::setVolume(const std::shared_ptr<const scene::Volume>& volume) {
    reformation_->setVolume(volume);
    reformation_->setVisible(volume != nullptr);
    crossSection_->setVolume(volume);
}

void PlanningDocks::showForAnalysis() {
    profileDock_->setVisible(state_->hasAnalysis());
    measurementsDock_->setVisible(state_->hasAnalysis());
}

std::optional<PlanningReport> PlanningDocks::plannedReport() {
    if (!state_->hasAnalysis()) {
        return std::nullopt;
    }
    try {
        return planningReport(*state_, *reformation_, *crossSection_);
    } catch (const vv::Error& e) {
        emit statusMessage(describeProblem(e, FileAccess::Writing).line());
        return std::nullopt;
    }
}

}  // namespace vv::gui
