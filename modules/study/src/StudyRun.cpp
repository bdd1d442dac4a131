// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/study/StudyRun.h"

#include <algorithm>
#include <map>
#include <set>

namespace vv::study {

StudyRun::StudyRun(StudyManifest manifest, std::string participant, std::filesystem::path results,
                   RunOptions options)
    : manifest_(std::move(manifest)),
      participant_(std::move(participant)),
      results_(std::move(results)),
      options_(options) {
    if (participant_.empty()) {
        throw StudyError("a run needs the participant's id");
    }
    std::error_code error;
    const std::vector<Answer> answers =
        std::filesystem::exists(results_, error) ? readResults(results_) : std::vector<Answer>{};
    plan_ = planRun(manifest_, participant_, participantOrder(answers, participant_));

    std::map<std::string, std::size_t> byId;
    for (std::size_t i = 0; i < manifest_.stimuli.size(); ++i) {
        byId[manifest_.stimuli[i].id] = i;
    }
    std::set<std::size_t> answered;
    for (const Answer& a : answers) {
        if (a.participant != participant_) {
            continue;
        }
        resumed_ = true;
        const auto at = byId.find(a.stimulus);
        if (at == byId.end()) {
            throw StudyError(results_, "participant '" + participant_ + "' answered image '" +
                                           a.stimulus +
                                           "', which this study does not have: the results "
                                           "file belongs to another study");
        }
        if (a.block == Block::Main) {
            answered.insert(at->second);
        } else {
            ++progress_.trainingAnswered;
        }
    }
    for (const std::size_t i : plan_.main) {
        if (!answered.contains(i)) {
            remaining_.push_back(i);
        }
    }
    progress_.mainTotal = plan_.main.size();
    progress_.mainAnswered = progress_.mainTotal - remaining_.size();
    block_ = options_.training && !plan_.training.empty() ? Block::Training : Block::Main;
    if (remaining_.empty()) {
        screen_ = RunScreen::Finished;
    }
}

const ManifestStimulus* StudyRun::stimulus() const {
    return current_ ? &manifest_.stimuli[*current_] : nullptr;
}

void StudyRun::nextTrial() {
    onset_.reset();
    if (block_ == Block::Training) {
        current_ = plan_.training[trainingAt_++ % plan_.training.size()];
    } else if (remaining_.empty()) {
        current_.reset();
        screen_ = RunScreen::Finished;
        return;
    } else {
        current_ = remaining_.front();
    }
    screen_ = RunScreen::Countdown;
}

void StudyRun::space() {
    switch (screen_) {
        case RunScreen::MainReady:
            block_ = Block::Main;
            nextTrial();
            break;
        case RunScreen::Instructions:
        case RunScreen::Ready:
        case RunScreen::Break:
        case RunScreen::Feedback:
            nextTrial();
            break;
        default:
            break;
    }
}

void StudyRun::enter() {
    if (screen_ == RunScreen::Feedback) {
        current_.reset();
        screen_ = RunScreen::MainReady;
    }
}

void StudyRun::countdownFinished() {
    if (screen_ == RunScreen::Countdown) {
        screen_ = RunScreen::Stimulus;
    }
}

void StudyRun::restartTrial() {
    if (screen_ == RunScreen::Countdown || screen_ == RunScreen::Stimulus) {
        onset_.reset();
        screen_ = RunScreen::Countdown;
    }
}

void StudyRun::stimulusShown(double ms) {
    if (screen_ == RunScreen::Stimulus && !onset_) {
        onset_ = ms;
    }
}

std::optional<Answer> StudyRun::answer(Side side, double ms) {
    if (screen_ != RunScreen::Stimulus || !onset_ || !current_) {
        return std::nullopt;
    }
    const ManifestStimulus& s = manifest_.stimuli[*current_];
    Answer a;
    a.participant = participant_;
    a.block = block_;
    a.trial = static_cast<int>(
        (block_ == Block::Main ? progress_.mainAnswered : progress_.trainingAnswered) + 1);
    a.stimulus = s.id;
    a.scene = s.scene;
    a.condition = s.condition;
    a.answer = side;
    a.correctAnswer = s.correctAnswer;
    a.responseMs = std::max(0.0, ms - *onset_);
    appendAnswer(results_, a);  // first: a failed write leaves the run on this image
    last_ = a;
    if (block_ == Block::Training) {
        ++progress_.trainingAnswered;
        screen_ = RunScreen::Feedback;
        return a;
    }
    ++progress_.mainAnswered;
    ++answeredThisRun_;
    remaining_.erase(remaining_.begin());
    current_.reset();
    if (remaining_.empty()) {
        screen_ = RunScreen::Finished;
    } else if (options_.breakEvery > 0 && answeredThisRun_ % options_.breakEvery == 0) {
        screen_ = RunScreen::Break;
    } else {
        screen_ = RunScreen::Ready;
    }
    return a;
}

}  // namespace vv::study
