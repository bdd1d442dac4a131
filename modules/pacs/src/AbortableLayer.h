// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// Stopping an association from another thread while DCMTK waits on it: the
// transport layer below DcmSCU records the socket of each connection it
// makes, and a stop (std::stop_token, requested from any thread) shuts that
// socket down (shutdown(2), never close(2)), so that DCMTK's wait for the
// peer — an A-ASSOCIATE-AC, a C-FIND response — ends at once with "network
// closed" instead of running into its timeout. The TCP connect itself is not
// interrupted (it has its own, short timeout): a stop during it takes effect
// as soon as the connection exists.

#include <dcmtk/config/osconfig.h>
#include <dcmtk/dcmnet/dcmlayer.h>
#include <dcmtk/dcmnet/dcmtrans.h>

#include <memory>
#include <mutex>
#include <optional>
#include <stop_token>

namespace vv::pacs::detail {

/// The socket a stop shuts down; shared by the layer, its connections and the
/// stop callback (any of them may go first). Thread-safe.
class AbortSwitch {
  public:
    /// Shuts the attached socket down, and any attached later.
    void abort() noexcept;
    [[nodiscard]] bool aborted() const noexcept;
    /// `socket` is the connection's now; shut down at once after abort().
    void attach(DcmNativeSocketType socket) noexcept;
    /// The connection closes `socket`: a later abort() must not touch the
    /// number (the system may give it to another file meanwhile).
    void detach(DcmNativeSocketType socket) noexcept;

  private:
    mutable std::mutex mutex_;
    DcmNativeSocketType socket_ = -1;
    bool aborted_ = false;
};

/// `inner` (the connection made on `socket`; taken over) with its socket
/// attached to `abortSwitch` until it is closed.
DcmTransportConnection* makeAbortableConnection(DcmNativeSocketType socket,
                                                DcmTransportConnection* inner,
                                                std::shared_ptr<AbortSwitch> abortSwitch);

/// Makes the connections of `inner` (a TLS layer) or, without one, plain TCP
/// connections, each attached to the switch that a stop of `stop` trips.
class AbortableLayer : public DcmTransportLayer {
  public:
    /// `inner` (may be null: plain TCP) must outlive this layer. `ioSeconds`
    /// (when above 0) bounds every blocking read and write on a connection
    /// (DCMTK's own bound within a PDU is a global 60 s).
    AbortableLayer(DcmTransportLayer* inner, const std::stop_token& stop, int ioSeconds = 0);
    AbortableLayer(const AbortableLayer&) = delete;
    AbortableLayer& operator=(const AbortableLayer&) = delete;
    AbortableLayer(AbortableLayer&&) = delete;
    AbortableLayer& operator=(AbortableLayer&&) = delete;
    ~AbortableLayer() override = default;

    /// DcmSCU marks every connection of a layer it is given as secure: the
    /// inner layer decides, never `useSecureLayer`. Null when the inner layer
    /// fails (DCMTK then reports a TCP initialisation error).
    DcmTransportConnection* createConnection(DcmNativeSocketType openSocket,
                                             OFBool useSecureLayer) override;

    /// True once the stop was requested.
    [[nodiscard]] bool stopped() const noexcept { return switch_->aborted(); }

  private:
    /// Trips the switch; runs on the thread that requests the stop.
    struct Trip {
        std::shared_ptr<AbortSwitch> target;
        void operator()() const noexcept { target->abort(); }
    };

    DcmTransportLayer* inner_;
    int ioSeconds_;
    std::shared_ptr<AbortSwitch> switch_ = std::make_shared<AbortSwitch>();
    std::optional<std::stop_callback<Trip>> onStop_;  ///< last: ends first
};

}  // namespace vv::pacs::detail
