// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QDialog>
#include <QString>
#include <filesystem>
#include <vector>

#include "gui/LatestRun.h"
#include "vv/pacs/LocalStore.h"

class QLabel;
class QPushButton;
class QTreeWidget;

namespace vv::gui {

class ListenerService;

/// DICOM > Local Studies…: the studies of the local study store (received by
/// the listener or retrieved), read from its index (SQLite on disk, so they
/// survive restarts; the files are not read). One row per study — patient,
/// patient ID, study date (UI locale), description, modalities, number of
/// series — with its series as child rows (description, modality, images).
/// A line above says where the store is and what the listener does. The
/// list refreshes by itself when the listener committed instances
/// (ListenerService::studiesChanged()) and when new settings name another
/// store folder (ListenerService::storeChanged()). Open (or a double click) asks to open
/// the chosen series, or the chosen study's folder, in the DICOM open path
/// (openRequested()). Delete… asks (naming the study by date and description)
/// and removes the chosen study from the store on a worker, never on the GUI
/// thread (LocalStore::remove); a study that is open — in this window or
/// another program — stays, and the message line says why. Not modal.
class LocalStudiesBrowser : public QDialog {
    Q_OBJECT

  public:
    explicit LocalStudiesBrowser(ListenerService& listener, QWidget* parent = nullptr);

    /// Reads the store's index again on a worker (SQLite: never on the GUI
    /// thread, which may wait for another writer up to the index's busy
    /// timeout). Until the rows come, the list shows the last read's rows and
    /// the top line says that the store is being read; a read that a newer
    /// refresh() overtook is dropped unseen. The selected series or study
    /// stays selected. A store that cannot be read empties the list and says
    /// so in the top line; a store folder that does not exist yet is an empty
    /// list (and is not created).
    void refresh();
    /// True from refresh() until its rows are shown.
    [[nodiscard]] bool isReading() const noexcept { return reading_; }

    /// Top-level items: studies (data of column 0 = the folder); children: series.
    [[nodiscard]] QTreeWidget* tree() const noexcept { return tree_; }
    [[nodiscard]] QPushButton* openButton() const noexcept { return open_; }
    /// Delete…: asks in a window-modal box (object name "deleteStudyBox",
    /// its "Delete" button removes), then removes the chosen study.
    [[nodiscard]] QPushButton* deleteButton() const noexcept { return delete_; }
    [[nodiscard]] bool isDeleting() const { return remover_.isRunning(); }
    /// The line about the store and the listener.
    [[nodiscard]] QLabel* statusLine() const noexcept { return status_; }
    /// The line under the list saying why the last action failed; hidden when
    /// nothing failed.
    [[nodiscard]] QLabel* messageLine() const noexcept { return message_; }

  public slots:
    /// Shows `message` in the message line (empty: hides it).
    void showMessage(const QString& message);

  signals:
    /// The rows of a refresh() are shown.
    void refreshed();
    /// Open the DICOM data under `folder` (a series' or a study's folder) of
    /// the study `studyUid`.
    void openRequested(const QString& folder, const QString& studyUid);

  private:
    /// What reading the store came to (on the worker).
    struct Listing {
        std::filesystem::path folder;
        bool failed = false;  ///< the store cannot be read
        std::vector<pacs::StoredStudy> studies;
    };
    /// What removing a study came to.
    enum class Removal { Removed, Open, Gone, Failed };

    /// Reads the store at `folder` (on a worker); never throws.
    static Listing readStore(const std::filesystem::path& folder);
    void showListing(const Listing& listing);
    void openSelected();
    void askToDeleteSelected();
    void startDelete(const QString& studyUid, const QString& name);
    void updateStatusLine();
    void updateButtons();

    ListenerService& listener_;
    QLabel* status_ = nullptr;
    QTreeWidget* tree_ = nullptr;
    QPushButton* open_ = nullptr;
    QPushButton* delete_ = nullptr;
    QLabel* message_ = nullptr;
    QString readProblem_;  ///< why the store could not be read; empty when fine
    bool reading_ = false;
    LatestRun<Listing, AtDestruction::Wait> reader_{this};   ///< stopped before the rest goes
    LatestRun<Removal, AtDestruction::Wait> remover_{this};  ///< last: stopped before the rest goes
};

}  // namespace vv::gui
