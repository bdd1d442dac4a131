// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/study/Statistics.h"

#include <algorithm>
#include <boost/math/distributions/binomial.hpp>
#include <boost/math/distributions/chi_squared.hpp>
#include <boost/math/distributions/normal.hpp>
#include <boost/math/distributions/students_t.hpp>
#include <cmath>
#include <numeric>

#include "vv/core/Error.h"

namespace vv::study {
namespace {

void checkProbability(double value, const char* what) {
    if (!(value > 0.0 && value < 1.0)) {
        throw InvalidArgumentError(std::string(what) + " must lie in (0, 1), got " +
                                   std::to_string(value));
    }
}

void checkTable(const BlockTable& values) {
    if (values.size() < 2) {
        throw InvalidArgumentError("Friedman's test needs at least 2 participants, got " +
                                   std::to_string(values.size()));
    }
    const std::size_t k = values.front().size();
    if (k < 2) {
        throw InvalidArgumentError("Friedman's test needs at least 2 conditions, got " +
                                   std::to_string(k));
    }
    for (std::size_t i = 0; i < values.size(); ++i) {
        if (values[i].size() != k) {
            throw InvalidArgumentError("participant " + std::to_string(i + 1) + " has " +
                                       std::to_string(values[i].size()) + " values, not " +
                                       std::to_string(k) + " (one per condition)");
        }
        for (const double v : values[i]) {
            if (!std::isfinite(v)) {
                throw InvalidArgumentError("participant " + std::to_string(i + 1) +
                                           " has a value that is not a number");
            }
        }
    }
}

/// Ranks 1..n of `row` (ties: their mean rank); adds sum (t^3 - t) over its
/// tie groups to `ties`.
std::vector<double> midRanks(const std::vector<double>& row, double& ties) {
    std::vector<std::size_t> order(row.size());
    std::iota(order.begin(), order.end(), 0U);
    std::ranges::stable_sort(order, [&](std::size_t a, std::size_t b) { return row[a] < row[b]; });
    std::vector<double> ranks(row.size());
    for (std::size_t i = 0; i < order.size();) {
        std::size_t j = i;
        while (j + 1 < order.size() && row[order[j + 1]] == row[order[i]]) {
            ++j;
        }
        const double rank = 0.5 * static_cast<double>(i + j) + 1.0;
        for (std::size_t m = i; m <= j; ++m) {
            ranks[order[m]] = rank;
        }
        const auto t = static_cast<double>(j - i + 1);
        ties += t * t * t - t;
        i = j + 1;
    }
    return ranks;
}

}  // namespace

FriedmanResult friedmanTest(const BlockTable& values) {
    checkTable(values);
    FriedmanResult r;
    r.participants = values.size();
    r.conditions = values.front().size();
    r.degreesOfFreedom = static_cast<int>(r.conditions) - 1;
    r.rankSums.assign(r.conditions, 0.0);
    double ties = 0.0;
    for (const auto& row : values) {
        const std::vector<double> ranks = midRanks(row, ties);
        for (std::size_t j = 0; j < r.conditions; ++j) {
            r.rankSums[j] += ranks[j];
        }
    }
    const auto n = static_cast<double>(r.participants);
    const auto k = static_cast<double>(r.conditions);
    double spread = 0.0;
    for (const double sum : r.rankSums) {
        const double d = sum - n * (k + 1.0) / 2.0;
        spread += d * d;
    }
    const double denominator = n * k * (k + 1.0) - ties / (k - 1.0);
    if (denominator <= 0.0 || spread <= 0.0) {
        return r;  // every row constant (nothing to rank), or rank sums all equal
    }
    r.chiSquared = 12.0 * spread / denominator;
    r.kendallW = r.chiSquared / (n * (k - 1.0));
    const boost::math::chi_squared distribution(k - 1.0);
    r.pValue = boost::math::cdf(boost::math::complement(distribution, r.chiSquared));
    return r;
}

std::string correctionName(Correction correction) {
    return correction == Correction::Bonferroni ? "Bonferroni" : "Holm";
}

std::vector<double> holmAdjusted(const std::vector<double>& pValues) {
    const std::size_t m = pValues.size();
    std::vector<std::size_t> order(m);
    std::iota(order.begin(), order.end(), 0U);
    std::ranges::stable_sort(order,
                             [&](std::size_t a, std::size_t b) { return pValues[a] < pValues[b]; });
    std::vector<double> adjusted(m, 1.0);
    double running = 0.0;
    for (std::size_t i = 0; i < m; ++i) {
        const double scaled = std::min(1.0, static_cast<double>(m - i) * pValues[order[i]]);
        running = std::max(running, scaled);
        adjusted[order[i]] = running;
    }
    return adjusted;
}

PostHoc rankSumComparisons(const FriedmanResult& friedman, double alpha, Correction correction) {
    checkProbability(alpha, "the significance level");
    PostHoc post;
    post.alpha = alpha;
    post.correction = correction;
    const auto n = static_cast<double>(friedman.participants);
    const auto k = static_cast<double>(friedman.conditions);
    const double sigma = std::sqrt(n * k * (k + 1.0) / 6.0);
    const boost::math::normal standard;
    post.criticalDifference =
        boost::math::quantile(standard, 1.0 - alpha / (k * (k - 1.0))) * sigma;
    std::vector<double> raw;
    for (std::size_t a = 0; a < friedman.conditions; ++a) {
        for (std::size_t b = a + 1; b < friedman.conditions; ++b) {
            PairComparison pair;
            pair.first = a;
            pair.second = b;
            pair.rankSumDifference = std::abs(friedman.rankSums[a] - friedman.rankSums[b]);
            pair.z = sigma > 0.0 ? pair.rankSumDifference / sigma : 0.0;
            pair.pValue = 2.0 * boost::math::cdf(boost::math::complement(standard, pair.z));
            raw.push_back(pair.pValue);
            post.pairs.push_back(pair);
        }
    }
    const std::vector<double> holm = holmAdjusted(raw);
    const auto m = static_cast<double>(post.pairs.size());
    for (std::size_t i = 0; i < post.pairs.size(); ++i) {
        PairComparison& pair = post.pairs[i];
        pair.adjustedP =
            correction == Correction::Bonferroni ? std::min(1.0, m * pair.pValue) : holm[i];
        pair.significant = pair.adjustedP < alpha;
    }
    return post;
}

ChanceTest testAgainstChance(std::size_t correct, std::size_t answers, double alpha,
                             double chance) {
    checkProbability(alpha, "the significance level");
    checkProbability(chance, "the chance rate");
    if (answers == 0) {
        throw InvalidArgumentError("a chance test needs at least one answer");
    }
    if (correct > answers) {
        throw InvalidArgumentError(std::to_string(correct) + " correct of " +
                                   std::to_string(answers) + " answers");
    }
    ChanceTest t;
    t.correct = correct;
    t.answers = answers;
    t.chance = chance;
    const boost::math::binomial distribution(static_cast<double>(answers), chance);
    // P(X >= correct) = 1 - P(X <= correct - 1).
    t.pValue = correct == 0 ? 1.0
                            : boost::math::cdf(boost::math::complement(
                                  distribution, static_cast<double>(correct - 1)));
    t.aboveChance = t.pValue < alpha;
    return t;
}

Summary summarise(std::vector<double> values, double confidence) {
    checkProbability(confidence, "the confidence");
    if (values.empty()) {
        throw InvalidArgumentError("a summary needs at least one value");
    }
    for (const double v : values) {
        if (!std::isfinite(v)) {
            throw InvalidArgumentError("a value to summarise is not a number");
        }
    }
    std::ranges::sort(values);
    Summary s;
    s.count = values.size();
    const auto n = static_cast<double>(s.count);
    s.mean = std::accumulate(values.begin(), values.end(), 0.0) / n;
    s.meanLow = s.mean;
    s.meanHigh = s.mean;
    if (s.count > 1) {
        double squares = 0.0;
        for (const double v : values) {
            squares += (v - s.mean) * (v - s.mean);
        }
        s.standardDeviation = std::sqrt(squares / (n - 1.0));
        const boost::math::students_t t(n - 1.0);
        const double half =
            boost::math::quantile(t, 0.5 + 0.5 * confidence) * s.standardDeviation / std::sqrt(n);
        s.meanLow = s.mean - half;
        s.meanHigh = s.mean + half;
    }
    const std::size_t middle = s.count / 2;
    s.median = s.count % 2 == 1 ? values[middle] : 0.5 * (values[middle - 1] + values[middle]);
    // [x(l), x(n + 1 - l)] covers the median with 1 - 2 P(B <= l - 1), B ~
    // Binomial(n, 1/2): the largest l that still covers `confidence`.
    const boost::math::binomial half(n, 0.5);
    std::size_t l = 1;
    while (l + 1 <= (s.count + 1) / 2 &&
           1.0 - 2.0 * boost::math::cdf(half, static_cast<double>(l)) >= confidence) {
        ++l;
    }
    s.medianLow = values[l - 1];
    s.medianHigh = values[s.count - l];
    s.medianConfidence = 1.0 - 2.0 * boost::math::cdf(half, static_cast<double>(l - 1));
    return s;
}

BoxStatistics boxStatistics(std::vector<double> values) {
    const Summary checked = summarise(values);  // refuses empty and non-finite input
    std::ranges::sort(values);
    const auto quantile = [&](double q) {
        const double at = q * static_cast<double>(values.size() - 1);
        const auto below = static_cast<std::size_t>(std::floor(at));
        const std::size_t above = std::min(below + 1, values.size() - 1);
        return values[below] + (at - static_cast<double>(below)) * (values[above] - values[below]);
    };
    BoxStatistics b;
    b.lowerQuartile = quantile(0.25);
    b.median = checked.median;
    b.upperQuartile = quantile(0.75);
    const double reach = 1.5 * (b.upperQuartile - b.lowerQuartile);
    b.lowerWhisker = b.lowerQuartile;
    b.upperWhisker = b.upperQuartile;
    for (const double v : values) {
        if (v < b.lowerQuartile - reach || v > b.upperQuartile + reach) {
            b.outliers.push_back(v);
        } else {
            b.lowerWhisker = std::min(b.lowerWhisker, v);
            b.upperWhisker = std::max(b.upperWhisker, v);
        }
    }
    return b;
}

}  // namespace vv::study
