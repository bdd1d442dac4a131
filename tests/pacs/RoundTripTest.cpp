// SPDX-License-Identifier: GPL-3.0-or-later
// The round trip of issue 21 with `vesselview-cli` run as a program against a
// real Orthanc: the synthetic CTA series is sent (pacs send), found (pacs
// find), retrieved with C-GET and with C-MOVE to our listener (pacs get
// [--move]), rendered into a report (report --png --dicom-sc --dicom-pdf),
// the report's DICOM outputs are sent back and found in the source study at
// series level. Rendering needs OpenGL: run under Xvfb (scripts/test does).
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <QImage>
#include <QString>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "CliRun.h"
#include "CtaSeriesFixture.h"
#include "OrthancServer.h"
#include "PacsTestUtil.h"
#include "vv/pacs/LocalStore.h"

namespace round_trip_test {

namespace fs = std::filesystem;

namespace {

constexpr const char* kOurAe = "VVROUND";

struct ProgramRun {
    int code = -1;
    std::string output;  ///< standard output and error
};

/// Runs `vesselview-cli ARGS...` as a program (at most 60 s).
ProgramRun cli(const std::vector<std::string>& args) {
    std::string command = std::string("timeout 60 '") + VV_CLI_EXE + "'";
    for (const std::string& a : args) {
        command += " '" + a + "'";
    }
    command += " 2>&1";
    ProgramRun run;
    FILE* pipe = ::popen(command.c_str(), "r");
    if (pipe == nullptr) {
        return run;
    }
    char buffer[4096];
    std::size_t n = 0;
    while ((n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0) {
        run.output.append(buffer, n);
    }
    const int status = ::pclose(pipe);
    run.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return run;
}

/// Every value of `"key": "value"` in the JSON text `json`.
std::vector<std::string> values(const std::string& json, const std::string& key) {
    std::vector<std::string> found;
    const std::string start = "\"" + key + "\": \"";
    for (auto at = json.find(start); at != std::string::npos; at = json.find(start, at + 1)) {
        const auto from = at + start.size();
        found.push_back(json.substr(from, json.find('"', from) - from));
    }
    return found;
}

/// Pixels of the vessels' red (the overlays are grey, white and dark).
long vesselPixels(const QImage& image) {
    long count = 0;
    for (int y = 0; y < image.height(); ++y) {
        for (int x = 0; x < image.width(); ++x) {
            const QRgb p = image.pixel(x, y);
            count += qRed(p) > 150 && qRed(p) > qGreen(p) + 50 ? 1 : 0;
        }
    }
    return count;
}

std::size_t lines(const std::string& text, const std::string& start) {
    std::size_t n = 0;
    for (std::size_t at = 0; at < text.size(); at = text.find('\n', at) + 1) {
        n += text.compare(at, start.size(), start) == 0 ? 1 : 0;
        if (text.find('\n', at) == std::string::npos) {
            break;
        }
    }
    return n;
}

}  // namespace

TEST(PacsRoundTripTest, SendFindRetrieveRenderReportAndFindTheReport) {
    const fs::path dir = vv::test::processTestDir("pacs-round-trip");
    fs::remove_all(dir);
    auto cta = vv::test::writeTestCtaSeries(dir / "series");
    std::vector<std::string> files;
    for (const fs::path& f : vv::test::filesOf(dir / "series")) {
        files.push_back(f.string());
    }
    const std::uint16_t ourPort = vv::test::freePort();
    vv::test::OrthancServer orthanc(kOurAe, ourPort);
    const vv::pacs::Node n = orthanc.node();
    const std::vector<std::string> node = {
        "--node", n.aeTitle + "@" + n.host + ":" + std::to_string(n.port), "--aet", kOurAe};
    const auto pacs = [&node](std::vector<std::string> args) {
        args.insert(args.begin() + 2, node.begin(), node.end());
        return cli(args);
    };

    // Send the series and find it.
    std::vector<std::string> send = {"pacs", "send"};
    send.insert(send.end(), files.begin(), files.end());
    const ProgramRun sent = pacs(send);
    ASSERT_EQ(sent.code, 0) << sent.output;
    EXPECT_EQ(lines(sent.output, "accepted"), files.size()) << sent.output;

    const ProgramRun studies =
        pacs({"pacs", "find", "--patient-id", "VV-DEMO", "--modality", "CT"});
    ASSERT_EQ(studies.code, 0) << studies.output;
    const auto studyUids = values(studies.output, "studyInstanceUid");
    ASSERT_EQ(studyUids.size(), 1U) << studies.output;
    const std::string study = studyUids[0];
    const ProgramRun series = pacs({"pacs", "find", "--study", study});
    ASSERT_EQ(series.code, 0) << series.output;
    const auto seriesUids = values(series.output, "seriesInstanceUid");
    ASSERT_EQ(seriesUids.size(), 1U) << series.output;

    // Retrieve it with C-GET and with C-MOVE to our listener: every instance arrives.
    for (const bool move : {false, true}) {
        const fs::path store = dir / (move ? "store-move" : "store-get");
        std::vector<std::string> get = {"pacs", "get", "--study", study, "--store", store.string()};
        if (move) {
            get.insert(get.end(),
                       {"--move", "--port", std::to_string(ourPort), "--bind", "127.0.0.1"});
        }
        const ProgramRun got = pacs(get);
        ASSERT_EQ(got.code, 0) << got.output;
        EXPECT_NE(got.output.find("retrieved " + std::to_string(files.size()) + " instance(s)"),
                  std::string::npos)
            << got.output;
        const auto stored = vv::pacs::LocalStore(store).studies();
        ASSERT_EQ(stored.size(), 1U) << (move ? "C-MOVE" : "C-GET");
        ASSERT_EQ(stored[0].series.size(), 1U);
        EXPECT_EQ(stored[0].series[0].instances, static_cast<int>(files.size()));
        EXPECT_EQ(vv::test::filesOf(stored[0].series[0].folder).size(), files.size());
    }

    // Render the retrieved series into the report and its DICOM outputs.
    const fs::path retrieved = dir / "store-get" / study / seriesUids[0];
    const fs::path out = dir / "report";
    fs::create_directories(out);
    const ProgramRun report =
        cli({"report", retrieved.string(), "-o", (out / "r.pdf").string(), "--png",
             (out / "view.png").string(), "--dicom-sc", (out / "sc.dcm").string(), "--dicom-pdf",
             (out / "doc.dcm").string(), "--size", "320x240", "--vss", "off", "--threshold",
             "200:700", "--triangles", "20000"});
    ASSERT_EQ(report.code, 0) << report.output;
    QImage view;
    ASSERT_TRUE(view.load(QString::fromStdString((out / "view.png").string())));
    EXPECT_GT(vesselPixels(view), view.width() * view.height() / 100)
        << "the rendered vessels cover at least 1 % of the view";

    // Send the report back and find its series in the source study.
    const ProgramRun back =
        pacs({"pacs", "send", (out / "sc.dcm").string(), (out / "doc.dcm").string()});
    ASSERT_EQ(back.code, 0) << back.output;
    EXPECT_EQ(lines(back.output, "accepted"), 2U) << back.output;
    const ProgramRun found = pacs({"pacs", "find", "--study", study});
    ASSERT_EQ(found.code, 0) << found.output;
    const auto modalities = values(found.output, "modality");
    const std::multiset<std::string> got(modalities.begin(), modalities.end());
    EXPECT_EQ(got.count("CT"), 1U) << found.output;
    EXPECT_EQ(got.count("DOC"), 1U) << found.output;
    EXPECT_EQ(values(found.output, "seriesInstanceUid").size(), 3U) << found.output;
    vv::test::removeTestCtaSeries(dir / "series", cta);
}

}  // namespace round_trip_test
