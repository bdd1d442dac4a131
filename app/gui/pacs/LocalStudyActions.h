// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// The main window's DICOM listener, Local studies and Send to PACS: menu
// entries, the status bar indicator and their wiring, kept out of MainWindow.

namespace vv::gui {

class DicomMenu;
class ListenerService;
class MainWindow;

/// Adds "Local Studies…" and "Send to PACS…" (enabled while a scene is
/// shown, object name "sendToPacs") to `menu`; creates the window's
/// ListenerService (a child of `window`), started from the PACS settings in
/// QSettings, with its state in a status bar label ("listenerIndicator").
/// The Local Studies browser (one per window) opens what the user picks with
/// window.openDicom() once a StoreLeases (a child of `window`, object name
/// "storeLeases") holds its study open; the lease ends when another document
/// replaces the scene or the window closes. What the menu's PACS browser
/// retrieves and opens is held open the same way. The browser learns from
/// the listener whether it runs (C-MOVE), and saved preferences re-apply it.
/// Returns the listener service.
ListenerService* addLocalStudyActions(MainWindow& window, DicomMenu& menu);

}  // namespace vv::gui
