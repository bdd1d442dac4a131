// SPDX-License-Identifier: GPL-3.0-or-later
// A results file of simulated participants for the analysis' front-end
// tests (CLI and GUI): participants `first`..`last` (P<n>) answer 20 images
// in each of three conditions, correct with probability 90 %, 90 % and 60 %;
// "guesser" guesses. Written at once (resultsHeader / resultsRow).
#pragma once

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include "vv/study/Results.h"

namespace vv::study::test {

inline void writeSimulatedResults(const std::filesystem::path& file, int first, int last,
                                  bool withGuesser) {
    std::mt19937 random(static_cast<std::uint32_t>(first));
    std::uniform_real_distribution<double> uniform(0.0, 1.0);
    const std::vector<std::string> conditions{"VSS-CD", "vessel-CD", "baseline"};
    const std::vector<double> accuracy{0.9, 0.9, 0.6};
    std::vector<std::string> ids;
    for (int p = first; p <= last; ++p) {
        ids.push_back("P" + std::to_string(p));
    }
    if (withGuesser) {
        ids.emplace_back("guesser");
    }
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    out << resultsHeader() << "\n";
    for (const std::string& id : ids) {
        int trial = 0;
        for (std::size_t c = 0; c < conditions.size(); ++c) {
            for (int i = 0; i < 20; ++i) {
                Answer a;
                a.participant = id;
                a.trial = ++trial;
                a.stimulus = conditions[c] + "/" + std::to_string(i);
                a.scene = "demo";
                a.condition = conditions[c];
                a.correctAnswer = i % 2 == 0 ? Side::Left : Side::Right;
                const double p = id == "guesser" ? 0.5 : accuracy[c];
                a.answer = uniform(random) < p
                               ? a.correctAnswer
                               : (a.correctAnswer == Side::Left ? Side::Right : Side::Left);
                a.responseMs = 1000.0 + 500.0 * uniform(random);
                out << resultsRow(a) << "\n";
            }
        }
    }
}

}  // namespace vv::study::test
