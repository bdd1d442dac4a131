// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// The app's DICOM listener: runs vv::pacs::StorageScp (which has its own
// worker thread) on the local study store of the PACS settings while they
// enable it, and tells the window what it is doing.

#include <QObject>
#include <QString>
#include <QTimer>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>

#include "gui/pacs/PacsSettings.h"

namespace vv::pacs {
class LocalStore;
class StorageScp;
}  // namespace vv::pacs

namespace vv::gui {

/// Owned by the main window. apply() (re)starts the listener from the
/// settings: our AE title, the bind address and port, TLS (listenerTls), its
/// limits (listenerLimits), and as allowed peers the nodes with allowPush; it
/// stops it when the settings disable it. A port that cannot be opened or TLS
/// files that cannot be read are a state (Failed, with a translated message),
/// never an exception, a crash or a fallback to plain TCP. While running, a timer on the GUI thread
/// polls the listener's counters (a mutex-guarded read, never a network wait)
/// and emits studiesChanged() when instances were committed.
class ListenerService : public QObject {
    Q_OBJECT

  public:
    enum class State { Stopped, Running, Failed };

    explicit ListenerService(QObject* parent = nullptr);
    ~ListenerService() override;
    ListenerService(const ListenerService&) = delete;
    ListenerService& operator=(const ListenerService&) = delete;
    ListenerService(ListenerService&&) = delete;
    ListenerService& operator=(ListenerService&&) = delete;

    [[nodiscard]] State state() const noexcept { return state_; }
    /// What the status bar shows: "DICOM listener: port 11112", "DICOM
    /// listener: port 2762 (TLS)", "DICOM listener off", "DICOM listener
    /// failed: port 11112 is in use" (translated).
    [[nodiscard]] QString stateText() const;
    /// The store folder of the settings last applied (also while stopped).
    [[nodiscard]] const std::filesystem::path& storeFolder() const noexcept { return storeFolder_; }
    /// Instances the running listener committed since it started.
    [[nodiscard]] std::size_t committedInstances() const noexcept { return committed_; }
    /// Associations the running listener refused since it started.
    [[nodiscard]] std::size_t refusedAssociations() const noexcept { return refused_; }

  public slots:
    /// Takes `settings`: restarts the listener when what it runs on changed
    /// (AE title, port, bind address, TLS, limits, allowed peers, store folder,
    /// on / off), else keeps it. Its store has the settings' size limit (openStore()): a
    /// new limit applies from the next commit on, without a restart.
    /// Stopping waits for the listener's thread (about a second).
    void apply(const vv::gui::PacsSettings& settings);

  signals:
    /// The state or its text changed (stateText()).
    void stateChanged(vv::gui::ListenerService::State state, const QString& text);
    /// The listener committed new instances to the store.
    void studiesChanged();
    /// apply() changed the store folder (what Local Studies lists).
    void storeChanged();

  private:
    void stop();
    void start(const PacsSettings& settings);
    void setState(State state, QString detail);
    void poll();

    std::unique_ptr<pacs::LocalStore> store_;
    std::unique_ptr<pacs::StorageScp> scp_;  // after store_: stops before it goes
    std::string runningKey_;                 ///< what the listener runs on; empty: stopped
    std::filesystem::path storeFolder_;
    State state_ = State::Stopped;
    QString detail_;  ///< the port, or the failure
    std::size_t committed_ = 0;
    std::size_t refused_ = 0;
    QTimer poll_;
};

}  // namespace vv::gui
