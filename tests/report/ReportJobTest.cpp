// SPDX-License-Identifier: GPL-3.0-or-later
// The shared report job (CLI and GUI) and the offscreen renderer on a worker
// thread. OpenGL: run under `xvfb-run -a` with QT_QPA_PLATFORM=xcb.
#include <gtest/gtest.h>

#include <QByteArray>
#include <QImage>
#include <QOffscreenSurface>
#include <QString>
#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>
#include <sstream>
#include <stop_token>
#include <string>
#include <thread>
#include <vector>

#include "ReportTestUtil.h"
#include "vv/core/Error.h"
#include "vv/report/ReportJob.h"
#include "vv/report/ViewExport.h"

namespace vv::report {
namespace {

namespace fs = std::filesystem;

std::string readAll(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

class ReportJobTest : public ::testing::Test {
  protected:
    static void SetUpTestSuite() { scene_.meshes.push_back(test::makeTube("tube")); }

    void SetUp() override {
        test::ensureGuiApplication();
        renderer_ = test::makeRenderer();
        ASSERT_TRUE(renderer_);
    }

    /// A small view of the tube with "wss" shown; VSS off to keep it quick.
    static ReportJobOptions options() {
        ReportJobOptions o;
        o.view.width = 320;
        o.view.height = 240;
        o.view.display.style.array = "wss";
        o.view.display.vss.enabled = false;
        o.view.display.ao.enabled = false;
        o.findings = "Findings of the job test.";
        o.source.files = {"tube.vtp"};
        return o;
    }

    static scene::Scene scene_;
    std::unique_ptr<render::OffscreenRenderer> renderer_;
};

scene::Scene ReportJobTest::scene_;

TEST_F(ReportJobTest, WritesEveryOutputAndReportsProgressInOrder) {
    const fs::path dir = test::testDir("job-all");
    ReportJobOptions o = options();
    o.outputs = {dir / "r.pdf", dir / "v.png", dir / "sc.dcm", dir / "doc.dcm", {}};
    o.secondView = render::namedViewFromName("anterior");
    o.secondViewName = "anterior";
    o.paper = PaperSize::Letter;
    std::vector<double> fractions;
    std::vector<std::string> stages;
    const Progress progress(
        [&](double fraction, std::string_view stage) {
            fractions.push_back(fraction);
            stages.emplace_back(stage);
        },
        {});
    const auto written = runReportJob(*renderer_, scene_, o, progress);
    ASSERT_EQ(written.size(), 4U);
    EXPECT_EQ(written[0].path, dir / "v.png");
    EXPECT_EQ(written[2].description, "PDF report, Letter");
    EXPECT_EQ(test::listing(dir), "doc.dcm r.pdf sc.dcm v.png ");
    QImage png;
    ASSERT_TRUE(png.load(QString::fromStdString((dir / "v.png").string())));
    EXPECT_EQ(png.size(), QSize(320, 240));

    // Progress: rising fractions, the stages in the order they run.
    ASSERT_GE(fractions.size(), 5U);
    EXPECT_TRUE(std::is_sorted(fractions.begin(), fractions.end()));
    EXPECT_EQ(stages.front(), "Rendering the image");
    EXPECT_NE(std::find(stages.begin(), stages.end(), "Rendering the second view"), stages.end());
    EXPECT_EQ(stages.back(), "Writing the files");

    std::string text;
    if (test::haveTool("pdftotext")) {
        ASSERT_EQ(test::runTool("pdftotext '" + (dir / "r.pdf").string() + "' -", text), 0);
        EXPECT_NE(text.find("Findings of the job test."), std::string::npos) << text;
        EXPECT_NE(text.find("Anterior view"), std::string::npos) << text;
        EXPECT_NE(text.find("wss"), std::string::npos) << text;
    } else {
        ADD_FAILURE() << "pdftotext missing (poppler-utils; scripts/setup-deps)";
    }
}

TEST_F(ReportJobTest, CancelledJobWritesNothingAndKeepsExistingFiles) {
    const fs::path dir = test::testDir("job-cancel");
    std::ofstream(dir / "r.pdf") << "the old report";
    ReportJobOptions o = options();
    o.outputs.pdf = dir / "r.pdf";
    o.outputs.png = dir / "v.png";
    // Stop at the last step, after every render: nothing may be written.
    std::stop_source stop;
    const Progress progress(
        [&](double, std::string_view stage) {
            if (stage == "Writing the files") {
                stop.request_stop();
            }
        },
        stop.get_token());
    EXPECT_THROW((void)runReportJob(*renderer_, scene_, o, progress), CancelledError);
    EXPECT_EQ(readAll(dir / "r.pdf"), "the old report");
    EXPECT_EQ(test::listing(dir), "r.pdf ");  // no PNG, no temporary file
}

TEST_F(ReportJobTest, WriteFailuresAndMissingOutputsAreTypedErrors) {
    const fs::path dir = test::testDir("job-errors");
    ReportJobOptions o = options();
    EXPECT_THROW((void)runReportJob(*renderer_, scene_, o), InvalidArgumentError);  // no outputs
    std::ofstream(dir / "file") << "a regular file";
    o.outputs.pdf = dir / "file" / "r.pdf";  // its parent is not a folder
    try {
        (void)runReportJob(*renderer_, scene_, o);
        ADD_FAILURE() << "no error";
    } catch (const ReportWriteError& e) {
        EXPECT_EQ(e.file(), o.outputs.pdf);
    }
}

TEST_F(ReportJobTest, AnExportedReportIsWrittenAsItIsAndABadOneNamed) {
    const fs::path dir = test::testDir("job-existing");
    // A report made before, with other findings.
    ReportJobOptions first = options();
    first.findings = "Findings of the first report.";
    first.outputs.pdf = dir / "first.pdf";
    (void)runReportJob(*renderer_, scene_, first);
    std::ifstream in(first.outputs.pdf, std::ios::binary);
    const std::string exported{std::istreambuf_iterator<char>(in),
                               std::istreambuf_iterator<char>()};
    ASSERT_TRUE(exported.starts_with("%PDF-"));

    // Sent as it is: the same bytes, whatever the findings now.
    ReportJobOptions again = options();
    again.existingPdf = first.outputs.pdf;
    again.outputs.pdf = dir / "again.pdf";
    (void)runReportJob(*renderer_, scene_, again);
    std::ifstream copy(again.outputs.pdf, std::ios::binary);
    EXPECT_EQ(std::string(std::istreambuf_iterator<char>(copy), std::istreambuf_iterator<char>()),
              exported);

    // Missing, or no PDF: an error naming the file; nothing written.
    again.outputs.pdf = dir / "never.pdf";
    for (const fs::path& bad : {dir / "missing.pdf", dir / "not-a-pdf.pdf"}) {
        std::ofstream(dir / "not-a-pdf.pdf") << "plain text";
        again.existingPdf = bad;
        try {
            (void)runReportJob(*renderer_, scene_, again);
            ADD_FAILURE() << "no error for " << bad;
        } catch (const Error& e) {
            EXPECT_EQ(e.file(), bad);
            EXPECT_NE(std::string(e.what()).find("exported report"), std::string::npos) << e.what();
        }
        EXPECT_FALSE(fs::exists(again.outputs.pdf));
    }
}

TEST_F(ReportJobTest, NamedViewCaptions) {
    EXPECT_EQ(namedViewCaption("far"), "Far view");
    EXPECT_EQ(namedViewCaption(""), "Default view, the whole tree fitted");
    // A patient's left is the left lateral view; a mesh's axes have no sides.
    EXPECT_EQ(namedViewCaption("left", scene::SceneFrame::PatientLps), "Left lateral view");
    EXPECT_EQ(namedViewCaption("right", scene::SceneFrame::PatientLps), "Right lateral view");
    EXPECT_EQ(namedViewCaption("left", scene::SceneFrame::Unknown), "Left view");
    EXPECT_EQ(namedViewCaption("anterior", scene::SceneFrame::PatientLps), "Anterior view");
}

TEST_F(ReportJobTest, RendererOnAWorkerThreadMatchesTheGuiThread) {
    ViewExportOptions view;
    view.render = options().view;
    view.render.display.vss.enabled = true;  // the solve runs on the worker too
    view.render.width = 400;
    view.render.height = 300;
    const QImage onGuiThread = renderView(*renderer_, scene_, view).image;

    // The surface is made here (the GUI thread), the context on the worker.
    const std::unique_ptr<QOffscreenSurface> surface = render::OffscreenRenderer::createSurface();
    QImage onWorker;
    std::string error;
    std::thread worker([&] {
        try {
            render::OffscreenRenderer renderer(*surface);
            onWorker = renderView(renderer, scene_, view).image;
        } catch (const std::exception& e) {
            error = e.what();
        }
    });
    worker.join();
    ASSERT_TRUE(error.empty()) << error;
    ASSERT_EQ(onWorker.size(), onGuiThread.size());
    int maxDifference = 0;
    for (int y = 0; y < onWorker.height(); ++y) {
        for (int x = 0; x < onWorker.width(); ++x) {
            const QRgb a = onWorker.pixel(x, y);
            const QRgb b = onGuiThread.pixel(x, y);
            maxDifference =
                std::max({maxDifference, std::abs(qRed(a) - qRed(b)),
                          std::abs(qGreen(a) - qGreen(b)), std::abs(qBlue(a) - qBlue(b))});
        }
    }
    EXPECT_LE(maxDifference, 1);
    EXPECT_NE(onWorker.pixel(200, 150), onWorker.pixel(2, 2));  // not a blank frame
}

}  // namespace
}  // namespace vv::report
