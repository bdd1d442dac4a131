// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QDialog>
#include <QFutureWatcher>
#include <QString>
#include <filesystem>
#include <optional>
#include <vector>

#include "vv/study/Analysis.h"

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QListWidget;
class QPushButton;
class QTextBrowser;

namespace vv::gui {

/// Study > Analyse Results…: what `vesselview-cli study analyse` does, in
/// the window. The results files of a study (one or more; read as one
/// study), the correction of the post-hoc tests and the significance level,
/// the PDF (in the UI's language, on the paper the report dialog uses) and,
/// when asked, the tables as CSV. The work runs off the GUI thread; its
/// outcome (the participants, the exclusions, Friedman's test and the
/// pairs that differ, per measure, with the UI's numbers) is shown in the
/// dialog, or the error naming the file and the problem.
class StudyAnalysisDialog : public QDialog {
    Q_OBJECT

  public:
    explicit StudyAnalysisDialog(QWidget* parent = nullptr);

    /// Fills the fields (as the person would).
    void addResultsFile(const QString& file);
    void setPdfPath(const QString& path);
    void setTablesFolder(const QString& folder);
    void setCorrection(study::Correction correction);

    /// Starts the analysis (the Analyse button); false when a field is
    /// missing (the dialog says which).
    bool analyse();
    /// What the dialog shows of the last analysis (or its error).
    [[nodiscard]] QString outcome() const;

  signals:
    void finished(bool ok);

  private:
    struct Outcome {
        std::optional<study::StudyAnalysis> analysis;
        QString error;
    };
    void done();

    QListWidget* files_ = nullptr;
    QComboBox* correction_ = nullptr;
    QDoubleSpinBox* alpha_ = nullptr;
    QComboBox* paper_ = nullptr;
    QLineEdit* pdf_ = nullptr;
    QLineEdit* tables_ = nullptr;
    QPushButton* analyseButton_ = nullptr;
    QPushButton* openPdf_ = nullptr;
    QTextBrowser* outcome_ = nullptr;
    QFutureWatcher<Outcome> watcher_;
};

}  // namespace vv::gui
