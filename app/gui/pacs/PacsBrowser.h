// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QDialog>
#include <QString>
#include <functional>
#include <memory>
#include <utility>
#include <vector>

#include "gui/LatestRun.h"
#include "gui/pacs/NetworkFailure.h"
#include "gui/pacs/PacsSettings.h"
#include "vv/pacs/Find.h"

class QButtonGroup;
class QComboBox;
class QDateEdit;
class QGridLayout;
class QGroupBox;
class QHBoxLayout;
class QLabel;
class QLineEdit;
class QProgressBar;
class QPushButton;
class QRadioButton;
class QSplitter;
class QTableWidget;
class QTimer;

namespace vv::gui {

struct RetrieveControl;
struct RetrieveOutcome;

/// DICOM > Query PACS…: choose a node, search its studies (C-FIND at study
/// level: patient name / ID, study date range, modality, description,
/// accession), see a study's series (C-FIND at series level, on selecting the
/// study), and retrieve the selected study or series with C-GET (default)
/// or C-MOVE to our own listener into the local store (PacsSettings'
/// storeFolder), with a progress bar and Cancel. Once retrieved, Open hands
/// the folder to openFolder() (the main window's DICOM open path).
/// Every network call runs on a worker; the window never waits for one, and
/// every failure is shown as a translated message naming the node.
class PacsBrowser : public QDialog {
    Q_OBJECT

  public:
    /// Tells whether our listener (the storage SCP of the app) runs now; C-MOVE
    /// needs it. Without one set, the listener counts as not running.
    using ListenerRunning = std::function<bool()>;

    explicit PacsBrowser(QWidget* parent = nullptr);
    Q_DISABLE_COPY_MOVE(PacsBrowser)
    ~PacsBrowser() override;

    void setListenerRunning(ListenerRunning running);
    /// Reads the nodes and the store folder from QSettings() again (after Preferences).
    void reloadSettings();

    /// The status line: what runs, found, failed or was retrieved.
    [[nodiscard]] QString status() const;
    /// True while a study search runs (not after its Cancel).
    [[nodiscard]] bool searching() const noexcept { return searchCall_.isRunning(); }
    [[nodiscard]] bool retrieving() const noexcept { return retrieve_ != nullptr; }

    [[nodiscard]] QComboBox* nodeBox() const noexcept { return node_; }
    [[nodiscard]] QLineEdit* patientNameEdit() const noexcept { return patientName_; }
    [[nodiscard]] QLineEdit* patientIdEdit() const noexcept { return patientId_; }
    [[nodiscard]] QDateEdit* dateFromEdit() const noexcept { return dateFrom_; }
    [[nodiscard]] QDateEdit* dateToEdit() const noexcept { return dateTo_; }
    [[nodiscard]] QComboBox* modalityBox() const noexcept { return modality_; }
    [[nodiscard]] QLineEdit* descriptionEdit() const noexcept { return description_; }
    [[nodiscard]] QLineEdit* accessionEdit() const noexcept { return accession_; }
    [[nodiscard]] QPushButton* searchButton() const noexcept { return search_; }
    /// Cancels the study or series search that runs: the association is
    /// aborted, the buttons come back at once and the status says
    /// "Search cancelled." (no rows are shown: none were found).
    [[nodiscard]] QPushButton* cancelSearchButton() const noexcept { return cancelSearch_; }
    [[nodiscard]] QTableWidget* studyTable() const noexcept { return studies_; }
    [[nodiscard]] QTableWidget* seriesTable() const noexcept { return series_; }
    [[nodiscard]] QRadioButton* getButton() const noexcept { return useGet_; }
    [[nodiscard]] QRadioButton* moveButton() const noexcept { return useMove_; }
    [[nodiscard]] QPushButton* retrieveStudyButton() const noexcept { return retrieveStudy_; }
    [[nodiscard]] QPushButton* retrieveSeriesButton() const noexcept { return retrieveSeries_; }
    [[nodiscard]] QProgressBar* progressBar() const noexcept { return progress_; }
    [[nodiscard]] QPushButton* cancelButton() const noexcept { return cancel_; }
    /// Enabled once a retrieve has finished, while the study (or series) it
    /// retrieved is the one selected.
    [[nodiscard]] QPushButton* openButton() const noexcept { return open_; }

  signals:
    /// Open was clicked: the retrieved series' (or study's) folder, in the
    /// study `studyUid` of the local store at `store`.
    void openFolder(const QString& folder, const QString& store, const QString& studyUid);
    /// A search ended (its rows are in the study table); false also when it
    /// failed or was cancelled (status() says which).
    void searchFinished(bool ok);
    /// The series of the selected study are in the series table (or failed,
    /// or the search was cancelled).
    void seriesFinished(bool ok);
    /// The retrieve's progress bar moved (share of the instances received).
    void retrieveProgress(double fraction);
    /// A retrieve ended: done, failed or cancelled (status() says which).
    void retrieveFinished(bool ok);

  protected:
    /// Shown again (Query PACS… after it was closed or stepped aside for
    /// Open): unless a retrieve still runs, the last retrieve's progress,
    /// status and Open are forgotten, so the dialog starts clean.
    void showEvent(QShowEvent* event) override;

  private:
    // The constructor's steps, in the order the widgets are created (their
    // tab order): the search fields, the study and series tables, the
    // retrieve controls; then the signals.
    QGroupBox* buildSearchBox();
    void layOutSearchBox(QGroupBox* queryBox, QGridLayout* grid);
    QSplitter* buildResultTables();
    QGroupBox* buildRetrieveBox();
    QHBoxLayout* buildRetrieveMethodRow(QGroupBox* retrieveBox);
    QHBoxLayout* buildRetrieveRunRow(QGroupBox* retrieveBox);
    void connectSearch();
    void connectRetrieve();
    /// The progress timer's tick: moves the bar to the running retrieve's share.
    void pollRetrieveProgress();

    [[nodiscard]] const PacsNode* currentNode() const;
    /// The UIDs of the study and series selected (series empty: none).
    [[nodiscard]] std::pair<std::string, std::string> selectedUids() const;
    /// Forgets the finished retrieve: progress bar, its status, Open.
    void forgetRetrieve();
    /// The node the tables' rows came from (nullptr when none or removed).
    [[nodiscard]] const PacsNode* resultsNode() const;
    [[nodiscard]] pacs::StudyQuery query() const;
    void startSearch();
    void cancelSearch();
    void showStudies(const std::vector<pacs::StudyResult>& studies);
    void studySelected();
    void showSeries(const std::vector<pacs::SeriesResult>& series);
    void startRetrieve(bool wholeStudy);
    void retrieveEnded(const RetrieveOutcome& outcome);
    void updateButtons();
    void updateMoveNote();
    void setStatus(const QString& message, bool problem = false);

    PacsSettings settings_;
    ListenerRunning listenerRunning_;
    std::string resultsNode_;  ///< the name of the node of the last successful search
    std::vector<pacs::StudyResult> studyResults_;
    std::vector<pacs::SeriesResult> seriesResults_;
    /// The study search, and the series search of the selected study: a
    /// cancelled or overtaken one's answer is dropped.
    LatestRun<std::pair<std::vector<pacs::StudyResult>, NetworkFailure>, AtDestruction::Detach>
        searchCall_{this};
    LatestRun<std::pair<std::vector<pacs::SeriesResult>, NetworkFailure>, AtDestruction::Detach>
        seriesCall_{this};
    std::shared_ptr<RetrieveControl> retrieve_;
    int retrieveTotal_ = -1;  ///< instances expected, when the PACS said
    QString retrievedFolder_;
    QString retrievedStore_;  ///< the store and study of the last retrieve
    QString retrievedStudy_;
    std::string retrievedSeries_;  ///< the series retrieved; empty: the whole study

    QComboBox* node_ = nullptr;
    QLineEdit* patientName_ = nullptr;
    QLineEdit* patientId_ = nullptr;
    QDateEdit* dateFrom_ = nullptr;
    QDateEdit* dateTo_ = nullptr;
    QComboBox* modality_ = nullptr;
    QLineEdit* description_ = nullptr;
    QLineEdit* accession_ = nullptr;
    QPushButton* search_ = nullptr;
    QPushButton* cancelSearch_ = nullptr;
    QTableWidget* studies_ = nullptr;
    QTableWidget* series_ = nullptr;
    QRadioButton* useGet_ = nullptr;
    QRadioButton* useMove_ = nullptr;
    QLabel* moveNote_ = nullptr;
    QPushButton* retrieveStudy_ = nullptr;
    QPushButton* retrieveSeries_ = nullptr;
    QProgressBar* progress_ = nullptr;
    QPushButton* cancel_ = nullptr;
    QPushButton* open_ = nullptr;
    QLabel* status_ = nullptr;
    QTimer* progressTimer_ = nullptr;
};

}  // namespace vv::gui
