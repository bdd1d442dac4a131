// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// Opening an association with DCMTK's DcmSCU and turning DCMTK's conditions
// into the typed errors of vv/pacs/PacsError.h.

#include <dcmtk/config/osconfig.h>
#include <dcmtk/dcmnet/dcmlayer.h>
#include <dcmtk/dcmnet/scu.h>

#include <memory>
#include <stop_token>
#include <string>
#include <vector>

#include "AbortableLayer.h"
#include "vv/pacs/Node.h"

namespace vv::pacs::detail {

/// Holds the transport layers; a base before DcmSCU, so that they outlive
/// DcmSCU's own clean-up (closing the association, dropping the network).
struct TlsLayerHolder {
    std::unique_ptr<DcmTransportLayer> tlsLayer;
    /// Over tlsLayer (or plain TCP) when a stop may abort the association.
    std::unique_ptr<AbortableLayer> abortableLayer;
};

/// DcmSCU with the TLS layer it may use, and a stop that aborts it.
class Scu : private TlsLayerHolder, public DcmSCU {
  public:
    /// Prepares TLS as `tls` says, the handshake bounded by `handshakeSeconds`;
    /// throws TlsError naming the file that failed.
    void secure(const TlsSettings& tls, int handshakeSeconds);
    /// A stop of `stop` (requested from any thread) aborts the association:
    /// DCMTK's wait for the peer ends at once, and throwIfStopped() throws.
    /// Call before open().
    void abortOn(std::stop_token stop);
    /// Puts the prepared layers (TLS, abort) on the initialised network.
    void attachLayers();
    /// Throws CancelledError when the stop of abortOn() was requested.
    void throwIfStopped() const;

  private:
    std::stop_token stop_;
};

/// Turns DCMTK's own logging off once per process: its messages may quote
/// attribute values (patient data). Failures reach the caller as typed errors.
void quietDcmtk();

/// Sets our AE title, the peer, its TLS and every timeout of `me` on `scu`
/// (non-blocking DIMSE, so that no wait is without a limit). Validates both.
void configure(Scu& scu, const LocalAe& me, const Node& peer);

/// Proposes `abstractSyntax` with explicit / implicit little endian.
void propose(DcmSCU& scu, const char* abstractSyntax, T_ASC_SC_ROLE role = ASC_SC_ROLE_DEFAULT);

/// initNetwork() + negotiateAssociation(); throws ConnectionRefusedError,
/// AssociationRejectedError, TimeoutError or PeerFailedError, and
/// CancelledError when the stop of Scu::abortOn() was requested.
void open(Scu& scu, const Node& peer);

/// The accepted presentation context for `abstractSyntax`; throws
/// AssociationRejectedError naming the SOP class when the peer accepted none.
T_ASC_PresentationContextID contextFor(DcmSCU& scu, const Node& peer, const char* abstractSyntax);

/// Throws the typed error for a failed `cond` during `what` ("C-FIND", ...).
[[noreturn]] void fail(const OFCondition& cond, const Node& peer, const std::string& what);

/// Releases the association (errors ignored: the work is done).
void release(DcmSCU& scu) noexcept;

/// Throws PeerFailedError for a DIMSE status that is neither success, pending
/// nor warning.
void checkStatus(Uint16 status, const Node& peer, const std::string& what);

}  // namespace vv::pacs::detail
