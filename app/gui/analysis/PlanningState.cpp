// SPDX-License-Identifier: GPL-3.0-or-later
#include "gui/analysis/PlanningState.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <limits>
#include <utility>

#include "common/MeasurementSection.h"
#include "vv/analysis/Stenosis.h"
#include "vv/core/Error.h"

namespace vv::gui {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

}  // namespace

PlanningState::PlanningState(QObject* parent) : QObject(parent) {}

void PlanningState::setAnalysis(std::shared_ptr<const analysis::VesselAnalysis> analysis) {
    analysis_ = std::move(analysis);
    names_.clear();
    references_.clear();
    landmarks_.clear();
    selected_ = -1;
    cursorMm_ = 0.0;
    path_ = {};
    profile_.clear();
    from_ = 0;
    to_ = 0;
    if (analysis_) {
        // The source to the end farthest from it: the main vessel, the path
        // a planner measures first.
        to_ = planning::farthestEnd(analysis_->tree);
        if (to_ > 0) {
            path_ = planning::VesselPath::betweenEnds(analysis_->tree, 0, to_);
            rebuildProfile();
            // The cursor on the first section that measures the vessel (the
            // path's first ones lie in its end's zone).
            const auto first = std::find_if(profile_.begin(), profile_.end(),
                                            [](const ProfilePoint& p) { return p.measured; });
            cursorMm_ = first != profile_.end() ? first->pathMm : 0.0;
        } else {
            to_ = 0;
        }
    }
    emit analysisChanged();
}

QString PlanningState::branchName(int id) const {
    if (const auto name = names_.find(id); name != names_.end()) {
        return QString::fromStdString(name->second);
    }
    return tr("Branch %1").arg(id);
}

void PlanningState::renameBranch(int id, const QString& name) {
    if (!analysis_ || id < 0 || id >= static_cast<int>(analysis_->tree.branches.size())) {
        return;
    }
    const std::string wanted = name.trimmed().toStdString();
    const auto old = names_.find(id);
    if (wanted.empty()) {
        if (old == names_.end()) {
            return;
        }
        names_.erase(old);
    } else {
        if (old != names_.end() && old->second == wanted) {
            return;
        }
        names_[id] = wanted;
    }
    emit branchNamesChanged();
}

std::vector<PathStenosis> PlanningState::stenoses() const {
    std::vector<PathStenosis> found;
    if (!analysis_) {
        return found;
    }
    for (const auto& branch : analysis_->tree.branches) {
        const auto s = analysis::gradeStenosis(analysis_->tree, analysis_->sections, branch.id,
                                               stenosisReference(branch.id));
        if (s) {
            found.push_back({branch.id, kNaN, s->diameterPercent, s->areaPercent,
                             s->referenceDiameterMm, s->method});
            if (const auto along = pathMmOf({branch.id, s->abscissaMm})) {
                found.back().pathMm = *along;
            }
        }
    }
    return found;
}

analysis::StenosisReference PlanningState::stenosisReference(int id) const {
    const auto given = references_.find(id);
    return given != references_.end() ? given->second : analysis::StenosisReference{};
}

bool PlanningState::setReferenceAtCursor(bool proximal) {
    if (!analysis_ || profile_.empty()) {
        return false;
    }
    const planning::TreeLocation at = cursorLocation();
    analysis::StenosisReference reference = stenosisReference(at.branch);
    if (reference.kind != analysis::StenosisReference::Kind::Given) {
        reference.kind = analysis::StenosisReference::Kind::Given;
        reference.proximalMm = at.abscissaMm;
        reference.distalMm = at.abscissaMm;
    }
    (proximal ? reference.proximalMm : reference.distalMm) = at.abscissaMm;
    try {
        if (!analysis::gradeStenosis(analysis_->tree, analysis_->sections, at.branch, reference)) {
            return false;
        }
    } catch (const InvalidArgumentError&) {
        return false;
    }
    references_[at.branch] = reference;
    emit stenosesChanged();
    return true;
}

void PlanningState::clearStenosisReference(int id) {
    if (references_.erase(id) > 0) {
        emit stenosesChanged();
    }
}

QString PlanningState::endName(int end) const {
    if (!analysis_ || end < 0 || end >= static_cast<int>(analysis_->tree.ends.size())) {
        return {};
    }
    if (end == 0) {
        return tr("Start (%1)").arg(branchName(0));
    }
    for (const auto& branch : analysis_->tree.branches) {
        if (branch.endIndex == end) {
            return tr("End %1 (%2)").arg(end).arg(branchName(branch.id));
        }
    }
    return tr("End %1").arg(end);
}

bool PlanningState::choosePath(int fromEnd, int toEnd) {
    if (!analysis_ || fromEnd == toEnd || fromEnd < 0 || toEnd < 0) {
        return false;
    }
    const auto& tree = analysis_->tree;
    planning::VesselPath path;
    try {
        path = planning::VesselPath::betweenEnds(tree, fromEnd, toEnd);
    } catch (const InvalidArgumentError&) {
        return false;
    }
    const planning::TreeLocation cursor = cursorLocation();
    from_ = fromEnd;
    to_ = toEnd;
    path_ = std::move(path);
    rebuildProfile();
    cursorMm_ = path_.abscissaOf(tree, cursor).value_or(0.0);
    emit pathChanged();
    emit cursorMoved(cursorMm_);
    return true;
}

void PlanningState::rebuildProfile() {
    profile_.clear();
    if (!analysis_) {
        return;
    }
    for (const planning::PathPoint& p : path_.points(analysis_->tree)) {
        const analysis::CrossSection& s =
            analysis_->sections[static_cast<std::size_t>(p.branch)][p.pointIndex];
        ProfilePoint point;
        point.pathMm = p.pathMm;
        point.location = {p.branch, analysis_->tree.branches[static_cast<std::size_t>(p.branch)]
                                        .points[p.pointIndex]
                                        .abscissaMm};
        point.measured = s.measuresTheVessel();
        point.equivalentMm = point.measured ? s.equivalentDiameterMm : kNaN;
        point.minMm = point.measured ? s.minDiameterMm : kNaN;
        point.maxMm = point.measured ? s.maxDiameterMm : kNaN;
        point.areaMm2 = point.measured ? s.areaMm2 : kNaN;
        profile_.push_back(point);
    }
}

std::vector<PathStenosis> PlanningState::pathStenoses() const {
    std::vector<PathStenosis> onPath;
    for (const PathStenosis& s : stenoses()) {
        if (std::isfinite(s.pathMm)) {
            onPath.push_back(s);
        }
    }
    return onPath;
}

std::optional<double> PlanningState::pathMmOf(const planning::TreeLocation& at) const {
    if (!analysis_ || profile_.empty()) {
        return std::nullopt;
    }
    return path_.abscissaOf(analysis_->tree, at);
}

void PlanningState::setCursorMm(double pathMm) {
    if (profile_.empty() || !std::isfinite(pathMm)) {
        return;
    }
    const double clamped = std::clamp(pathMm, 0.0, path_.lengthMm());
    if (clamped == cursorMm_) {
        return;
    }
    cursorMm_ = clamped;
    emit cursorMoved(cursorMm_);
}

std::size_t PlanningState::nearestProfileIndex(double pathMm) const {
    const auto after =
        std::lower_bound(profile_.begin(), profile_.end(), pathMm,
                         [](const ProfilePoint& p, double s) { return p.pathMm < s; });
    if (after == profile_.end()) {
        return profile_.size() - 1;
    }
    if (after == profile_.begin()) {
        return 0;
    }
    const auto before = std::prev(after);
    const auto index = after - profile_.begin();
    return static_cast<std::size_t>(pathMm - before->pathMm <= after->pathMm - pathMm ? index - 1
                                                                                      : index);
}

void PlanningState::stepCursor(int steps) {
    if (profile_.empty()) {
        return;
    }
    const auto at = static_cast<long long>(nearestProfileIndex(cursorMm_)) + steps;
    const auto last = static_cast<long long>(profile_.size()) - 1;
    setCursorMm(profile_[static_cast<std::size_t>(std::clamp(at, 0LL, last))].pathMm);
}

planning::TreeLocation PlanningState::cursorLocation() const {
    if (profile_.empty()) {
        return {};
    }
    return path_.locationAt(cursorMm_);
}

std::optional<ProfilePoint> PlanningState::cursorPoint() const {
    if (profile_.empty()) {
        return std::nullopt;
    }
    return profile_[nearestProfileIndex(cursorMm_)];
}

bool PlanningState::moveCursorNear(const glm::dvec3& world) {
    if (!analysis_ || profile_.size() < 2) {
        return false;
    }
    // The nearest place on the path's polyline (not on the tree: near a
    // bifurcation the tree's nearest place may lie on a branch the path
    // does not take).
    const auto& tree = analysis_->tree;
    const auto position = [&tree](const ProfilePoint& p) {
        return planning::sampleAt(tree, p.location).position;
    };
    double best = std::numeric_limits<double>::infinity();
    double bestMm = 0.0;
    glm::dvec3 a = position(profile_.front());
    for (std::size_t i = 1; i < profile_.size(); ++i) {
        const glm::dvec3 b = position(profile_[i]);
        const glm::dvec3 ab = b - a;
        const double span = glm::dot(ab, ab);
        const double t = span > 0.0 ? std::clamp(glm::dot(world - a, ab) / span, 0.0, 1.0) : 0.0;
        const double d = glm::length(world - (a + t * ab));
        if (d < best) {
            best = d;
            bestMm = profile_[i - 1].pathMm + t * (profile_[i].pathMm - profile_[i - 1].pathMm);
        }
        a = b;
    }
    if (best > 2.0 * planning::sampleAt(tree, path_.locationAt(bestMm)).radiusMm) {
        return false;
    }
    setCursorMm(bestMm);
    return true;
}

QString PlanningState::landmarkLabel(const planning::Landmark& landmark) {
    if (landmark.kind != planning::LandmarkKind::Free &&
        landmark.name == planning::landmarkEnglishName(landmark.kind)) {
        return QString::fromStdString(app::landmarkName(landmark.kind));
    }
    return QString::fromStdString(landmark.name);
}

int PlanningState::placeLandmarkAtCursor(planning::LandmarkKind kind, const QString& freeName) {
    if (!analysis_ || profile_.empty()) {
        return -1;
    }
    const auto& tree = analysis_->tree;
    planning::Landmark landmark;
    landmark.kind = kind;
    if (kind == planning::LandmarkKind::Free) {
        landmark.name = freeName.trimmed().toStdString();
        if (landmark.name.empty()) {
            return -1;
        }
    } else {
        landmark.name = std::string(planning::landmarkEnglishName(kind));
    }
    landmark.location =
        planning::placeLandmark(tree, kind, planning::sampleAt(tree, cursorLocation()).position);
    int index = -1;
    if (kind != planning::LandmarkKind::Free) {
        for (std::size_t i = 0; i < landmarks_.size(); ++i) {
            if (landmarks_[i].kind == kind) {
                landmarks_[i] = landmark;
                index = static_cast<int>(i);
                break;
            }
        }
    }
    if (index < 0) {
        landmarks_.push_back(landmark);
        index = static_cast<int>(landmarks_.size()) - 1;
    }
    emit landmarksChanged();
    selectLandmark(index);
    return index;
}

void PlanningState::moveLandmark(int index, double pathMm) {
    if (index < 0 || index >= static_cast<int>(landmarks_.size()) || profile_.empty() ||
        !std::isfinite(pathMm)) {
        return;
    }
    landmarks_[static_cast<std::size_t>(index)].location =
        path_.locationAt(std::clamp(pathMm, 0.0, path_.lengthMm()));
    emit landmarksChanged();
}

void PlanningState::removeLandmark(int index) {
    if (index < 0 || index >= static_cast<int>(landmarks_.size())) {
        return;
    }
    landmarks_.erase(landmarks_.begin() + index);
    if (selected_ >= index) {
        selected_ = selected_ == index ? -1 : selected_ - 1;
        emit landmarkSelected(selected_);
    }
    emit landmarksChanged();
}

void PlanningState::selectLandmark(int index) {
    const int chosen = index >= 0 && index < static_cast<int>(landmarks_.size()) ? index : -1;
    if (chosen == selected_) {
        return;
    }
    selected_ = chosen;
    emit landmarkSelected(selected_);
}

void PlanningState::stepSelectedLandmark(int steps) {
    if (selected_ < 0 || profile_.empty()) {
        return;
    }
    const auto along = pathMmOf(landmarks_[static_cast<std::size_t>(selected_)].location);
    if (!along) {
        return;  // not on this path: the keys move along the path only
    }
    const auto at = static_cast<long long>(nearestProfileIndex(*along)) + steps;
    const auto last = static_cast<long long>(profile_.size()) - 1;
    moveLandmark(selected_, profile_[static_cast<std::size_t>(std::clamp(at, 0LL, last))].pathMm);
}

void PlanningState::setGivenEnds(std::optional<glm::dvec3> source,
                                 std::vector<glm::dvec3> targets) {
    source_ = source;
    targets_ = std::move(targets);
}

analysis::CenterlineOptions PlanningState::centerlineOptions() const {
    analysis::CenterlineOptions options;
    options.source = source_;
    options.targets = targets_;
    return options;
}

std::optional<app::PlanningSessionState> PlanningState::sessionState() const {
    if (!analysis_) {
        return std::nullopt;
    }
    app::PlanningSessionState s;
    s.source = source_;
    s.targets = targets_;
    s.pathFrom = from_;
    s.pathTo = to_;
    s.cursorMm = cursorMm_;
    s.branchNames = names_;
    s.landmarks = landmarks_;
    s.stenosisReferences = references_;
    return s;
}

int PlanningState::applySessionState(const app::PlanningSessionState& saved) {
    if (!analysis_) {
        return 0;
    }
    const auto& tree = analysis_->tree;
    const auto branches = static_cast<int>(tree.branches.size());
    int dropped = 0;
    names_.clear();
    for (const auto& [id, name] : saved.branchNames) {
        if (id < branches) {
            names_[id] = name;
        } else {
            ++dropped;
        }
    }
    references_.clear();
    for (const auto& [id, reference] : saved.stenosisReferences) {
        bool fits = false;
        try {
            fits = id < branches &&
                   analysis::gradeStenosis(tree, analysis_->sections, id, reference).has_value();
        } catch (const InvalidArgumentError&) {
            fits = false;
        }
        if (fits) {
            references_[id] = reference;
        } else {
            ++dropped;
        }
    }
    landmarks_.clear();
    selected_ = -1;
    for (const planning::Landmark& l : saved.landmarks) {
        if (l.location.branch < branches) {
            landmarks_.push_back({l.name, l.kind, planning::clampedLocation(tree, l.location)});
        } else {
            ++dropped;
        }
    }
    if (!choosePath(saved.pathFrom, saved.pathTo)) {
        ++dropped;  // the default path stays
    }
    emit branchNamesChanged();
    emit stenosesChanged();
    emit landmarksChanged();
    emit landmarkSelected(selected_);
    setCursorMm(saved.cursorMm);
    return dropped;
}

app::MeasurementInput PlanningState::measurementInput() const {
    app::MeasurementInput input;
    input.analysis = analysis_.get();
    for (const planning::Landmark& l : landmarks_) {
        input.landmarks.push_back({l, std::nullopt, 0.0});
    }
    input.branchNames = names_;
    input.stenosisReferences = references_;
    if (!profile_.empty()) {
        input.path = app::MeasurementInput::Path{from_, to_};
    }
    return input;
}

}  // namespace vv::gui
