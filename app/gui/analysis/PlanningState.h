// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QObject>
#include <QString>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "common/MeasurementFile.h"
#include "common/Session.h"
#include "vv/analysis/Sections.h"
#include "vv/analysis/Stenosis.h"
#include "vv/planning/Landmarks.h"
#include "vv/planning/VesselPath.h"

namespace vv::gui {

/// One point of the diameter profile along the chosen path.
struct ProfilePoint {
    double pathMm = 0.0;  ///< along the path from its start
    planning::TreeLocation location;
    /// The section measures the vessel (a closed contour, outside the end
    /// zones of caps and junctions); the sizes below are NaN otherwise.
    bool measured = false;
    double equivalentMm = 0.0;
    double minMm = 0.0;
    double maxMm = 0.0;
    double areaMm2 = 0.0;
};

/// A stenosis the engine graded on a branch the path passes.
struct PathStenosis {
    int branch = 0;
    double pathMm = 0.0;  ///< where along the path its narrowest section lies
    double diameterPercent = 0.0;
    double areaPercent = 0.0;
    double referenceMm = 0.0;  ///< the reference diameter
    std::string reference;     ///< how the reference was found (the engine's words)
};

/// The planning work on the shown scene (issue 35): the vessel analysis of
/// its surface, the names the user gave branches, the path chosen through
/// the tree (from one end to another), the landmarks and the cursor on the
/// path. The Analysis panel, the diameter profile and the 3-D overlay show
/// it and change it only through its setters; each change emits the signal
/// that names it. No widgets and no long work: the analysis arrives from
/// AnalysisTask.
class PlanningState : public QObject {
    Q_OBJECT

  public:
    explicit PlanningState(QObject* parent = nullptr);

    /// Takes a new analysis (nullptr clears): names, landmarks and the
    /// cursor go; the path runs from the source (end 0) to the end farthest
    /// from it along the centrelines. Emits analysisChanged() (then nothing
    /// else: everything changed).
    void setAnalysis(std::shared_ptr<const analysis::VesselAnalysis> analysis);
    [[nodiscard]] const std::shared_ptr<const analysis::VesselAnalysis>& analysis() const noexcept {
        return analysis_;
    }
    [[nodiscard]] bool hasAnalysis() const noexcept { return analysis_ != nullptr; }

    // Branches ----------------------------------------------------------------
    /// The name the user gave branch `id`, else "Branch <id>" in the UI language.
    [[nodiscard]] QString branchName(int id) const;
    /// Names branch `id` (trimmed; empty: back to its number). Ignored for an
    /// unknown branch. Emits branchNamesChanged() when the name changes.
    void renameBranch(int id, const QString& name);
    [[nodiscard]] const std::map<int, std::string>& branchNames() const noexcept { return names_; }
    /// The graded stenosis of every branch the analysis graded, against the
    /// reference set for it (stenosisReference()).
    [[nodiscard]] std::vector<PathStenosis> stenoses() const;
    /// The reference branch `id` is graded against: automatic unless set.
    [[nodiscard]] analysis::StenosisReference stenosisReference(int id) const;
    /// Grades the branch the cursor lies on against the mean diameter at two
    /// places (the cursor now: `proximal` true sets the proximal place, false
    /// the distal one; the other stays where it was set, or at the same
    /// place until set). Returns false, changing nothing, off a branch or
    /// when the branch cannot be graded against it. Emits stenosesChanged().
    bool setReferenceAtCursor(bool proximal);
    /// Back to the automatic reference for branch `id`. Emits stenosesChanged().
    void clearStenosisReference(int id);

    // Path --------------------------------------------------------------------
    /// A name for end `end` in the UI language: "Start" for the source, else
    /// "End <n>", with the name of the branch that reaches it.
    [[nodiscard]] QString endName(int end) const;
    [[nodiscard]] int pathFrom() const noexcept { return from_; }
    [[nodiscard]] int pathTo() const noexcept { return to_; }
    /// Measures along the path from end `fromEnd` to end `toEnd`. Returns
    /// false, changing nothing, for ends out of range or the same end twice.
    /// The cursor keeps its place on the tree when the new path passes it,
    /// else goes to the path's start. Emits pathChanged().
    bool choosePath(int fromEnd, int toEnd);
    /// The chosen path; only valid with an analysis.
    [[nodiscard]] const planning::VesselPath& path() const noexcept { return path_; }
    /// The sections along the path, in its order.
    [[nodiscard]] const std::vector<ProfilePoint>& profile() const noexcept { return profile_; }
    /// The stenoses on the branches the path passes, where the path passes
    /// their narrowest section.
    [[nodiscard]] std::vector<PathStenosis> pathStenoses() const;
    /// The path abscissa of `at`; nullopt when the path does not pass it.
    [[nodiscard]] std::optional<double> pathMmOf(const planning::TreeLocation& at) const;

    // Cursor ------------------------------------------------------------------
    [[nodiscard]] double cursorMm() const noexcept { return cursorMm_; }
    /// Moves the cursor to `pathMm` (clamped to the path). Emits
    /// cursorMoved() when it moved.
    void setCursorMm(double pathMm);
    /// Moves the cursor to the profile point nearest to `pathMm` plus `steps`
    /// points (the keyboard's step: one section).
    void stepCursor(int steps);
    /// The place on the tree of the cursor.
    [[nodiscard]] planning::TreeLocation cursorLocation() const;
    /// The profile point at the cursor (the nearest); nullopt without a path.
    [[nodiscard]] std::optional<ProfilePoint> cursorPoint() const;
    /// Moves the cursor to the place on the path nearest `world` (a click on
    /// the vessel). Returns false, moving nothing, when that place is farther
    /// than twice its inscribed radius from `world` (another vessel).
    bool moveCursorNear(const glm::dvec3& world);

    // Landmarks ---------------------------------------------------------------
    [[nodiscard]] const std::vector<planning::Landmark>& landmarks() const noexcept {
        return landmarks_;
    }
    /// A landmark's name as shown: a preset's in the UI language, a free
    /// one as given.
    [[nodiscard]] static QString landmarkLabel(const planning::Landmark& landmark);
    /// Places a landmark at the cursor: a preset of `kind` (replacing the one
    /// of that kind there may be: the sizing takes one of each; one that
    /// names a bifurcation goes to the bifurcation when the cursor lies within
    /// its inscribed radius), or a free one named `freeName` (trimmed; not
    /// empty). Returns its index, or -1 without an analysis or a name.
    /// Emits landmarksChanged().
    int placeLandmarkAtCursor(planning::LandmarkKind kind, const QString& freeName = {});
    /// Moves landmark `index` to `pathMm` on the path. Emits landmarksChanged().
    void moveLandmark(int index, double pathMm);
    void removeLandmark(int index);
    /// The landmark the keyboard and "Move to cursor" act on; -1 for none.
    [[nodiscard]] int selectedLandmark() const noexcept { return selected_; }
    /// Selects landmark `index` (-1 or out of range: none). Emits
    /// landmarkSelected() when the selection changes.
    void selectLandmark(int index);
    /// Moves the selected landmark by `steps` profile points along the path
    /// (the keyboard's step); nothing without a selection.
    void stepSelectedLandmark(int steps);

    // Sessions ----------------------------------------------------------------
    /// The end points the analysis is asked to use (nullopt source: the
    /// automatic ends); sessions keep them.
    [[nodiscard]] const std::optional<glm::dvec3>& givenSource() const noexcept { return source_; }
    [[nodiscard]] const std::vector<glm::dvec3>& givenTargets() const noexcept { return targets_; }
    void setGivenEnds(std::optional<glm::dvec3> source, std::vector<glm::dvec3> targets);
    /// The analysis's options: the defaults with the given ends.
    [[nodiscard]] analysis::CenterlineOptions centerlineOptions() const;
    /// What a session keeps of the planning work; nullopt without an analysis.
    [[nodiscard]] std::optional<app::PlanningSessionState> sessionState() const;
    /// Restores names, references, path, landmarks and cursor onto the
    /// current analysis (found again from the session's surface and ends).
    /// What does not fit the tree (a branch or an end it lacks) is left out;
    /// the returned count says how many items were. Emits the signals of what changed.
    int applySessionState(const app::PlanningSessionState& saved);

    // Measurements ------------------------------------------------------------
    /// What a measurement file is written from (common/MeasurementFile.h);
    /// its `analysis` points into this state: use it while the state holds it.
    [[nodiscard]] app::MeasurementInput measurementInput() const;

  signals:
    void analysisChanged();
    void branchNamesChanged();
    void pathChanged();
    void cursorMoved(double pathMm);
    void landmarksChanged();
    void landmarkSelected(int index);
    void stenosesChanged();

  private:
    void rebuildProfile();
    [[nodiscard]] std::size_t nearestProfileIndex(double pathMm) const;

    std::shared_ptr<const analysis::VesselAnalysis> analysis_;
    std::map<int, std::string> names_;
    std::map<int, analysis::StenosisReference> references_;
    int from_ = 0;
    int to_ = 0;
    planning::VesselPath path_;
    std::vector<ProfilePoint> profile_;
    double cursorMm_ = 0.0;
    std::vector<planning::Landmark> landmarks_;
    int selected_ = -1;
    std::optional<glm::dvec3> source_;
    std::vector<glm::dvec3> targets_;
};

}  // namespace vv::gui
