// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// What the user sets up for DICOM networking (Preferences > DICOM network),
// kept in QSettings under the group "pacs/": our own AE title and listener
// (with its limits), the PACS nodes we talk to, and the local study store
// (folder, size limit).
// The PACS browser, the listener, Local studies and Send all read it from here.

#include <cstdint>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "vv/core/Error.h"
#include "vv/pacs/LocalStore.h"
#include "vv/pacs/Node.h"
#include "vv/pacs/StorageScp.h"

class QSettings;

namespace vv::gui {

/// The highest TCP port a node or the listener may name.
inline constexpr int kMaxPort = 65535;

/// One configured peer: a display name and the node itself. `allowPush`
/// lets the node push studies to our listener (it then joins the listener's
/// allowed peers, by calling AE title and host).
struct PacsNode {
    std::string name;  ///< what the user calls it ("Radiology PACS"); unique
    pacs::Node node;
    bool allowPush = true;
};

/// The longest timeout the settings take (each from 1 s), as the CLI's --timeout.
inline constexpr int kMaxTimeoutSeconds = pacs::Timeouts::kMaxSeconds;

struct PacsSettings {
    /// Our AE title and how long we wait for a node (connect, association,
    /// each DIMSE message; each 1 to kMaxTimeoutSeconds).
    pacs::LocalAe me;
    bool listenerEnabled = false;  ///< run the storage SCP while the app runs
    std::uint16_t listenerPort = 11112;
    std::string listenerBindAddress = "127.0.0.1";  ///< IPv4; 0.0.0.0: all interfaces
    /// The listener's TLS: when enabled it speaks only TLS, shows
    /// `certificate` (with `privateKey`) and lets in only peers whose
    /// certificate chains to `trustedCertificates`; all three are required.
    pacs::TlsSettings listenerTls;
    /// What the listener lets its peers use (associations, connections, the
    /// association request deadline, size caps); always valid when read.
    pacs::ListenerLimits listenerLimits;
    std::vector<PacsNode> nodes;
    std::filesystem::path storeFolder;  ///< the local study store
    std::uint64_t storeLimitBytes = 0;  ///< 0: no limit; else oldest-first clean-up
};

/// The store folder used when none is set: <GenericDataLocation>/VesselView/studies
/// (~/.local/share/VesselView/studies on Linux), or, when only that exists,
/// the one earlier versions used, <AppLocalDataLocation>/studies (which
/// named VesselView twice): an existing store is never left behind.
[[nodiscard]] std::filesystem::path defaultStoreFolder();

/// Reads the settings from `store` ("pacs/" group). Missing entries take the
/// defaults above (storeFolder: defaultStoreFolder()); an invalid entry (AE
/// title, port out of range, a node without host, a listener limit out of
/// the range ListenerLimits::validate() states, a timeout not within 1 to
/// kMaxTimeoutSeconds) is skipped, never guessed.
/// Listener limits that do not fit together (connections in all below the
/// simultaneous associations, per address above in all; the largest
/// association below the largest instance) are skipped together: the
/// connection limits, or the two size caps, take their defaults.
/// The listener's TLS is read as written: when it is on without its files,
/// the listener fails to start (it never falls back to plain TCP).
[[nodiscard]] PacsSettings readPacsSettings(const QSettings& store);

/// What writePacsSettings() refused: which setting (and node), so that the
/// GUI can name it in the UI language; what() is the English detail
/// ("node 'PACS': AE title ...").
class PacsSettingsError : public InvalidArgumentError {
  public:
    enum class Setting {
        OurAeTitle,      ///< our AE title is not a valid one
        ListenerPort,    ///< the listener port is 0
        ListenerTls,     ///< the listener's TLS is on without its three files
        ListenerLimits,  ///< ListenerLimits::validate() refused the listener's limits
        Timeouts,        ///< a timeout is not within 1 to kMaxTimeoutSeconds
        NodeName,        ///< a node has no name (node() empty) or shares node()'s
        Node,            ///< node()'s AE title, host or port is invalid
    };
    PacsSettingsError(Setting setting, std::string node, const std::string& problem)
        : InvalidArgumentError(problem), setting_(setting), node_(std::move(node)) {}
    [[nodiscard]] Setting setting() const noexcept { return setting_; }
    /// The node's name (Setting::NodeName, Setting::Node); else empty.
    [[nodiscard]] const std::string& node() const noexcept { return node_; }

  private:
    Setting setting_;
    std::string node_;
};

/// Writes `settings` into `store` ("pacs/" group), replacing what was there.
/// Throws PacsSettingsError (an InvalidArgumentError) naming the setting when
/// our AE title, a node or a port is invalid, when two nodes share a name,
/// when the listener's TLS is on without its three files, when its limits
/// are invalid (what() then is ListenerLimits::validate()'s), or when a
/// timeout is not within 1 to kMaxTimeoutSeconds; then nothing is written.
void writePacsSettings(const PacsSettings& settings, QSettings& store);

/// The local study store of `settings` (storeFolder, made when missing) with
/// its size limit set from storeLimitBytes: every store the GUI writes into
/// (the listener, a retrieve) comes from here. It opens the store's index
/// (SQLite: quick, unless another process is writing it, then up to 10 s)
/// and may create folders: on a worker where the GUI must not wait.
/// Throws what pacs::LocalStore's constructor throws (IoError, FormatError).
[[nodiscard]] pacs::LocalStore openStore(const PacsSettings& settings);

/// The node called `name`, or nullptr.
[[nodiscard]] const PacsNode* findNode(const PacsSettings& settings, const std::string& name);

}  // namespace vv::gui
