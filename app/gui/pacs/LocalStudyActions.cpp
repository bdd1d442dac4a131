// SPDX-License-Identifier: GPL-3.0-or-later
#include "gui/pacs/LocalStudyActions.h"

#include <QAction>
#include <QCoreApplication>
#include <QLabel>
#include <QMenu>
#include <QPointer>
#include <QSettings>
#include <QStatusBar>
#include <memory>

#include "gui/DocumentController.h"
#include "gui/MainWindow.h"
#include "gui/SliceWorkspace.h"
#include "gui/pacs/DicomMenu.h"
#include "gui/pacs/ListenerService.h"
#include "gui/pacs/LocalStudiesBrowser.h"
#include "gui/pacs/SendDialog.h"
#include "gui/pacs/StoreLeases.h"

namespace vv::gui {
namespace {

/// The window's one Local Studies browser, made on first use: what it
/// opens is held open by `leases` first.
void showBrowser(MainWindow& window, ListenerService& listener, StoreLeases& leases,
                 QPointer<LocalStudiesBrowser>& browser) {
    if (browser.isNull()) {
        browser = new LocalStudiesBrowser(listener, &window);
        LocalStudiesBrowser* shown = browser.data();
        QObject::connect(shown, &LocalStudiesBrowser::openRequested, &leases,
                         [&listener, &leases](const QString& folder, const QString& uid) {
                             leases.open(listener.storeFolder(), uid.toStdString(), folder);
                         });
        QObject::connect(&leases, &StoreLeases::refused, shown, [shown](const QString& message) {
            shown->refresh();
            shown->showMessage(message);
        });
    }
    browser->show();
    browser->raise();
    browser->activateWindow();
}

/// A Send dialog for the scene on screen (deleted when closed).
void showSendDialog(MainWindow& window) {
    auto* dialog = new SendDialog(*window.viewer(), window.reportSource(),
                                  readPacsSettings(QSettings()), &window);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    SliceWorkspace* slices = window.sliceWorkspace();
    dialog->setSliceSource([slices] { return slices->reportSlice(); });
    DocumentController* document = window.document();
    dialog->setFindings(document->findings());
    const DocumentController::ExportedReport exported = document->exportedReport();
    dialog->setExportedReport(exported.pdf, exported.findings);
    dialog->setSegmentation(document->labelMap());
    if (const auto planned = window.plannedReport()) {
        dialog->setMeasurements(planned->section, planned->groups);
    }
    QObject::connect(dialog, &SendDialog::findingsEdited, document,
                     &DocumentController::setFindings);
    // A segmentation preview on screen that was not applied is never sent.
    const auto block = [dialog, document] {
        dialog->setBlocked(document->showsPreview() ? MainWindow::previewNotApplied() : QString());
    };
    block();
    // Other data on screen: the dialog offers it, not the last send's results.
    QObject::connect(&window, &MainWindow::sceneShown, dialog, [&window, dialog, document, block] {
        const DocumentController::ExportedReport report = document->exportedReport();
        dialog->showScene(window.reportSource(), document->labelMap(), document->findings(),
                          report.pdf, report.findings);
        block();
    });
    // A DICOM series' segmentation arrives after its scene (an applied one with its scene).
    QObject::connect(document, &DocumentController::volumeChanged, dialog,
                     [dialog, document] { dialog->setSegmentation(document->labelMap()); });
    dialog->show();
}

}  // namespace

ListenerService* addLocalStudyActions(MainWindow& window, DicomMenu& menu) {
    auto* listener = new ListenerService(&window);
    listener->setObjectName(QStringLiteral("listenerService"));
    auto* indicator = new QLabel(&window);
    indicator->setObjectName(QStringLiteral("listenerIndicator"));
    window.statusBar()->addPermanentWidget(indicator);
    QObject::connect(
        listener, &ListenerService::stateChanged, indicator,
        [indicator](ListenerService::State, const QString& text) { indicator->setText(text); });

    auto* leases = new StoreLeases(&window);
    leases->setObjectName(QStringLiteral("storeLeases"));
    window.installEventFilter(leases);  // the window closes: the leases end
    QObject::connect(leases, &StoreLeases::ready, &window,
                     [&window](const QString& folder) { window.openDicom(folder); });
    QObject::connect(window.document(), &DocumentController::sceneChanged, leases,
                     [leases](const std::shared_ptr<const scene::Scene>&, const QString&,
                              const QStringList& files) { leases->documentShown(files); });

    auto browser = std::make_shared<QPointer<LocalStudiesBrowser>>();
    QAction* local =
        menu.addAction(QCoreApplication::translate("vv::gui::LocalStudyActions", "&Local Studies…"),
                       &window, [&window, listener, leases, browser] {
                           showBrowser(window, *listener, *leases, *browser);
                       });
    local->setObjectName(QStringLiteral("localStudies"));

    QAction* send =
        menu.addAction(QCoreApplication::translate("vv::gui::LocalStudyActions", "&Send to PACS…"),
                       &window, [&window] { showSendDialog(window); });
    send->setObjectName(QStringLiteral("sendToPacs"));
    const auto updateSend = [&window, send] {
        const bool shown = window.viewer()->scene() != nullptr;
        // A segmentation preview that was not applied is never sent.
        const bool preview = window.document()->showsPreview();
        send->setEnabled(shown && !preview);
        send->setToolTip(
            !shown    ? QCoreApplication::translate("vv::gui::LocalStudyActions",
                                                    "Open data first: there is nothing to send")
            : preview ? MainWindow::previewNotApplied()
                      : QString());
    };
    QObject::connect(&window, &MainWindow::sceneShown, send, updateSend);
    updateSend();

    // The PACS browser's C-MOVE needs our listener; saved preferences restart it.
    const QPointer<ListenerService> guarded(listener);
    QObject::connect(leases, &StoreLeases::refused, &window, [&window](const QString& message) {
        window.statusBar()->showMessage(message, 15000);
    });
    // The PACS browser's Open: the retrieved study is held open like one opened from Local Studies.
    QObject::connect(
        &menu, &DicomMenu::openFolder, leases,
        [leases](const QString& folder, const QString& store, const QString& studyUid) {
            leases->open(store.toStdString(), studyUid.toStdString(), folder);
        });
    menu.setListenerRunning(
        [guarded] { return guarded && guarded->state() == ListenerService::State::Running; });
    QObject::connect(&menu, &DicomMenu::preferencesChanged, listener,
                     [listener] { listener->apply(readPacsSettings(QSettings())); });

    listener->apply(readPacsSettings(QSettings()));
    indicator->setText(listener->stateText());
    return listener;
}

}  // namespace vv::gui
