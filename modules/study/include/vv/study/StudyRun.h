// SPDX-License-Identifier: GPL-3.0-or-later
// One participant's run through a study, as the runner shows it (the
// paper's procedure): instructions; a training phase with feedback for as
// long as the participant wants; the main block in the participant's order
// (RunPlan.h). Every image is preceded by a neutral screen that waits for
// the space bar and a countdown; the answer (left or right: the marker that
// looks closer) ends the image. Optional breaks every N main images.
//
// The class holds the state only: what the screen shows and what a key does
// there. The window that shows it calls the event functions; the times it
// passes are milliseconds of one monotonic clock. Every answer is appended to
// the results file before the screen moves on (appendAnswer, atomic), so a
// crash loses at most the image on screen, and a new StudyRun for the same
// participant and file goes on where the last one stopped.
#pragma once

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "vv/study/Manifest.h"
#include "vv/study/Results.h"
#include "vv/study/RunPlan.h"

namespace vv::study {

struct RunOptions {
    bool training = true;  ///< offer the training phase first (when the study has images for it)
    std::size_t breakEvery = 0;  ///< a break after every N main images; 0 for none
};

enum class RunScreen {
    Instructions,  ///< the task and the keys; space starts
    Ready,         ///< neutral: space shows the next image (after the countdown)
    Countdown,     ///< the focus countdown; the window calls countdownFinished()
    Stimulus,      ///< the image; left or right answers
    Feedback,      ///< training: right or wrong; space: another, enter: the main block
    MainReady,     ///< training over; space starts the main block
    Break,         ///< a pause; space goes on
    Finished,      ///< every main image answered
};

/// What the participant's file already holds for them.
struct RunProgress {
    std::size_t mainAnswered = 0;
    std::size_t mainTotal = 0;
    std::size_t trainingAnswered = 0;
};

class StudyRun {
  public:
    /// Reads the results file (when it exists) for the participant's earlier
    /// answers and order. Throws StudyError for an empty participant id, a
    /// results file that cannot be read, or answers of this participant to
    /// images the manifest does not have; and what planRun throws.
    StudyRun(StudyManifest manifest, std::string participant, std::filesystem::path results,
             RunOptions options);

    [[nodiscard]] RunScreen screen() const noexcept { return screen_; }
    [[nodiscard]] Block block() const noexcept { return block_; }
    /// The image of the current trial (on Countdown, Stimulus and Feedback).
    [[nodiscard]] const ManifestStimulus* stimulus() const;
    [[nodiscard]] const RunPlan& plan() const noexcept { return plan_; }
    [[nodiscard]] const RunProgress& progress() const noexcept { return progress_; }
    [[nodiscard]] const std::string& participant() const noexcept { return participant_; }
    /// Whether this run goes on from answers given earlier.
    [[nodiscard]] bool resumed() const noexcept { return resumed_; }
    /// The last answer given (Feedback shows it).
    [[nodiscard]] const std::optional<Answer>& lastAnswer() const noexcept { return last_; }

    /// Space: Instructions, Ready, Feedback, MainReady and Break go on.
    void space();
    /// Enter on Feedback: the training ends (MainReady).
    void enter();
    void countdownFinished();
    /// The image was interrupted (the person running the study paused on
    /// it): on Countdown or Stimulus it is shown again from its countdown,
    /// its onset forgotten, so its response time never counts the pause.
    void restartTrial();
    /// The image is on screen (after the buffer swap) at `ms`.
    void stimulusShown(double ms);
    /// A left/right key at `ms`: records the answer (appended to the results
    /// file for both blocks) and returns it; nothing (and no record) when no
    /// image is on screen yet. Throws IoError when the file cannot be
    /// written, the run then stays on the image.
    std::optional<Answer> answer(Side side, double ms);

  private:
    void nextTrial();

    StudyManifest manifest_;
    std::string participant_;
    std::filesystem::path results_;
    RunOptions options_;
    RunPlan plan_;
    RunProgress progress_;
    std::vector<std::size_t> remaining_;  ///< main images not yet answered, in order
    std::size_t trainingAt_ = 0;
    std::size_t answeredThisRun_ = 0;
    bool resumed_ = false;
    RunScreen screen_ = RunScreen::Instructions;
    Block block_ = Block::Main;
    std::optional<std::size_t> current_;
    std::optional<double> onset_;
    std::optional<Answer> last_;
};

}  // namespace vv::study
