// SPDX-License-Identifier: GPL-3.0-or-later
// The study target's body: separate because it needs vv::study (the
// manifest, the run plan, the runner's states, the results file and the
// analysis); the readers' targets do not.
#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <iostream>

#include "FuzzBodies.h"
#include "vv/core/Error.h"
#include "vv/study/Analysis.h"
#include "vv/study/Manifest.h"
#include "vv/study/RunPlan.h"
#include "vv/study/StudyRun.h"

namespace vv::fuzz {
namespace {

/// A broken promise of the study code: the fuzzer reports the abort.
void require(bool holds, const char* what) {
    if (!holds) {
        std::cerr << "fuzz study: " << what << "\n";
        std::abort();
    }
}

/// Images a manifest may name: stimuli/a.png ... stimuli/h.png in the
/// scratch folder (readManifest checks only that they are files).
void ensureImages(const std::filesystem::path& folder) {
    std::filesystem::create_directories(folder / "stimuli");
    for (char c = 'a'; c <= 'h'; ++c) {
        const auto image = folder / "stimuli" / (std::string(1, c) + ".png");
        if (!std::filesystem::exists(image)) {
            std::ofstream(image) << "png";
        }
    }
}

void exploreManifest(const std::filesystem::path& file) {
    const study::StudyManifest manifest = study::readManifest(file);
    const std::vector<std::size_t> main = manifest.indicesOf(study::Block::Main);
    require(!main.empty(), "a manifest read without main images");
    const std::size_t rows = study::balancedLatinSquare(manifest.conditions.size()).size();
    for (std::size_t order = 0; order < std::min<std::size_t>(rows, 3); ++order) {
        const study::RunPlan plan = study::planRun(manifest, "P", order);
        std::vector<std::size_t> shown = plan.main;
        std::sort(shown.begin(), shown.end());
        require(shown == main, "a plan that is not the main block's images, each once");
        require(plan.row < plan.rows, "a plan's row out of the square");
    }
    if (main.size() > 40) {
        return;  // a run rewrites the results file per answer: kept short
    }
    // A whole run, every image answered, into a fresh results file.
    const auto results = file.parent_path() / "run-results.csv";
    std::filesystem::remove(results);
    study::StudyRun run(manifest, "P", results, {.training = true, .breakEvery = 3});
    run.space();
    double now = 0.0;
    for (std::size_t step = 0;
         step < 4 * main.size() + 16 && run.screen() != study::RunScreen::Finished; ++step) {
        if (run.screen() == study::RunScreen::Countdown) {
            run.countdownFinished();
            run.stimulusShown(now += 10.0);
            const auto answer = run.answer(study::Side::Left, now += 300.0);
            require(answer.has_value(), "an image on screen that took no answer");
            require(answer->responseMs == 300.0, "a response time not from the onset");
        } else if (run.screen() == study::RunScreen::Feedback) {
            run.enter();  // one training image is enough
        } else {
            run.space();
        }
    }
    require(run.screen() == study::RunScreen::Finished, "a run that did not end");
    std::size_t mainAnswers = 0;
    for (const study::Answer& a : study::readResults(results)) {
        mainAnswers += a.block == study::Block::Main ? 1 : 0;
    }
    require(mainAnswers == main.size(), "a run that did not save every main answer");
}

void exploreResults(const std::filesystem::path& file) {
    const study::StudyAnalysis s = study::analyseResultsFiles({file});
    require(s.included >= 2 && s.included <= s.participants.size(), "included out of range");
    require(s.conditions.size() >= 2, "an analysis of fewer than 2 conditions");
    for (const study::ParticipantResult& p : s.participants) {
        require(p.accuracy >= 0.0 && p.accuracy <= 1.0, "an accuracy out of [0, 1]");
        require(p.correct <= p.answers, "more correct answers than answers");
    }
    for (const study::MeasureResult* m : {&s.accuracy, &s.responseTime}) {
        require(m->friedman.pValue >= 0.0 && m->friedman.pValue <= 1.0, "a p out of [0, 1]");
        for (const study::PairComparison& pair : m->postHoc.pairs) {
            require(pair.adjustedP >= pair.pValue - 1e-12 && pair.adjustedP <= 1.0,
                    "a corrected p below its p or above 1");
        }
    }
}

}  // namespace

Outcome feedStudy(Bytes bytes) {
    const bool manifest = !bytes.empty() && bytes[0] == 'M';
    const Bytes rest = bytes.empty() ? bytes : bytes.subspan(1);
    Outcome outcome;
    outcome.file = writeScratch(manifest ? "manifest.json" : "results.csv", rest);
    try {
        if (manifest) {
            ensureImages(outcome.file.parent_path());
            exploreManifest(outcome.file);
        } else {
            exploreResults(outcome.file);
        }
        outcome.loaded = true;
    } catch (const vv::Error& e) {
        outcome.error = e.what();
    }
    return outcome;
}

}  // namespace vv::fuzz
