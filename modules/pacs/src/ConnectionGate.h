// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// The listener's front door: one thread that accepts TCP connections, holds
// each (non-blocking, costing no worker) until it has presented its
// association request, and only then hands it on. A connection over a cap of
// the ConnectionBudget is reset at once; one that presents nothing within the
// deadline, whose first bytes are no association request (plain TCP: an
// A-ASSOCIATE-RQ PDU; TLS: a handshake record), or that the peer closes
// first, is dropped. So silent, slow or garbage connections never hold up a
// configured node; DCMTK reads only from connections handed on.

#include <array>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <thread>
#include <vector>

#include "ConnectionBudget.h"
#include "RefusalLog.h"
#include "Socket.h"

namespace vv::pacs::detail {

/// A connection that has presented its association request: its socket
/// (blocking again, for DCMTK) and its share of the budget.
struct ReadyConnection {
    OwnedSocket socket;
    ConnectionBudget::Slot slot;
    /// Plain TCP: the whole A-ASSOCIATE-RQ is in the socket's buffer (reading
    /// it cannot wait on the peer).
    bool requestBuffered = false;
};

class ConnectionGate {
  public:
    struct Settings {
        bool tls = false;                  ///< the first bytes must be a TLS handshake record
        std::chrono::seconds deadline{5};  ///< to present the request
    };
    /// Called on the gate's thread for each connection reset over a cap /
    /// dropped before it was handed on (counters; the log lines are the gate's).
    struct Counters {
        std::function<void()> refused;
        std::function<void()> dropped;
    };
    /// Takes a ready connection, on the gate's thread; must not wait on the network.
    using Ready = std::function<void(ReadyConnection&&)>;

    /// Starts the gate's thread on `listening` (a non-blocking listening
    /// socket). `budget` and `log` must outlive the gate.
    ConnectionGate(OwnedSocket listening, Settings settings, ConnectionBudget& budget,
                   RefusalLog& log, Counters counters, Ready ready);
    /// Stops: closes the listening socket and every connection not yet handed on.
    ~ConnectionGate();
    ConnectionGate(const ConnectionGate&) = delete;
    ConnectionGate& operator=(const ConnectionGate&) = delete;
    ConnectionGate(ConnectionGate&&) = delete;
    ConnectionGate& operator=(ConnectionGate&&) = delete;

    /// The largest association request (A-ASSOCIATE-RQ PDU, bytes) taken; a
    /// longer one is dropped. Real ones are a few kB.
    static constexpr std::uint32_t kMaxRequestBytes = 1U << 20;
    /// Bytes of the request the gate waits for before it hands a connection
    /// on (the whole request when it is shorter).
    static constexpr std::size_t kPeekBytes = 16384;

  private:
    struct Pending {
        OwnedSocket socket;
        ConnectionBudget::Slot slot;
        std::chrono::steady_clock::time_point deadline;
    };
    enum class Verdict { Wait, Ready, ReadyBuffered, NotARequest, Closed };

    void run();
    void acceptAll();
    void admit(OwnedSocket socket, const std::string& address);
    Verdict inspect(const Pending& pending, std::string& why);
    void handOn(Pending&& pending, bool buffered);
    void drop(Pending&& pending, const std::string& why);

    OwnedSocket listening_;
    OwnedSocket wake_;   ///< an eventfd: written to stop the thread
    OwnedSocket spare_;  ///< a descriptor kept to accept-and-close when out of descriptors
    Settings settings_;
    ConnectionBudget& budget_;
    RefusalLog& log_;
    Counters counters_;
    Ready ready_;
    std::vector<Pending> pending_;
    std::array<std::uint8_t, kPeekBytes> peek_{};
    std::thread thread_;
};

}  // namespace vv::pacs::detail
