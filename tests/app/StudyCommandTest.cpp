// SPDX-License-Identifier: GPL-3.0-or-later
// `vesselview-cli study make`: the stimuli of a mesh file.
// `vesselview-cli study analyse`: two results files of simulated
// participants read as one study; the summary names the exclusion and the
// differences, the tables are written; a bad file exits 3 naming it and its
// line; bad options exit 2.
#include <gtest/gtest.h>

#include <QImage>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>

#include "CliRun.h"
#include "SimulatedResults.h"
#include "vv/demo/DemoTree.h"
#include "vv/meshio/MeshWriter.h"
#include "vv/study/Results.h"

namespace study_command_test {

namespace {

using vv::study::Answer;
using vv::study::Side;
using vv::test::runCli;

std::filesystem::path scratch() {
    auto dir = vv::test::processTestDir("study");
    std::filesystem::create_directories(dir);
    return dir;
}

/// Simulated participants `first`..`last` (and a guesser) in `name`.
std::filesystem::path writeResults(const std::string& name, int first, int last, bool withGuesser) {
    auto file = scratch() / name;
    vv::study::test::writeSimulatedResults(file, first, last, withGuesser);
    return file;
}

TEST(StudyCommand, AnalysesSeveralFilesAsOneStudy) {
    const auto first = writeResults("first.csv", 1, 6, false);
    const auto second = writeResults("second.csv", 7, 12, true);
    const auto tables = scratch() / "tables";
    std::filesystem::remove_all(tables);
    const auto run = runCli({"study", "analyse", first.string(), second.string(), "--tables",
                             tables.string(), "--correction", "holm"});
    ASSERT_EQ(run.code, 0) << run.err;
    EXPECT_NE(run.out.find("Participants: 13, included 12"), std::string::npos) << run.out;
    EXPECT_NE(run.out.find("excluded guesser: at chance level"), std::string::npos) << run.out;
    EXPECT_NE(run.out.find("accuracy: Friedman chi^2(2)"), std::string::npos) << run.out;
    EXPECT_NE(run.out.find("post hoc (Holm"), std::string::npos) << run.out;
    EXPECT_NE(run.out.find("VSS-CD vs baseline"), std::string::npos) << run.out;
    for (const char* table : {"conditions.csv", "comparisons.csv", "participants.csv"}) {
        EXPECT_TRUE(std::filesystem::exists(tables / table)) << table;
    }
}

/// Runs `command` through the shell; its exit status, its output in `text`.
int runShell(const std::string& command, std::string& text) {
    std::FILE* pipe = ::popen((command + " 2>&1").c_str(), "r");
    if (pipe == nullptr) {
        return -1;
    }
    std::array<char, 4096> buffer{};
    for (std::size_t n = 0; (n = std::fread(buffer.data(), 1, buffer.size(), pipe)) > 0;) {
        text.append(buffer.data(), n);
    }
    return ::pclose(pipe);
}

// The program itself (it finds its translations as installed, next to it).
TEST(StudyCommand, WritesThePdfInTheAskedLanguage) {
    const auto results = writeResults("pdf.csv", 1, 8, true);
    const auto pdf = scratch() / "study-de.pdf";
    std::filesystem::remove(pdf);
    std::string output;
    ASSERT_EQ(runShell(std::string("'") + VV_CLI_EXE + "' study analyse '" + results.string() +
                           "' -o '" + pdf.string() + "' --lang de --paper letter",
                       output),
              0)
        << output;
    std::ifstream in(pdf, std::ios::binary);
    std::string head(4, '\0');
    in.read(head.data(), 4);
    EXPECT_EQ(head, "%PDF");
    std::string text;
    ASSERT_EQ(runShell("pdftotext '" + pdf.string() + "' -", text), 0) << text;
    EXPECT_NE(text.find("Rangsumme"), std::string::npos) << text.substr(0, 400);
    EXPECT_NE(text.find("guesser"), std::string::npos);
}

TEST(StudyCommand, ABadFileExitsThreeNamingItsLine) {
    const auto file = scratch() / "bad.csv";
    {
        std::ofstream out(file);
        out << vv::study::resultsHeader() << "\nP1,main,1,s1,demo,VSS-CD,left,left,1,fast\n";
    }
    const auto run = runCli({"study", "analyse", file.string()});
    EXPECT_EQ(run.code, 3);
    EXPECT_NE(run.err.find("bad.csv"), std::string::npos) << run.err;
    EXPECT_NE(run.err.find("line 2"), std::string::npos) << run.err;
}

/// A three-generation demo tree written to `name` in the scratch folder.
std::filesystem::path smallTree(const std::string& name) {
    vv::demo::DemoTreeOptions o;
    o.generations = 3;
    auto mesh = scratch() / name;
    vv::meshio::writeVtp(vv::demo::buildVesselSurface(vv::demo::generateVesselTree(o), o), mesh);
    return mesh;
}

/// The scratch folder `name`, emptied.
std::filesystem::path emptied(const std::string& name) {
    auto folder = scratch() / name;
    std::filesystem::remove_all(folder);
    return folder;
}

// Stimuli from a mesh file: the asked conditions and pairs, a manifest that
// lists them; bad options exit 2, a missing scene 3.
TEST(StudyCommand, MakesTheStimuliOfAMeshFile) {
    const auto mesh = smallTree("tree.vtp");
    const auto folder = emptied("made");
    const auto run = runCli({"study", "make", mesh.string(), "-o", folder.string(), "--pairs", "2",
                             "--conditions", "VSS-CD,baseline", "--size", "400x300", "--seed", "9",
                             "--training-pairs", "1"});
    ASSERT_EQ(run.code, 0) << run.err;
    EXPECT_NE(run.out.find("4 stimuli and 2 training stimuli"), std::string::npos) << run.out;
    for (const char* name :
         {"tree-p1-VSS-CD.png", "tree-p2-baseline.png", "tree-t1-baseline.png"}) {
        EXPECT_TRUE(std::filesystem::exists(folder / "stimuli" / name)) << name;
    }
    std::ifstream in(folder / "manifest.json");
    std::stringstream text;
    text << in.rdbuf();
    const QJsonObject manifest =
        QJsonDocument::fromJson(QByteArray::fromStdString(text.str())).object();
    EXPECT_EQ(manifest["stimuli"].toArray().size(), 6);
    EXPECT_EQ(manifest["seed"].toString(), "9");
    EXPECT_EQ(manifest["width"].toInt(), 400);

    EXPECT_EQ(
        runCli({"study", "make", mesh.string(), "-o", folder.string(), "--conditions", "VSS-XX"})
            .code,
        2);
    EXPECT_EQ(
        runCli({"study", "make", mesh.string(), "-o", folder.string(), "--training-pairs", "-1"})
            .code,
        2);
    EXPECT_EQ(runCli({"study", "make", mesh.string(), "-o", folder.string(), "--pairs", "0"}).code,
              2);
    EXPECT_EQ(runCli({"study", "make", mesh.string()}).code, 2);
    EXPECT_EQ(
        runCli({"study", "make", (scratch() / "missing.vtp").string(), "-o", folder.string()}).code,
        3);
}

// Conditions of one's own: any display setting of the schema, from a paper
// condition; what they show is in the images and the manifest says how
// they were given; a setting that is not one, or a bad value, exits 2.
TEST(StudyCommand, ConditionsFromAnyDisplaySetting) {
    const auto mesh = smallTree("tree-conditions.vtp");
    const auto folder = emptied("conditions");
    const auto run = runCli({"study", "make", mesh.string(), "-o", folder.string(), "--pairs", "1",
                             "--training-pairs", "0", "--size", "320x240", "--conditions",
                             "baseline", "--condition", "fog:cue=fog,fog-strength=1", "--condition",
                             "VSS-iso:from=VSS-CD,isolines=8,light=-30,20"});
    ASSERT_EQ(run.code, 0) << run.err;
    std::ifstream in(folder / "manifest.json");
    std::stringstream text;
    text << in.rdbuf();
    const QJsonObject manifest =
        QJsonDocument::fromJson(QByteArray::fromStdString(text.str())).object();
    const QJsonArray conditions = manifest["conditions"].toArray();
    ASSERT_EQ(conditions.size(), 3);
    EXPECT_EQ(conditions[0].toObject()["name"].toString(), "baseline");
    const QJsonObject fog = conditions[1].toObject();
    EXPECT_EQ(fog["name"].toString(), "fog");
    EXPECT_EQ(fog["settings"].toString(), "cue=fog,fog-strength=1");
    EXPECT_EQ(fog["display"].toObject()["vessel_cue"].toString(), "fog");
    EXPECT_DOUBLE_EQ(fog["display"].toObject()["fog_strength"].toDouble(), 1.0);
    EXPECT_FALSE(fog["display"].toObject()["vss"].toBool());
    const QJsonObject iso = conditions[2].toObject()["display"].toObject();
    EXPECT_TRUE(iso["vss"].toBool());
    EXPECT_EQ(iso["vss_scale"].toString(), "chromadepth");
    EXPECT_EQ(iso["iso_lines"].toInt(), 8);
    EXPECT_DOUBLE_EQ(iso["light_azimuth_deg"].toDouble(), -30.0);
    // The fog condition's image differs from the baseline's: the far vessels
    // fade toward the background.
    const QImage plain(
        QString::fromStdString((folder / "stimuli/tree-conditions-p1-baseline.png").string()));
    const QImage fogged(
        QString::fromStdString((folder / "stimuli/tree-conditions-p1-fog.png").string()));
    ASSERT_FALSE(plain.isNull());
    ASSERT_EQ(plain.size(), fogged.size());
    int differing = 0;
    for (int y = 0; y < plain.height(); ++y) {
        for (int x = 0; x < plain.width(); ++x) {
            differing += plain.pixel(x, y) != fogged.pixel(x, y) ? 1 : 0;
        }
    }
    EXPECT_GT(differing, 500);

    for (const char* bad : {"fog", "fog:", ":cue=fog", "fog:frobnicate=1", "fog:isolines=-3",
                            "fog:from=VSS-XX", "fog:cue"}) {
        const auto refused =
            runCli({"study", "make", mesh.string(), "-o", folder.string(), "--condition", bad});
        EXPECT_EQ(refused.code, 2) << bad;
        EXPECT_NE(refused.err.find("--condition"), std::string::npos) << refused.err;
    }
    EXPECT_EQ(
        runCli({"study", "make", mesh.string(), "-o", folder.string(), "--conditions", "none"})
            .code,
        2);
}

TEST(StudyCommand, BadOptionsAreUsageErrors) {
    const auto file = writeResults("options.csv", 1, 3, false);
    EXPECT_EQ(runCli({"study"}).code, 2);
    EXPECT_EQ(runCli({"study", "frobnicate"}).code, 2);
    EXPECT_EQ(runCli({"study", "analyse"}).code, 2);
    EXPECT_EQ(runCli({"study", "analyse", file.string(), "--alpha", "2"}).code, 2);
    EXPECT_EQ(runCli({"study", "analyse", file.string(), "--correction", "none"}).code, 2);
    EXPECT_EQ(runCli({"study", "analyse", file.string(), "--frobnicate"}).code, 2);
    EXPECT_EQ(runCli({"study", "analyse", file.string(), "-o", "study.txt"}).code, 2);
    EXPECT_EQ(runCli({"study", "analyse", file.string(), "-o", "s.pdf", "--lang", "xx"}).code, 2);
    EXPECT_EQ(runCli({"study", "analyse", file.string(), "-o", "s.pdf", "--paper", "a3"}).code, 2);
    EXPECT_EQ(runCli({"study", "--help"}).code, 0);
}

}  // namespace

}  // namespace study_command_test
