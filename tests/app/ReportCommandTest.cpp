// SPDX-License-Identifier: GPL-3.0-or-later
// `vesselview-cli report` through vv::cli::run. Rendering needs OpenGL: run
// under `xvfb-run -a` (QT_QPA_PLATFORM=xcb). The PDF text is read back with
// pdftotext (poppler-utils) and the DICOM files with dcmdump (dcmtk). The
// DICOM input is the synthetic CTA series of tests/support (SyntheticCta.h).
#include <gtest/gtest.h>
#include <unistd.h>

#include <QImage>
#include <QString>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "DicomTestUtil.h"
#include "ReportTestUtil.h"
#include "SyntheticCta.h"
#include "TestMeshes.h"
#include "cli/Cli.h"
#include "cli/RenderOptions.h"
#include "common/Session.h"
#include "common/SliceReport.h"
#include "vv/demo/DemoTree.h"
#include "vv/dicom/SeriesWriter.h"
#include "vv/meshio/MeshWriter.h"
#include "vv/report/ReportJob.h"
#include "vv/scene/Mesh.h"
#include "vv/segmentation/SceneSource.h"
#include "vv/slices/SlicePlane.h"

namespace {

namespace fs = std::filesystem;

fs::path testDir() {
    const fs::path dir =
        fs::path(VV_TEST_TMP) / "report-command" / ("run-" + std::to_string(::getpid()));
    fs::create_directories(dir);
    return dir;
}

/// A fresh empty folder `name` in testDir().
fs::path freshDir(const std::string& name) {
    const fs::path dir = testDir() / name;
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

/// An open tube along x (radius 1, length 20) with "wss" (Pa) rising 0..10.
vv::scene::Mesh tube(bool withArray) {
    vv::scene::Mesh mesh = vv::test::tube(
        {.radius = 1.0F, .start = glm::vec3(0.0F), .length = 20.0F, .segments = 24, .rings = 20});
    if (withArray) {
        vv::test::addAxialArray(mesh, "wss", "Pa", 0.0F, [](float x) { return 0.5F * x; });
    }
    return mesh;
}

/// The tube written as `dir`/`name`.vtp.
fs::path writeTube(const fs::path& dir, const std::string& name, bool withArray = true) {
    const fs::path file = dir / (name + ".vtp");
    vv::meshio::writeVtp(tube(withArray), file);
    return file;
}

struct RunResult {
    int code;
    std::string out;
    std::string err;
};

RunResult report(const std::vector<std::string>& rest) {
    std::vector<std::string> args{"report"};
    args.insert(args.end(), rest.begin(), rest.end());
    std::ostringstream out;
    std::ostringstream err;
    const int code = vv::cli::run(args, out, err);
    return {code, out.str(), err.str()};
}

using vv::report::test::runTool;

std::string pdfText(const fs::path& pdf) {
    std::string text;
    EXPECT_EQ(runTool("pdftotext -layout '" + pdf.string() + "' -", text), 0)
        << "pdftotext (poppler-utils; scripts/setup-deps): " << text;
    return text;
}

std::size_t fileCount(const fs::path& dir) {
    std::size_t n = 0;
    for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) {
        ++n;
    }
    return n;
}

TEST(ReportCommandTest, WritesPdfPngAndDicom) {
    const fs::path dir = freshDir("single");
    const fs::path input = writeTube(dir, "tube");
    const fs::path out = freshDir("single-out");
    const auto r = report({input.string(),
                           "-o",
                           (out / "r.pdf").string(),
                           "--png",
                           (out / "v.png").string(),
                           "--dicom-sc",
                           (out / "sc.dcm").string(),
                           "--dicom-pdf",
                           (out / "doc.dcm").string(),
                           "--size",
                           "400x300",
                           "--note",
                           "Low WSS proximal.",
                           "--second-view",
                           "anterior",
                           "--paper",
                           "letter",
                           "--transparent",
                           "--below",
                           "1"});
    ASSERT_EQ(r.code, vv::cli::kOk) << r.err;
    EXPECT_NE(r.out.find("PDF report, Letter"), std::string::npos) << r.out;

    const std::string text = pdfText(out / "r.pdf");
    for (const char* expected :
         {"Vessel tree report", "tube.vtp", "Low WSS proximal.", "Second view", "Anterior view",
          "Parameter statistics", "wss (Pa)", "Area <", "10.0 %", "Rendering settings"}) {
        EXPECT_NE(text.find(expected), std::string::npos) << "missing '" << expected << "' in\n"
                                                          << text;
    }
    EXPECT_EQ(text.find("Patient"), std::string::npos);  // meshes carry no patient data

    QImage png;
    ASSERT_TRUE(png.load(QString::fromStdString((out / "v.png").string()), "PNG"));
    EXPECT_EQ(png.size(), QSize(400, 300));
    EXPECT_TRUE(png.hasAlphaChannel());

    // Both DICOM files parse and share one new study.
    const auto studyUid = [](const std::string& dump) {
        const auto at = dump.find("(0020,000d) UI [");
        return at == std::string::npos ? std::string()
                                       : dump.substr(at + 16, dump.find(']', at) - at - 16);
    };
    std::string dump;
    ASSERT_EQ(runTool("dcmdump '" + (out / "sc.dcm").string() + "'", dump), 0) << dump;
    EXPECT_NE(dump.find("SecondaryCaptureImageStorage"), std::string::npos);
    EXPECT_NE(dump.find("US 300"), std::string::npos);  // Rows
    const std::string study = studyUid(dump);
    EXPECT_GT(study.size(), 10U) << dump;
    ASSERT_EQ(runTool("dcmdump '" + (out / "doc.dcm").string() + "'", dump), 0) << dump;
    EXPECT_NE(dump.find("EncapsulatedPDFStorage"), std::string::npos);
    EXPECT_NE(dump.find("[application/pdf]"), std::string::npos);
    EXPECT_EQ(studyUid(dump), study);
    EXPECT_EQ(fileCount(out), 4U);  // no temporary files left
}

TEST(ReportCommandTest, UsageErrors) {
    const fs::path dir = freshDir("usage");
    const fs::path input = writeTube(dir, "tube");
    const std::string in = input.string();
    const std::string pdf = (dir / "r.pdf").string();
    EXPECT_EQ(report({in}).code, vv::cli::kUsage);  // no -o
    EXPECT_EQ(report({in, "-o", pdf, "--paper", "a5"}).code, vv::cli::kUsage);
    EXPECT_EQ(report({in, "-o", pdf, "--second-view", "sideways"}).code, vv::cli::kUsage);
    EXPECT_EQ(report({in, "-o", pdf, "--size", "8000x100"}).code, vv::cli::kUsage);
    EXPECT_EQ(report({in, "-o", pdf, "--frobnicate"}).code, vv::cli::kUsage);
    EXPECT_EQ(report({in, "-o", pdf, "--png", pdf}).code, vv::cli::kUsage);  // twice
    EXPECT_EQ(report({in, "-o", pdf, "--out-dir", dir.string()}).code, vv::cli::kUsage);
    EXPECT_EQ(report({"--batch", "list.txt", "-o", pdf}).code, vv::cli::kUsage);
    EXPECT_EQ(report({"--batch", "list.txt"}).code, vv::cli::kUsage);  // no --out-dir
    // Never over the input.
    const auto over = report({in, "-o", pdf, "--png", in});
    EXPECT_EQ(over.code, vv::cli::kUsage);
    EXPECT_NE(over.err.find("would overwrite the input"), std::string::npos) << over.err;
    EXPECT_TRUE(fs::exists(input));
    EXPECT_EQ(fileCount(dir), 1U);  // only the input: nothing was written
}

TEST(ReportCommandTest, UnwritableOutputFailsWithCode4) {
    const fs::path dir = freshDir("unwritable");
    const fs::path input = writeTube(dir, "tube");
    // The parent of the output is a regular file (works as root, too).
    const auto r = report({input.string(), "-o", (input / "r.pdf").string()});
    EXPECT_EQ(r.code, vv::cli::kCannotWrite) << r.err;
    const auto missing = report({input.string(), "-o", (dir / "no" / "r.pdf").string()});
    EXPECT_EQ(missing.code, vv::cli::kCannotWrite);
    EXPECT_EQ(fileCount(dir), 1U);
}

TEST(ReportCommandTest, BatchGoesOnAfterAFailureAndSummarises) {
    const fs::path dir = freshDir("batch-in");
    const fs::path sub = dir / "sub";
    fs::create_directories(sub);
    writeTube(dir, "first");
    writeTube(sub, "first");  // same stem: gets a suffix
    std::ofstream(dir / "broken.vtp") << "not a mesh";
    {
        std::ofstream list(dir / "list.txt");
        list << "# cases\nfirst.vtp\n\nbroken.vtp\nsub/first.vtp\n";
    }
    const fs::path out = freshDir("batch-out");
    const auto r = report({"--batch", (dir / "list.txt").string(), "--out-dir", out.string(),
                           "--formats", "pdf,png", "--size", "320x240", "--vss", "off"});
    EXPECT_EQ(r.code, vv::cli::kInvalidInput) << r.out << r.err;
    EXPECT_NE(r.out.find("2 of 3 inputs done, 1 failed"), std::string::npos) << r.out;
    EXPECT_NE(r.err.find("broken.vtp"), std::string::npos) << r.err;
    EXPECT_TRUE(fs::exists(out / "first.pdf"));
    EXPECT_TRUE(fs::exists(out / "first.png"));
    EXPECT_TRUE(fs::exists(out / "first-2.pdf"));
    EXPECT_TRUE(fs::exists(out / "first-2.png"));
    EXPECT_EQ(fileCount(out), 4U);

    // The output folder must not be an input's folder.
    const auto next = report({"--batch", (dir / "list.txt").string(), "--out-dir", dir.string()});
    EXPECT_EQ(next.code, vv::cli::kUsage) << next.err;
}

TEST(ReportCommandTest, DicomInputGoesIntoTheSourceStudyWithItsPatient) {
    const fs::path dir = freshDir("dicom");
    const auto cta = vv::test::makeSyntheticCta({64, 64, 48}, 3);
    const std::string series = vv::test::writeCtSeries(dir / "series", cta.volume);
    // The source study UID, as the series files carry it.
    std::string dump;
    const fs::path first = *fs::directory_iterator(dir / "series");
    ASSERT_EQ(runTool("dcmdump '" + first.string() + "'", dump), 0) << dump;
    const auto studyUid = [](const std::string& text) {
        const auto at = text.find("(0020,000d) UI [");
        return at == std::string::npos ? std::string()
                                       : text.substr(at + 16, text.find(']', at) - at - 16);
    };
    const std::string study = studyUid(dump);
    ASSERT_GT(study.size(), 10U);

    for (const bool anonymise : {false, true}) {
        const fs::path out = freshDir(anonymise ? "dicom-anon-out" : "dicom-out");
        std::vector<std::string> args{(dir / "series").string(),
                                      "-o",
                                      (out / "r.pdf").string(),
                                      "--dicom-sc",
                                      (out / "sc.dcm").string(),
                                      "--dicom-pdf",
                                      (out / "doc.dcm").string(),
                                      "--size",
                                      "320x240",
                                      "--vss",
                                      "off",
                                      "--series",
                                      series,
                                      "--threshold",
                                      "200:700",
                                      "--triangles",
                                      "20000"};
        if (anonymise) {
            args.emplace_back("--anonymise");
        }
        const auto r = report(args);
        ASSERT_EQ(r.code, vv::cli::kOk) << r.err;
        const std::string text = pdfText(out / "r.pdf");
        EXPECT_NE(text.find("Patient and study"), std::string::npos) << text;
        std::string pseudonym;
        for (const std::string file : {"sc.dcm", "doc.dcm"}) {
            ASSERT_EQ(runTool("dcmdump '" + (out / file).string() + "'", dump), 0) << dump;
            if (anonymise) {  // a pseudonymous study, the same for both instances
                EXPECT_NE(studyUid(dump), study) << file;
                EXPECT_EQ(studyUid(dump).rfind("2.25.", 0), 0U) << file;
                if (pseudonym.empty()) {
                    pseudonym = studyUid(dump);
                }
                EXPECT_EQ(studyUid(dump), pseudonym) << file;
            } else {
                EXPECT_EQ(studyUid(dump), study) << file;  // the source study
            }
            EXPECT_NE(dump.find("[VesselView report]"), std::string::npos) << file;
            if (anonymise) {
                EXPECT_EQ(dump.find("Secretname"), std::string::npos) << file;
                EXPECT_EQ(dump.find(vv::test::kPatientId), std::string::npos) << file;
                EXPECT_NE(dump.find("PatientIdentityRemoved"), std::string::npos) << file;
            } else {
                EXPECT_NE(dump.find(vv::test::kPatientName), std::string::npos) << file;
                EXPECT_NE(dump.find(vv::test::kPatientId), std::string::npos) << file;
            }
        }
        if (anonymise) {
            EXPECT_EQ(text.find("Secretname"), std::string::npos) << text;
            EXPECT_EQ(text.find(vv::test::kPatientId), std::string::npos) << text;
            EXPECT_NE(text.find("anonymised"), std::string::npos) << text;
        } else {
            EXPECT_NE(text.find("Secretname, Jane"), std::string::npos) << text;
            EXPECT_NE(text.find(vv::test::kPatientId), std::string::npos) << text;
        }
    }
}

TEST(ReportCommandTest, EverySecondViewsLegendDescribesItsOwnImage) {
    // The demo tree without arrays: only the depth legend is over the views.
    const fs::path dir = freshDir("second-views");
    const fs::path input = dir / "demo.vtp";
    // (A smaller tree than the bundled one, drawn as its facets (the smooth
    // copy of a coarse mesh has tests of its own: SmoothCoarseTest): nine
    // reports stay quick.)
    vv::meshio::writeVtp(vv::demo::generateDemoMesh({.generations = 4, .maxTriangles = 40000}),
                         input);
    vv::report::test::ensureGuiApplication();
    const vv::scene::Scene scene = vv::segmentation::loadSceneSource(input);
    vv::cli::RenderOptionValues values;
    values.array = "";
    values.smoothCoarseMeshes = false;
    const vv::render::OffscreenOptions base = vv::cli::offscreenOptions(values, scene, input);
    vv::render::OffscreenRenderer renderer;
    for (const std::string& name : vv::report::test::namedViews()) {
        SCOPED_TRACE(name);
        const fs::path pdf = dir / (name + ".pdf");
        const auto r = report({input.string(), "-o", pdf.string(), "--second-view", name, "--array",
                               "none", "--smooth-coarse", "off"});
        ASSERT_EQ(r.code, vv::cli::kOk) << r.err;
        const auto view = vv::render::namedViewFromName(name);
        ASSERT_TRUE(view.has_value());
        const auto [dmin, dmax] = vv::report::test::ownDepthRange(
            renderer, scene, base, *view, base.display.vss.range, vv::report::PaperSize::A4);
        const std::string caption = vv::report::namedViewCaption(name);
        vv::render::DepthLegend legend;
        legend.dmin = dmin;
        legend.dmax = dmax;
        const std::string problem =
            vv::report::test::depthLegendProblem(vv::report::test::pdfWords(pdf), "Second",
                                                 caption.substr(0, caption.find(' ')), legend);
        EXPECT_TRUE(problem.empty()) << problem;
    }
}

TEST(ReportCommandTest, ASessionsSliceViewsGiveTheSlicePage) {
    // `report --session F.vvs --slice coronal`: the coronal view's position,
    // the window and the overlay style as the GUI saved them.
    const fs::path dir = freshDir("session-slice");
    const auto cta = vv::test::makeSyntheticCta({64, 64, 48}, 3);
    (void)vv::test::writeCtSeries(dir / "series", cta.volume);
    vv::segmentation::SceneSourceReport loaded;
    (void)vv::segmentation::loadSceneSource(dir / "series", {}, {}, &loaded);
    ASSERT_TRUE(loaded.volume);
    const vv::slices::SliceStack coronal =
        vv::slices::sliceStack(*loaded.volume, vv::slices::SliceOrientation::Coronal);
    const double position = coronal.position(coronal.count / 3);  // not the middle one

    vv::app::Session session;
    session.files = {QString::fromStdString((dir / "series").string())};
    vv::app::SliceSessionState slices;
    slices.window = {100.0, 50.0};  // level 100, width 50: chosen by hand, no preset
    slices.fill = false;
    slices.outline = true;
    slices.views.at(1).position = position;
    session.slices = slices;
    const fs::path file = dir / "slices.vvs";
    vv::app::saveSession(file, session);
    const fs::path pdf = dir / "report.pdf";
    const auto r = report({"--session", file.string(), "-o", pdf.string(), "--slice", "coronal"});
    ASSERT_EQ(r.code, vv::cli::kOk) << r.err;
    std::string text;
    for (const auto& w : vv::report::test::pdfWords(pdf)) {
        text += w.text + " ";
    }
    text = vv::report::test::withoutLigatures(text);
    vv::app::SliceFacts facts;
    facts.orientation = vv::slices::SliceOrientation::Coronal;
    facts.axis = coronal.axis;
    facts.position = position;
    facts.window = slices.window;
    facts.unit = "HU";
    facts.overlay = vv::slices::OverlayStyle{false, true};
    // (Spaces as pdftotext writes them: no-break spaces become plain ones.)
    const std::string caption = vv::report::test::withoutLigatures(
        vv::app::sliceCaption(facts).replace(QChar(0x00A0), QLatin1Char(' ')).toStdString());
    QString words;
    for (const QString& word :
         QString::fromStdString(caption).split(QLatin1Char(' '), Qt::SkipEmptyParts)) {
        words += word + QLatin1Char(' ');
    }
    EXPECT_NE(text.find(words.trimmed().toStdString()), std::string::npos)
        << words.toStdString() << "\nin\n"
        << text;
    EXPECT_NE(text.find("W 50 HU L 100 HU. Coloured outline: the segmentation."), std::string::npos)
        << text;
}

}  // namespace
