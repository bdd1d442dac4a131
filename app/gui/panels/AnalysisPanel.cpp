// SPDX-License-Identifier: GPL-3.0-or-later
#include "gui/panels/AnalysisPanel.h"

#include <QComboBox>
#include <QFileDialog>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QLocale>
#include <QMouseEvent>
#include <QProgressBar>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>
#include <cmath>
#include <exception>
#include <limits>
#include <string>
#include <utility>

#include "common/MeasurementFile.h"
#include "common/MeasurementSection.h"
#include "common/SectionsCsv.h"
#include "gui/ViewerWidget.h"
#include "gui/analysis/AnalysisTask.h"
#include "gui/analysis/MeasurementTables.h"
#include "gui/analysis/PlanningOverlay.h"
#include "gui/analysis/PlanningState.h"
#include "gui/panels/PanelUtil.h"
#include "vv/report/PdfReport.h"

namespace vv::gui::panels {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// `mm` as the report prints it ("15,0 mm"), or a dash.
QString millimetres(double mm, int decimals = 1) {
    report::MeasurementCell cell;
    if (std::isfinite(mm)) {
        cell.value = mm;
    }
    cell.decimals = decimals;
    cell.unit = "mm";
    return QString::fromStdString(report::measurementCellText(cell));
}

/// `value` in the UI locale without a unit (the column's header names it),
/// or a dash.
QString number(double value, int decimals = 1) {
    report::MeasurementCell cell;
    if (std::isfinite(value)) {
        cell.value = value;
    }
    cell.decimals = decimals;
    return QString::fromStdString(report::measurementCellText(cell));
}

QTableWidgetItem* readOnly(const QString& text) {
    auto* item = new QTableWidgetItem(text);
    item->setFlags(item->flags() & ~Qt::ItemIsEditable);
    return item;
}

QTableWidget* compactTable(QWidget* parent, const QString& objectName, const QStringList& headers) {
    auto* table = new QTableWidget(0, static_cast<int>(headers.size()), parent);
    table->setObjectName(objectName);
    table->setHorizontalHeaderLabels(headers);
    table->verticalHeader()->hide();
    table->setSelectionBehavior(QAbstractItemView::SelectRows);
    table->setSelectionMode(QAbstractItemView::SingleSelection);
    // The side panel is narrow: the first column takes what the others
    // (numbers, sized to their contents) leave.
    table->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    table->horizontalHeader()->setSectionResizeMode(0, QHeaderView::Stretch);
    table->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    table->setMinimumHeight(110);
    return table;
}

}  // namespace

AnalysisPanel::AnalysisPanel(ViewerWidget* viewer, PlanningState* state, QWidget* parent)
    : QWidget(parent), viewer_(viewer), state_(state), analysed_(new QWidget(this)) {
    setObjectName(QStringLiteral("analysisPanel"));
    auto* outer = new QVBoxLayout(this);
    buildAnalysisRows();
    auto* inner = new QVBoxLayout(analysed_);
    inner->setContentsMargins(0, 0, 0, 0);
    outer->addWidget(analysed_);
    buildPathRows();
    buildLandmarkRows();
    connect(state_, &PlanningState::analysisChanged, this, &AnalysisPanel::showAnalysis);
    connect(state_, &PlanningState::branchNamesChanged, this, [this] {
        showBranches();
        showEnds();
        showMeasurements();
    });
    connect(state_, &PlanningState::stenosesChanged, this, [this] {
        showBranches();
        showMeasurements();
    });
    connect(state_, &PlanningState::pathChanged, this, [this] {
        showBranches();
        showEnds();
        showLandmarks();
        showMeasurements();
    });
    connect(state_, &PlanningState::cursorMoved, this, &AnalysisPanel::showCursor);
    connect(state_, &PlanningState::landmarksChanged, this, [this] {
        showLandmarks();
        showMeasurements();
    });
    connect(state_, &PlanningState::landmarkSelected, this, [this](int index) {
        if (landmarks_->currentRow() != index) {
            landmarks_->selectRow(index);
        }
        moveHere_->setEnabled(index >= 0);
        remove_->setEnabled(index >= 0);
    });
    viewer_->installEventFilter(this);
    showAnalysis();
    sceneChanged();
}

AnalysisPanel::~AnalysisPanel() = default;

void AnalysisPanel::buildAnalysisRows() {
    auto* outer = qobject_cast<QVBoxLayout*>(layout());
    find_ = new QPushButton(tr("Find Centrelines"), this);
    find_->setObjectName(QStringLiteral("findCenterlines"));
    find_->setToolTip(
        tr("Compute the centrelines of the shown surface, their cross-sections and stenoses"));
    cancel_ = new QPushButton(tr("Cancel"), this);
    cancel_->setObjectName(QStringLiteral("cancelAnalysis"));
    cancel_->setEnabled(false);
    auto* row = new QHBoxLayout;
    row->addWidget(find_, 1);
    row->addWidget(cancel_);
    outer->addLayout(row);
    pickEnds_ = new QPushButton(tr("Pick Ends"), this);
    pickEnds_->setObjectName(QStringLiteral("pickEnds"));
    pickEnds_->setCheckable(true);
    pickEnds_->setToolTip(
        tr("Click the vessel where the centrelines start (first click) and "
           "where they end (each further click); Find Centrelines then uses "
           "them instead of the automatic ends"));
    clearEnds_ = new QPushButton(tr("Automatic Ends"), this);
    clearEnds_->setObjectName(QStringLiteral("automaticEnds"));
    clearEnds_->setToolTip(tr("Forget the picked ends: the open ends and tips are found"));
    auto* ends = new QHBoxLayout;
    ends->addWidget(pickEnds_, 1);
    ends->addWidget(clearEnds_, 1);
    outer->addLayout(ends);
    ends_ = new QLabel(this);
    ends_->setObjectName(QStringLiteral("endsLabel"));
    ends_->setWordWrap(true);
    outer->addWidget(ends_);
    connect(clearEnds_, &QPushButton::clicked, this, [this] {
        state_->setGivenEnds(std::nullopt, {});
        pickEnds_->setChecked(false);
        showEnds();
    });
    connect(pickEnds_, &QPushButton::toggled, this, [this](bool on) {
        if (on) {
            pick_->setChecked(false);  // one kind of click at a time
        }
    });
    progress_ = new QProgressBar(this);
    progress_->setObjectName(QStringLiteral("analysisProgress"));
    progress_->setRange(0, 1000);
    progress_->setTextVisible(false);
    progress_->hide();
    outer->addWidget(progress_);
    status_ = new QLabel(this);
    status_->setObjectName(QStringLiteral("analysisStatus"));
    status_->setWordWrap(true);
    outer->addWidget(status_);
    connect(find_, &QPushButton::clicked, this, &AnalysisPanel::findCenterlines);
    connect(cancel_, &QPushButton::clicked, this, &AnalysisPanel::cancelAnalysis);
}

void AnalysisPanel::buildPathRows() {
    auto* inner = qobject_cast<QVBoxLayout*>(analysed_->layout());
    branches_ = compactTable(analysed_, QStringLiteral("branchTable"),
                             {tr("Branch"), tr("Length (mm)"), tr("\u00d8 (mm)")});
    branches_->setToolTip(
        tr("Double-click a name to rename the branch (the name goes into reports). "
           "\u00d8: the narrowest and the widest equivalent diameter, 2\u221a(area/\u03c0), "
           "outside the ends of the branch."));
    inner->addWidget(branches_);
    stenoses_ = compactTable(analysed_, QStringLiteral("stenosisTable"),
                             {tr("Stenosis"), tr("\u00d8 / area (%)"), tr("At (mm)")});
    stenoses_->setToolTip(
        tr("The narrowest point of each branch against its reference diameter (hover a row "
           "for how the reference was found)"));
    inner->addWidget(stenoses_);
    auto* reference = new QHBoxLayout;
    reference->addWidget(new QLabel(tr("Reference:"), analysed_));
    auto* proximal = new QPushButton(tr("Proximal"), analysed_);
    proximal->setObjectName(QStringLiteral("referenceProximal"));
    proximal->setToolTip(
        tr("Grade the branch at the cursor against the diameter here "
           "(proximal reference) and at its distal reference"));
    auto* distal = new QPushButton(tr("Distal"), analysed_);
    distal->setObjectName(QStringLiteral("referenceDistal"));
    distal->setToolTip(
        tr("Grade the branch at the cursor against the diameter here "
           "(distal reference) and at its proximal reference"));
    auto* automatic = new QPushButton(tr("Automatic"), analysed_);
    automatic->setObjectName(QStringLiteral("referenceAutomatic"));
    automatic->setToolTip(
        tr("Grade the branch at the cursor against healthy stretches either "
           "side of its narrowest point"));
    reference->addWidget(proximal);
    reference->addWidget(distal);
    reference->addWidget(automatic);
    inner->addLayout(reference);
    for (auto [button, isProximal] : {std::pair{proximal, true}, std::pair{distal, false}}) {
        connect(button, &QPushButton::clicked, this, [this, isProximal = isProximal] {
            if (!state_->setReferenceAtCursor(isProximal)) {
                emit statusMessage(tr("The branch cannot be graded against a reference here"));
            }
        });
    }
    connect(automatic, &QPushButton::clicked, this,
            [this] { state_->clearStenosisReference(state_->cursorLocation().branch); });
    connect(branches_, &QTableWidget::itemChanged, this, [this](QTableWidgetItem* item) {
        if (!filling_ && item->column() == 0) {
            state_->renameBranch(item->data(Qt::UserRole).toInt(), item->text());
        }
    });
    auto* form = new QFormLayout;
    from_ = new QComboBox(analysed_);
    from_->setObjectName(QStringLiteral("pathFrom"));
    to_ = new QComboBox(analysed_);
    to_->setObjectName(QStringLiteral("pathTo"));
    for (QComboBox* box : {from_, to_}) {
        box->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
        box->setMinimumContentsLength(12);
    }
    form->addRow(tr("Path from:"), from_);
    form->addRow(tr("to:"), to_);
    lines_ = new QComboBox(analysed_);
    lines_->setObjectName(QStringLiteral("linesColouring"));
    lines_->addItem(tr("Path highlighted"), static_cast<int>(PlanningOverlay::Colouring::Path));
    lines_->addItem(tr("By branch"), static_cast<int>(PlanningOverlay::Colouring::Branch));
    lines_->addItem(tr("By diameter"), static_cast<int>(PlanningOverlay::Colouring::Diameter));
    lines_->setToolTip(tr("How the centrelines are coloured in the 3-D view"));
    lines_->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    lines_->setMinimumContentsLength(12);
    form->addRow(tr("Lines:"), lines_);
    connect(lines_, &QComboBox::currentIndexChanged, this,
            [this] { emit linesColouringChosen(lines_->currentData().toInt()); });
    inner->addLayout(form);
    cursor_ = new QLabel(analysed_);
    cursor_->setObjectName(QStringLiteral("cursorSizes"));
    cursor_->setWordWrap(true);
    inner->addWidget(cursor_);
    pick_ = new QPushButton(tr("Pick on Vessel"), analysed_);
    pick_->setObjectName(QStringLiteral("pickOnVessel"));
    pick_->setCheckable(true);
    pick_->setToolTip(tr("Click a vessel in the 3-D view: the cursor moves to the path there"));
    inner->addWidget(pick_);
    const auto choose = [this] {
        if (filling_) {
            return;
        }
        if (!state_->choosePath(from_->currentData().toInt(), to_->currentData().toInt())) {
            emit statusMessage(tr("A path needs two different ends"));
            showEnds();
        }
    };
    connect(from_, &QComboBox::activated, this, choose);
    connect(to_, &QComboBox::activated, this, choose);
}

void AnalysisPanel::buildLandmarkRows() {
    auto* inner = qobject_cast<QVBoxLayout*>(analysed_->layout());
    kind_ = new QComboBox(analysed_);
    kind_->setObjectName(QStringLiteral("landmarkKind"));
    for (const planning::LandmarkKind kind : planning::landmarkPresets()) {
        kind_->addItem(QString::fromStdString(app::landmarkName(kind)), static_cast<int>(kind));
    }
    kind_->addItem(tr("Free name"), static_cast<int>(planning::LandmarkKind::Free));
    kind_->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    kind_->setMinimumContentsLength(12);
    freeName_ = new QLineEdit(analysed_);
    freeName_->setObjectName(QStringLiteral("landmarkName"));
    freeName_->setPlaceholderText(tr("Name"));
    freeName_->setEnabled(false);
    place_ = new QPushButton(tr("Place at Cursor"), analysed_);
    place_->setObjectName(QStringLiteral("placeLandmark"));
    place_->setToolTip(tr("Place the landmark at the cursor (Insert in the diameter profile)"));
    auto* form = new QFormLayout;
    form->addRow(tr("Landmark:"), kind_);
    form->addRow(tr("Name:"), freeName_);
    inner->addLayout(form);
    inner->addWidget(place_);
    landmarks_ =
        compactTable(analysed_, QStringLiteral("landmarkTable"), {tr("Landmark"), tr("At (mm)")});
    landmarks_->setToolTip(
        tr("Select a landmark to move it: Ctrl+Left / Ctrl+Right in the "
           "diameter profile, or drag its line there"));
    inner->addWidget(landmarks_);
    moveHere_ = new QPushButton(tr("Move to Cursor"), analysed_);
    moveHere_->setObjectName(QStringLiteral("moveLandmark"));
    remove_ = new QPushButton(tr("Remove"), analysed_);
    remove_->setObjectName(QStringLiteral("removeLandmark"));
    auto* buttons = new QHBoxLayout;
    buttons->addWidget(moveHere_);
    buttons->addWidget(remove_);
    inner->addLayout(buttons);
    // Shown by the window in a dock of its own: its tables are wider than
    // the side panel.
    measurements_ = new MeasurementTables(analysed_);
    measurements_->hide();
    save_ = new QPushButton(tr("Save Measurements…"), analysed_);
    save_->setObjectName(QStringLiteral("saveMeasurements"));
    save_->setToolTip(
        tr("A measurement file for the report (vesselview-cli report "
           "--measurements) and other programs"));
    csv_ = new QPushButton(tr("Export Sections…"), analysed_);
    csv_->setObjectName(QStringLiteral("exportSections"));
    csv_->setToolTip(tr("The cross-sections along the path as CSV"));
    auto* files = new QHBoxLayout;
    files->addWidget(save_);
    files->addWidget(csv_);
    inner->addLayout(files);

    connect(kind_, &QComboBox::currentIndexChanged, this, [this] {
        freeName_->setEnabled(kind_->currentData().toInt() ==
                              static_cast<int>(planning::LandmarkKind::Free));
    });
    connect(place_, &QPushButton::clicked, this, [this] {
        const auto kind = static_cast<planning::LandmarkKind>(kind_->currentData().toInt());
        if (state_->placeLandmarkAtCursor(kind, freeName_->text()) < 0) {
            emit statusMessage(tr("A free landmark needs a name"));
        }
    });
    connect(landmarks_, &QTableWidget::currentCellChanged, this,
            [this](int row) { state_->selectLandmark(row); });
    connect(moveHere_, &QPushButton::clicked, this,
            [this] { state_->moveLandmark(state_->selectedLandmark(), state_->cursorMm()); });
    connect(remove_, &QPushButton::clicked, this,
            [this] { state_->removeLandmark(state_->selectedLandmark()); });
    connect(save_, &QPushButton::clicked, this, &AnalysisPanel::saveMeasurements);
    connect(csv_, &QPushButton::clicked, this, &AnalysisPanel::exportSections);
}

void AnalysisPanel::sceneChanged() {
    cancelAnalysis();
    pending_.reset();
    state_->setGivenEnds(std::nullopt, {});
    pickEnds_->setChecked(false);
    state_->setAnalysis(nullptr);
    const auto& scene = viewer_->scene();
    const bool surface = scene != nullptr && !scene->meshes.empty();
    setApplicable(find_, surface, find_->toolTip(), tr("Open a vessel surface first"));
    status_->setText(surface ? tr("Find the centrelines to measure along the vessels.")
                             : QString());
}

void AnalysisPanel::findCenterlines() {
    const auto& scene = viewer_->scene();
    if (scene == nullptr || scene->meshes.empty()) {
        return;
    }
    stopTask();  // a restored session's pending state stays for the new run
    auto* task = new AnalysisTask(scene, state_->centerlineOptions(), this);
    task_ = task;
    connect(task, &AnalysisTask::progressChanged, this,
            [this, task](double fraction, const QString& stage) {
                if (task_ == task) {
                    progress_->setValue(static_cast<int>(std::lround(fraction * 1000.0)));
                    status_->setText(stage);
                }
            });
    connect(task, &AnalysisTask::succeeded, this,
            [this, task](const std::shared_ptr<const analysis::VesselAnalysis>& analysis) {
                if (task_ == task) {
                    lastWorkSeconds_ = task->workSeconds();
                    state_->setAnalysis(analysis);
                    if (pending_) {
                        const int dropped = state_->applySessionState(*pending_);
                        pending_.reset();
                        if (dropped > 0) {
                            emit statusMessage(
                                tr("%1 saved item(s) do not fit the centrelines found and were "
                                   "left out")
                                    .arg(dropped));
                        }
                    }
                }
            });
    connect(task, &AnalysisTask::failed, this, [this, task](const ProblemText& problem) {
        if (task_ == task) {
            status_->setText(problem.line());
            emit statusMessage(problem.summary);
        }
    });
    connect(task, &AnalysisTask::cancelled, this, [this, task] {
        if (task_ == task) {
            status_->setText(tr("Cancelled."));
        }
    });
    connect(task, &AnalysisTask::finished, this, [this, task] {
        if (task_ == task) {
            analysisFinished();
        }
        task->deleteLater();
    });
    state_->setAnalysis(nullptr);
    progress_->setValue(0);
    progress_->show();
    find_->setEnabled(false);
    cancel_->setEnabled(true);
    status_->setText(tr("Starting…"));
    task->start();
}

void AnalysisPanel::addEnd(const glm::dvec3& point) {
    if (!state_->givenSource()) {
        state_->setGivenEnds(point, {});
    } else {
        std::vector<glm::dvec3> targets = state_->givenTargets();
        targets.push_back(point);
        state_->setGivenEnds(state_->givenSource(), std::move(targets));
    }
    showEnds();
}

void AnalysisPanel::restoreSession(const app::PlanningSessionState& saved) {
    state_->setGivenEnds(saved.source, saved.targets);
    pending_ = saved;
    findCenterlines();
}

std::optional<app::PlanningSessionState> AnalysisPanel::sessionState() const {
    if (pending_ && task_ != nullptr) {
        return pending_;
    }
    return state_->sessionState();
}

void AnalysisPanel::cancelAnalysis() {
    pending_.reset();
    stopTask();
}

void AnalysisPanel::stopTask() {
    if (task_ != nullptr) {
        AnalysisTask* task = task_;
        task_ = nullptr;  // its signals no longer count
        task->cancel();
        analysisFinished();
        status_->setText(tr("Cancelled."));
    }
}

bool AnalysisPanel::analysing() const {
    // Until its result is delivered (the worker may be done before).
    return task_ != nullptr;
}

void AnalysisPanel::analysisFinished() {
    task_ = nullptr;
    progress_->hide();
    cancel_->setEnabled(false);
    const auto& scene = viewer_->scene();
    find_->setEnabled(scene != nullptr && !scene->meshes.empty());
}

void AnalysisPanel::showAnalysis() {
    const bool have = state_->hasAnalysis();
    analysed_->setVisible(have);
    if (have) {
        const auto& tree = state_->analysis()->tree;
        double length = 0.0;
        for (const auto& b : tree.branches) {
            length += b.lengthMm;
        }
        status_->setText(tr("Branches: %1; centreline: %2.")
                             .arg(QLocale().toString(static_cast<qulonglong>(tree.branches.size())),
                                  millimetres(length, 0)));
        // The engine's notes (English, technical): behind the summary.
        QStringList notes;
        for (const std::string& note : tree.notes) {
            notes << QString::fromStdString(note);
        }
        status_->setToolTip(notes.join(QStringLiteral("\n\n")));
    }
    showBranches();
    showEnds();
    showCursor();
    showLandmarks();
    showMeasurements();
}

void AnalysisPanel::showBranches() {
    filling_ = true;
    branches_->setRowCount(0);
    if (state_->hasAnalysis()) {
        const auto& a = *state_->analysis();
        branches_->setRowCount(static_cast<int>(a.tree.branches.size()));
        for (const auto& b : a.tree.branches) {
            const int row = b.id;
            auto* name = new QTableWidgetItem(state_->branchName(b.id));
            name->setData(Qt::UserRole, b.id);
            branches_->setItem(row, 0, name);
            branches_->setItem(row, 1, readOnly(number(b.lengthMm)));
            const app::BranchExtremes e =
                app::branchExtremes(a.sections[static_cast<std::size_t>(b.id)]);
            branches_->setItem(row, 2,
                               readOnly(e.narrowest != nullptr && e.widest != nullptr
                                            ? QStringLiteral("%1\u2013%2")
                                                  .arg(number(e.narrowest->equivalentDiameterMm),
                                                       number(e.widest->equivalentDiameterMm))
                                            : number(kNaN)));
        }
    }
    stenoses_->setRowCount(0);
    if (state_->hasAnalysis()) {
        for (const PathStenosis& s : state_->stenoses()) {
            const int row = stenoses_->rowCount();
            stenoses_->insertRow(row);
            auto* name = readOnly(state_->branchName(s.branch));
            name->setToolTip(
                tr("Reference %1: %2")
                    .arg(millimetres(s.referenceMm), QString::fromStdString(s.reference)));
            stenoses_->setItem(row, 0, name);
            stenoses_->setItem(row, 1,
                               readOnly(QStringLiteral("%1 / %2").arg(number(s.diameterPercent, 0),
                                                                      number(s.areaPercent, 0))));
            auto* at = readOnly(number(s.pathMm));  // a dash off the path
            if (!std::isfinite(s.pathMm)) {
                at->setToolTip(tr("not on the path"));
            }
            stenoses_->setItem(row, 2, at);
        }
    }
    filling_ = false;
}

void AnalysisPanel::showEnds() {
    const auto& targets = state_->givenTargets();
    ends_->setText(!state_->givenSource()
                       ? tr("Ends: found automatically")
                       : tr("Ends: picked, a start and %1 more")
                             .arg(QLocale().toString(static_cast<qulonglong>(targets.size()))));
    clearEnds_->setEnabled(state_->givenSource().has_value());
    filling_ = true;
    from_->clear();
    to_->clear();
    if (state_->hasAnalysis()) {
        const int ends = static_cast<int>(state_->analysis()->tree.ends.size());
        for (int end = 0; end < ends; ++end) {
            from_->addItem(state_->endName(end), end);
            to_->addItem(state_->endName(end), end);
        }
        from_->setCurrentIndex(from_->findData(state_->pathFrom()));
        to_->setCurrentIndex(to_->findData(state_->pathTo()));
    }
    filling_ = false;
}

void AnalysisPanel::showCursor() {
    const auto point = state_->cursorPoint();
    if (!point) {
        cursor_->clear();
        return;
    }
    QString text = tr("Cursor at %1 along the path (%2).")
                       .arg(millimetres(state_->cursorMm()),
                            state_->branchName(state_->cursorLocation().branch));
    if (point->measured) {
        report::MeasurementCell area{point->areaMm2, 0, "mm²", {}};
        text += QStringLiteral("\n") +
                tr("Diameter %1 (minimum %2, maximum %3), area %4")
                    .arg(millimetres(point->equivalentMm), millimetres(point->minMm),
                         millimetres(point->maxMm),
                         QString::fromStdString(report::measurementCellText(area)));
    } else {
        text += QStringLiteral("\n") + tr("No section here (an end or a junction)");
    }
    cursor_->setText(text);
}

void AnalysisPanel::showLandmarks() {
    filling_ = true;
    const auto& list = state_->landmarks();
    landmarks_->setRowCount(static_cast<int>(list.size()));
    for (std::size_t i = 0; i < list.size(); ++i) {
        const int row = static_cast<int>(i);
        landmarks_->setItem(row, 0, readOnly(PlanningState::landmarkLabel(list[i])));
        const auto along = state_->pathMmOf(list[i].location);
        auto* at = readOnly(number(along ? *along : kNaN));
        if (!along) {
            at->setToolTip(tr("not on the path"));
        }
        landmarks_->setItem(row, 1, at);
    }
    landmarks_->selectRow(state_->selectedLandmark());
    moveHere_->setEnabled(state_->selectedLandmark() >= 0);
    remove_->setEnabled(state_->selectedLandmark() >= 0);
    filling_ = false;
}

void AnalysisPanel::showMeasurements() {
    measurements_->clear();
    if (!state_->hasAnalysis()) {
        return;
    }
    try {
        measurements_->setSection(
            app::measurementSection(app::measurementsOf(state_->measurementInput())));
    } catch (const std::exception& e) {
        emit statusMessage(QString::fromStdString(e.what()));
    }
}

ProblemText AnalysisPanel::saveMeasurementsTo(const std::filesystem::path& path) {
    if (!state_->hasAnalysis()) {
        return {tr("Find the centrelines first."), {}};
    }
    try {
        app::writeMeasurementFile(path, state_->measurementInput());
    } catch (const std::exception& e) {
        return describeProblem(e, FileAccess::Writing);
    }
    return {};
}

ProblemText AnalysisPanel::exportSectionsTo(const std::filesystem::path& path) {
    if (!state_->hasAnalysis()) {
        return {tr("Find the centrelines first."), {}};
    }
    std::vector<app::SectionRow> rows;
    for (const planning::PathPoint& p : state_->path().points(state_->analysis()->tree)) {
        rows.push_back({p.branch, p.pointIndex, p.pathMm});
    }
    try {
        app::writeSectionsCsv(path, *state_->analysis(), rows, state_->branchNames());
    } catch (const std::exception& e) {
        return describeProblem(e, FileAccess::Writing);
    }
    return {};
}

void AnalysisPanel::saveMeasurements() {
    const QString file = QFileDialog::getSaveFileName(this, tr("Save Measurements"), QString(),
                                                      tr("Measurement files (*.json)"));
    if (file.isEmpty()) {
        return;
    }
    const ProblemText problem = saveMeasurementsTo(file.toStdString());
    if (!problem.summary.isEmpty()) {
        showProblem(this, QStringLiteral("measurementSaveProblem"), tr("Save Measurements"),
                    problem);
    } else {
        emit statusMessage(tr("Measurements saved to %1").arg(file));
    }
}

void AnalysisPanel::exportSections() {
    const QString file = QFileDialog::getSaveFileName(this, tr("Export Sections"), QString(),
                                                      tr("CSV files (*.csv)"));
    if (file.isEmpty()) {
        return;
    }
    const ProblemText problem = exportSectionsTo(file.toStdString());
    if (!problem.summary.isEmpty()) {
        showProblem(this, QStringLiteral("sectionExportProblem"), tr("Export Sections"), problem);
    } else {
        emit statusMessage(tr("Sections exported to %1").arg(file));
    }
}

bool AnalysisPanel::eventFilter(QObject* watched, QEvent* event) {
    const bool picking = pick_->isChecked() && state_->hasAnalysis();
    if (watched == viewer_ && (picking || pickEnds_->isChecked())) {
        if (const auto at = click_.clicked(event)) {
            const auto hit = viewer_->probeAt(*at);
            if (pickEnds_->isChecked()) {
                if (hit) {
                    addEnd(glm::dvec3(hit->worldPosition));
                } else {
                    emit statusMessage(tr("No vessel under the mouse: click on a vessel"));
                }
            } else if (!hit || !state_->moveCursorNear(glm::dvec3(hit->worldPosition))) {
                emit statusMessage(tr("No vessel of the path under the mouse"));
            }
        }
    }
    return QWidget::eventFilter(watched, event);
}

}  // namespace vv::gui::panels
