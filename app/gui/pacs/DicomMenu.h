// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QMenu>
#include <QPointer>

#include "gui/pacs/PacsBrowser.h"

namespace vv::gui {

class NetworkPreferencesDialog;

/// The main window's "DICOM" menu: Preferences… (the network preferences)
/// and Query PACS… (one PACS browser, kept while the window lives; its Open
/// hides it and emits openFolder(), which the window hands to its DICOM open
/// path).
class DicomMenu : public QMenu {
    Q_OBJECT

  public:
    explicit DicomMenu(QWidget* window);

    /// Tells the PACS browser whether our listener runs (C-MOVE needs it).
    void setListenerRunning(PacsBrowser::ListenerRunning running);

    /// Opens the preferences (window-modal, not blocking); returns the dialog.
    NetworkPreferencesDialog* showPreferences();
    /// Shows the PACS browser (made on first use); returns it.
    PacsBrowser* showBrowser();

  signals:
    /// The PACS browser's Open: `folder` of the study `studyUid` in the local store at `store`.
    void openFolder(const QString& folder, const QString& store, const QString& studyUid);
    /// The preferences were saved.
    void preferencesChanged();

  private:
    QWidget* window_;
    PacsBrowser::ListenerRunning listenerRunning_;
    QPointer<PacsBrowser> browser_;
};

}  // namespace vv::gui
