// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/study/Analysis.h"

#include <algorithm>
#include <map>
#include <set>
#include <utility>

#include "vv/core/NumberText.h"

namespace vv::study {
namespace {

/// Index of `name` in `names`, appended when new.
std::size_t indexOf(std::vector<std::string>& names, const std::string& name) {
    const auto found = std::ranges::find(names, name);
    if (found != names.end()) {
        return static_cast<std::size_t>(found - names.begin());
    }
    names.push_back(name);
    return names.size() - 1;
}

double medianOf(std::vector<double> values) {
    std::ranges::sort(values);
    const std::size_t middle = values.size() / 2;
    return values.size() % 2 == 1 ? values[middle] : 0.5 * (values[middle - 1] + values[middle]);
}

/// Per participant and condition: the answers' correctness and times.
struct Cell {
    std::size_t answers = 0;
    std::size_t correct = 0;
    std::vector<double> times;
};

MeasureResult measure(std::string name, std::string unit, BlockTable table,
                      const AnalysisOptions& options) {
    MeasureResult m;
    m.name = std::move(name);
    m.unit = std::move(unit);
    m.table = std::move(table);
    const std::size_t k = m.table.front().size();
    for (std::size_t c = 0; c < k; ++c) {
        std::vector<double> column;
        for (const auto& row : m.table) {
            column.push_back(row[c]);
        }
        m.perCondition.push_back(summarise(column));
    }
    m.friedman = friedmanTest(m.table);
    m.postHoc = rankSumComparisons(m.friedman, options.alpha, options.correction);
    return m;
}

}  // namespace

StudyAnalysis analyseStudy(const std::vector<Answer>& answers, const AnalysisOptions& options) {
    if (!(options.alpha > 0.0 && options.alpha < 1.0) ||
        !(options.chance > 0.0 && options.chance < 1.0)) {
        throw InvalidArgumentError("the significance level and the chance rate must lie in (0, 1)");
    }
    StudyAnalysis study;
    study.options = options;
    std::vector<std::string> ids;
    std::map<std::pair<std::size_t, std::size_t>, Cell> cells;
    std::set<std::pair<std::string, std::string>> seen;  // participant, stimulus
    std::size_t repeated = 0;
    for (const Answer& a : answers) {
        if (a.block != Block::Main) {
            continue;
        }
        if (!seen.emplace(a.participant, a.stimulus).second) {
            ++repeated;
            continue;
        }
        const std::size_t p = indexOf(ids, a.participant);
        const std::size_t c = indexOf(study.conditions, a.condition);
        Cell& cell = cells[{p, c}];
        ++cell.answers;
        cell.correct += a.correct() ? 1 : 0;
        cell.times.push_back(a.responseMs);
    }
    study.repeatedAnswers = repeated;
    if (repeated > 0) {
        study.notes.push_back(std::to_string(repeated) +
                              " main-block answers repeated a stimulus the participant had "
                              "answered before (a resumed run): only the first counts");
    }
    study.exclusionRule =
        "A participant is excluded when their main-block answers are not above chance: the "
        "one-sided exact binomial test of their correct answers against a rate of " +
        fixedText(100.0 * options.chance, 0) + " % gives p >= " + fixedText(options.alpha, 2) +
        "; or when they have no answer in some condition.";
    if (study.conditions.size() < 2) {
        throw StudyError("the answers hold " + std::to_string(study.conditions.size()) +
                         " condition(s) in the main block; the analysis needs at least 2");
    }
    const std::size_t k = study.conditions.size();
    BlockTable accuracy;
    BlockTable times;
    for (std::size_t p = 0; p < ids.size(); ++p) {
        ParticipantResult r;
        r.id = ids[p];
        std::vector<double> allTimes;
        std::vector<double> accuracyRow(k, 0.0);
        std::vector<double> timeRow(k, 0.0);
        for (std::size_t c = 0; c < k; ++c) {
            const auto found = cells.find({p, c});
            if (found == cells.end()) {
                r.missingConditions.push_back(study.conditions[c]);
                continue;
            }
            const Cell& cell = found->second;
            r.answers += cell.answers;
            r.correct += cell.correct;
            allTimes.insert(allTimes.end(), cell.times.begin(), cell.times.end());
            accuracyRow[c] = static_cast<double>(cell.correct) / static_cast<double>(cell.answers);
            timeRow[c] = medianOf(cell.times);
        }
        r.accuracy = static_cast<double>(r.correct) / static_cast<double>(r.answers);
        r.medianResponseMs = medianOf(allTimes);
        r.chance = testAgainstChance(r.correct, r.answers, options.alpha, options.chance);
        if (!r.chance.aboveChance) {
            r.excluded = true;
            r.exclusionReason = "at chance level: " + std::to_string(r.correct) + " of " +
                                std::to_string(r.answers) +
                                " correct (p = " + fixedText(r.chance.pValue, 3) + ")";
        } else if (!r.missingConditions.empty()) {
            r.excluded = true;
            r.exclusionReason = "no answer in " + std::to_string(r.missingConditions.size()) +
                                " condition(s), first " + r.missingConditions.front();
        } else {
            accuracy.push_back(accuracyRow);
            times.push_back(timeRow);
            ++study.included;
        }
        study.participants.push_back(std::move(r));
    }
    if (study.included < 2) {
        throw StudyError(std::to_string(study.included) + " of " +
                         std::to_string(study.participants.size()) +
                         " participants remain after the exclusions; the analysis needs at "
                         "least 2. " +
                         study.exclusionRule);
    }
    study.accuracy = measure("accuracy", "", std::move(accuracy), options);
    study.responseTime = measure("response time", "ms", std::move(times), options);
    return study;
}

StudyAnalysis analyseResultsFiles(const std::vector<std::filesystem::path>& files,
                                  const AnalysisOptions& options) {
    if (files.empty()) {
        throw InvalidArgumentError("an analysis needs at least one results file");
    }
    std::vector<Answer> answers;
    std::string names;
    for (const auto& file : files) {
        const std::vector<Answer> read = readResults(file);
        answers.insert(answers.end(), read.begin(), read.end());
        names += (names.empty() ? "" : ", ") + file.string();
    }
    try {
        return analyseStudy(answers, options);
    } catch (const StudyError& e) {
        if (!e.file().empty()) {
            throw;
        }
        throw StudyError(names, e.problem());
    }
}

}  // namespace vv::study
