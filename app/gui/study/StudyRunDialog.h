// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QDialog>
#include <optional>
#include <vector>

#include "vv/study/Manifest.h"
#include "vv/study/Results.h"

class QCheckBox;
class QDialogButtonBox;
class QLabel;
class QLineEdit;
class QSpinBox;

namespace vv::gui {

class StudyRunnerWidget;

/// Study > Run Study…: the person running the study picks the study folder
/// (made by `vesselview-cli study make`), the results file (the folder's
/// results.csv unless another is chosen; every participant's answers go to
/// one file, which is what gives each new participant the next Latin-square
/// order) and the participant's id; the dialog says what the folder holds
/// and what the id means (a new participant and their order, or how far an
/// earlier run came: the same id goes on from there). Start opens the
/// runner full screen on the screen the dialog is on.
class StudyRunDialog : public QDialog {
    Q_OBJECT

  public:
    explicit StudyRunDialog(QWidget* parent = nullptr);

    /// Fills the fields (as the person would type them).
    void setStudyFolder(const QString& folder);
    void setParticipant(const QString& id);

    /// What the dialog says about the folder and the participant.
    [[nodiscard]] QString studySummary() const;
    [[nodiscard]] QString participantSummary() const;

    /// Starts the run (Start); the runner it opened, or nullptr when it
    /// could not start (the dialog says why).
    StudyRunnerWidget* start();

  signals:
    void runnerStarted(vv::gui::StudyRunnerWidget* runner);

  private:
    void folderChanged();
    void resultsChanged();
    void participantChanged();
    void fitHeight();

    QLineEdit* folder_ = nullptr;
    QLineEdit* results_ = nullptr;
    QLineEdit* participant_ = nullptr;
    QLabel* studySummary_ = nullptr;
    QLabel* participantSummary_ = nullptr;
    QCheckBox* training_ = nullptr;
    QSpinBox* countdown_ = nullptr;
    QSpinBox* breakEvery_ = nullptr;
    QDialogButtonBox* buttons_ = nullptr;
    QString defaultResults_;
    std::optional<study::StudyManifest> manifest_;
    std::vector<study::Answer> answers_;
    bool resultsReadable_ = true;
};

}  // namespace vv::gui
