// SPDX-License-Identifier: GPL-3.0-or-later
#include "gui/pacs/DicomMenu.h"

#include "gui/pacs/NetworkPreferencesDialog.h"

namespace vv::gui {

DicomMenu::DicomMenu(QWidget* window) : QMenu(tr("&DICOM"), window), window_(window) {
    setObjectName(QStringLiteral("dicomMenu"));
    QAction* preferences = addAction(tr("&Preferences…"), this, [this] { showPreferences(); });
    preferences->setObjectName(QStringLiteral("dicomPreferences"));
    preferences->setMenuRole(QAction::NoRole);
    QAction* query = addAction(tr("&Query PACS…"), this, [this] { showBrowser(); });
    query->setObjectName(QStringLiteral("queryPacs"));
}

void DicomMenu::setListenerRunning(PacsBrowser::ListenerRunning running) {
    listenerRunning_ = std::move(running);
    if (browser_ != nullptr) {
        browser_->setListenerRunning(listenerRunning_);
    }
}

NetworkPreferencesDialog* DicomMenu::showPreferences() {
    auto* dialog = new NetworkPreferencesDialog(window_);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    connect(dialog, &QDialog::accepted, this, [this] {
        if (browser_ != nullptr) {
            browser_->reloadSettings();
        }
        emit preferencesChanged();
    });
    dialog->open();
    return dialog;
}

PacsBrowser* DicomMenu::showBrowser() {
    if (browser_ == nullptr) {
        browser_ = new PacsBrowser(window_);
        browser_->setListenerRunning(listenerRunning_);
        // The browser steps aside for the series chooser and the scene (Query PACS… shows it
        // again).
        connect(browser_, &PacsBrowser::openFolder, this,
                [this](const QString& folder, const QString& store, const QString& studyUid) {
                    browser_->hide();
                    emit openFolder(folder, store, studyUid);
                });
    } else {
        browser_->reloadSettings();
    }
    browser_->show();
    browser_->raise();
    browser_->activateWindow();
    return browser_;
}

}  // namespace vv::gui
