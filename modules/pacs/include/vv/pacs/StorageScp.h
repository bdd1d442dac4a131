// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// The storage SCP (our DICOM listener): receives instances pushed by a PACS
// (C-STORE, e.g. as the destination of a C-MOVE) into the local store, on its
// own worker thread. It lets in only configured nodes (calling AE title and
// host both match), only the storage SOP classes VesselView can use (and
// C-ECHO), caps the bytes of one association, and refuses the rest with a log
// line ("vv.pacs") that names the peer but no patient data. Each association
// is one store transaction: committed on a normal release, discarded on an
// abort, a refusal or the cap. With TLS, it speaks only TLS (BCP 195) and lets
// in only peers whose certificate chains to the trusted CA(s); a failed TLS
// handshake (an untrusted or missing certificate, a peer speaking plain TCP)
// is refused with a log line naming the peer's address.

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "vv/pacs/LocalStore.h"
#include "vv/pacs/Node.h"

namespace vv::pacs {

struct ListenerConfig {
    std::string aeTitle = "VESSELVIEW";  ///< the called AE title we answer to
    std::uint16_t port = 11112;
    std::string bindAddress = "127.0.0.1";  ///< the interface (IPv4) to listen on; 0.0.0.0: all
    std::vector<Node> allowedPeers;         ///< calling AE title + host (IP address) pairs
    std::size_t maxAssociationBytes = std::size_t{4} << 30;  ///< bytes of one association
    Timeouts timeouts;
    /// TLS: when enabled, `certificate` and `privateKey` (ours, shown to the
    /// peer) and `trustedCertificates` (the CA(s) the peer's certificate must
    /// chain to) are all required.
    TlsSettings tls;
};

/// Counters of what the listener did (no patient data).
struct ListenerStats {
    std::size_t acceptedAssociations = 0;
    std::size_t refusedAssociations = 0;  ///< including failed TLS handshakes
    std::size_t committedInstances = 0;
    std::size_t discardedAssociations = 0;  ///< aborted or over the cap
};

class StorageScp {
  public:
    /// Validates `config` (InvalidArgumentError) and starts listening on its
    /// address and port on a worker thread; throws TlsError when its TLS
    /// files cannot be read or do not match, IoError when the port cannot be
    /// opened.
    StorageScp(LocalStore& store, ListenerConfig config);
    /// Stops listening (within about a second) and joins the worker.
    ~StorageScp();
    StorageScp(const StorageScp&) = delete;
    StorageScp& operator=(const StorageScp&) = delete;

    [[nodiscard]] ListenerStats stats() const;

  private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace vv::pacs
