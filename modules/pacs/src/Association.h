// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// Opening an association with DCMTK's DcmSCU and turning DCMTK's conditions
// into the typed errors of vv/pacs/PacsError.h.

#include <dcmtk/config/osconfig.h>
#include <dcmtk/dcmnet/dcmlayer.h>
#include <dcmtk/dcmnet/scu.h>

#include <memory>
#include <string>
#include <vector>

#include "vv/pacs/Node.h"

namespace vv::pacs::detail {

/// Holds the TLS layer; a base before DcmSCU, so that it outlives DcmSCU's
/// own clean-up (closing the association, dropping the network).
struct TlsLayerHolder {
    std::unique_ptr<DcmTransportLayer> tlsLayer;
};

/// DcmSCU with the TLS layer it may use.
class Scu : private TlsLayerHolder, public DcmSCU {
  public:
    /// Prepares TLS as `tls` says, the handshake bounded by `handshakeSeconds`;
    /// throws TlsError naming the file that failed.
    void secure(const TlsSettings& tls, int handshakeSeconds);
    /// Puts the prepared TLS layer (if any) on the initialised network.
    void attachTls();
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
/// AssociationRejectedError, TimeoutError or PeerFailedError.
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
