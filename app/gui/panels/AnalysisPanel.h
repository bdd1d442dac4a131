// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QPointF>
#include <QPointer>
#include <QString>
#include <QWidget>
#include <filesystem>
#include <glm/vec3.hpp>
#include <optional>

#include "common/Session.h"
#include "gui/EngineTexts.h"
#include "gui/panels/PanelUtil.h"

class QComboBox;
class QLabel;
class QLineEdit;
class QProgressBar;
class QPushButton;
class QTableWidget;

namespace vv::gui {

class AnalysisTask;
class MeasurementTables;
class PlanningState;
class ViewerWidget;

namespace panels {

/// The "Analysis" panel (issue 35): the planning workflow on the shown
/// vessel surface.
///
/// - "Find centrelines" analyses the scene's first surface on a worker
///   (AnalysisTask) with progress and Cancel; a new scene cancels it and
///   clears the analysis. The GUI thread never waits for it. Its ends are
///   found automatically (open ends, closed tips) or picked: "Pick Ends",
///   then a click on the vessel for the start and one for each end.
/// - The branch table: each branch's name (editable: the name goes into
///   measurement files and reports), length, narrowest and widest
///   equivalent diameter; the stenosis table: each graded branch's diameter
///   and area percent, where along the path, the reference in its tooltip.
///   Numbers in the UI locale, the units in the headers (the panel is narrow).
/// - The path: from one end to another (PlanningState::choosePath); the
///   cursor's place on it and its section's sizes.
/// - Landmarks: a preset of aortic planning or a free name, placed at the
///   cursor; the list (select one to move it with "Move to cursor" or
///   Ctrl+Left / Ctrl+Right in the diameter profile); Remove.
/// - The measurements as the report prints them (app::measurementSection):
///   the landmarks' sections, the lengths between them, the aortic sizing
///   table, the branches; a blank value with why (measurementTables(): the
///   window shows it in a dock of its own, wider than the side panel).
/// - "Save measurements…" (a measurement file `vesselview-cli report
///   --measurements` reads) and "Export sections…" (CSV of the sections
///   along the path).
/// - "Pick on vessel": a click on the vessel (press and release without
///   moving) moves the cursor to the path place nearest it.
class AnalysisPanel : public QWidget {
    Q_OBJECT

  public:
    /// The task is a child: deleting the panel cancels and waits for it.
    AnalysisPanel(ViewerWidget* viewer, PlanningState* state, QWidget* parent = nullptr);
    ~AnalysisPanel() override;
    AnalysisPanel(const AnalysisPanel&) = delete;
    AnalysisPanel& operator=(const AnalysisPanel&) = delete;
    AnalysisPanel(AnalysisPanel&&) = delete;
    AnalysisPanel& operator=(AnalysisPanel&&) = delete;

    /// Starts the analysis of the viewer's scene (what "Find centrelines"
    /// does); cancels one running. Does nothing without a scene.
    void findCenterlines();
    /// Cancels a running analysis (the Cancel button).
    void cancelAnalysis();
    /// From findCenterlines() until its result (or failure) is shown.
    [[nodiscard]] bool analysing() const;
    /// How long the last analysis's worker took (wall seconds; benchmarks).
    [[nodiscard]] double lastWorkSeconds() const noexcept { return lastWorkSeconds_; }
    /// The viewer shows another scene: cancels a running analysis, clears
    /// the state, enables "Find centrelines" when the scene has a surface.
    void sceneChanged();

    /// A session's planning work: finds the centrelines again (with its end
    /// points) and then restores its path, names, landmarks, references and
    /// cursor (PlanningState::applySessionState).
    void restoreSession(const app::PlanningSessionState& saved);
    /// What a session saves now: the state's, or, while a restored session's
    /// analysis runs, the session's own.
    [[nodiscard]] std::optional<app::PlanningSessionState> sessionState() const;

    /// Writes the measurement file to `path` (atomically). Returns the
    /// problem, empty on success.
    [[nodiscard]] ProblemText saveMeasurementsTo(const std::filesystem::path& path);
    /// Writes the sections along the path as CSV to `path` (atomically).
    [[nodiscard]] ProblemText exportSectionsTo(const std::filesystem::path& path);

    [[nodiscard]] QPushButton* findButton() const noexcept { return find_; }
    [[nodiscard]] QPushButton* cancelButton() const noexcept { return cancel_; }
    [[nodiscard]] QPushButton* pickButton() const noexcept { return pick_; }
    /// "Pick Ends": while checked, a click on the vessel adds an end point
    /// (the first the start); "Automatic Ends" forgets them.
    [[nodiscard]] QPushButton* pickEndsButton() const noexcept { return pickEnds_; }
    [[nodiscard]] QPushButton* automaticEndsButton() const noexcept { return clearEnds_; }
    [[nodiscard]] QLabel* endsLabel() const noexcept { return ends_; }
    /// Adds an end point for the next analysis (what a click does while
    /// picking ends): the start first, then the ends.
    void addEnd(const glm::dvec3& point);
    [[nodiscard]] QTableWidget* branchTable() const noexcept { return branches_; }
    /// The graded stenoses: branch (tooltip: the reference), diameter and
    /// area percent, where along the path.
    [[nodiscard]] QTableWidget* stenosisTable() const noexcept { return stenoses_; }
    [[nodiscard]] QComboBox* fromEndChooser() const noexcept { return from_; }
    [[nodiscard]] QComboBox* toEndChooser() const noexcept { return to_; }
    /// How the centrelines are coloured in 3-D (item data: PlanningOverlay::Colouring as int).
    [[nodiscard]] QComboBox* linesChooser() const noexcept { return lines_; }
    [[nodiscard]] QComboBox* landmarkKindChooser() const noexcept { return kind_; }
    [[nodiscard]] QLineEdit* freeNameField() const noexcept { return freeName_; }
    [[nodiscard]] QPushButton* placeButton() const noexcept { return place_; }
    [[nodiscard]] QTableWidget* landmarkTable() const noexcept { return landmarks_; }
    /// The measurement tables (the window shows them in a dock of its own).
    [[nodiscard]] MeasurementTables* measurementTables() const noexcept { return measurements_; }
    [[nodiscard]] QLabel* statusLabel() const noexcept { return status_; }
    [[nodiscard]] QLabel* cursorLabel() const noexcept { return cursor_; }

  signals:
    /// A one-line message for the status bar.
    void statusMessage(const QString& message);
    /// The lines' colouring was chosen (PlanningOverlay::Colouring as int).
    void linesColouringChosen(int colouring);

  protected:
    /// "Pick on vessel": a click on the viewer moves the cursor.
    bool eventFilter(QObject* watched, QEvent* event) override;

  private:
    void buildAnalysisRows();
    void buildPathRows();
    void buildLandmarkRows();
    void showAnalysis();
    void showBranches();
    void showEnds();
    void showCursor();
    void showLandmarks();
    void showMeasurements();
    void analysisFinished();
    /// Stops a running analysis (its result is not taken).
    void stopTask();
    void saveMeasurements();
    void exportSections();

    ViewerWidget* viewer_;
    PlanningState* state_;
    QPointer<AnalysisTask> task_;
    std::optional<app::PlanningSessionState> pending_;  ///< restored once its analysis arrives
    QPushButton* find_ = nullptr;
    QPushButton* cancel_ = nullptr;
    QPushButton* pickEnds_ = nullptr;
    QPushButton* clearEnds_ = nullptr;
    QLabel* ends_ = nullptr;
    QProgressBar* progress_ = nullptr;
    QLabel* status_ = nullptr;
    QTableWidget* branches_ = nullptr;
    QTableWidget* stenoses_ = nullptr;
    QComboBox* from_ = nullptr;
    QComboBox* to_ = nullptr;
    QComboBox* lines_ = nullptr;
    QLabel* cursor_ = nullptr;
    QPushButton* pick_ = nullptr;
    QComboBox* kind_ = nullptr;
    QLineEdit* freeName_ = nullptr;
    QPushButton* place_ = nullptr;
    QTableWidget* landmarks_ = nullptr;
    QPushButton* moveHere_ = nullptr;
    QPushButton* remove_ = nullptr;
    MeasurementTables* measurements_ = nullptr;
    QPushButton* save_ = nullptr;
    QPushButton* csv_ = nullptr;
    QWidget* analysed_ = nullptr;  ///< everything shown once there is an analysis
    double lastWorkSeconds_ = 0.0;
    bool filling_ = false;  ///< while tables are refilled: edits are not the user's
    ClickDetector click_;   ///< clicks on the viewer (picking ends or the cursor)
};

}  // namespace panels
}  // namespace vv::gui
