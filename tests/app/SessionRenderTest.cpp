// SPDX-License-Identifier: GPL-3.0-or-later
// `vesselview-cli render --session` and `report --session`: a saved session's
// files, camera and display settings, options after it overriding it, and
// exit code 3 with the file and the field for a session that names a missing
// file or holds a bad value. Needs OpenGL: run under `xvfb-run -a`.
#include <gtest/gtest.h>

#include <QByteArray>
#include <QFile>
#include <QImage>
#include <QString>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "CliRun.h"
#include "cli/Cli.h"
#include "common/Session.h"
#include "vv/demo/DemoTree.h"
#include "vv/meshio/MeshWriter.h"
#include "vv/scene/Mesh.h"

namespace vv::test {
namespace {

namespace fs = std::filesystem;

fs::path dir() {
    const fs::path d = processTestDir("session-render");
    fs::create_directories(d);
    return d;
}

std::string readAll(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

/// A small demo tree (with its "wss" array), as VTP.
fs::path writeTree() {
    const fs::path file = dir() / "tree.vtp";
    if (!fs::exists(file)) {
        demo::DemoTreeOptions options;
        options.generations = 3;
        options.voxelSizeMm = 1.0;
        meshio::writeVtp(demo::generateDemoMesh(options), file);
    }
    return file;
}

/// A session of the tree unlike the defaults: a turned camera, the
/// dark-means-deep scale, p = 4, iso-lines, inferno, a light, no legends.
app::Session treeSession() {
    app::Session s;
    s.files = {QString::fromStdString(writeTree().string())};
    s.cameraTarget = glm::vec3(0.0F, 0.0F, 20.0F);
    s.cameraDistance = 120.0F;
    s.cameraRotation = glm::normalize(glm::quat(0.9F, 0.2F, 0.3F, 0.0F));
    s.vss.scale = colormaps::DepthScale::DarkMeansDeep;
    s.vss.solver.p = 4.0;
    s.vss.isoLines = 5;
    s.style.array = "wss";
    s.style.colorMap = colormaps::ColorMap::Inferno;
    s.style.light = {40.0F, 10.0F};
    s.legends = false;
    return s;
}

fs::path save(const std::string& name, const app::Session& session) {
    const fs::path file = dir() / name;
    app::saveSession(file, session);
    return file;
}

/// The saved session `file` with `from` replaced by `to` (exactly once).
fs::path edited(const fs::path& file, const std::string& name, const QByteArray& from,
                const QByteArray& to) {
    QFile in(QString::fromStdString(file.string()));
    EXPECT_TRUE(in.open(QIODevice::ReadOnly));
    QByteArray json = in.readAll();
    EXPECT_EQ(json.count(from), 1) << from.toStdString();
    json.replace(from, to);
    const fs::path out = dir() / name;
    QFile write(QString::fromStdString(out.string()));
    EXPECT_TRUE(write.open(QIODevice::WriteOnly | QIODevice::Truncate));
    write.write(json);
    return out;
}

CliRunResult render(const fs::path& session, const fs::path& output,
                    const std::vector<std::string>& before = {},
                    const std::vector<std::string>& after = {}) {
    std::vector<std::string> args{"render"};
    args.insert(args.end(), before.begin(), before.end());
    args.insert(args.end(),
                {"--session", session.string(), "-o", output.string(), "--size", "240x180"});
    args.insert(args.end(), after.begin(), after.end());
    return runCli(args);
}

TEST(SessionRender, RendersTheSessionAndOptionsAfterItOverrideIt) {
    const fs::path session = save("tree.vvs", treeSession());
    app::Session chromadepth = treeSession();
    chromadepth.vss.scale = colormaps::DepthScale::Chromadepth;
    const fs::path other = save("tree-cd.vvs", chromadepth);

    const auto a = render(session, dir() / "a.png");
    ASSERT_EQ(a.code, cli::kOk) << a.err;
    EXPECT_NE(a.out.find("dark-means-deep p=4"), std::string::npos) << a.out;
    EXPECT_NE(a.out.find("through inferno"), std::string::npos) << a.out;
    const QImage image(QString::fromStdString((dir() / "a.png").string()));
    ASSERT_EQ(image.size(), QSize(240, 180));
    EXPECT_GT(litPixels(image), 240L * 180L / 10L);

    ASSERT_EQ(render(other, dir() / "b.png").code, cli::kOk);
    ASSERT_EQ(render(session, dir() / "c.png", {}, {"--scale", "cd"}).code, cli::kOk);
    ASSERT_EQ(render(session, dir() / "d.png", {"--scale", "cd"}).code, cli::kOk);
    EXPECT_NE(readAll(dir() / "a.png"), readAll(dir() / "b.png")) << "the scale shows";
    EXPECT_EQ(readAll(dir() / "c.png"), readAll(dir() / "b.png")) << "an option after --session";
    EXPECT_EQ(readAll(dir() / "d.png"), readAll(dir() / "a.png")) << "an option before it";

    // The session's camera, unless --view follows.
    ASSERT_EQ(render(session, dir() / "e.png", {}, {"--view", "anterior"}).code, cli::kOk);
    EXPECT_NE(readAll(dir() / "e.png"), readAll(dir() / "a.png"));

    const auto report = runCli({"report", "--session", session.string(), "-o",
                                (dir() / "r.pdf").string(), "--size", "240x180"});
    ASSERT_EQ(report.code, cli::kOk) << report.err;
    EXPECT_GT(fs::file_size(dir() / "r.pdf"), 1000U);
}

TEST(SessionRender, AMissingFileExitsThreeNamingTheSessionAndTheField) {
    app::Session s = treeSession();
    s.files << QString::fromStdString((dir() / "gone.vtp").string());
    const fs::path session = save("missing.vvs", s);
    for (const char* command : {"render", "report"}) {
        const auto r = runCli({command, "--session", session.string(), "-o",
                               (dir() / (std::string(command) + "-never")).string()});
        EXPECT_EQ(r.code, cli::kInvalidInput) << command << ": " << r.err;
        for (const char* part : {"missing.vvs", "'files[1]'", "gone.vtp"}) {
            EXPECT_NE(r.err.find(part), std::string::npos) << command << ": " << r.err;
        }
    }
    EXPECT_FALSE(fs::exists(dir() / "render-never"));
}

TEST(SessionRender, BadValuesExitThreeNamingTheSessionAndTheField) {
    const fs::path good = save("good.vvs", treeSession());
    struct Case {
        const char* name;
        QByteArray from;
        QByteArray to;
        const char* field;
    };
    const Case cases[] = {
        {"range.vvs", "\"p\": 4", "\"p\": 100", "'view.vss.p'"},
        {"type.vvs", "\"isoLines\": 5", "\"isoLines\": \"five\"", "'view.vss.isoLines'"},
        {"name.vvs", "\"inferno\"", "\"jet\"", "'view.style.colorMap'"},
        {"array.vvs", "\"array\": \"wss\"", "\"array\": \"speed\"", "'view.style.array'"},
    };
    for (const Case& c : cases) {
        const fs::path session = edited(good, c.name, c.from, c.to);
        for (const char* command : {"render", "report"}) {
            const auto r = runCli(
                {command, "--session", session.string(), "-o", (dir() / "never.out").string()});
            EXPECT_EQ(r.code, cli::kInvalidInput) << c.name << " " << command << ": " << r.err;
            EXPECT_NE(r.err.find(c.name), std::string::npos) << r.err;
            EXPECT_NE(r.err.find(c.field), std::string::npos) << r.err;
        }
    }
    EXPECT_FALSE(fs::exists(dir() / "never.out"));
}

TEST(SessionRender, TheSliceStateIsCheckedAndOtherwiseIgnored) {
    // A session saved from a DICOM scene keeps its slice views; the command
    // line renders the 3-D view, the same as without them.
    app::Session withSlices = treeSession();
    app::SliceSessionState state;
    state.layout = 2;  // "axial"
    state.window = {40.0, 400.0};
    state.preset = slices::WindowPreset::SoftTissue;
    state.views.at(0) = {12.5, 3.0, {5.0, -2.0}};
    state.cursor = glm::dvec3(1.0, 2.0, 3.0);
    withSlices.slices = state;
    const fs::path session = save("slices.vvs", withSlices);
    const auto a = render(save("no-slices.vvs", treeSession()), dir() / "no-slices.png");
    ASSERT_EQ(a.code, cli::kOk) << a.err;
    const auto b = render(session, dir() / "slices.png");
    ASSERT_EQ(b.code, cli::kOk) << b.err;
    EXPECT_EQ(readAll(dir() / "slices.png"), readAll(dir() / "no-slices.png"));
    // A bad slice value is refused as any other field.
    const fs::path bad = edited(session, "bad-slices.vvs", "\"zoom\": 3", "\"zoom\": -3");
    const auto c = render(bad, dir() / "never.png");
    EXPECT_EQ(c.code, cli::kInvalidInput) << c.err;
    EXPECT_NE(c.err.find("bad-slices.vvs"), std::string::npos) << c.err;
    EXPECT_NE(c.err.find("'slices.axial.zoom'"), std::string::npos) << c.err;
    EXPECT_FALSE(fs::exists(dir() / "never.png"));
}

TEST(SessionRender, SessionsDoNotMixWithOtherInputs) {
    const fs::path session = save("plain.vvs", treeSession());
    const std::string out = (dir() / "x.png").string();
    EXPECT_EQ(runCli({"render", "in.vtp", "--session", session.string(), "-o", out}).code,
              cli::kUsage);
    EXPECT_EQ(runCli({"render", "--session", session.string(), "-o", out, "--raycast"}).code,
              cli::kUsage);
    EXPECT_EQ(runCli({"report", "--session", session.string(), "--batch", "l.txt", "--out-dir",
                      dir().string()})
                  .code,
              cli::kUsage);
    EXPECT_EQ(runCli({"render", "-o", out, "--session"}).code, cli::kUsage);
    EXPECT_EQ(runCli({"render", "--session", (dir() / "none.vvs").string(), "-o", out}).code,
              cli::kInvalidInput);
}

}  // namespace
}  // namespace vv::test
