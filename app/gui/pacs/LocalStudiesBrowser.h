// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QDialog>
#include <QString>

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
/// (openRequested()). Not modal.
class LocalStudiesBrowser : public QDialog {
    Q_OBJECT

  public:
    explicit LocalStudiesBrowser(ListenerService& listener, QWidget* parent = nullptr);

    /// Reads the store's index again (quick: the index is small) and keeps
    /// the selected series or study selected. A store that cannot be read
    /// empties the list and says so in the top line; a store folder that does
    /// not exist yet is an empty list (and is not created).
    void refresh();

    /// Top-level items: studies (data of column 0 = the folder); children: series.
    [[nodiscard]] QTreeWidget* tree() const noexcept { return tree_; }
    [[nodiscard]] QPushButton* openButton() const noexcept { return open_; }
    /// The line about the store and the listener.
    [[nodiscard]] QLabel* statusLine() const noexcept { return status_; }

  signals:
    /// Open the DICOM data under `folder` (a series' or a study's folder).
    void openRequested(const QString& folder);

  private:
    void openSelected();
    void updateStatusLine();

    ListenerService& listener_;
    QLabel* status_ = nullptr;
    QTreeWidget* tree_ = nullptr;
    QPushButton* open_ = nullptr;
    QString readProblem_;  ///< why the store could not be read; empty when fine
};

}  // namespace vv::gui
