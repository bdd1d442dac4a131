// SPDX-License-Identifier: GPL-3.0-or-later
// The planning workflow in the GUI (issue 35), driven as a planner drives it:
// Find centrelines (progress, Cancel, the GUI thread free meanwhile), a path
// chosen between two ends, the cursor moved by the keyboard and by a click on
// the vessel, the six aortic presets placed at the cursor, the sizing table
// read off the panel and compared with the phantom's truth; a branch renamed,
// the measurement file and the section CSV saved and read back; the diameter
// profile's curves against the truth; and the segmented synthetic CTA
// measured against the tree it was voxelised from.
#include <QCheckBox>
#include <QComboBox>
#include <QDockWidget>
#include <QKeyEvent>
#include <QLabel>
#include <QLineEdit>
#include <QLineSeries>
#include <QLocale>
#include <QProgressBar>
#include <QPushButton>
#include <QSlider>
#include <QTableWidget>
#include <QWheelEvent>
#include <array>
#include <cmath>
#include <cstring>
#include <fstream>
#include <glm/geometric.hpp>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "AneurysmTruth.h"
#include "DicomTestUtil.h"
#include "GuiFixture.h"
#include "ReportTestUtil.h"
#include "SyntheticCta.h"
#include "common/MeasurementFile.h"
#include "common/Session.h"
#include "gui/ReportDialog.h"
#include "gui/SliceCursor.h"
#include "gui/SliceWorkspace.h"
#include "gui/analysis/AnalysisTask.h"
#include "gui/analysis/CrossSectionView.h"
#include "gui/analysis/CurvedReformation.h"
#include "gui/analysis/DiameterProfile.h"
#include "gui/analysis/MeasurementTables.h"
#include "gui/analysis/PlanningOverlay.h"
#include "gui/analysis/PlanningState.h"
#include "gui/panels/AnalysisPanel.h"
#include "vv/analysis/Stenosis.h"
#include "vv/colormaps/LabelPalette.h"
#include "vv/core/Error.h"
#include "vv/demo/AneurysmPhantom.h"
#include "vv/meshio/MeshWriter.h"
#include "vv/planning/AorticSizing.h"
#include "vv/report/PdfReport.h"

namespace vv::test {
namespace {

using planning::LandmarkKind;

class PlanningGui : public GuiFixture {
  protected:
    gui::panels::AnalysisPanel& panel() { return *window_->analysisPanel(); }
    gui::PlanningState& state() { return *window_->planning(); }

    /// Clicks Find Centrelines and waits for the analysis; checks on the way
    /// that the GUI thread stayed free (the viewer drew frames while it ran)
    /// and that progress showed.
    void findCenterlines() {
        ASSERT_TRUE(panel().findButton()->isEnabled())
            << panel().findButton()->toolTip().toStdString();
        panel().findButton()->click();
        ASSERT_TRUE(panel().analysing());
        EXPECT_TRUE(panel().cancelButton()->isEnabled());
        EXPECT_FALSE(panel().findButton()->isEnabled());
        EXPECT_TRUE(window_->findChild<QProgressBar*>(QStringLiteral("analysisProgress"))
                        ->isVisibleTo(&panel()));
        const quint64 frames = window_->viewer()->framesWithScene();
        window_->viewer()->update();
        EXPECT_TRUE(waitUntil([&] {
            return window_->viewer()->framesWithScene() > frames || !panel().analysing();
        })) << "no frame while the analysis ran";
        ASSERT_TRUE(waitUntil([&] { return !panel().analysing(); }, 240000));
        ASSERT_TRUE(state().hasAnalysis()) << panel().statusLabel()->text().toStdString();
        EXPECT_TRUE(panel().findButton()->isEnabled());
        EXPECT_FALSE(panel().cancelButton()->isEnabled());
        EXPECT_TRUE(window_->diameterProfileDock()->isVisible());
    }

    /// Chooses the path by the end choosers as a person does.
    void choosePath(int from, int to) {
        QComboBox* a = panel().fromEndChooser();
        QComboBox* b = panel().toEndChooser();
        a->setCurrentIndex(a->findData(from));
        emit a->activated(a->currentIndex());
        b->setCurrentIndex(b->findData(to));
        emit b->activated(b->currentIndex());
        ASSERT_EQ(state().pathFrom(), from);
        ASSERT_EQ(state().pathTo(), to);
    }

    /// The end whose branch runs towards `direction` from the tree's source.
    int endToward(const glm::dvec3& point) {
        const auto& tree = state().analysis()->tree;
        int best = -1;
        double bestDistance = 1e300;
        for (int end = 1; end < static_cast<int>(tree.ends.size()); ++end) {
            const double d = glm::length(tree.ends[static_cast<std::size_t>(end)].position - point);
            if (d < bestDistance) {
                bestDistance = d;
                best = end;
            }
        }
        return best;
    }

    /// Places a preset (or free) landmark with the panel's controls at the
    /// path place nearest `point`.
    void place(LandmarkKind kind, const glm::dvec3& point, const QString& name = {}) {
        ASSERT_TRUE(state().moveCursorNear(point))
            << "not on the path: " << static_cast<int>(kind) << " at " << point.x << "," << point.y
            << "," << point.z;
        QComboBox* kinds = panel().landmarkKindChooser();
        kinds->setCurrentIndex(kinds->findData(static_cast<int>(kind)));
        panel().freeNameField()->setText(name);
        const auto before = state().landmarks().size();
        panel().placeButton()->click();
        ASSERT_GE(state().landmarks().size(), kind == LandmarkKind::Free ? before + 1 : before);
    }

    /// The number in the measurement tree's table `title`, row `label`,
    /// value column `column` (1 = the first value); NaN when blank ("—").
    double tableValue(const QString& title, const QString& label, int column = 1) {
        QTableWidget* table = panel().measurementTables()->table(title);
        if (table == nullptr) {
            ADD_FAILURE() << "no table " << title.toStdString();
            return std::nan("");
        }
        for (int r = 0; r < table->rowCount(); ++r) {
            if (table->item(r, 0)->text() != label) {
                continue;
            }
            const QString text = table->item(r, column)->text();
            if (text == QStringLiteral("\u2014")) {
                return std::nan("");
            }
            // "20.0 mm", "35°": the number before the unit.
            QString number;
            for (const QChar c : text) {
                if (c.isDigit() || c == QLocale().decimalPoint() || c == u'-' ||
                    c == QLocale().negativeSign()) {
                    number += c;
                } else if (!number.isEmpty()) {
                    break;
                }
            }
            bool ok = false;
            const double value = QLocale().toDouble(number, &ok);
            EXPECT_TRUE(ok) << text.toStdString();
            return value;
        }
        ADD_FAILURE() << "no row " << label.toStdString() << " in " << title.toStdString();
        return std::nan("");
    }
};

/// The phantom of AorticSizingTest (open ends as a CFD surface comes).
demo::AneurysmPhantom phantom() {
    demo::AneurysmPhantomOptions options;
    options.targetTriangles = 50'000;
    options.openEnds = true;
    return demo::makeAneurysmPhantom(options);
}

TEST_F(PlanningGui, CancelStopsTheAnalysisAndLeavesNoneBehind) {
    auto scene = std::make_shared<scene::Scene>();
    scene->meshes.push_back(phantom().mesh);
    window_->setScene(scene, QStringLiteral("phantom"));
    ASSERT_TRUE(waitForFrames());
    panel().findButton()->click();
    ASSERT_TRUE(panel().analysing());
    panel().cancelButton()->click();
    EXPECT_FALSE(panel().analysing());
    EXPECT_TRUE(panel().findButton()->isEnabled());
    EXPECT_FALSE(panel().cancelButton()->isEnabled());
    EXPECT_EQ(panel().statusLabel()->text(), QStringLiteral("Cancelled."));
    // A result arriving after the cancel is not taken.
    QCoreApplication::processEvents();
    EXPECT_TRUE(waitUntil([&] { return panel().findChildren<gui::AnalysisTask*>().isEmpty(); }));
    EXPECT_FALSE(state().hasAnalysis());
    EXPECT_FALSE(window_->diameterProfileDock()->isVisible());
}

TEST_F(PlanningGui, ThePresetsOnThePhantomFillTheSizingTableWithItsTruth) {
    const demo::AneurysmPhantom truth = phantom();
    const auto& o = truth.options;
    auto scene = std::make_shared<scene::Scene>();
    scene->meshes.push_back(truth.mesh);
    window_->setScene(scene, QStringLiteral("phantom"));
    ASSERT_TRUE(waitForFrames());
    ASSERT_NO_FATAL_FAILURE(findCenterlines());
    const auto& tree = state().analysis()->tree;
    ASSERT_EQ(tree.ends.size(), 3U);

    // The default path runs from the source to the farthest end; the left
    // iliac's end (iliacDirections[1]) is chosen.
    const double iliacMm = 40.0;
    const glm::dvec3 left = truth.bifurcationPoint + iliacMm * truth.iliacDirections[1];
    const glm::dvec3 right = truth.bifurcationPoint + iliacMm * truth.iliacDirections[0];
    const int leftEnd =
        endToward(truth.bifurcationPoint + o.iliacLengthMm * truth.iliacDirections[1]);
    const int rightEnd =
        endToward(truth.bifurcationPoint + o.iliacLengthMm * truth.iliacDirections[0]);
    ASSERT_NE(leftEnd, rightEnd);
    choosePath(0, leftEnd);

    // The profile: equivalent diameters on the straight trunk as built.
    const QList<QLineSeries*> equivalent =
        window_->diameterProfile()->seriesNamed(QStringLiteral("Equivalent"));
    ASSERT_FALSE(equivalent.isEmpty());
    std::size_t checked = 0;
    for (const gui::ProfilePoint& p : state().profile()) {
        if (p.measured && p.location.branch == 0) {
            const double z = planning::sampleAt(tree, p.location).position.z;
            const double built = 2.0 * truth.trunkRadiusAt(z);
            EXPECT_NEAR(p.equivalentMm, built, 0.02 * built) << "at z " << z;
            ++checked;
        }
    }
    EXPECT_GT(checked, 200U);
    std::size_t plotted = 0;
    for (const QLineSeries* run : equivalent) {
        plotted += static_cast<std::size_t>(run->count());
    }
    EXPECT_EQ(plotted, static_cast<std::size_t>(
                           std::count_if(state().profile().begin(), state().profile().end(),
                                         [](const gui::ProfilePoint& p) { return p.measured; })));

    // The cursor: the keyboard steps one section, a click on the vessel moves it.
    window_->diameterProfile()->setFocus();
    state().setCursorMm(50.0);
    const double before = state().cursorMm();
    QKeyEvent right1(QEvent::KeyPress, Qt::Key_Right, Qt::NoModifier);
    QCoreApplication::sendEvent(window_->diameterProfile(), &right1);
    EXPECT_NEAR(state().cursorMm() - before, 0.5, 0.05) << "one section (the 0.5 mm step)";

    // The cross-section of a mesh: the contour alone, its calipers the
    // widest section's 40 mm at the bulge's centre.
    ASSERT_TRUE(state().moveCursorNear({0, 0, o.bulgeCentreMm}));
    const auto& widest = window_->crossSection()->section();
    ASSERT_TRUE(widest.has_value());
    EXPECT_TRUE(window_->crossSection()->image().isNull());
    EXPECT_NEAR(widest->maxDiameterMm, truth.maxDiameterMm, 0.01 * truth.maxDiameterMm);
    EXPECT_FALSE(window_->curvedReformation()->isVisible()) << "no image series";

    // The presets, placed where a planner clicks.
    const double renalZ = 20.0;
    const double startZ = o.bulgeCentreMm - o.bulgeLengthMm / 2.0;
    place(LandmarkKind::LowestRenalArtery, {0, 0, renalZ});
    place(LandmarkKind::AneurysmStart, {0, 0, startZ});
    place(LandmarkKind::LargestAneurysmDiameter, {0, 0, o.bulgeCentreMm});
    place(LandmarkKind::AorticBifurcation, truth.bifurcationPoint);
    place(LandmarkKind::LeftInternalIliacOrigin, left);
    choosePath(0, rightEnd);
    place(LandmarkKind::RightInternalIliacOrigin, right);
    ASSERT_EQ(state().landmarks().size(), 6U);
    EXPECT_EQ(panel().landmarkTable()->rowCount(), 6);

    // The sizing table as the panel shows it, against the truth (1 %, 1 degree).
    const QString diameters = QStringLiteral("Aortic sizing: diameters");
    const QString lengths = QStringLiteral("Aortic sizing: lengths and angles");
    for (std::size_t i = 0; i < planning::AorticSizing::kNeckDepthsMm.size(); ++i) {
        const double depth = planning::AorticSizing::kNeckDepthsMm[i];
        const QString label = i == 0 ? QStringLiteral("Neck at the lowest renal artery")
                                     : QStringLiteral("Neck %1 mm below the lowest renal artery")
                                           .arg(static_cast<int>(depth));
        const double built = 2.0 * truth.trunkRadiusAt(renalZ + depth);
        EXPECT_NEAR(tableValue(diameters, label), built, 0.01 * built + 0.05)
            << label.toStdString();
    }
    EXPECT_NEAR(tableValue(diameters, QStringLiteral("Largest aneurysm diameter")),
                truth.maxDiameterMm, 0.01 * truth.maxDiameterMm + 0.05);
    const double iliac = 2.0 * o.iliacRadiusMm;
    EXPECT_NEAR(tableValue(diameters, QStringLiteral("Smallest left iliac (access)"), 2), iliac,
                0.01 * iliac + 0.05);
    EXPECT_NEAR(tableValue(diameters, QStringLiteral("Smallest right iliac (access)"), 2), iliac,
                0.01 * iliac + 0.05);
    // Lengths: along the phantom's axes between where the landmarks are.
    const auto along = [&](LandmarkKind from, LandmarkKind to) {
        const auto* a = planning::findLandmark(state().landmarks(), from);
        const auto* b = planning::findLandmark(state().landmarks(), to);
        return truthAlongAxes(truth, tree, a->location, b->location);
    };
    const double neck = along(LandmarkKind::LowestRenalArtery, LandmarkKind::AneurysmStart);
    EXPECT_NEAR(neck, startZ - renalZ, 0.5) << "the landmarks went where they were clicked";
    EXPECT_NEAR(
        tableValue(lengths,
                   QStringLiteral("Neck length (lowest renal artery to start of the aneurysm)")),
        neck, 0.01 * neck + 0.05);
    EXPECT_NEAR(tableValue(lengths, QStringLiteral("Angle \u03b1 (suprarenal aorta to neck)")), 0.0,
                1.0);
    EXPECT_NEAR(tableValue(lengths, QStringLiteral("Angle \u03b2 (neck to aneurysm)")), 0.0, 1.0);
    const double toFork = along(LandmarkKind::LowestRenalArtery, LandmarkKind::AorticBifurcation);
    EXPECT_NEAR(tableValue(lengths, QStringLiteral("Lowest renal artery to aortic bifurcation")),
                toFork, 0.01 * toFork + 0.05);
    for (const auto& [side, origin] :
         {std::pair{QStringLiteral("left"), LandmarkKind::LeftInternalIliacOrigin},
          std::pair{QStringLiteral("right"), LandmarkKind::RightInternalIliacOrigin}}) {
        const double fromFork = along(LandmarkKind::AorticBifurcation, origin);
        EXPECT_NEAR(fromFork, iliacMm, 1.5) << "the landmarks went where they were clicked";
        EXPECT_NEAR(
            tableValue(lengths,
                       QStringLiteral("Aortic bifurcation to %1 internal iliac origin").arg(side)),
            fromFork, 0.01 * fromFork + 0.05);
        const double fromRenal = along(LandmarkKind::LowestRenalArtery, origin);
        EXPECT_NEAR(
            tableValue(lengths,
                       QStringLiteral("Lowest renal artery to %1 internal iliac origin").arg(side)),
            fromRenal, 0.01 * fromRenal + 0.05);
    }

    // A landmark moved by the keyboard changes the table: the neck grows by one section.
    state().selectLandmark(1);  // the start of the aneurysm
    ASSERT_TRUE(state().pathMmOf(state().landmarks()[1].location).has_value());
    const double neckBefore = tableValue(
        lengths, QStringLiteral("Neck length (lowest renal artery to start of the aneurysm)"));
    QKeyEvent ctrlRight(QEvent::KeyPress, Qt::Key_Right, Qt::ControlModifier);
    QCoreApplication::sendEvent(window_->diameterProfile(), &ctrlRight);
    EXPECT_NEAR(
        tableValue(lengths,
                   QStringLiteral("Neck length (lowest renal artery to start of the aneurysm)")) -
            neckBefore,
        0.5, 0.11);

    // The trunk's stenosis: by default against healthy stretches the engine
    // finds (on an aneurysmal trunk the bulge raises them); against the
    // neck's diameter at the renal artery and above the bifurcation, as a
    // planner sets it, the narrowest section is no narrowing at all.
    const auto trunkStenosis = [&] {
        for (const gui::PathStenosis& s : state().stenoses()) {
            if (s.branch == 0) {
                return s.diameterPercent;
            }
        }
        return std::nan("");
    };
    const auto automatic = analysis::gradeStenosis(tree, state().analysis()->sections, 0);
    ASSERT_TRUE(automatic.has_value());
    EXPECT_DOUBLE_EQ(trunkStenosis(), automatic->diameterPercent);
    ASSERT_TRUE(state().moveCursorNear({0, 0, renalZ}));
    window_->findChild<QPushButton*>(QStringLiteral("referenceProximal"))->click();
    ASSERT_TRUE(state().moveCursorNear({0, 0, o.trunkLengthMm - 12.0}));
    window_->findChild<QPushButton*>(QStringLiteral("referenceDistal"))->click();
    EXPECT_EQ(state().stenosisReference(0).kind, analysis::StenosisReference::Kind::Given);
    EXPECT_NEAR(trunkStenosis(), 0.0, 2.0) << "the neck against the neck's own diameter";
    QTableWidget* stenoses = panel().stenosisTable();
    ASSERT_GE(stenoses->rowCount(), 1);
    EXPECT_TRUE(stenoses->item(0, 0)->toolTip().contains(QStringLiteral("mm")))
        << "names its reference";

    // A branch renamed: the table, the end names and the measurement file carry the name.
    QTableWidgetItem* name = panel().branchTable()->item(0, 0);
    ASSERT_NE(name, nullptr);
    name->setText(QStringLiteral("abdominal aorta"));
    EXPECT_EQ(state().branchName(0), QStringLiteral("abdominal aorta"));
    EXPECT_TRUE(panel().fromEndChooser()->itemText(0).contains(QStringLiteral("abdominal aorta")));
    const fs::path dir = panelTestDir() / "planning";
    fs::create_directories(dir);
    const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
    const fs::path file = dir / (std::string(info->name()) + ".json");
    const gui::ProblemText saved = panel().saveMeasurementsTo(file);
    ASSERT_TRUE(saved.summary.isEmpty()) << saved.line().toStdString();
    const app::ReportMeasurements read = app::readMeasurements(file);
    ASSERT_TRUE(read.sizing.has_value());
    EXPECT_NEAR(
        read.sizing->neckLengthMm.value.value(),
        tableValue(lengths,
                   QStringLiteral("Neck length (lowest renal artery to start of the aneurysm)")),
        0.051);
    ASSERT_FALSE(read.branches.empty());
    EXPECT_EQ(read.branches[0].name, "abdominal aorta");
    ASSERT_TRUE(read.branches[0].stenosisDiameterPercent.has_value());
    EXPECT_NEAR(*read.branches[0].stenosisDiameterPercent, trunkStenosis(), 1e-9)
        << "the file grades as the panel does";
    EXPECT_EQ(read.landmarks.size(), 6U);

    // The sections along the path as CSV: one row per profile point, in its order.
    const fs::path csv = dir / (std::string(info->name()) + ".csv");
    const gui::ProblemText exported = panel().exportSectionsTo(csv);
    ASSERT_TRUE(exported.summary.isEmpty()) << exported.line().toStdString();
    std::ifstream in(csv);
    std::string header;
    std::getline(in, header);
    EXPECT_EQ(header.rfind("path_mm,branch_id,branch_name,point,", 0), 0U) << header;
    std::size_t rows = 0;
    double last = -1.0;
    for (std::string line; std::getline(in, line);) {
        const double rowMm = std::stod(line.substr(0, line.find(',')));
        EXPECT_GE(rowMm, last);
        last = rowMm;
        ++rows;
    }
    EXPECT_EQ(rows, state().profile().size());
    EXPECT_NEAR(last, state().path().lengthMm(), 1e-3);

    // A new scene clears the analysis and its views.
    window_->setScene(makeTubeScene(), QStringLiteral("tube"));
    EXPECT_FALSE(state().hasAnalysis());
    EXPECT_FALSE(window_->diameterProfileDock()->isVisible());
}

TEST_F(PlanningGui, TheSegmentedCtaMeasuresAsTheTreeItWasBuiltFrom) {
    const auto cta = makeSyntheticCta({96, 96, 80}, 3);
    const fs::path dir = panelTestDir() / "planning-cta";
    fs::remove_all(dir);
    (void)writeCtSeries(dir / "series", cta.volume);
    openDicomFolder(dir / "series");
    ASSERT_TRUE(waitForFrames());
    ASSERT_NO_FATAL_FAILURE(findCenterlines());
    // The root vessel: from the source, along the root's built centreline.
    const auto& root = cta.tree.segments.front();
    const glm::dvec3 a(root.centerline[root.centerline.size() / 4]);
    const glm::dvec3 b(root.centerline[root.centerline.size() / 2]);
    // The path from the source to any end passes the root.
    ASSERT_TRUE(state().moveCursorNear(a)) << "the root's first quarter is not on the default path";
    place(LandmarkKind::Free, a, QStringLiteral("A"));
    place(LandmarkKind::Free, b, QStringLiteral("B"));
    ASSERT_EQ(state().landmarks().size(), 2U);
    double builtAlong = 0.0;
    for (std::size_t i = root.centerline.size() / 4; i < root.centerline.size() / 2; ++i) {
        builtAlong +=
            glm::length(glm::dvec3(root.centerline[i + 1]) - glm::dvec3(root.centerline[i]));
    }
    const glm::dvec3 spacing = cta.volume.spacing();
    const double voxel = std::max({spacing.x, spacing.y, spacing.z});
    // A section's wall within half a voxel on each side: the diameter within a voxel.
    const QString landmarks = QStringLiteral("Landmarks");
    for (const QString& label : {QStringLiteral("A"), QStringLiteral("B")}) {
        EXPECT_NEAR(tableValue(landmarks, label), 2.0 * root.radiusMm, voxel)
            << label.toStdString();
    }
    // The length between them along the centreline: each end within a voxel.
    EXPECT_NEAR(
        tableValue(QStringLiteral("Lengths between landmarks"), QStringLiteral("A \u2013 B")),
        builtAlong, 2.0 * voxel);

    // The curved reformation: the path straight along x. Its middle row runs
    // down the lumen (contrast ~400 HU) wherever a section measures the
    // vessel; rows two radii and two voxels off it lie in tissue (~40 HU).
    gui::CurvedReformation* cpr = window_->curvedReformation();
    ASSERT_TRUE(cpr->isVisible());
    {
        const Image<float>& values = cpr->values();
        ASSERT_EQ(static_cast<std::size_t>(values.width()), state().profile().size());
        const int middle = values.height() / 2;
        EXPECT_NEAR(middle * cpr->rowSpacingMm(), cpr->halfWidthMm(), cpr->rowSpacingMm());
        std::vector<float> lumen;
        std::vector<float> tissue;
        for (int c = 0; c < values.width(); ++c) {
            const gui::ProfilePoint& p = state().profile()[static_cast<std::size_t>(c)];
            if (!p.measured) {
                continue;
            }
            lumen.push_back(values(c, middle));
            const int off =
                static_cast<int>(std::ceil((p.maxMm + 2.0 * voxel) / cpr->rowSpacingMm()));
            for (const int r : {middle - off, middle + off}) {
                if (r >= 0 && r < values.height() && std::isfinite(values(c, r))) {
                    tissue.push_back(values(c, r));
                }
            }
        }
        const auto median = [](std::vector<float> v) {
            std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2),
                             v.end());
            return v[v.size() / 2];
        };
        ASSERT_GT(lumen.size(), 50U);
        ASSERT_GT(tissue.size(), 50U);
        EXPECT_GT(median(lumen), 250.0F);
        EXPECT_LT(median(tissue), 150.0F);
    }
    // Turned about the path the lumen stays in the middle row.
    cpr->rotationSlider()->setValue(90);
    EXPECT_EQ(cpr->rotation(), 90);
    EXPECT_GT(cpr->values()(cpr->values().width() / 2, cpr->values().height() / 2), 250.0F)
        << "at the path's middle";

    // The cross-section at the cursor: the image resliced across the
    // vessel, bright at the centreline, its calipers the section's sizes.
    ASSERT_TRUE(state().moveCursorNear(a));
    gui::CrossSectionView* section = window_->crossSection();
    ASSERT_TRUE(section->section().has_value());
    const QImage& image = section->image();
    ASSERT_FALSE(image.isNull());
    EXPECT_GT(qGray(image.pixel(image.width() / 2, image.height() / 2)), 160);
    EXPECT_LT(qGray(image.pixel(2, 2)), 160) << "tissue or outside at the corner";
    const QString texts = section->texts().join(QLatin1Char(' '));
    EXPECT_TRUE(texts.contains(QString::fromStdString(
        report::measurementCellText({section->section()->minDiameterMm, 1, "mm", {}}))))
        << texts.toStdString();

    // File > Export Report with the measurements and their SR: the PDF shows
    // the profile (its equivalent diameter's colour), the reformation and
    // the cross-sections (the contour's colour) within its margins; the SR
    // carries the landmarks' diameters.
    const fs::path pdf = dir / "report.pdf";
    const fs::path sr = dir / "report-sr.dcm";
    const QString failure = exportReport(pdf, [&](gui::ReportDialog& dialog) {
        ASSERT_NE(dialog.measurementsBox(), nullptr);
        EXPECT_TRUE(dialog.measurementsBox()->isChecked());
        dialog.dicomSrBox()->setChecked(true);
        dialog.dicomSrEdit()->setText(QString::fromStdString(sr.string()));
    });
    ASSERT_TRUE(failure.isEmpty()) << failure.toStdString();
    std::string text;
    ASSERT_EQ(report::test::runTool("pdftotext -layout '" + pdf.string() + "' -", text), 0);
    text = report::test::withoutLigatures(text);
    EXPECT_NE(text.find("Diameter profile along the path"), std::string::npos);
    EXPECT_NE(text.find("Curved reformation along the path"), std::string::npos);
    const std::vector<QImage> pages = report::test::pdfPages(pdf, dir / "pages", 100);
    int blue = 0;
    int contour = 0;
    for (const QImage& page : pages) {
        EXPECT_TRUE(report::test::marginProblems(page, 100).empty());
        for (int y = 0; y < page.height(); ++y) {
            for (int x = 0; x < page.width(); ++x) {
                const QColor c = page.pixelColor(x, y);
                const auto near = [&c](int red, int green, int blue2) {
                    return std::abs(c.red() - red) < 30 && std::abs(c.green() - green) < 30 &&
                           std::abs(c.blue() - blue2) < 30;
                };
                blue += near(0, 114, 178) ? 1 : 0;
                contour += near(230, 170, 0) ? 1 : 0;
            }
        }
    }
    EXPECT_GT(blue, 200) << "the profile's equivalent diameter line";
    EXPECT_GT(contour, 100) << "the cross-sections' contours";
    std::string dump;
    ASSERT_EQ(report::test::runTool("dsrdump +Pl '" + sr.string() + "'", dump), 0) << dump;
    EXPECT_NE(dump.find("Equivalent diameter (2 sqrt(area / pi)), at A"), std::string::npos)
        << dump;

    // The slice views follow the cursor, and the mouse over the profile.
    const auto placeAt = [&](double mm) {
        return planning::sampleAt(state().analysis()->tree, state().path().locationAt(mm)).position;
    };
    gui::SliceCursor* slices = window_->sliceWorkspace()->cursor();
    ASSERT_TRUE(slices->point().has_value());
    EXPECT_LT(glm::distance(*slices->point(), placeAt(state().cursorMm())), 1e-6);
    emit window_->diameterProfile()->hovered(20.0);
    EXPECT_LT(glm::distance(*slices->point(), placeAt(20.0)), 1e-6);
    emit window_->diameterProfile()->hovered(std::nan(""));
    EXPECT_LT(glm::distance(*slices->point(), placeAt(state().cursorMm())), 1e-6);

    // The wheel steps along the path, one section a notch.
    state().stepCursor(0);  // onto a section
    const double before = state().cursorMm();
    QWheelEvent wheel(QPointF(10, 10), section->mapToGlobal(QPointF(10, 10)), QPoint(),
                      QPoint(0, -120), Qt::NoButton, Qt::NoModifier, Qt::NoScrollPhase, false);
    QCoreApplication::sendEvent(section, &wheel);
    EXPECT_NEAR(state().cursorMm() - before, 0.5, 0.05);
}

TEST_F(PlanningGui, ASessionReopensTheCentrelinesPathLandmarksAndCursor) {
    const demo::AneurysmPhantom truth = phantom();
    const fs::path dir = panelTestDir() / "planning-session";
    fs::create_directories(dir);
    const fs::path surface = dir / "aorta.vtp";
    meshio::writeMeshFile(truth.mesh, surface);
    window_->openFiles({QString::fromStdString(surface.string())});
    ASSERT_TRUE(waitUntil([&] { return window_->viewer()->scene() != nullptr; }));
    ASSERT_TRUE(waitForFrames());
    ASSERT_NO_FATAL_FAILURE(findCenterlines());
    const int last = static_cast<int>(state().analysis()->tree.ends.size()) - 1;
    choosePath(last, 0);  // against the default direction
    place(LandmarkKind::LowestRenalArtery, {0, 0, 20.0});
    place(LandmarkKind::Free, {0, 0, 100.0}, QStringLiteral("Thrombus begins"));
    state().renameBranch(0, QStringLiteral("aorta"));
    ASSERT_TRUE(state().moveCursorNear({0, 0, 30.0}));
    ASSERT_TRUE(state().setReferenceAtCursor(true));
    ASSERT_TRUE(state().moveCursorNear({0, 0, 60.0}));
    const auto before = state().sessionState();
    ASSERT_TRUE(before.has_value());
    const fs::path session = dir / "planning.vvs";
    ASSERT_TRUE(window_->saveSessionTo(QString::fromStdString(session.string())));

    ASSERT_TRUE(openSessionInNewWindow(QString::fromStdString(session.string())));
    ASSERT_TRUE(waitUntil([&] { return state().hasAnalysis() && !panel().analysing(); }, 240000))
        << panel().statusLabel()->text().toStdString();
    const auto after = state().sessionState();
    ASSERT_TRUE(after.has_value());
    EXPECT_EQ(after->pathFrom, last);
    EXPECT_EQ(after->pathTo, 0);
    EXPECT_NEAR(after->cursorMm, before->cursorMm, 1e-9);
    EXPECT_EQ(after->branchNames, before->branchNames);
    ASSERT_EQ(after->landmarks.size(), 2U);
    for (std::size_t i = 0; i < 2; ++i) {
        EXPECT_EQ(after->landmarks[i].name, before->landmarks[i].name);
        EXPECT_EQ(after->landmarks[i].kind, before->landmarks[i].kind);
        EXPECT_EQ(after->landmarks[i].location.branch, before->landmarks[i].location.branch);
        EXPECT_NEAR(after->landmarks[i].location.abscissaMm,
                    before->landmarks[i].location.abscissaMm, 1e-9);
    }
    ASSERT_EQ(after->stenosisReferences.count(0), 1U);
    EXPECT_NEAR(after->stenosisReferences.at(0).proximalMm,
                before->stenosisReferences.at(0).proximalMm, 1e-9);
    // What the person sees: the panel's rows and the profile's dock.
    EXPECT_EQ(panel().landmarkTable()->rowCount(), 2);
    EXPECT_EQ(panel().branchTable()->item(0, 0)->text(), QStringLiteral("aorta"));
    EXPECT_TRUE(window_->diameterProfileDock()->isVisible());
}

TEST_F(PlanningGui, PickedEndsAreWhereTheCentrelinesStartAndEndAndLinesTakeTheirColours) {
    demo::AneurysmPhantomOptions options;
    options.targetTriangles = 30'000;
    options.openEnds = false;  // closed: the automatic ends are the tips
    const demo::AneurysmPhantom truth = demo::makeAneurysmPhantom(options);
    auto scene = std::make_shared<scene::Scene>();
    scene->meshes.push_back(truth.mesh);
    window_->setScene(scene, QStringLiteral("phantom"));
    ASSERT_TRUE(waitForFrames());
    // A click on the trunk picks the start (through the viewer's probe).
    panel().pickEndsButton()->setChecked(true);
    const auto at = window_->planningOverlay()->project({0.0, 0.0, 40.0});
    ASSERT_TRUE(at.has_value());
    QMouseEvent press(QEvent::MouseButtonPress, *at, window_->viewer()->mapToGlobal(*at),
                      Qt::LeftButton, Qt::LeftButton, Qt::NoModifier);
    QCoreApplication::sendEvent(window_->viewer(), &press);
    QMouseEvent release(QEvent::MouseButtonRelease, *at, window_->viewer()->mapToGlobal(*at),
                        Qt::LeftButton, Qt::NoButton, Qt::NoModifier);
    QCoreApplication::sendEvent(window_->viewer(), &release);
    ASSERT_TRUE(state().givenSource().has_value()) << "the click picked no start";
    EXPECT_LT(std::hypot(state().givenSource()->x, state().givenSource()->y),
              1.5 * options.radiusMm)
        << "on the trunk";
    // The right iliac's end only, 50 mm down it: the left iliac is left out.
    panel().addEnd(truth.bifurcationPoint + 50.0 * truth.iliacDirections[0]);
    EXPECT_TRUE(panel().endsLabel()->text().contains(QStringLiteral("1")));
    ASSERT_NO_FATAL_FAILURE(findCenterlines());
    const auto& tree = state().analysis()->tree;
    ASSERT_EQ(tree.ends.size(), 2U);
    EXPECT_EQ(tree.ends[0].kind, analysis::EndPoint::Kind::Given);
    // Where the click's ray met the wall (the surface nearest the viewer).
    EXPECT_LT(glm::length(tree.ends[0].position - *state().givenSource()),
              options.maxRadiusMm + 3.0);
    EXPECT_NEAR(glm::length(tree.ends[1].position -
                            (truth.bifurcationPoint + 50.0 * truth.iliacDirections[0])),
                0.0, 3.0);
    ASSERT_TRUE(state().sessionState()->source.has_value()) << "sessions keep the picked ends";

    // The lines by branch: the overlay paints the label palette's colours.
    const auto countColour = [&](const glm::vec3& c) {
        window_->planningOverlay()->repaint();
        const QImage image = window_->planningOverlay()->grab().toImage();
        const QColor want = QColor::fromRgbF(c.r, c.g, c.b);
        int n = 0;
        for (int y = 0; y < image.height(); ++y) {
            for (int x = 0; x < image.width(); ++x) {
                const QColor got = image.pixelColor(x, y);
                n += std::abs(got.red() - want.red()) + std::abs(got.green() - want.green()) +
                                 std::abs(got.blue() - want.blue()) <
                             30
                         ? 1
                         : 0;
            }
        }
        return n;
    };
    const glm::vec3 branchOne = colormaps::labelColor(0);  // the one branch
    const int before = countColour(branchOne);
    QComboBox* lines = panel().linesChooser();
    lines->setCurrentIndex(
        lines->findData(static_cast<int>(gui::PlanningOverlay::Colouring::Branch)));
    EXPECT_EQ(window_->planningOverlay()->colouring(), gui::PlanningOverlay::Colouring::Branch);
    EXPECT_GT(countColour(branchOne), before + 20) << "branch 0 in its palette colour";

    // Back to the automatic ends.
    panel().automaticEndsButton()->click();
    EXPECT_FALSE(state().givenSource().has_value());
}

TEST(PlanningSession, ABadPlanningObjectIsRefusedNamingItsField) {
    app::Session s;
    s.files << QStringLiteral("/data/aorta.vtp");
    app::PlanningSessionState p;
    p.pathTo = 2;
    p.landmarks.push_back({"Lowest renal artery", LandmarkKind::LowestRenalArtery, {0, 12.5}});
    p.branchNames[1] = "left iliac";
    s.planning = p;
    const fs::path file = "/tmp/x.vvs";
    const QByteArray json = app::sessionToJson(s, file);
    const app::Session back = app::sessionFromJson(json, file);
    ASSERT_TRUE(back.planning.has_value());
    EXPECT_EQ(back.planning->pathTo, 2);
    EXPECT_EQ(back.planning->landmarks.at(0).kind, LandmarkKind::LowestRenalArtery);
    EXPECT_EQ(back.planning->branchNames.at(1), "left iliac");
    const std::array<std::pair<const char*, const char*>, 3> broken{{
        {R"("kind": "lowest_renal_artery")", R"("kind": "renal")"},
        {R"("cursor_mm": 0)", R"("cursor_mm": -5)"},
        {R"("to": 2)", R"("to": "two")"},
    }};
    const std::array<std::string, 3> fields{"planning.landmarks[0].kind", "planning.cursor_mm",
                                            "planning.path.to"};
    for (std::size_t i = 0; i < std::size(broken); ++i) {
        std::string text = json.toStdString();
        const auto at = text.find(broken[i].first);
        ASSERT_NE(at, std::string::npos) << broken[i].first << " in " << text;
        text.replace(at, std::strlen(broken[i].first), broken[i].second);
        try {
            (void)app::sessionFromJson(QByteArray::fromStdString(text), file);
            ADD_FAILURE() << "accepted " << broken[i].second;
        } catch (const FormatError& e) {
            EXPECT_NE(std::string(e.what()).find(fields[i]), std::string::npos) << e.what();
            EXPECT_NE(std::string(e.what()).find("x.vvs"), std::string::npos) << e.what();
        }
    }
}

}  // namespace
}  // namespace vv::test
