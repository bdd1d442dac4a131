// SPDX-License-Identifier: GPL-3.0-or-later
// The order in which one participant sees the study's images (the paper:
// "randomized and counterbalanced using Latin square"). The main block is
// cut into as many segments as there are conditions; every marker pair
// (a scene's pair, shown once per condition) appears once per segment, each
// time in another condition, the conditions' order across the segments taken
// from a row of a balanced Latin square (Williams' design: every condition
// in every position, and after every other condition, equally often over the
// rows). Pair p of participant row r follows row (r + p) of the square, so
// each segment shows every condition about equally often. Within a segment
// the order is shuffled, from a seed made of the study's seed and the
// participant's id: the same participant gets the same order again, which
// is what lets an interrupted run be resumed.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "vv/study/Manifest.h"
#include "vv/study/Results.h"

namespace vv::study {

/// Williams' balanced Latin square for `k` conditions: k rows for an even k,
/// 2k rows (each row and its reverse) for an odd k; each row a permutation
/// of 0..k-1. Throws InvalidArgumentError for k < 1.
[[nodiscard]] std::vector<std::vector<std::size_t>> balancedLatinSquare(std::size_t k);

/// The participant's row of the square (before taking it modulo the rows):
/// participants take rows in the order they first appear in `answers`; a
/// participant not in it takes the next one.
[[nodiscard]] std::size_t participantOrder(const std::vector<Answer>& answers,
                                           const std::string& participant);

struct RunPlan {
    std::size_t order = 0;  ///< participantOrder's value
    std::size_t row = 0;    ///< the square's row, order modulo the rows
    std::size_t rows = 0;
    /// Indices into the manifest's stimuli, in showing order.
    std::vector<std::size_t> training;
    std::vector<std::size_t> main;
};

/// The participant's plan. Throws StudyError when the main block is not a
/// full set (a marker pair missing in some condition): a plan from it would
/// not be balanced.
[[nodiscard]] RunPlan planRun(const StudyManifest& manifest, const std::string& participant,
                              std::size_t order);

}  // namespace vv::study
