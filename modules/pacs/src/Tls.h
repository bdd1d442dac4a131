// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// DICOM over TLS with DCMTK's dcmtls (BCP 195 profile, the peer's certificate
// required and checked against the trusted CAs), for both sides: the SCU that
// calls a node and the listener that accepts. Handshakes have our timeout;
// the listener's layer reports each connection whose TLS handshake failed (an
// untrusted certificate, no certificate, a peer that does not speak TLS) with
// the peer's address.

#include <dcmtk/config/osconfig.h>
#include <dcmtk/dcmtls/tlslayer.h>

#include <functional>
#include <string>

#include "vv/pacs/Node.h"

namespace vv::pacs::detail {

/// Sets `layer` up as `tls` says: BCP 195 profile, the trusted CA
/// certificate(s), our certificate and key when given, and the peer's
/// certificate required. `role` says which side we are: the acceptor must
/// have a certificate of its own. Throws TlsError naming the file that failed.
void prepareTls(DcmTLSTransportLayer& layer, const TlsSettings& tls, T_ASC_NetworkRole role);

/// A TLS layer as prepareTls(`networkRole`) whose handshakes take at most
/// `handshakeSeconds` (DCMTK's own bound is the socket's 60 s receive
/// timeout): a peer that connects and stays silent holds the listener, or a
/// TLS port that never answers holds the caller, no longer. On the listener,
/// every connection whose handshake fails is reported to `onRefused` with the
/// peer's IP address and DCMTK's reason (never patient data: nothing of
/// DICOM has been read yet).
class TimedTlsLayer : public DcmTLSTransportLayer {
  public:
    using Refused = std::function<void(const std::string& host, const std::string& problem)>;
    /// Throws TlsError as prepareTls.
    TimedTlsLayer(T_ASC_NetworkRole networkRole, const TlsSettings& tls, int handshakeSeconds,
                  Refused onRefused = {});
    DcmTransportConnection* createConnection(DcmNativeSocketType openSocket,
                                             OFBool useSecureLayer) override;

  private:
    int handshakeSeconds_;
    Refused onRefused_;
};

}  // namespace vv::pacs::detail
