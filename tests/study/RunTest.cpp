// SPDX-License-Identifier: GPL-3.0-or-later
// One participant's run: the manifest read back (and every kind of bad one
// refused, naming the file and the problem), the Latin-square order (every
// pair once per segment, every condition in every segment, the square
// balanced, the same participant the same order), and the runner's states:
// training with feedback until the participant goes on, the main block in
// the plan's order, breaks, the response time from the onset, every answer
// in the results file at once, and a run that resumes where it stopped.
#include <gtest/gtest.h>

#include <map>
#include <set>

#include "StudyFolder.h"
#include "vv/study/Manifest.h"
#include "vv/study/RunPlan.h"
#include "vv/study/StudyRun.h"

namespace vv::study::run_test {
namespace {

std::filesystem::path scratch(const std::string& name) {
    return std::filesystem::path(VV_TEST_TMP) / "study-run" / name;
}

std::string messageOf(const std::filesystem::path& dir, const QJsonObject& manifest) {
    test::writeManifestJson(dir, manifest);
    try {
        static_cast<void>(readManifest(dir));
    } catch (const StudyError& e) {
        return e.what();
    }
    return "(read without an error)";
}

TEST(StudyManifestFile, ReadsWhatTheFolderHolds) {
    const auto dir = scratch("manifest");
    test::writeStudyFolder(dir);
    const StudyManifest m = readManifest(dir);
    EXPECT_EQ(m.conditions.size(), 5U);
    EXPECT_EQ(m.width, 320);
    ASSERT_EQ(m.stimuli.size(), 2U * 3U * 5U);
    EXPECT_EQ(m.indicesOf(Block::Main).size(), 20U);
    EXPECT_EQ(m.indicesOf(Block::Training).size(), 10U);
    EXPECT_EQ(m.stimuli[0].id, "tree-p1-VSS-CD");
    EXPECT_EQ(m.stimuli[0].image, std::filesystem::absolute(dir) / "stimuli/tree-p1-VSS-CD.png");
    EXPECT_EQ(m.stimuli[5].correctAnswer, Side::Right);  // tree pair 2
    EXPECT_EQ(m.stimuli[0].right.x, 240);
    // The manifest file itself names the same study.
    EXPECT_EQ(readManifest(dir / "manifest.json").stimuli.size(), m.stimuli.size());
}

TEST(StudyManifestFile, BadManifestsAreRefusedNamingTheProblem) {
    const auto dir = scratch("bad-manifest");
    test::writeStudyFolder(dir);
    const QJsonObject good = test::studyManifestJson({});
    const auto withStimulus = [&](const char* key, const QJsonValue& value) {
        QJsonObject m = good;
        QJsonArray stimuli = m["stimuli"].toArray();
        QJsonObject first = stimuli[0].toObject();
        if (value.isUndefined()) {
            first.remove(key);
        } else {
            first[key] = value;
        }
        stimuli[0] = first;
        m["stimuli"] = stimuli;
        return m;
    };
    EXPECT_NE(messageOf(dir, {{"format", "something-else"}}).find("not a VesselView study"),
              std::string::npos);
    EXPECT_NE(messageOf(dir, withStimulus("image", "../../etc/passwd")).find("stimuli/"),
              std::string::npos);
    EXPECT_NE(messageOf(dir, withStimulus("image", "/etc/passwd")).find("stimuli/"),
              std::string::npos);
    EXPECT_NE(messageOf(dir, withStimulus("image", "stimuli/gone.png")).find("is missing"),
              std::string::npos);
    EXPECT_NE(messageOf(dir, withStimulus("condition", "fog")).find("'fog' is not in"),
              std::string::npos);
    EXPECT_NE(messageOf(dir, withStimulus("correct_answer", "up")).find("correct_answer 'up'"),
              std::string::npos);
    EXPECT_NE(messageOf(dir, withStimulus("left", QJsonObject{{"x", 5000}, {"y", 1}}))
                  .find("marker left"),
              std::string::npos);
    EXPECT_NE(messageOf(dir, withStimulus("left", QJsonObject{{"x", 1e60}, {"y", 1}}))
                  .find("marker left"),
              std::string::npos);
    EXPECT_NE(messageOf(dir, withStimulus("pair", 1.5)).find("\"pair\""), std::string::npos);
    EXPECT_NE(messageOf(dir, withStimulus("id", "tree-p1-VSS-PCD")).find("used twice"),
              std::string::npos);
    // A second image of a pair in one condition (here: pair 2's first image
    // claims to be pair 1): one of the two would never be shown.
    EXPECT_NE(messageOf(dir,
                        [&] {
                            QJsonObject m = good;
                            QJsonArray stimuli = m["stimuli"].toArray();
                            QJsonObject other = stimuli[5].toObject();  // tree-p2-VSS-CD
                            other["pair"] = 1;
                            stimuli[5] = other;
                            m["stimuli"] = stimuli;
                            return m;
                        }())
                  .find("has a second image in condition 'VSS-CD'"),
              std::string::npos);
    EXPECT_NE(messageOf(dir, withStimulus("id", QJsonValue(QJsonValue::Undefined)))
                  .find("\"id\" is missing"),
              std::string::npos);
    QJsonObject noMain = good;
    noMain["stimuli"] = QJsonArray{};
    EXPECT_NE(messageOf(dir, noMain).find("no image for the main block"), std::string::npos);
    // Not JSON at all, and an empty file: the error names the file.
    std::ofstream(dir / "manifest.json") << "{\"format\": ";
    try {
        static_cast<void>(readManifest(dir));
        ADD_FAILURE() << "a truncated manifest was read";
    } catch (const StudyError& e) {
        EXPECT_NE(std::string(e.what()).find("manifest.json"), std::string::npos);
        EXPECT_NE(std::string(e.what()).find("not JSON"), std::string::npos);
    }
    std::ofstream(dir / "manifest.json", std::ios::trunc).close();
    EXPECT_THROW(static_cast<void>(readManifest(dir)), StudyError);
    EXPECT_THROW(static_cast<void>(readManifest(scratch("no-such-folder"))), StudyError);
}

TEST(LatinSquare, EveryConditionInEveryPositionAndAfterEveryOtherEquallyOften) {
    for (std::size_t k = 1; k <= 7; ++k) {
        const auto square = balancedLatinSquare(k);
        const std::size_t rows = k % 2 == 0 || k == 1 ? k : 2 * k;
        ASSERT_EQ(square.size(), rows) << k;
        std::map<std::pair<std::size_t, std::size_t>, int> positions;
        std::map<std::pair<std::size_t, std::size_t>, int> successions;
        for (const auto& row : square) {
            ASSERT_EQ(std::set<std::size_t>(row.begin(), row.end()).size(), k);
            for (std::size_t j = 0; j < k; ++j) {
                ++positions[{j, row[j]}];
                if (j > 0) {
                    ++successions[{row[j - 1], row[j]}];
                }
            }
        }
        for (const auto& [key, count] : positions) {
            EXPECT_EQ(count, static_cast<int>(rows / k)) << "k " << k;
        }
        if (k > 1) {
            EXPECT_EQ(successions.size(), k * (k - 1)) << "k " << k;
            for (const auto& [key, count] : successions) {
                EXPECT_EQ(count, static_cast<int>(rows / k)) << "k " << k;
            }
        }
    }
    EXPECT_THROW(static_cast<void>(balancedLatinSquare(0)), InvalidArgumentError);
}

TEST(RunPlanOrder, EverySegmentShowsEveryPairOnceAndTheConditionsRotate) {
    const auto dir = scratch("plan");
    test::writeStudyFolder(dir, {.scenes = {"a", "b", "c", "d", "e"}, .pairs = 2});
    const StudyManifest m = readManifest(dir);
    const std::size_t k = m.conditions.size();
    std::map<std::pair<std::size_t, std::string>, int> conditionInSegmentOverParticipants;
    for (std::size_t order = 0; order < 10; ++order) {
        const RunPlan plan = planRun(m, "P" + std::to_string(order), order);
        EXPECT_EQ(plan.row, order % 10);  // 5 conditions: 10 rows (each and its reverse)
        ASSERT_EQ(plan.main.size(), 50U);
        EXPECT_EQ(std::set<std::size_t>(plan.main.begin(), plan.main.end()).size(), 50U);
        const std::size_t segment = plan.main.size() / k;
        for (std::size_t s = 0; s < k; ++s) {
            std::set<std::pair<std::string, int>> pairs;
            std::map<std::string, int> conditions;
            for (std::size_t i = s * segment; i < (s + 1) * segment; ++i) {
                const ManifestStimulus& st = m.stimuli[plan.main[i]];
                EXPECT_EQ(st.block, Block::Main);
                pairs.insert({st.scene, st.pair});
                ++conditions[st.condition];
                ++conditionInSegmentOverParticipants[{s, st.condition}];
            }
            EXPECT_EQ(pairs.size(), segment) << "a pair twice in segment " << s;
            // 10 pairs over 5 conditions: each condition twice per segment.
            for (const auto& [name, count] : conditions) {
                EXPECT_EQ(count, 2) << name << " in segment " << s << ", order " << order;
            }
        }
        EXPECT_EQ(plan.training.size(), 25U);
    }
    for (const auto& [key, count] : conditionInSegmentOverParticipants) {
        EXPECT_EQ(count, 20);
    }
    // The same participant, the same order; another, another order.
    EXPECT_EQ(planRun(m, "P1", 1).main, planRun(m, "P1", 1).main);
    EXPECT_NE(planRun(m, "P1", 1).main, planRun(m, "Q1", 1).main);
}

TEST(RunPlanOrder, AnIncompleteMainBlockIsRefused) {
    const auto dir = scratch("plan-incomplete");
    test::writeStudyFolder(dir);
    QJsonObject manifest = test::studyManifestJson({});
    QJsonArray stimuli = manifest["stimuli"].toArray();
    stimuli.removeAt(3);
    manifest["stimuli"] = stimuli;
    test::writeManifestJson(dir, manifest);
    try {
        static_cast<void>(planRun(readManifest(dir), "P1", 0));
        ADD_FAILURE() << "a plan from an incomplete study";
    } catch (const StudyError& e) {
        EXPECT_NE(std::string(e.what()).find("no image in condition 'vessel-PCD'"),
                  std::string::npos)
            << e.what();
    }
}

TEST(ParticipantOrder, ParticipantsTakeRowsInTheOrderTheyFirstAnswered) {
    std::vector<Answer> answers(4);
    answers[0].participant = "B";
    answers[1].participant = "A";
    answers[2].participant = "B";
    answers[3].participant = "C";
    EXPECT_EQ(participantOrder(answers, "B"), 0U);
    EXPECT_EQ(participantOrder(answers, "A"), 1U);
    EXPECT_EQ(participantOrder(answers, "C"), 2U);
    EXPECT_EQ(participantOrder(answers, "D"), 3U);
    EXPECT_EQ(participantOrder({}, "D"), 0U);
}

/// Answers the image on screen: onset at `at`, the key `ms` later.
Answer answerNow(StudyRun& run, Side side, double at, double ms) {
    EXPECT_EQ(run.screen(), RunScreen::Countdown);
    run.countdownFinished();
    EXPECT_EQ(run.screen(), RunScreen::Stimulus);
    EXPECT_FALSE(run.answer(side, at - 1.0).has_value()) << "an answer before the onset";
    run.stimulusShown(at);
    run.stimulusShown(at + 500.0);  // a later frame does not move the onset
    const auto a = run.answer(side, at + ms);
    EXPECT_TRUE(a.has_value());
    return a.value_or(Answer{});
}

TEST(StudyRunStates, TrainingThenTheMainBlockInThePlansOrderEveryAnswerInTheFile) {
    const auto dir = scratch("run");
    test::writeStudyFolder(dir);
    const auto results = dir / "results.csv";
    StudyRun run(readManifest(dir), "P01", results, {.training = true, .breakEvery = 7});
    EXPECT_FALSE(run.resumed());
    EXPECT_EQ(run.screen(), RunScreen::Instructions);
    EXPECT_EQ(run.block(), Block::Training);
    run.space();
    // Training: feedback after each answer, space for another, enter ends it.
    const Answer t1 = answerNow(run, Side::Left, 1000.0, 640.0);
    EXPECT_EQ(t1.block, Block::Training);
    EXPECT_DOUBLE_EQ(t1.responseMs, 640.0);
    EXPECT_EQ(run.screen(), RunScreen::Feedback);
    ASSERT_TRUE(run.lastAnswer().has_value());
    run.space();
    static_cast<void>(answerNow(run, Side::Right, 3000.0, 300.0));
    run.enter();
    EXPECT_EQ(run.screen(), RunScreen::MainReady);
    run.space();
    EXPECT_EQ(run.block(), Block::Main);

    const std::vector<std::size_t> order = run.plan().main;
    ASSERT_EQ(order.size(), 20U);
    std::size_t breaks = 0;
    for (std::size_t i = 0; i < order.size(); ++i) {
        ASSERT_NE(run.stimulus(), nullptr);
        EXPECT_EQ(run.stimulus()->id, readManifest(dir).stimuli[order[i]].id);
        const Answer a =
            answerNow(run, i % 3 == 0 ? Side::Right : Side::Left, 10000.0 * static_cast<double>(i),
                      400.0 + static_cast<double>(i));
        EXPECT_EQ(a.trial, static_cast<int>(i + 1));
        EXPECT_EQ(readResults(results).size(), i + 3) << "every answer in the file at once";
        if (run.screen() == RunScreen::Break) {
            ++breaks;
        } else if (i + 1 < order.size()) {
            EXPECT_EQ(run.screen(), RunScreen::Ready);
        }
        run.space();
    }
    EXPECT_EQ(breaks, 2U);  // after 7 and 14
    EXPECT_EQ(run.screen(), RunScreen::Finished);
    const std::vector<Answer> file = readResults(results);
    ASSERT_EQ(file.size(), 22U);
    EXPECT_EQ(file[0].block, Block::Training);
    EXPECT_EQ(file[2].block, Block::Main);
    EXPECT_DOUBLE_EQ(file[2].responseMs, 400.0);
    EXPECT_EQ(file[2].correct(), file[2].answer == file[2].correctAnswer);
}

TEST(StudyRunStates, AnInterruptedRunGoesOnWhereItStopped) {
    const auto dir = scratch("resume");
    test::writeStudyFolder(dir);
    const auto results = dir / "results.csv";
    std::vector<std::string> shown;
    {
        StudyRun other(readManifest(dir), "P00", results, {.training = false});
        other.space();
        static_cast<void>(answerNow(other, Side::Left, 0.0, 100.0));
    }
    std::vector<std::size_t> order;
    {
        StudyRun run(readManifest(dir), "P01", results, {.training = false});
        EXPECT_EQ(run.plan().order, 1U) << "the second participant in the file";
        order = run.plan().main;
        run.space();
        for (int i = 0; i < 6; ++i) {
            shown.push_back(run.stimulus()->id);
            static_cast<void>(answerNow(run, Side::Left, 0.0, 100.0));
            run.space();
        }
        // The run stops here with an image on screen, unanswered.
    }
    StudyRun resumed(readManifest(dir), "P01", results, {.training = false});
    EXPECT_TRUE(resumed.resumed());
    EXPECT_EQ(resumed.plan().order, 1U);
    EXPECT_EQ(resumed.plan().main, order);
    EXPECT_EQ(resumed.progress().mainAnswered, 6U);
    resumed.space();
    const Answer next = answerNow(resumed, Side::Right, 0.0, 100.0);
    EXPECT_EQ(next.trial, 7);
    EXPECT_EQ(next.stimulus, readManifest(dir).stimuli[order[6]].id);
    for (const auto& id : shown) {
        EXPECT_NE(next.stimulus, id);
    }
}

TEST(StudyRunStates, ResultsOfAnotherStudyAreRefused) {
    const auto dir = scratch("foreign");
    test::writeStudyFolder(dir);
    const auto results = dir / "results.csv";
    Answer a;
    a.participant = "P01";
    a.trial = 1;
    a.stimulus = "not-in-this-study";
    a.scene = "x";
    a.condition = "baseline";
    appendAnswer(results, a);
    EXPECT_THROW(StudyRun(readManifest(dir), "P01", results, {}), StudyError);
    EXPECT_THROW(StudyRun(readManifest(dir), "", results, {}), StudyError);
    // Another participant is not concerned by P01's rows.
    StudyRun other(readManifest(dir), "P02", results, {});
    EXPECT_EQ(other.plan().order, 1U);
}

// A pause on an image shows it again from its countdown; its response time
// runs from the new onset, never over the pause.
TEST(StudyRunStates, AnInterruptedImageIsShownAgainAndTimedFromItsNewOnset) {
    const auto dir = scratch("restart");
    test::writeStudyFolder(dir);
    StudyRun run(readManifest(dir), "P01", dir / "results.csv", {.training = false});
    run.space();
    run.countdownFinished();
    run.stimulusShown(1000.0);
    const std::string shown = run.stimulus()->id;
    run.restartTrial();  // the pause
    EXPECT_EQ(run.screen(), RunScreen::Countdown);
    EXPECT_EQ(run.stimulus()->id, shown);
    const Answer a = answerNow(run, Side::Left, 60000.0, 450.0);
    EXPECT_DOUBLE_EQ(a.responseMs, 450.0);
    EXPECT_EQ(a.stimulus, shown);
    run.restartTrial();  // not on an image: nothing happens
    EXPECT_EQ(run.screen(), RunScreen::Ready);
}

TEST(StudyRunStates, AStudyWithoutTrainingImagesStartsWithTheMainBlock) {
    const auto dir = scratch("no-training");
    test::writeStudyFolder(dir, {.trainingPairs = 0});
    StudyRun run(readManifest(dir), "P01", dir / "results.csv", {.training = true});
    EXPECT_EQ(run.block(), Block::Main);
    run.space();
    EXPECT_EQ(run.screen(), RunScreen::Countdown);
}

}  // namespace
}  // namespace vv::study::run_test
