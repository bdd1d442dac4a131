// SPDX-License-Identifier: GPL-3.0-or-later
// Saved sessions (.vvs): JSON round trip, the version-0 converter, clear
// errors for bad files (never a crash), and save -> load giving the same image.
#include <QAction>
#include <QByteArray>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLabel>
#include <QLineF>
#include <QMessageBox>
#include <QMouseEvent>
#include <array>
#include <cmath>
#include <filesystem>
#include <span>
#include <string>

#include "GuiFixture.h"
#include "gui/MeasureOverlay.h"
#include "gui/Session.h"
#include "vv/core/Error.h"

namespace vv::test {
namespace {

fs::path sessionDir() {
    const fs::path dir = panelTestDir() / "sessions";
    fs::create_directories(dir);
    return dir;
}

fs::path writeText(const std::string& name, const QByteArray& text) {
    const fs::path path = sessionDir() / name;
    QFile f(QString::fromStdString(path.string()));
    EXPECT_TRUE(f.open(QIODevice::WriteOnly | QIODevice::Truncate));
    f.write(text);
    return path;
}

gui::Session sampleSession() {
    gui::Session s;
    s.files = {QStringLiteral("/data/a.vtp"), QStringLiteral("/data/b.stl")};
    s.cameraTarget = glm::vec3(1.5F, -2.0F, 3.25F);
    s.cameraDistance = 42.0F;
    s.cameraRotation = glm::normalize(glm::quat(0.9F, 0.1F, -0.3F, 0.2F));
    s.fieldOfView = 40.0F;
    s.vss.enabled = false;
    s.vss.scale = colormaps::DepthScale::DarkMeansDeep;
    s.vss.solver.kind = vss::SolverKind::Step;
    s.vss.solver.p = 5.5;
    s.vss.solver.step = 4;
    s.vss.solver.tolerance = 0.01;
    s.vss.isoLines = 3;
    s.vss.isoLineStrength = 0.25F;
    s.vss.lighting = 0.5F;
    s.vss.range.mode = vss::RangeMode::Fixed;
    s.vss.range.dmin = 80.0;
    s.vss.range.dmax = 215.5;
    s.ao.enabled = false;
    s.ao.radius = 6.0F;
    s.ao.strength = 0.4F;
    s.cue.cue = render::VesselCue::Fog;
    s.cue.fogStrength = 0.3F;
    s.style.array = "pressure";
    s.style.colorMap = colormaps::ColorMap::Cividis;
    s.style.bins = 7;
    s.style.range = std::make_pair(-1.5F, 20.0F);
    s.style.vesselColor = glm::vec3(0.25F, 0.5F, 0.75F);
    s.background = glm::vec3(1.0F, 1.0F, 1.0F);
    s.legends = false;
    s.layout = QByteArray("layout bytes");
    return s;
}

void expectSame(const gui::Session& a, const gui::Session& b) {
    EXPECT_EQ(a.files, b.files);
    EXPECT_EQ(a.cameraTarget, b.cameraTarget);
    EXPECT_FLOAT_EQ(a.cameraDistance, b.cameraDistance);
    EXPECT_NEAR(glm::dot(a.cameraRotation, b.cameraRotation), 1.0F, 1e-6F);
    EXPECT_FLOAT_EQ(a.fieldOfView, b.fieldOfView);
    EXPECT_EQ(a.vss.enabled, b.vss.enabled);
    EXPECT_EQ(a.vss.scale, b.vss.scale);
    EXPECT_EQ(a.vss.range.mode, b.vss.range.mode);
    EXPECT_DOUBLE_EQ(a.vss.range.dmin, b.vss.range.dmin);
    EXPECT_DOUBLE_EQ(a.vss.range.dmax, b.vss.range.dmax);
    EXPECT_EQ(a.vss.solver.kind, b.vss.solver.kind);
    EXPECT_DOUBLE_EQ(a.vss.solver.p, b.vss.solver.p);
    EXPECT_EQ(a.vss.solver.step, b.vss.solver.step);
    EXPECT_DOUBLE_EQ(a.vss.solver.tolerance, b.vss.solver.tolerance);
    EXPECT_EQ(a.vss.isoLines, b.vss.isoLines);
    EXPECT_FLOAT_EQ(a.vss.isoLineStrength, b.vss.isoLineStrength);
    EXPECT_FLOAT_EQ(a.vss.lighting, b.vss.lighting);
    EXPECT_EQ(a.ao.enabled, b.ao.enabled);
    EXPECT_FLOAT_EQ(a.ao.radius, b.ao.radius);
    EXPECT_FLOAT_EQ(a.ao.strength, b.ao.strength);
    EXPECT_EQ(a.cue.cue, b.cue.cue);
    EXPECT_FLOAT_EQ(a.cue.fogStrength, b.cue.fogStrength);
    EXPECT_EQ(a.style.array, b.style.array);
    EXPECT_EQ(a.style.colorMap, b.style.colorMap);
    EXPECT_EQ(a.style.bins, b.style.bins);
    EXPECT_EQ(a.style.range, b.style.range);
    EXPECT_EQ(a.style.vesselColor, b.style.vesselColor);
    EXPECT_EQ(a.background, b.background);
    EXPECT_EQ(a.legends, b.legends);
    EXPECT_EQ(a.layout, b.layout);
}

/// The session error for `json`: the FormatError's message ("" when none was thrown).
std::string errorFor(const std::string& name, const QByteArray& json) {
    const fs::path path = writeText(name, json);
    try {
        static_cast<void>(gui::loadSession(path));
    } catch (const FormatError& e) {
        EXPECT_EQ(e.file(), path);
        EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
        return e.problem();
    }
    return {};
}

/// `json` with `from` (found once) replaced by `to`, saved as `name`: its
/// error names the field `field` ('field').
struct BadValue {
    const char* name;
    QByteArray from;
    QByteArray to;
    const char* field;
};

void expectRefused(const QByteArray& json, std::span<const BadValue> cases) {
    for (const BadValue& c : cases) {
        QByteArray bad = json;
        ASSERT_EQ(bad.count(c.from), 1) << c.name << ": " << json.toStdString();
        bad.replace(c.from, c.to);
        const std::string error = errorFor(c.name, bad);
        EXPECT_NE(error.find(std::string("'") + c.field + "'"), std::string::npos)
            << c.name << ": " << error;
    }
}

/// The valid sample as JSON with `from` replaced by `to` (exactly once).
QByteArray sampleWith(const QByteArray& from, const QByteArray& to) {
    QByteArray json = gui::sessionToJson(sampleSession(), sessionDir() / "x.vvs");
    EXPECT_EQ(json.count(from), 1) << from.toStdString();
    return json.replace(from, to);
}

TEST(SessionFile, RoundTripKeepsEverything) {
    const gui::Session s = sampleSession();
    const fs::path path = sessionDir() / "round-trip.vvs";
    gui::saveSession(path, s);
    expectSame(gui::loadSession(path), s);
    // Atomic write: no temporary file stays behind.
    for (const auto& entry : fs::directory_iterator(sessionDir())) {
        EXPECT_EQ(entry.path().filename().string().find(".tmp"), std::string::npos) << entry.path();
    }
    const QByteArray json = gui::sessionToJson(s, path);
    EXPECT_TRUE(json.contains("\"version\": 1")) << json.toStdString();
}

TEST(SessionFile, TheDepthRangeIsOptionalAndChecked) {
    // Written before the range existed: the visible range.
    QByteArray json = gui::sessionToJson(sampleSession(), sessionDir() / "x.vvs");
    const QJsonDocument doc = QJsonDocument::fromJson(json);
    QJsonObject root = doc.object();
    QJsonObject view = root.value(QStringLiteral("view")).toObject();
    QJsonObject vssObject = view.value(QStringLiteral("vss")).toObject();
    vssObject.remove(QStringLiteral("range"));
    view.insert(QStringLiteral("vss"), vssObject);
    root.insert(QStringLiteral("view"), view);
    const gui::Session old =
        gui::sessionFromJson(QJsonDocument(root).toJson(), sessionDir() / "old.vvs");
    EXPECT_EQ(old.vss.range.mode, vss::RangeMode::Visible);
    // Far before near, and an unknown mode, are refused with the field's name.
    EXPECT_NE(errorFor("range-far.vvs", sampleWith("\"far\": 215.5", "\"far\": 10"))
                  .find("view.vss.range.far"),
              std::string::npos);
    EXPECT_NE(errorFor("range-mode.vvs", sampleWith("\"fixed\"", "\"sideways\""))
                  .find("view.vss.range.mode"),
              std::string::npos);
}

TEST(SessionFile, TheDicomSourceRoundTripsAndIsChecked) {
    gui::Session s = sampleSession();
    EXPECT_FALSE(gui::sessionFromJson(gui::sessionToJson(s, sessionDir() / "x.vvs"),
                                      sessionDir() / "x.vvs")
                     .dicom.has_value());  // meshes: none
    segmentation::SceneSourceOptions dicom;
    dicom.seriesInstanceUid = "1.2.826.0.1.3680043.2.1125.5";
    dicom.segmentation.range = segmentation::ThresholdRange{250.0F, 650.0F, "chosen"};
    dicom.segmentation.keepComponents = 3;
    dicom.segmentation.seed = glm::ivec3(4, 5, 6);
    dicom.segmentation.removeBone = false;
    dicom.surface.targetTriangles = 12345;
    s.dicom = dicom;
    const QByteArray json = gui::sessionToJson(s, sessionDir() / "dicom.vvs");
    const gui::Session back = gui::sessionFromJson(json, sessionDir() / "dicom.vvs");
    ASSERT_TRUE(back.dicom.has_value());
    EXPECT_EQ(back.dicom->seriesInstanceUid, dicom.seriesInstanceUid);
    ASSERT_TRUE(back.dicom->segmentation.range.has_value());
    EXPECT_FLOAT_EQ(back.dicom->segmentation.range->lower, 250.0F);
    EXPECT_FLOAT_EQ(back.dicom->segmentation.range->upper, 650.0F);
    EXPECT_EQ(back.dicom->segmentation.keepComponents, 3);
    EXPECT_EQ(back.dicom->segmentation.seed, glm::ivec3(4, 5, 6));
    EXPECT_EQ(back.dicom->segmentation.removeBone, std::optional<bool>(false));
    EXPECT_EQ(back.dicom->surface.targetTriangles, 12345U);

    QByteArray bad = json;
    bad.replace("\"components\": 3", "\"components\": 0");
    EXPECT_NE(errorFor("dicom-components.vvs", bad).find("dicom.components"), std::string::npos);
    bad = json;
    bad.replace("650", "-650");
    EXPECT_NE(errorFor("dicom-threshold.vvs", bad).find("dicom.threshold"), std::string::npos);
}

// The MR intensity correction as the Segmentation panel had it (issue 30):
// saved when set, absent in older sessions (the modality's default then).
TEST(SessionFile, TheIntensityCorrectionRoundTripsAndIsChecked) {
    gui::Session s = sampleSession();
    segmentation::SceneSourceOptions dicom;
    dicom.seriesInstanceUid = "1.2.826.0.1.3680043.2.1125.6";
    dicom.segmentation.correctIntensity = false;
    s.dicom = dicom;
    const QByteArray json = gui::sessionToJson(s, sessionDir() / "mr.vvs");
    EXPECT_TRUE(json.contains("\"intensityCorrection\": false")) << json.toStdString();
    gui::Session back = gui::sessionFromJson(json, sessionDir() / "mr.vvs");
    ASSERT_TRUE(back.dicom.has_value());
    EXPECT_EQ(back.dicom->segmentation.correctIntensity, std::optional<bool>(false));
    s.dicom->segmentation.correctIntensity.reset();
    back = gui::sessionFromJson(gui::sessionToJson(s, sessionDir() / "mr2.vvs"),
                                sessionDir() / "mr2.vvs");
    EXPECT_FALSE(back.dicom->segmentation.correctIntensity.has_value());

    QByteArray bad = json;
    bad.replace("\"intensityCorrection\": false", "\"intensityCorrection\": 3");
    EXPECT_NE(errorFor("dicom-correction.vvs", bad).find("dicom.intensityCorrection"),
              std::string::npos);
}

// The title the window gave a series ("dicom.title") goes into the session
// and comes back, so that a reopened series is not named after its folder.
TEST(SessionFile, TheSeriesTitleRoundTripsAndIsChecked) {
    gui::Session s = sampleSession();
    s.seriesTitle = QStringLiteral("Becken-Bein-Angio – arterielle Phase 1,0 mm");
    // Without DICOM data there is no series to name: nothing is written.
    EXPECT_FALSE(gui::sessionToJson(s, sessionDir() / "x.vvs").contains("\"title\""));
    segmentation::SceneSourceOptions dicom;
    dicom.seriesInstanceUid = "1.2.826.0.1.3680043.2.1125.7";
    s.dicom = dicom;
    const QByteArray json = gui::sessionToJson(s, sessionDir() / "titled.vvs");
    const QJsonObject written = QJsonDocument::fromJson(json).object();
    EXPECT_EQ(written.value(QStringLiteral("dicom")).toObject().value(QStringLiteral("title")),
              QJsonValue(s.seriesTitle));
    EXPECT_EQ(written.value(QStringLiteral("version")).toInt(), 1);  // optional within version 1
    const gui::Session back = gui::sessionFromJson(json, sessionDir() / "titled.vvs");
    EXPECT_EQ(back.seriesTitle, s.seriesTitle);
    ASSERT_TRUE(back.dicom.has_value());
    EXPECT_EQ(back.dicom->seriesInstanceUid, dicom.seriesInstanceUid);
    expectSame(back, s);

    // Checked: a string, not blank, one line, not absurdly long.
    const QByteArray quoted = R"("title": ")" + s.seriesTitle.toUtf8() + R"(")";
    ASSERT_EQ(json.count(quoted), 1) << json.toStdString();
    for (const QByteArray& bad : {QByteArray(R"("title": 5)"), QByteArray(R"("title": "  ")"),
                                  QByteArray(R"("title": "CTA\nangio")"),
                                  R"("title": ")" + QByteArray(1025, 'x') + R"(")"}) {
        const std::string problem =
            errorFor("title-bad.vvs", QByteArray(json).replace(quoted, bad));
        EXPECT_NE(problem.find("dicom.title"), std::string::npos) << bad.toStdString();
    }
}

// A session written before the title existed (its "dicom" object as the
// earlier version-1 files have it) loads as before: the same series and
// segmentation, no title, so the series is named after its folder as then.
TEST(SessionFile, ASessionWithoutASeriesTitleLoadsAsBefore) {
    QJsonObject root =
        QJsonDocument::fromJson(gui::sessionToJson(sampleSession(), sessionDir() / "x.vvs"))
            .object();
    root.insert(QStringLiteral("dicom"),
                QJsonDocument::fromJson(R"({"series": "1.2.826.0.1.3680043.2.1125.9",
                    "components": 2, "triangles": 5000, "threshold": [200, 600],
                    "boneRemoval": true})")
                    .object());
    const fs::path path = writeText("untitled-v1.vvs", QJsonDocument(root).toJson());
    const gui::Session s = gui::loadSession(path);
    EXPECT_TRUE(s.seriesTitle.isEmpty());
    ASSERT_TRUE(s.dicom.has_value());
    EXPECT_EQ(s.dicom->seriesInstanceUid, "1.2.826.0.1.3680043.2.1125.9");
    EXPECT_EQ(s.dicom->segmentation.keepComponents, 2);
    EXPECT_EQ(s.dicom->surface.targetTriangles, 5000U);
    ASSERT_TRUE(s.dicom->segmentation.range.has_value());
    EXPECT_FLOAT_EQ(s.dicom->segmentation.range->lower, 200.0F);
    EXPECT_EQ(s.dicom->segmentation.removeBone, std::optional<bool>(true));
    expectSame(s, sampleSession());
    // Written again, it stays without a title.
    EXPECT_FALSE(gui::sessionToJson(s, path).contains("\"title\""));
}

/// Slice views unlike the defaults: one large coronal slice, the bone
/// preset, outline only, moved, zoomed and panned views, a cursor.
app::SliceSessionState sampleSlices() {
    app::SliceSessionState s;
    s.layout = 3;  // "coronal"
    s.window = {400.0, 1800.0};
    s.preset = slices::WindowPreset::Bone;
    s.fill = false;
    s.outline = true;
    s.views = {app::SliceViewState{-12.5, 2.0, {4.25, -3.0}},
               app::SliceViewState{7.0, 0.5, {0.0, 1.5}},
               app::SliceViewState{30.75, 31.0, {-100.0, 0.0}}};
    s.cursor = glm::dvec3(-20.5, 14.0, 33.25);
    return s;
}

TEST(SessionFile, TheSliceStateRoundTripsAndIsChecked) {
    gui::Session s = sampleSession();
    // Mesh sessions (and older ones) have none.
    EXPECT_FALSE(gui::sessionToJson(s, sessionDir() / "x.vvs").contains("\"slices\""));
    s.slices = sampleSlices();
    const QByteArray json = gui::sessionToJson(s, sessionDir() / "slices.vvs");
    EXPECT_TRUE(json.contains("\"version\": 1")) << "an optional object needs no new version";
    const gui::Session back = gui::sessionFromJson(json, sessionDir() / "slices.vvs");
    expectSame(back, s);
    ASSERT_TRUE(back.slices.has_value());
    const app::SliceSessionState& a = *back.slices;
    const app::SliceSessionState b = sampleSlices();
    EXPECT_EQ(a.layout, b.layout);
    EXPECT_DOUBLE_EQ(a.window.center, b.window.center);
    EXPECT_DOUBLE_EQ(a.window.width, b.window.width);
    EXPECT_EQ(a.preset, b.preset);
    EXPECT_EQ(a.fill, b.fill);
    EXPECT_EQ(a.outline, b.outline);
    for (std::size_t n = 0; n < 3; ++n) {
        EXPECT_DOUBLE_EQ(a.views.at(n).position, b.views.at(n).position) << n;
        EXPECT_DOUBLE_EQ(a.views.at(n).zoom, b.views.at(n).zoom) << n;
        EXPECT_EQ(a.views.at(n).pan, b.views.at(n).pan) << n;
    }
    EXPECT_EQ(a.cursor, b.cursor);
    // No preset (a dragged window) and no cursor stay absent.
    gui::Session none = s;
    none.slices->preset.reset();
    none.slices->cursor.reset();
    const gui::Session noneBack = gui::sessionFromJson(
        gui::sessionToJson(none, sessionDir() / "none.vvs"), sessionDir() / "none.vvs");
    ASSERT_TRUE(noneBack.slices.has_value());
    EXPECT_FALSE(noneBack.slices->preset.has_value());
    EXPECT_FALSE(noneBack.slices->cursor.has_value());

    // Bad values are refused naming the field.
    const auto cases = std::to_array<BadValue>({
        {"slices-layout.vvs", "\"coronal\",", "\"quad\",", "slices.layout"},
        {"slices-width.vvs", "\"width\": 1800", "\"width\": 0", "slices.window.width"},
        {"slices-level.vvs", "\"level\": 400", "\"level\": \"NaN\"", "slices.window.level"},
        {"slices-preset.vvs", "\"bone\"", "\"lung\"", "slices.window.preset"},
        {"slices-fill.vvs", "\"fill\": false", "\"fill\": 0", "slices.overlay.fill"},
        {"slices-zoom.vvs", "\"zoom\": 31", "\"zoom\": 100", "slices.sagittal.zoom"},
        {"slices-position.vvs", "\"position\": -12.5", "\"position\": null",
         "slices.axial.position"},
        {"slices-pan.vvs", "4.25", "\"left\"", "slices.axial.pan[0]"},
        {"slices-cursor.vvs", "-20.5", "1e300", "slices.cursor[0]"},
    });
    expectRefused(json, cases);
    QByteArray missing = json;
    missing.replace("\"outline\": true", "\"outlined\": true");
    EXPECT_NE(errorFor("slices-missing.vvs", missing).find("'slices.overlay.outline' is missing"),
              std::string::npos);
}

TEST(SessionFile, TheMeasurementRoundTripsAndIsChecked) {
    gui::Session s = sampleSession();
    EXPECT_FALSE(gui::sessionToJson(s, sessionDir() / "x.vvs").contains("\"measurement\""));
    s.measurement =
        std::array<glm::vec3, 2>{glm::vec3(1.5F, -2.25F, 30.0F), glm::vec3(-7.0F, 12.5F, -3.75F)};
    const QByteArray json = gui::sessionToJson(s, sessionDir() / "measured.vvs");
    EXPECT_TRUE(json.contains("\"version\": 1")) << "an optional object needs no new version";
    const gui::Session back = gui::sessionFromJson(json, sessionDir() / "measured.vvs");
    expectSame(back, s);
    ASSERT_TRUE(back.measurement.has_value());
    EXPECT_EQ(back.measurement->at(0), s.measurement->at(0));
    EXPECT_EQ(back.measurement->at(1), s.measurement->at(1));
    // Older sessions (without it) load without a measurement.
    EXPECT_FALSE(gui::sessionFromJson(gui::sessionToJson(sampleSession(), sessionDir() / "o.vvs"),
                                      sessionDir() / "o.vvs")
                     .measurement.has_value());
    // Bad values are refused naming the field.
    const auto cases = std::to_array<BadValue>({
        {"m-value.vvs", "-3.75", "\"deep\"", "measurement.points[1][2]"},
        {"m-huge.vvs", "12.5", "1e300", "measurement.points[1][1]"},
        {"m-points.vvs", "\"points\"", "\"pints\"", "measurement.points"},
    });
    expectRefused(json, cases);
    QJsonObject oneOnly = QJsonDocument::fromJson(json).object();
    oneOnly.insert(QStringLiteral("measurement"),
                   QJsonObject{{QStringLiteral("points"), QJsonArray{QJsonArray{1, 2, 3}}}});
    EXPECT_NE(errorFor("m-one.vvs", QJsonDocument(oneOnly).toJson()).find("two points"),
              std::string::npos);
}

TEST(SessionFile, RelativeFilesResolveAgainstTheSessionFolder) {
    QByteArray json = sampleWith("\"/data/a.vtp\"", "\"meshes/a.vtp\"");
    const gui::Session s = gui::sessionFromJson(json, sessionDir() / "rel.vvs");
    EXPECT_EQ(s.files.front().toStdString(), (sessionDir() / "meshes" / "a.vtp").string());
}

TEST(SessionFile, VersionZeroIsConverted) {
    // The prototype's layout: no version, flat settings with ViewSettings keys.
    const QByteArray v0 = R"({
        "files": ["tree.vtp"],
        "camera": {"target": [1, 2, 3], "distance": 10, "rotation": [1, 0, 0, 0],
                   "fieldOfView": 35},
        "settings": {"vss": true, "depthScale": "dark-means-deep", "power": 3.5,
                     "solver": "step", "step": 5, "isoLines": 4, "ao": false,
                     "aoRadius": 2.5, "colorMap": "cividis", "bins": 6, "vesselCue": 3,
                     "background": [0, 0, 0], "legends": false, "array": "wss"}
    })";
    const fs::path path = writeText("old-v0.vvs", v0);
    const gui::Session s = gui::loadSession(path);
    EXPECT_EQ(s.files.front().toStdString(), (sessionDir() / "tree.vtp").string());
    EXPECT_FLOAT_EQ(s.cameraDistance, 10.0F);
    EXPECT_FLOAT_EQ(s.fieldOfView, 35.0F);
    EXPECT_EQ(s.vss.scale, colormaps::DepthScale::DarkMeansDeep);
    EXPECT_DOUBLE_EQ(s.vss.solver.p, 3.5);
    EXPECT_EQ(s.vss.solver.kind, vss::SolverKind::Step);
    EXPECT_EQ(s.vss.solver.step, 5);
    EXPECT_EQ(s.vss.isoLines, 4);
    EXPECT_FALSE(s.ao.enabled);
    EXPECT_FLOAT_EQ(s.ao.radius, 2.5F);
    EXPECT_EQ(s.style.colorMap, colormaps::ColorMap::Cividis);
    EXPECT_EQ(s.style.bins, 6);
    EXPECT_EQ(s.cue.cue, render::allVesselCues()[3]);
    EXPECT_EQ(s.background, glm::vec3(0.0F));
    EXPECT_FALSE(s.legends);
    EXPECT_EQ(s.style.array, "wss");
    // Keys version 0 did not have take today's defaults.
    EXPECT_FLOAT_EQ(s.vss.opacity, render::VssSettings{}.opacity);
    EXPECT_FLOAT_EQ(s.ao.strength, render::AoSettings{}.strength);
    // A bad value in a version-0 file is reported under its converted name.
    const std::string problem =
        errorFor("old-v0-bad.vvs", QByteArray(v0).replace("\"power\": 3.5", "\"power\": \"x\""));
    EXPECT_NE(problem.find("view.vss.p"), std::string::npos) << problem;
}

TEST(SessionFile, BadFilesGiveClearErrors) {
    const QByteArray good = gui::sessionToJson(sampleSession(), sessionDir() / "x.vvs");
    struct Case {
        const char* name;
        QByteArray json;
        const char* expected;  ///< part of the message
    };
    const Case cases[] = {
        {"empty.vvs", "", "JSON"},
        {"truncated.vvs", good.left(good.size() / 2), "JSON"},
        {"array.vvs", "[1, 2]", "not an object"},
        {"future.vvs", sampleWith("\"version\": 1", "\"version\": 99"), "newer"},
        {"no-version.vvs", sampleWith("\"version\": 1,", ""), "'version' is missing"},
        {"version-text.vvs", sampleWith("\"version\": 1", "\"version\": \"1\""), "'version'"},
        {"wrong-format.vvs", sampleWith("\"vesselview-session\"", "\"other\""), "'format'"},
        {"no-camera.vvs", sampleWith("\"camera\"", "\"kamera\""), "'camera' is missing"},
        {"distance-text.vvs", sampleWith("\"distance\": 42", "\"distance\": \"far\""),
         "'camera.distance' must be a number"},
        {"distance-negative.vvs", sampleWith("\"distance\": 42", "\"distance\": -1"),
         "'camera.distance'"},
        {"nan.vvs", sampleWith("\"distance\": 42", "\"distance\": NaN"), "JSON"},
        {"infinite.vvs", sampleWith("\"distance\": 42", "\"distance\": 1e999"), "JSON"},
        {"p-range.vvs", sampleWith("\"p\": 5.5", "\"p\": 100"), "'view.vss.p'"},
        {"scale-name.vvs", sampleWith("\"dark-means-deep\"", "\"rainbow\""), "view.vss.scale"},
        {"solver-name.vvs", sampleWith("\"solver\": \"step\"", "\"solver\": \"magic\""),
         "view.vss.solver"},
        {"cue-name.vvs", sampleWith("\"cue\": \"fog\"", "\"cue\": \"smoke\""), "view.cue.cue"},
        {"bins.vvs", sampleWith("\"bins\": 7", "\"bins\": 2.5"), "whole number"},
        {"range.vvs", sampleWith("\"range\": [", "\"range\": [30, "), "view.style.range"},
        {"files.vvs", sampleWith("\"files\": [", "\"files\": [3, "), "files[0]"},
        {"legends.vvs", sampleWith("\"legends\": false", "\"legends\": 0"), "view.legends"},
        {"colour.vvs", sampleWith("\"background\": [", "\"background\": [2, "), "view.background"},
    };
    for (const Case& c : cases) {
        const std::string problem = errorFor(c.name, c.json);
        EXPECT_NE(problem.find(c.expected), std::string::npos)
            << c.name << ": got \"" << problem << "\", expected \"" << c.expected << "\"";
    }
    EXPECT_THROW(static_cast<void>(gui::loadSession(sessionDir() / "does-not-exist.vvs")), IoError);
    EXPECT_THROW(gui::saveSession(sessionDir() / "no-such-dir" / "s.vvs", sampleSession()),
                 IoError);
}

class SessionTest : public GuiFixture {};

TEST_F(SessionTest, BadSessionShowsErrorAndKeepsTheView) {
    const fs::path path = writeText("broken.vvs", "{\"version\": 1, \"files\": [");
    const double p = window_->viewer()->vssSettings().solver.p;
    EXPECT_FALSE(window_->openSession(QString::fromStdString(path.string())));
    EXPECT_TRUE(window_->lastError().contains(QStringLiteral("broken.vvs")))
        << window_->lastError().toStdString();
    EXPECT_DOUBLE_EQ(window_->viewer()->vssSettings().solver.p, p);
    auto* box = window_->findChild<QMessageBox*>(QStringLiteral("errorMessageBox"));
    ASSERT_NE(box, nullptr);
    box->close();
}

TEST_F(SessionTest, SaveThenOpenGivesTheSameImage) {
    window_->openFiles({QStringLiteral(VV_DEMO_VTP)});
    ASSERT_TRUE(waitUntil([&] { return window_->viewer()->scene() != nullptr; }, 60000));
    ASSERT_TRUE(waitForFrames(1));
    auto* viewer = window_->viewer();
    // A view unlike the defaults: camera turned and moved, settings changed.
    render::Camera camera = viewer->camera();
    camera.rotateView(0.6F, glm::vec3(0.0F, 1.0F, 0.0F));
    camera.zoom(1.4F);
    viewer->setCamera(camera);
    render::VssSettings vss = viewer->vssSettings();
    vss.scale = colormaps::DepthScale::PseudoChromadepth;
    vss.solver.p = 4.0;
    vss.isoLines = 5;
    viewer->setVssSettings(vss);
    render::MeshStyle style = viewer->style();
    style.colorMap = colormaps::ColorMap::Inferno;
    viewer->setStyle(style);
    viewer->setVesselCue({render::VesselCue::Fog, 0.6F, 1.0F});
    ASSERT_TRUE(waitForVss());
    const QImage before = viewer->grabFramebuffer();

    const render::Camera savedCamera = viewer->camera();
    const QString path = QString::fromStdString((sessionDir() / "view.vvs").string());
    ASSERT_TRUE(window_->saveSessionTo(path));
    ASSERT_EQ(window_->shownFiles().size(), 1);
    {
        // A mesh scene has no slice views, so its session keeps none.
        QFile saved(path);
        ASSERT_TRUE(saved.open(QIODevice::ReadOnly));
        EXPECT_FALSE(saved.readAll().contains("\"slices\""));
    }

    // A fresh window from the defaults, then the session.
    ASSERT_TRUE(openSessionInNewWindow(path)) << "the session was never applied";
    viewer = window_->viewer();
    EXPECT_EQ(viewer->vssSettings().scale, colormaps::DepthScale::PseudoChromadepth);
    EXPECT_DOUBLE_EQ(viewer->vssSettings().solver.p, 4.0);
    EXPECT_EQ(viewer->style().colorMap, colormaps::ColorMap::Inferno);
    EXPECT_EQ(viewer->vesselCue().cue, render::VesselCue::Fog);
    EXPECT_NEAR(viewer->camera().distance(), savedCamera.distance(),
                1e-4F * savedCamera.distance());
    EXPECT_NEAR(std::abs(glm::dot(viewer->camera().rotation(), savedCamera.rotation())), 1.0F,
                1e-5F);
    EXPECT_LT(glm::length(viewer->camera().target() - savedCamera.target()), 1e-3F);
    ASSERT_TRUE(waitForVss());
    // Frames follow the settings (and the exact VSS) asynchronously: poll.
    QImage after;
    waitUntil(
        [&] {
            after = viewer->grabFramebuffer();
            return changedFraction(before, after) < 0.01;
        },
        30000);
    ASSERT_EQ(after.size(), before.size());
    const double changed = changedFraction(before, after);
    EXPECT_LT(changed, 0.01) << "the reopened session looks different";
    if (changed >= 0.01) {
        before.save(QString::fromStdString((sessionDir() / "before.png").string()));
        after.save(QString::fromStdString((sessionDir() / "after.png").string()));
    }
}

TEST_F(SessionTest, AMeasurementIsSavedAndRestored) {
    window_->openFiles({QStringLiteral(VV_DEMO_VTP)});
    ASSERT_TRUE(waitUntil([&] { return window_->viewer()->scene() != nullptr; }, 60000));
    ASSERT_TRUE(waitForFrames(1));
    auto* viewer = window_->viewer();
    // Two points on vessels, picked as a person does (measure mode, two clicks).
    std::vector<QPointF> onVessels;
    for (int y = 20; y < viewer->height() && onVessels.size() < 2; y += 10) {
        for (int x = 20; x < viewer->width() && onVessels.size() < 2; x += 10) {
            const QPointF at(x, y);
            if (viewer->probeAt(at) &&
                (onVessels.empty() || QLineF(onVessels.front(), at).length() > 150.0)) {
                onVessels.push_back(at);
            }
        }
    }
    ASSERT_EQ(onVessels.size(), 2U) << "no two vessel points far apart";
    window_->measureToggle()->setChecked(true);
    for (const QPointF& at : onVessels) {
        for (const QEvent::Type type : {QEvent::MouseButtonPress, QEvent::MouseButtonRelease}) {
            QMouseEvent event(type, at, viewer->mapToGlobal(at), Qt::LeftButton,
                              type == QEvent::MouseButtonPress ? Qt::LeftButton : Qt::NoButton,
                              Qt::NoModifier);
            QCoreApplication::sendEvent(viewer, &event);
        }
    }
    ASSERT_EQ(window_->measurePoints().size(), 2);
    const glm::vec3 a = window_->measurePoints()[0].worldPosition;
    const glm::vec3 b = window_->measurePoints()[1].worldPosition;
    const QString text = window_->measureLabel()->text();
    ASSERT_TRUE(text.startsWith(QStringLiteral("Distance 1–2: "))) << text.toStdString();
    const auto markA = window_->measureOverlay()->project(window_->measurePoints()[0]);
    ASSERT_TRUE(markA);

    const QString path = QString::fromStdString((sessionDir() / "measured.vvs").string());
    ASSERT_TRUE(window_->saveSessionTo(path));
    ASSERT_TRUE(openSessionInNewWindow(path)) << "the session was never applied";
    ASSERT_TRUE(waitForFrames(1));
    QCoreApplication::processEvents();
    // The same two points, marked where they were, and the same words and numbers.
    ASSERT_EQ(window_->measurePoints().size(), 2);
    EXPECT_LT(glm::distance(window_->measurePoints()[0].worldPosition, a), 1e-4F);
    EXPECT_LT(glm::distance(window_->measurePoints()[1].worldPosition, b), 1e-4F);
    EXPECT_EQ(window_->measureLabel()->text(), text);
    EXPECT_TRUE(window_->measureOverlay()->isVisible());
    const auto markAfter = window_->measureOverlay()->project(window_->measurePoints()[0]);
    ASSERT_TRUE(markAfter);
    EXPECT_LT(QLineF(*markA, *markAfter).length(), 0.5);
    // Measure mode itself is not part of it; Esc (Clear Measurement) still clears it.
    EXPECT_FALSE(window_->measureToggle()->isChecked());
    auto* clear = window_->findChild<QAction*>(QStringLiteral("clearMeasurement"));
    ASSERT_NE(clear, nullptr);
    clear->trigger();
    EXPECT_TRUE(window_->measurePoints().isEmpty());
}

}  // namespace
}  // namespace vv::test
