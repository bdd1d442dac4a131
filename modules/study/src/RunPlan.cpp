// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/study/RunPlan.h"

#include <algorithm>
#include <cstdint>
#include <map>
#include <random>
#include <utility>

#include "vv/core/Error.h"

namespace vv::study {
namespace {

/// FNV-1a: a stable hash of the participant's id (std::hash may differ
/// between library versions, and a resumed run must find the same order).
std::uint64_t stableHash(const std::string& text) {
    std::uint64_t h = 1469598103934665603ULL;
    for (const char c : text) {
        h ^= static_cast<unsigned char>(c);
        h *= 1099511628211ULL;
    }
    return h;
}

/// Fisher-Yates with the generator's raw output: the same on every standard
/// library (std::shuffle and the distributions are not specified exactly).
void shuffle(std::vector<std::size_t>& items, std::mt19937_64& random) {
    for (std::size_t i = items.size(); i > 1; --i) {
        std::swap(items[i - 1], items[random() % i]);
    }
}

}  // namespace

std::vector<std::vector<std::size_t>> balancedLatinSquare(std::size_t k) {
    if (k < 1) {
        throw InvalidArgumentError("a Latin square needs at least one condition");
    }
    // First row 0, 1, k-1, 2, k-2, ...; row r adds r to each entry.
    std::vector<std::size_t> first{0};
    first.reserve(k);
    for (std::size_t low = 1, high = k - 1; first.size() < k;) {
        first.push_back(first.size() % 2 == 1 ? low++ : high--);
    }
    std::vector<std::vector<std::size_t>> square;
    square.reserve(2 * k);
    for (std::size_t r = 0; r < k; ++r) {
        std::vector<std::size_t> row;
        row.reserve(k);
        for (const std::size_t c : first) {
            row.push_back((c + r) % k);
        }
        square.push_back(std::move(row));
    }
    if (k % 2 == 1 && k > 1) {
        for (std::size_t r = 0; r < k; ++r) {
            square.emplace_back(square[r].rbegin(), square[r].rend());
        }
    }
    return square;
}

std::size_t participantOrder(const std::vector<Answer>& answers, const std::string& participant) {
    std::vector<std::string> seen;
    for (const Answer& a : answers) {
        if (a.participant == participant) {
            return static_cast<std::size_t>(std::find(seen.begin(), seen.end(), participant) -
                                            seen.begin());
        }
        if (std::find(seen.begin(), seen.end(), a.participant) == seen.end()) {
            seen.push_back(a.participant);
        }
    }
    return seen.size();
}

RunPlan planRun(const StudyManifest& manifest, const std::string& participant, std::size_t order) {
    const std::size_t k = manifest.conditions.size();
    const auto square = balancedLatinSquare(k);
    RunPlan plan;
    plan.order = order;
    plan.rows = square.size();
    plan.row = order % plan.rows;

    // The main block's marker pairs, in manifest order, each with its image
    // per condition.
    std::map<std::string, std::size_t> conditionIndex;
    for (std::size_t c = 0; c < k; ++c) {
        conditionIndex[manifest.conditions[c]] = c;
    }
    std::vector<std::pair<std::string, int>> pairs;
    std::map<std::pair<std::string, int>, std::vector<std::size_t>> images;
    for (const std::size_t i : manifest.indicesOf(Block::Main)) {
        const ManifestStimulus& s = manifest.stimuli[i];
        const auto key = std::make_pair(s.scene, s.pair);
        auto [at, added] = images.try_emplace(key, std::vector<std::size_t>(k, SIZE_MAX));
        if (added) {
            pairs.push_back(key);
        }
        at->second[conditionIndex.at(s.condition)] = i;
    }
    for (const auto& key : pairs) {
        for (std::size_t c = 0; c < k; ++c) {
            if (images[key][c] == SIZE_MAX) {
                throw StudyError(manifest.folder / "manifest.json",
                                 "scene '" + key.first + "' pair " + std::to_string(key.second) +
                                     " has no image in condition '" + manifest.conditions[c] +
                                     "'; the main block must show every pair in every condition");
            }
        }
    }

    std::mt19937_64 random(stableHash(manifest.seed + "\n" + participant));
    for (std::size_t segment = 0; segment < k; ++segment) {
        std::vector<std::size_t> part;
        for (std::size_t p = 0; p < pairs.size(); ++p) {
            const auto& conditionsInOrder = square[(plan.row + p) % plan.rows];
            part.push_back(images[pairs[p]][conditionsInOrder[segment]]);
        }
        shuffle(part, random);
        plan.main.insert(plan.main.end(), part.begin(), part.end());
    }
    plan.training = manifest.indicesOf(Block::Training);
    shuffle(plan.training, random);
    return plan;
}

}  // namespace vv::study
