// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QImage>
#include <QOpenGLWidget>
#include <QTimer>
#include <memory>

#include "vv/study/StudyRun.h"

namespace vv::gui {

/// The study runner's screen (Study > Run Study…): shown full screen, it
/// shows a StudyRun's states — the instructions, the neutral screen that
/// waits for the space bar, the focus countdown, the image, the training's
/// feedback, breaks — and passes the keys to it: F or Left for the left
/// marker, J or Right for the right one, space to go on, Enter to end the
/// training, Escape to stop (the answers given stay in the results file; the
/// same participant id resumes the run).
///
/// The response time runs from the buffer swap that put the image on screen
/// (frameSwapped after the frame that painted it) to the key press, both
/// read from one monotonic clock (nowMs()).
class StudyRunnerWidget : public QOpenGLWidget {
    Q_OBJECT

  public:
    /// `countdownMs`: the focus countdown before each image (the paper's
    /// three seconds; 0 shows the image at once).
    StudyRunnerWidget(std::unique_ptr<study::StudyRun> run, int countdownMs,
                      QWidget* parent = nullptr);

    [[nodiscard]] const study::StudyRun& run() const noexcept { return *run_; }

    /// Milliseconds on the runner's clock (std::chrono::steady_clock, which
    /// is CLOCK_MONOTONIC on Linux): what onsets and key presses are read
    /// from.
    [[nodiscard]] static double nowMs();

  signals:
    /// The image is on screen: the swap after the frame that painted it
    /// returned at `ms` (nowMs()).
    void stimulusOnset(double ms);
    /// An answer was given and written to the results file.
    void answered(const vv::study::Answer& answer);
    /// The screen changed (the run's state).
    void screenChanged(vv::study::RunScreen screen);

  protected:
    void paintGL() override;
    void keyPressEvent(QKeyEvent* event) override;

  private:
    void afterSwap();
    void enterScreen();
    void countdownTick();
    void answer(study::Side side, double ms);
    void stop();
    void paintText(QPainter& painter, const QString& title, const QString& body,
                   bool centred) const;
    [[nodiscard]] QString screenText(QString* title) const;

    std::unique_ptr<study::StudyRun> run_;
    int countdownMs_ = 3000;
    int countdownLeft_ = 0;  ///< seconds still shown
    QTimer countdown_;
    QImage image_;  ///< the current trial's image, loaded on its countdown
    bool stimulusPainted_ = false;
    bool onsetSent_ = false;
};

}  // namespace vv::gui
