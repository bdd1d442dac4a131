// SPDX-License-Identifier: GPL-3.0-or-later
// The study's stimuli rendered from a vessel tree: the manifest's markers
// sit where its depths say (read back from the G-buffer) and the answer key
// follows them; the markers are drawn where the manifest puts them and
// leave the marked point itself as it was; the conditions show what their
// names say; the same seed makes the same study.
#include <gtest/gtest.h>

#include <QFile>
#include <QImage>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <algorithm>
#include <cmath>
#include <filesystem>

#include "GlTestSupport.h"
#include "vv/demo/DemoTree.h"
#include "vv/study/Manifest.h"
#include "vv/study/Stimuli.h"

namespace vv::study {
namespace {

constexpr int kWidth = 480;
constexpr int kHeight = 320;

/// The demo tree of 4 generations, made once.
const StimulusScene& tree() {
    static const StimulusScene scene = [] {
        demo::DemoTreeOptions o;
        o.generations = 4;
        StimulusScene made{"tree", "demo, 4 generations", {}};
        made.scene.meshes.push_back(demo::buildVesselSurface(demo::generateVesselTree(o), o));
        return made;
    }();
    return scene;
}

class StimuliTest : public ::testing::Test {
  protected:
    static void SetUpTestSuite() { test::ensureGuiApplication(); }
    static std::filesystem::path folder(const std::string& name) {
        auto dir = std::filesystem::path(VV_TEST_TMP) / "study-stimuli" / name;
        std::filesystem::remove_all(dir);
        return dir;
    }
    static StimulusOptions options() {
        StimulusOptions o;
        o.width = kWidth;
        o.height = kHeight;
        o.pairsPerScene = 3;
        o.trainingPairsPerScene = 1;
        o.seed = 5;
        return o;
    }
    static std::vector<StimulusCondition> twoConditions() {
        const auto all = paperConditions();
        return {all[0], all[4]};  // VSS-CD, baseline
    }
    static QJsonObject manifestOf(const std::filesystem::path& dir) {
        QFile file(QString::fromStdString((dir / "manifest.json").string()));
        EXPECT_TRUE(file.open(QIODevice::ReadOnly));
        return QJsonDocument::fromJson(file.readAll()).object();
    }
};

TEST(StudyConditions, ThePapersFive) {
    const auto c = paperConditions();
    ASSERT_EQ(c.size(), 5U);
    EXPECT_EQ(c[0].name, "VSS-CD");
    EXPECT_TRUE(c[0].display.vss.enabled);
    EXPECT_EQ(c[1].display.vss.scale, colormaps::DepthScale::PseudoChromadepth);
    EXPECT_FALSE(c[2].display.vss.enabled);
    EXPECT_EQ(c[2].display.cue.cue, render::VesselCue::Chromadepth);
    EXPECT_EQ(c[3].display.cue.cue, render::VesselCue::PseudoChromadepth);
    EXPECT_FALSE(c[4].display.vss.enabled);
    EXPECT_EQ(c[4].display.cue.cue, render::VesselCue::None);
    for (const auto& condition : c) {
        EXPECT_FALSE(condition.display.legends) << condition.name;
        EXPECT_EQ(condition.display.vss.isoLines, 0) << condition.name;
    }
}

TEST_F(StimuliTest, TheMarkersSitWhereTheManifestSaysAndTheKeyFollowsTheDepths) {
    auto renderer = test::makeOffscreenRenderer();
    ASSERT_NE(renderer, nullptr);
    const auto dir = folder("main");
    const StudyStimuli made = makeStimuli(*renderer, {tree()}, twoConditions(), options(), dir);
    ASSERT_EQ(made.stimuli.size(), 8U);  // (3 main + 1 training pair) x 2 conditions
    const QJsonObject manifest = manifestOf(dir);
    const QJsonArray stimuli = manifest["stimuli"].toArray();
    ASSERT_EQ(stimuli.size(), 8);

    // The runner reads back what was written: blocks, answers, markers.
    const StudyManifest read = readManifest(dir);
    ASSERT_EQ(read.stimuli.size(), made.stimuli.size());
    EXPECT_EQ(read.conditions, (std::vector<std::string>{"VSS-CD", "baseline"}));
    EXPECT_EQ(read.indicesOf(Block::Training).size(), 2U);
    for (std::size_t i = 0; i < read.stimuli.size(); ++i) {
        const Stimulus& m = made.stimuli[i];
        const ManifestStimulus& r = read.stimuli[i];
        EXPECT_EQ(r.id, m.id);
        EXPECT_EQ(r.block, m.block);
        EXPECT_EQ(r.correctAnswer, m.markers.leftIsCloser ? Side::Left : Side::Right);
        EXPECT_EQ(r.left.x, m.markers.left.x);
        EXPECT_EQ(r.right.y, m.markers.right.y);
        EXPECT_TRUE(std::filesystem::is_regular_file(r.image));
        if (m.block == Block::Training) {
            EXPECT_NE(m.id.find("-t1-"), std::string::npos) << m.id;
            // A training pair is none of the main pairs.
            for (const Stimulus& other : made.stimuli) {
                if (other.block == Block::Main) {
                    EXPECT_FALSE(other.markers.left.x == m.markers.left.x &&
                                 other.markers.left.y == m.markers.left.y)
                        << m.id << " repeats " << other.id;
                }
            }
        }
    }

    render::OffscreenOptions view;
    view.width = kWidth;
    view.height = kHeight;
    view.display = paperConditions()[0].display;
    view.camera = render::OffscreenRenderer::cameraFor(tree().scene, view);
    const Image<float> depth = renderer->renderDepth(tree().scene, view);
    const int radius = options().criteria.markerRadius;
    for (const auto& value : stimuli) {
        const QJsonObject s = value.toObject();
        const QJsonObject left = s["left"].toObject();
        const QJsonObject right = s["right"].toObject();
        const int lx = left["x"].toInt();
        const int ly = left["y"].toInt();
        const int rx = right["x"].toInt();
        const int ry = right["y"].toInt();
        // The depths are the G-buffer's at those pixels.
        EXPECT_NEAR(left["depth"].toDouble(), depth.view()(lx, ly), 1e-4);
        EXPECT_NEAR(right["depth"].toDouble(), depth.view()(rx, ry), 1e-4);
        EXPECT_EQ(s["correct_answer"].toString(),
                  left["depth"].toDouble() < right["depth"].toDouble() ? "left" : "right");
        EXPECT_LT(lx, rx);
        EXPECT_GE(s["depth_difference"].toDouble(), 0.1);
        // The markers drawn there: a white arm, a black outline beyond it,
        // and the marked point itself as the unmarked image shows it.
        const QImage image(
            QString::fromStdString((dir / s["image"].toString().toStdString()).string()));
        ASSERT_EQ(image.size(), QSize(kWidth, kHeight));
        view.display = s["condition"].toString() == "VSS-CD" ? paperConditions()[0].display
                                                             : paperConditions()[4].display;
        const QImage plain = renderer->render(tree().scene, view);
        for (const auto& [x, y] : {std::pair{lx, ly}, std::pair{rx, ry}}) {
            const QColor arm(image.pixel(x + static_cast<int>(0.7 * radius), y));
            EXPECT_GT(arm.lightness(), 230) << s["id"].toString().toStdString();
            const QColor edge(image.pixel(x + radius, y));
            EXPECT_LT(edge.lightness(), 80) << s["id"].toString().toStdString();
            const QColor centre(image.pixel(x, y));
            const QColor unmarked(plain.pixel(x, y));
            EXPECT_NEAR(centre.red(), unmarked.red(), 2);
            EXPECT_NEAR(centre.green(), unmarked.green(), 2);
            EXPECT_NEAR(centre.blue(), unmarked.blue(), 2);
        }
    }
}

TEST_F(StimuliTest, TheConditionsShowWhatTheirNamesSay) {
    auto renderer = test::makeOffscreenRenderer();
    ASSERT_NE(renderer, nullptr);
    const auto dir = folder("conditions");
    const StudyStimuli made = makeStimuli(*renderer, {tree()}, twoConditions(), options(), dir);
    const QImage vss(QString::fromStdString((dir / made.stimuli[0].image).string()));
    const auto firstBaseline =
        std::find_if(made.stimuli.begin(), made.stimuli.end(),
                     [](const auto& s) { return s.condition == "baseline"; });
    ASSERT_NE(firstBaseline, made.stimuli.end());
    const QImage baseline(QString::fromStdString((dir / firstBaseline->image).string()));
    ASSERT_EQ(made.stimuli[0].condition, "VSS-CD");
    // On the background (no vessel) the VSS paints the void; the baseline does not.
    render::OffscreenOptions view;
    view.width = kWidth;
    view.height = kHeight;
    const Image<float> depth = renderer->renderDepth(tree().scene, view);
    const QRgb background = baseline.pixel(0, 0);
    long voidPixels = 0;
    long painted = 0;
    long plainBaseline = 0;
    for (int y = 0; y < kHeight; ++y) {
        for (int x = 0; x < kWidth; ++x) {
            if (std::isfinite(depth.view()(x, y))) {
                continue;
            }
            ++voidPixels;
            painted += vss.pixel(x, y) != background ? 1 : 0;
            plainBaseline += baseline.pixel(x, y) == background ? 1 : 0;
        }
    }
    ASSERT_GT(voidPixels, 1000);
    EXPECT_GT(painted, voidPixels / 2);
    EXPECT_GT(plainBaseline, voidPixels * 95 / 100);
}

TEST_F(StimuliTest, TheSameSeedMakesTheSameStudy) {
    auto renderer = test::makeOffscreenRenderer();
    ASSERT_NE(renderer, nullptr);
    const auto first = folder("seed-a");
    const auto second = folder("seed-b");
    static_cast<void>(makeStimuli(*renderer, {tree()}, twoConditions(), options(), first));
    static_cast<void>(makeStimuli(*renderer, {tree()}, twoConditions(), options(), second));
    EXPECT_EQ(manifestOf(first)["stimuli"], manifestOf(second)["stimuli"]);
    StimulusOptions other = options();
    other.seed = 6;
    const auto third = folder("seed-c");
    static_cast<void>(makeStimuli(*renderer, {tree()}, twoConditions(), other, third));
    EXPECT_NE(manifestOf(first)["stimuli"], manifestOf(third)["stimuli"]);
}

TEST_F(StimuliTest, BadInputIsRefused) {
    auto renderer = test::makeOffscreenRenderer();
    ASSERT_NE(renderer, nullptr);
    const auto dir = folder("bad");
    EXPECT_THROW(makeStimuli(*renderer, {}, twoConditions(), options(), dir), InvalidArgumentError);
    auto conditions = twoConditions();
    conditions[1].name = "VSS-CD";
    EXPECT_THROW(makeStimuli(*renderer, {tree()}, conditions, options(), dir),
                 InvalidArgumentError);
    conditions[1].name = "../escape";
    EXPECT_THROW(makeStimuli(*renderer, {tree()}, conditions, options(), dir),
                 InvalidArgumentError);
    StimulusScene empty{"empty", "nothing", {}};
    EXPECT_THROW(makeStimuli(*renderer, {empty}, twoConditions(), options(), dir), Error);
}

}  // namespace
}  // namespace vv::study
