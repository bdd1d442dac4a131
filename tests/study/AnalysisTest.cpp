// SPDX-License-Identifier: GPL-3.0-or-later
// The study's analysis on simulated participants whose accuracy and speed
// depend on the condition by known amounts: the differences are found, the
// summaries hold the truth, a guessing participant and one who missed a
// condition are excluded with their reasons, repeated and training answers
// do not count; the tables written are the numbers of the analysis.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "vv/study/Analysis.h"

namespace vv::study {
namespace {

const std::vector<std::string> kConditions{"VSS-CD", "VSS-PCD", "vessel-CD", "baseline"};
// Per condition: the chance of a correct answer and the mean response time.
const std::vector<double> kAccuracy{0.9, 0.9, 0.8, 0.6};
const std::vector<double> kTimeMs{1200.0, 1250.0, 1800.0, 1900.0};
constexpr int kPerCondition = 30;

/// One simulated participant's main-block answers (and a training block).
void simulate(const std::string& id, double accuracyShift, std::mt19937& random,
              std::vector<Answer>& out, std::size_t conditions = kConditions.size(),
              bool guessing = false) {
    std::uniform_real_distribution<double> uniform(0.0, 1.0);
    std::lognormal_distribution<double> spread(0.0, 0.25);
    int trial = 0;
    for (int t = 0; t < 5; ++t) {  // training: must not count
        Answer a;
        a.participant = id;
        a.block = Block::Training;
        a.trial = ++trial;
        a.stimulus = "train" + std::to_string(t);
        a.condition = "training-only";
        a.answer = Side::Right;
        a.correctAnswer = Side::Left;
        a.responseMs = 99999.0;
        out.push_back(a);
    }
    trial = 0;
    for (std::size_t c = 0; c < conditions; ++c) {
        for (int i = 0; i < kPerCondition; ++i) {
            Answer a;
            a.participant = id;
            a.trial = ++trial;
            a.stimulus = kConditions[c] + "/" + std::to_string(i);
            a.scene = "tree " + std::to_string(i % 6);
            a.condition = kConditions[c];
            a.correctAnswer = uniform(random) < 0.5 ? Side::Left : Side::Right;
            const double p = guessing ? 0.5 : std::min(1.0, kAccuracy[c] + accuracyShift);
            const bool right = uniform(random) < p;
            a.answer = right ? a.correctAnswer
                             : (a.correctAnswer == Side::Left ? Side::Right : Side::Left);
            a.responseMs = kTimeMs[c] * spread(random);
            out.push_back(a);
        }
    }
}

std::vector<Answer> simulatedStudy() {
    std::mt19937 random(2018);
    std::normal_distribution<double> skill(0.0, 0.03);
    std::vector<Answer> answers;
    for (int p = 1; p <= 16; ++p) {
        simulate("P" + std::to_string(p), skill(random), random, answers);
    }
    simulate("guesser", 0.0, random, answers, kConditions.size(), true);
    simulate("left early", 0.0, random, answers, 2);
    return answers;
}

TEST(StudyAnalysis, FindsTheSimulatedDifferencesAndExcludesByTheRule) {
    const StudyAnalysis study = analyseStudy(simulatedStudy());
    EXPECT_EQ(study.conditions, kConditions);  // training's condition left out
    ASSERT_EQ(study.participants.size(), 18U);
    EXPECT_EQ(study.included, 16U);
    const ParticipantResult& guesser = study.participants[16];
    EXPECT_EQ(guesser.id, "guesser");
    EXPECT_TRUE(guesser.excluded);
    EXPECT_NE(guesser.exclusionReason.find("chance"), std::string::npos);
    EXPECT_EQ(guesser.answers, 120U);
    const ParticipantResult& early = study.participants[17];
    EXPECT_TRUE(early.excluded);
    EXPECT_EQ(early.missingConditions, (std::vector<std::string>{"vessel-CD", "baseline"}));
    EXPECT_NE(study.exclusionRule.find("binomial"), std::string::npos);

    // Accuracy: 0.9 / 0.9 / 0.8 / 0.6 differ, the truth within each interval.
    ASSERT_EQ(study.accuracy.table.size(), 16U);
    EXPECT_LT(study.accuracy.friedman.pValue, 1e-4);
    for (std::size_t c = 0; c < kConditions.size(); ++c) {
        const Summary& s = study.accuracy.perCondition[c];
        EXPECT_EQ(s.count, 16U);
        EXPECT_LT(s.meanLow, kAccuracy[c]) << kConditions[c];
        EXPECT_GT(s.meanHigh, kAccuracy[c]) << kConditions[c];
    }
    // Post hoc: VSS-CD against the baseline (0.9 against 0.6) differs; the
    // two VSS conditions (0.9 and 0.9) do not.
    const auto pair = [](const PostHoc& post, std::size_t a, std::size_t b) {
        for (const PairComparison& p : post.pairs) {
            if (p.first == a && p.second == b) {
                return p;
            }
        }
        return PairComparison{};
    };
    EXPECT_TRUE(pair(study.accuracy.postHoc, 0, 3).significant);
    EXPECT_FALSE(pair(study.accuracy.postHoc, 0, 1).significant);
    // Response time: 1200 / 1250 against 1800 / 1900 ms (median of a
    // log-normal spread around them).
    EXPECT_LT(study.responseTime.friedman.pValue, 1e-4);
    EXPECT_TRUE(pair(study.responseTime.postHoc, 0, 2).significant);
    EXPECT_FALSE(pair(study.responseTime.postHoc, 2, 3).significant);
    EXPECT_NEAR(study.responseTime.perCondition[0].median, 1200.0, 120.0);
    EXPECT_EQ(study.responseTime.unit, "ms");
}

TEST(StudyAnalysis, ARepeatedStimulusCountsOnce) {
    std::vector<Answer> answers = simulatedStudy();
    const std::size_t before = answers.size();
    // P1 resumed and answered their first three main stimuli again, wrongly.
    for (std::size_t i = 5; i < 8; ++i) {
        Answer again = answers[i];
        again.answer = again.correctAnswer == Side::Left ? Side::Right : Side::Left;
        answers.push_back(again);
    }
    const StudyAnalysis once = analyseStudy(
        std::vector<Answer>(answers.begin(), answers.begin() + static_cast<long>(before)));
    const StudyAnalysis twice = analyseStudy(answers);
    EXPECT_EQ(twice.participants[0].answers, once.participants[0].answers);
    EXPECT_EQ(twice.participants[0].correct, once.participants[0].correct);
    ASSERT_EQ(twice.notes.size(), 1U);
    EXPECT_NE(twice.notes[0].find("3 main-block answers"), std::string::npos) << twice.notes[0];
}

TEST(StudyAnalysis, TooLittleToAnalyseIsSaid) {
    std::mt19937 random(1);
    std::vector<Answer> one;
    simulate("P1", 0.0, random, one, 1);
    EXPECT_THROW(static_cast<void>(analyseStudy(one)), StudyError);
    std::vector<Answer> single;
    simulate("P1", 0.0, random, single);
    try {
        static_cast<void>(analyseStudy(single));
        ADD_FAILURE() << "analysed one participant";
    } catch (const StudyError& e) {
        EXPECT_NE(std::string(e.what()).find("1 of 1 participants"), std::string::npos) << e.what();
    }
    AnalysisOptions bad;
    bad.alpha = 1.5;
    EXPECT_THROW(static_cast<void>(analyseStudy(simulatedStudy(), bad)), InvalidArgumentError);
}

// Files analysed as one study: their answers together, and an analysis
// that cannot be made names the files it read.
TEST(StudyAnalysis, ResultsFilesAreAnalysedAsOneAndTheirErrorsNameThem) {
    const auto dir = std::filesystem::path(VV_TEST_TMP) / "study-analysis-files";
    std::filesystem::create_directories(dir);
    const std::vector<Answer> all = simulatedStudy();
    const auto half = static_cast<std::ptrdiff_t>(all.size() / 2);
    // Split at a participant's first answer: each file holds whole participants.
    auto cut = all.begin() + half;
    while (cut != all.end() && cut->participant == (cut - 1)->participant) {
        ++cut;
    }
    const auto write = [&](const std::string& name, auto from, auto to) {
        auto file = dir / name;
        std::ofstream out(file, std::ios::binary | std::ios::trunc);
        out << resultsHeader() << "\n";
        for (auto a = from; a != to; ++a) {
            out << resultsRow(*a) << "\n";
        }
        return file;
    };
    const auto first = write("first.csv", all.begin(), cut);
    const auto second = write("second.csv", cut, all.end());
    const StudyAnalysis together = analyseResultsFiles({first, second});
    const StudyAnalysis direct = analyseStudy(all);
    EXPECT_EQ(together.participants.size(), direct.participants.size());
    EXPECT_DOUBLE_EQ(together.accuracy.friedman.chiSquared, direct.accuracy.friedman.chiSquared);

    std::mt19937 random(3);
    std::vector<Answer> alone;
    simulate("P1", 0.0, random, alone);
    const auto lonely = write("lonely.csv", alone.begin(), alone.end());
    try {
        static_cast<void>(analyseResultsFiles({lonely}));
        ADD_FAILURE() << "analysed one participant";
    } catch (const StudyError& e) {
        EXPECT_EQ(e.file(), lonely);
        EXPECT_NE(std::string(e.what()).find("1 of 1 participants"), std::string::npos) << e.what();
    }
    EXPECT_THROW(static_cast<void>(analyseResultsFiles({})), InvalidArgumentError);
    EXPECT_THROW(static_cast<void>(analyseResultsFiles({dir / "missing.csv"})), Error);
}

/// The rows of a CSV table (no quoted fields in these).
std::vector<std::vector<std::string>> rowsOf(const std::filesystem::path& file) {
    std::ifstream in(file);
    std::vector<std::vector<std::string>> rows;
    std::string line;
    while (std::getline(in, line)) {
        std::vector<std::string> fields;
        std::stringstream words(line);
        std::string f;
        while (std::getline(words, f, ',')) {
            fields.push_back(f);
        }
        rows.push_back(fields);
    }
    return rows;
}

TEST(StudyAnalysis, TheTablesHoldTheAnalysisNumbers) {
    const StudyAnalysis study = analyseStudy(simulatedStudy());
    const auto folder = std::filesystem::path(VV_TEST_TMP) / "study-tables";
    std::filesystem::remove_all(folder);
    std::filesystem::create_directories(folder);
    writeAnalysisTables(study, folder);
    const auto conditions = rowsOf(folder / "conditions.csv");
    ASSERT_EQ(conditions.size(), 1 + 2 * kConditions.size());
    EXPECT_EQ(conditions[0][0], "measure");
    for (std::size_t c = 0; c < kConditions.size(); ++c) {
        const auto& row = conditions[1 + c];
        EXPECT_EQ(row[0], "accuracy");
        EXPECT_EQ(row[1], kConditions[c]);
        EXPECT_NEAR(std::stod(row[3]), study.accuracy.perCondition[c].mean, 1e-5);
        const auto& time = conditions[1 + kConditions.size() + c];
        EXPECT_EQ(time[0], "response time [ms]");
        EXPECT_NEAR(std::stod(time[7]), study.responseTime.perCondition[c].median,
                    1e-5 * study.responseTime.perCondition[c].median);
    }
    const auto comparisons = rowsOf(folder / "comparisons.csv");
    // Per measure: Friedman, Kendall's W and 6 pairs.
    ASSERT_EQ(comparisons.size(), 1U + 2U * (2U + 6U));
    EXPECT_EQ(comparisons[1][1], "Friedman");
    EXPECT_NEAR(std::stod(comparisons[1][4]), study.accuracy.friedman.chiSquared,
                1e-5 * study.accuracy.friedman.chiSquared);
    const auto participants = rowsOf(folder / "participants.csv");
    ASSERT_EQ(participants.size(), 1U + study.participants.size());
    EXPECT_EQ(participants[17][0], "guesser");
    EXPECT_EQ(participants[17][6], "yes");
    EXPECT_EQ(participants[1][6], "no");
}

}  // namespace
}  // namespace vv::study
