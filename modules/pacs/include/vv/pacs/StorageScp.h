// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// The storage SCP (our DICOM listener): receives instances pushed by a PACS
// (C-STORE, e.g. as the destination of a C-MOVE) into the local store. It lets
// in only configured nodes (calling AE title and host both match), only the
// storage SOP classes VesselView can use (and C-ECHO), and refuses the rest
// with a log line ("vv.pacs") that names the peer but no patient data. Each
// association is one store transaction: committed on a normal release,
// discarded on an abort, a refusal or the association cap. With TLS, it
// speaks only TLS (BCP 195) and lets in only peers whose certificate chains to
// the trusted CA(s); a failed TLS handshake (an untrusted or missing
// certificate, a peer speaking plain TCP) is refused with a log line naming
// the peer's address.
//
// Under load and abuse (a hostile network): one thread accepts connections
// and holds each until it has presented its association request (plain TCP:
// the A-ASSOCIATE-RQ; TLS: the first handshake record), within
// ListenerLimits::requestSeconds, else drops it; only then does a worker (at
// most maxAssociations at once) take it, so silent, slow or garbage
// connections never hold up a configured node. Connections over a cap are
// closed at once. Datasets are written to the staging folder as they arrive,
// never held in memory. Refused and dropped connections are counted and
// logged (at most one line per address and reason a minute, with the count
// of the ones left out).

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "vv/pacs/LocalStore.h"
#include "vv/pacs/Node.h"

namespace vv::pacs {

/// What one listener lets its peers use. The defaults suit a workstation that
/// receives from a few PACS and modalities; validate() says what is allowed.
struct ListenerLimits {
    /// Associations served at once (a worker thread each). One more is
    /// refused with A-ASSOCIATE-RJ "local limit exceeded" (transient: the
    /// peer may try again).
    int maxAssociations = 16;
    /// Open connections (waiting or served) from one IP address that is a
    /// configured node's host. Addresses that are no configured node's host
    /// can never be let in, only told so: they get at most
    /// kStrangerConnectionsPerAddress each and kStrangerConnections together.
    int maxConnectionsPerAddress = 8;
    /// Open connections in all. A connection over a cap is closed at once.
    int maxConnections = 64;
    /// Seconds a new connection has to present its association request (with
    /// TLS: its first handshake record, then again to finish the handshake)
    /// before it is dropped.
    int requestSeconds = 5;
    /// Bytes of one instance as received. The rest of a larger one is read
    /// and thrown away, the instance refused (status 0xA700, out of
    /// resources); the association goes on.
    std::uint64_t maxInstanceBytes = 4'000'000'000ULL;
    /// Bytes of one association. The instance that crosses it and every
    /// later one are refused (0xA700) and nothing of the association is kept.
    std::uint64_t maxAssociationBytes = 50'000'000'000ULL;

    static constexpr int kStrangerConnectionsPerAddress = 2;
    static constexpr int kStrangerConnections = 8;

    /// The ends of the ranges validate() allows (front ends offer them).
    static constexpr int kMaxAssociations = 256;
    static constexpr int kMaxConnections = 1024;  ///< in all, and so per address
    static constexpr int kMaxRequestSeconds = 120;
    static constexpr std::uint64_t kMinInstanceBytes = 1000;

    /// Throws InvalidArgumentError naming the limit unless: maxAssociations
    /// 1..256, maxConnections 1..1024 and at least maxAssociations,
    /// maxConnectionsPerAddress 1..maxConnections, requestSeconds 1..120,
    /// maxInstanceBytes at least 1 kB (1000 B), maxAssociationBytes at least
    /// maxInstanceBytes.
    void validate() const;
};

struct ListenerConfig {
    std::string aeTitle = "VESSELVIEW";  ///< the called AE title we answer to
    std::uint16_t port = 11112;
    std::string bindAddress = "127.0.0.1";  ///< the interface (IPv4) to listen on; 0.0.0.0: all
    std::vector<Node> allowedPeers;         ///< calling AE title + host (IP address) pairs
    ListenerLimits limits;
    /// associateSeconds: the A-ASSOCIATE-RQ once a worker has it, the release;
    /// responseSeconds: each DIMSE message, each PDU of a dataset (a peer
    /// that stalls longer mid-dataset is dropped, its association discarded).
    Timeouts timeouts;
    /// TLS: when enabled, `certificate` and `privateKey` (ours, shown to the
    /// peer) and `trustedCertificates` (the CA(s) the peer's certificate must
    /// chain to) are all required.
    TlsSettings tls;
};

/// Counters of what the listener did (no patient data), and two gauges.
struct ListenerStats {
    std::size_t acceptedAssociations = 0;
    /// Refused association requests: not a configured node, not our AE
    /// title, all workers busy, a failed TLS handshake.
    std::size_t refusedAssociations = 0;
    std::size_t committedInstances = 0;
    std::size_t discardedAssociations = 0;  ///< aborted, broken off or over the cap
    std::size_t refusedInstances = 0;       ///< over a size cap, unreadable, or not storable
    /// Connections closed at once: over the per-address or the total cap.
    std::size_t refusedConnections = 0;
    /// Connections dropped before a worker took them: no association request
    /// in time, not DICOM (or not TLS on a TLS listener), closed by the peer.
    std::size_t droppedConnections = 0;
    std::size_t openConnections = 0;     ///< now: waiting or served
    std::size_t activeAssociations = 0;  ///< now: served by a worker
};

class StorageScp {
  public:
    /// Validates `config` (InvalidArgumentError) and starts listening on its
    /// address and port; throws TlsError when its TLS files cannot be read or
    /// do not match, IoError when the port cannot be opened.
    StorageScp(LocalStore& store, ListenerConfig config);
    /// Stops at once: closes the port and every connection (the associations
    /// under way are broken off and discarded) and joins the threads.
    ~StorageScp();
    StorageScp(const StorageScp&) = delete;
    StorageScp& operator=(const StorageScp&) = delete;

    [[nodiscard]] ListenerStats stats() const;

  private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace vv::pacs
