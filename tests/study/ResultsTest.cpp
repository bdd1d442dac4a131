// SPDX-License-Identifier: GPL-3.0-or-later
// The results file: answers appended one by one come back as they were
// (ids with commas and quotes too); every kind of bad file gets an error
// naming the file, the line and the problem, and is never changed.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "vv/study/Results.h"

namespace vv::study {
namespace {

std::filesystem::path scratch(const std::string& name) {
    const auto dir = std::filesystem::path(VV_TEST_TMP) / "study-results";
    std::filesystem::create_directories(dir);
    auto file = dir / name;
    std::filesystem::remove(file);
    return file;
}

Answer answer(const std::string& participant, int trial, const std::string& condition, Side chosen,
              Side closer, double ms) {
    Answer a;
    a.participant = participant;
    a.trial = trial;
    a.stimulus = "s" + std::to_string(trial);
    a.scene = "demo tree";
    a.condition = condition;
    a.answer = chosen;
    a.correctAnswer = closer;
    a.responseMs = ms;
    return a;
}

std::string contents(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

TEST(ResultsFile, AnswersAppendedComeBackAsTheyWere) {
    const auto file = scratch("round-trip.csv");
    std::vector<Answer> written{answer("P01", 1, "VSS-CD", Side::Left, Side::Left, 812.25),
                                answer("Doe, \"J\"", 2, "vessel-PCD", Side::Right, Side::Left, 0.0),
                                answer("P01", 3, "baseline", Side::Right, Side::Right, 15000.5)};
    written[1].block = Block::Training;
    for (const Answer& a : written) {
        appendAnswer(file, a);
    }
    const std::vector<Answer> read = readResults(file);
    ASSERT_EQ(read.size(), written.size());
    for (std::size_t i = 0; i < read.size(); ++i) {
        EXPECT_EQ(read[i].participant, written[i].participant);
        EXPECT_EQ(read[i].block, written[i].block);
        EXPECT_EQ(read[i].trial, written[i].trial);
        EXPECT_EQ(read[i].stimulus, written[i].stimulus);
        EXPECT_EQ(read[i].scene, written[i].scene);
        EXPECT_EQ(read[i].condition, written[i].condition);
        EXPECT_EQ(read[i].answer, written[i].answer);
        EXPECT_EQ(read[i].correctAnswer, written[i].correctAnswer);
        EXPECT_NEAR(read[i].responseMs, written[i].responseMs, 1e-3);
    }
    EXPECT_TRUE(read[0].correct());
    EXPECT_FALSE(read[1].correct());
    // One header, one line per answer.
    const std::string text = contents(file);
    EXPECT_EQ(text.rfind(resultsHeader() + "\n", 0), 0U);
    EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 4);
}

TEST(ResultsFile, AHeaderAloneHoldsNoAnswers) {
    const auto file = scratch("header-only.csv");
    std::ofstream(file) << resultsHeader() << "\r\n";
    EXPECT_TRUE(readResults(file).empty());
}

TEST(ResultsFile, EveryBadFileIsRefusedNamingFileLineAndProblem) {
    const std::string good = "P1,main,1,s1,demo,VSS-CD,left,left,1,500";
    const std::vector<std::pair<std::string, std::string>> cases{
        {"", "no header"},
        {"participant,block\n", "header"},
        {good + ",extra", "11 fields"},
        {"P1,main,1,s1,demo,VSS-CD,left,left,1", "9 fields"},
        {"P1,warmup,1,s1,demo,VSS-CD,left,left,1,500", "column block"},
        {"P1,main,0,s1,demo,VSS-CD,left,left,1,500", "column trial"},
        {"P1,main,x,s1,demo,VSS-CD,left,left,1,500", "column trial"},
        {"P1,main,1,s1,demo,VSS-CD,up,left,1,500", "column answer"},
        {"P1,main,1,s1,demo,VSS-CD,left,down,1,500", "column correct_answer"},
        {"P1,main,1,s1,demo,VSS-CD,left,right,1,500", "column correct"},
        {"P1,main,1,s1,demo,VSS-CD,left,left,1,nan", "column response_ms"},
        {"P1,main,1,s1,demo,VSS-CD,left,left,1,-3", "column response_ms"},
        {"P1,main,1,s1,demo,VSS-CD,left,left,1,", "column response_ms"},
        {",main,1,s1,demo,VSS-CD,left,left,1,500", "column participant"},
        {"P1,main,1,s1,demo,,left,left,1,500", "column condition"},
        {"\"P1,main,1,s1,demo,VSS-CD,left,left,1,500", "not closed"},
    };
    int n = 0;
    for (const auto& [body, words] : cases) {
        const auto file = scratch("bad-" + std::to_string(n++) + ".csv");
        std::string text = body;
        if (!body.empty() && body.rfind("participant,", 0) != 0) {
            text = resultsHeader();
            text.append("\n").append(good).append("\n").append(body).append("\n");
        }
        std::ofstream(file, std::ios::binary) << text;
        try {
            static_cast<void>(readResults(file));
            ADD_FAILURE() << "read a bad file: " << text;
        } catch (const StudyError& e) {
            const std::string what = e.what();
            EXPECT_NE(what.find(file.filename().string()), std::string::npos) << what;
            EXPECT_NE(what.find(words), std::string::npos) << what;
            if (!body.empty() && body.rfind("participant,", 0) != 0) {
                EXPECT_NE(what.find("line 3"), std::string::npos) << what;
            }
        }
        // Appending to it is refused and leaves it as it was.
        EXPECT_THROW(appendAnswer(file, answer("P", 1, "c", Side::Left, Side::Left, 1.0)),
                     StudyError);
        EXPECT_EQ(contents(file), text);
    }
}

TEST(ResultsFile, MissingAndHugeFilesAreRefused) {
    EXPECT_THROW(static_cast<void>(readResults(scratch("missing.csv"))), StudyError);
    const auto huge = scratch("huge.csv");
    std::ofstream(huge) << resultsHeader() << "\n";
    std::filesystem::resize_file(huge, 65ULL << 20U);
    try {
        static_cast<void>(readResults(huge));
        ADD_FAILURE() << "read a 65 MiB file";
    } catch (const StudyError& e) {
        EXPECT_NE(std::string(e.what()).find("64 MiB"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace vv::study
