// SPDX-License-Identifier: GPL-3.0-or-later
// The analysis of a study's answers, as the paper reports it: per
// participant the accuracy and the median response time in each condition
// (main block only); participants at chance level excluded by a stated
// rule; per measure each condition's summary, Friedman's test over the
// included participants and the post-hoc comparisons of the conditions.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "vv/study/Results.h"
#include "vv/study/Statistics.h"

namespace vv::study {

struct AnalysisOptions {
    double alpha = 0.05;  ///< for Friedman's test, the post-hoc tests and the chance test
    Correction correction = Correction::Bonferroni;
    double chance = 0.5;  ///< the rate of correct answers by guessing (two markers)
};

struct ParticipantResult {
    std::string id;
    std::size_t answers = 0;  ///< in the main block
    std::size_t correct = 0;
    double accuracy = 0.0;          ///< correct / answers
    double medianResponseMs = 0.0;  ///< over all main-block answers
    ChanceTest chance;
    /// Conditions of the study this participant has no main-block answer in.
    std::vector<std::string> missingConditions;
    bool excluded = false;
    std::string exclusionReason;  ///< empty when included
};

/// One measure (accuracy, or response time) over the included participants.
struct MeasureResult {
    std::string name;  ///< "accuracy" or "response time"
    std::string unit;  ///< "" (a proportion) or "ms"
    /// table[participant][condition], the included participants in the
    /// order of StudyAnalysis::participants.
    BlockTable table;
    std::vector<Summary> perCondition;  ///< in the order of StudyAnalysis::conditions
    FriedmanResult friedman;
    PostHoc postHoc;
};

struct StudyAnalysis {
    /// The conditions, in the order they first appear in the answers.
    std::vector<std::string> conditions;
    /// Every participant with a main-block answer, in the order they first appear.
    std::vector<ParticipantResult> participants;
    std::size_t included = 0;
    /// The rule participants were excluded by, in words.
    std::string exclusionRule;
    MeasureResult accuracy;      ///< per participant and condition: correct / answers
    MeasureResult responseTime;  ///< per participant and condition: median ms
    AnalysisOptions options;
    /// Main-block answers to a stimulus the participant had answered before
    /// (a resumed run): left out, the first answer counts.
    std::size_t repeatedAnswers = 0;
    /// What the reader should know, in words: the repeated answers, ...
    std::vector<std::string> notes;
};

/// Analyses `answers` (of one or more results files). A participant is
/// excluded when their main-block answers are not above chance (the
/// one-sided binomial test at options.alpha) or when they have no answer in
/// some condition (Friedman's test needs every condition of every
/// participant); a stimulus a participant answered twice in the main block
/// (a resumed run) counts once, the first answer, and a note says so.
/// Throws InvalidArgumentError for options out of range, StudyError when
/// fewer than 2 conditions or 2 included participants remain (naming why).
[[nodiscard]] StudyAnalysis analyseStudy(const std::vector<Answer>& answers,
                                         const AnalysisOptions& options = {});

/// readResults() of every file in turn, then analyseStudy() of all their
/// answers as one study. An error of the analysis itself (too few
/// participants or conditions left) names the files it read ("a.csv, b.csv:
/// ..."). Throws what readResults() and analyseStudy() throw;
/// InvalidArgumentError for no file.
[[nodiscard]] StudyAnalysis analyseResultsFiles(const std::vector<std::filesystem::path>& files,
                                                const AnalysisOptions& options = {});

/// Writes the analysis as three CSV tables into `folder` (which must exist),
/// each written atomically, numbers with a decimal point, units in the
/// headers:
///   conditions.csv   per measure and condition: n, mean with its interval,
///                    median with its interval and coverage, rank sum
///   comparisons.csv  per measure and pair: the rank-sum difference, the
///                    critical difference, z, p, the corrected p, significant;
///                    and per measure Friedman's chi-squared, df, p, Kendall's W
///   participants.csv per participant: answers, correct, accuracy, median
///                    response time, the chance test's p, excluded and why
/// Throws IoError naming the file that cannot be written.
void writeAnalysisTables(const StudyAnalysis& study, const std::filesystem::path& folder);

}  // namespace vv::study
