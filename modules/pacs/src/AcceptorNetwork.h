// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// Handing a socket the listener accepted itself to DCMTK. DCMTK 3.6.7 reads
// an association request only through its own accept(), unless the global
// dcmExternalSocketHandle names a connected socket (the "inetd" mode of
// storescp), which it reads once at the start of the receive. The handing
// over is therefore serialised by a lock, held only until DCMTK has made its
// connection on the socket (our transport layer's createConnection(), before
// any read or TLS handshake): the workers then read their requests side by
// side. The network has no listen socket of its own.

#include <dcmtk/config/osconfig.h>
#include <dcmtk/dcmnet/assoc.h>
#include <dcmtk/dcmnet/dcmlayer.h>

#include <memory>

#include "AbortableLayer.h"
#include "Socket.h"

namespace vv::pacs::detail {

class AcceptorNetwork {
  public:
    /// `requestSeconds`: how long DCMTK waits for the A-ASSOCIATE-RQ on an
    /// adopted socket. `ioSeconds`: the longest any one read or write on it
    /// may block — DCMTK's own bound on the reads within a PDU is a global
    /// 60 s, so a peer that stalls mid-PDU would hold a worker that long.
    /// `tls`: the TLS layer (outlives this network), or null for plain TCP.
    /// Throws IoError when DCMTK cannot make the network.
    AcceptorNetwork(int requestSeconds, int ioSeconds, DcmTransportLayer* tls);
    ~AcceptorNetwork();
    AcceptorNetwork(const AcceptorNetwork&) = delete;
    AcceptorNetwork& operator=(const AcceptorNetwork&) = delete;
    AcceptorNetwork(AcceptorNetwork&&) = delete;
    AcceptorNetwork& operator=(AcceptorNetwork&&) = delete;

    /// Lets DCMTK take `socket` (connected, blocking) over and read its
    /// association request (with TLS: after the handshake) into
    /// `association` — whose connection owns the socket, attached to
    /// `abortSwitch` until closed. Returns DCMTK's condition: when bad, there
    /// is no association and the socket is closed.
    OFCondition adopt(OwnedSocket socket, std::shared_ptr<AbortSwitch> abortSwitch, long maxPdu,
                      T_ASC_Association*& association);

  private:
    class Layer;
    std::unique_ptr<Layer> layer_;
    T_ASC_Network* network_ = nullptr;
    bool tls_;
};

}  // namespace vv::pacs::detail
