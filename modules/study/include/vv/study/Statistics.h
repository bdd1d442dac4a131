// SPDX-License-Identifier: GPL-3.0-or-later
// The statistics of the depth-judgement study (issue 34), as the paper
// (Kreiser et al. 2018, "Statistical Analysis") reports them: Friedman's
// test per measure over a within-subject design, post-hoc comparisons of
// the conditions' rank sums with Bonferroni correction (Siegel and
// Castellan's critical difference; Holm's step-down as an option), the
// exclusion of participants at chance level, and each condition's mean and
// median with 95 % confidence intervals. Plain C++: no Qt, no GL.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace vv::study {

/// A within-subject table: values[participant][condition] (one measure, as
/// each participant's accuracy or median response time per condition).
/// Complete: every row as long as the first, every value finite.
using BlockTable = std::vector<std::vector<double>>;

/// Friedman's rank test (Friedman 1937; as R's friedman.test and scipy's
/// friedmanchisquare): each participant's values ranked 1..k (ties get
/// their mean rank), the conditions' rank sums compared.
struct FriedmanResult {
    std::size_t participants = 0;  ///< n, the blocks
    std::size_t conditions = 0;    ///< k
    std::vector<double> rankSums;  ///< per condition; they add up to n k (k + 1) / 2
    /// The statistic, corrected for ties: 12 sum (R_j - n (k + 1) / 2)^2 /
    /// (n k (k + 1) - sum over tie groups (t^3 - t) / (k - 1)). 0 when every
    /// participant gave every condition the same value (nothing to rank).
    double chiSquared = 0.0;
    int degreesOfFreedom = 0;  ///< k - 1
    /// Upper tail of the chi-squared distribution at chiSquared (the large-
    /// sample approximation R and scipy use); 1 when chiSquared is 0.
    double pValue = 1.0;
    /// Kendall's coefficient of concordance: chiSquared / (n (k - 1)), in [0, 1].
    double kendallW = 0.0;
};

/// Throws InvalidArgumentError for fewer than 2 participants or 2
/// conditions, rows of different lengths, or a value that is not finite.
[[nodiscard]] FriedmanResult friedmanTest(const BlockTable& values);

/// How the post-hoc p-values are corrected for the m = k (k - 1) / 2 pairs.
enum class Correction {
    Bonferroni,  ///< p * m (the paper's)
    Holm,        ///< Holm's step-down: the i-th smallest p times (m - i + 1), kept monotone
};
[[nodiscard]] std::string correctionName(Correction correction);

/// One pair of conditions compared after Friedman's test.
struct PairComparison {
    std::size_t first = 0;  ///< condition index, first < second
    std::size_t second = 0;
    /// |R_first - R_second|: the "observed difference" of the paper.
    double rankSumDifference = 0.0;
    /// rankSumDifference / sqrt(n k (k + 1) / 6): standard normal when the
    /// conditions do not differ.
    double z = 0.0;
    double pValue = 1.0;       ///< two-sided, uncorrected
    double adjustedP = 1.0;    ///< by the correction, at most 1
    bool significant = false;  ///< adjustedP < alpha
};

struct PostHoc {
    double alpha = 0.05;
    Correction correction = Correction::Bonferroni;
    /// The smallest rank-sum difference significant with Bonferroni's
    /// correction: z(1 - alpha / (k (k - 1))) sqrt(n k (k + 1) / 6) (Siegel
    /// and Castellan 1988; 28.07034 for the paper's 20 participants and 5
    /// conditions at alpha 0.05).
    double criticalDifference = 0.0;
    std::vector<PairComparison> pairs;  ///< every pair, (0,1), (0,2), ..., (k-2,k-1)
};

/// The pairwise comparisons of the rank sums of `friedman`. Throws
/// InvalidArgumentError for alpha outside (0, 1).
[[nodiscard]] PostHoc rankSumComparisons(const FriedmanResult& friedman, double alpha = 0.05,
                                         Correction correction = Correction::Bonferroni);

/// Holm's step-down adjustment of `pValues` (in their order): the i-th
/// smallest times (m - i + 1), at most 1, never below an adjusted smaller one.
[[nodiscard]] std::vector<double> holmAdjusted(const std::vector<double>& pValues);

/// Whether a participant answered better than chance: the one-sided exact
/// binomial test of `correct` of `answers` against the chance rate.
struct ChanceTest {
    std::size_t correct = 0;
    std::size_t answers = 0;
    double chance = 0.5;
    double pValue = 1.0;       ///< P(at least `correct` right by guessing)
    bool aboveChance = false;  ///< pValue < alpha
};

/// Throws InvalidArgumentError for no answers, correct > answers, chance
/// or alpha outside (0, 1).
[[nodiscard]] ChanceTest testAgainstChance(std::size_t correct, std::size_t answers,
                                           double alpha = 0.05, double chance = 0.5);

/// One condition's values (over the participants): mean with its t-based
/// confidence interval, median with its distribution-free interval (two
/// order statistics, from the binomial distribution; at least the asked
/// confidence, the confidence reached stated).
struct Summary {
    std::size_t count = 0;
    double mean = 0.0;
    double standardDeviation = 0.0;  ///< the sample's (n - 1); 0 for one value
    double meanLow = 0.0;            ///< equal to the mean for one value
    double meanHigh = 0.0;
    double median = 0.0;
    double medianLow = 0.0;         ///< the smallest value when the sample is too small
    double medianHigh = 0.0;        ///< the largest value then
    double medianConfidence = 0.0;  ///< what [medianLow, medianHigh] covers
};

/// Throws InvalidArgumentError for no values, a value that is not finite,
/// or confidence outside (0, 1).
[[nodiscard]] Summary summarise(std::vector<double> values, double confidence = 0.95);

/// What a box plot of `values` shows (Tukey's): the quartiles (R's default,
/// type 7: linear between order statistics), the whiskers at the most
/// extreme values within 1.5 interquartile ranges of the box, and the
/// values beyond them.
struct BoxStatistics {
    double lowerQuartile = 0.0;
    double median = 0.0;
    double upperQuartile = 0.0;
    double lowerWhisker = 0.0;
    double upperWhisker = 0.0;
    std::vector<double> outliers;  ///< ascending
};

/// Throws InvalidArgumentError for no values or a value that is not finite.
[[nodiscard]] BoxStatistics boxStatistics(std::vector<double> values);

}  // namespace vv::study
