// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// DICOM over TLS with DCMTK's dcmtls (BCP 195 profile, the peer's certificate
// required and checked against the trusted CAs), for both sides: the SCU that
// calls a node and the listener that accepts. The listener's layer reports
// each connection whose TLS handshake failed (an untrusted certificate, no
// certificate, a peer that does not speak TLS) with the peer's address.

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

/// The listener's TLS layer: as prepareTls(NET_ACCEPTOR), and every accepted
/// connection whose TLS handshake fails is reported to `onRefused` with the
/// peer's IP address and DCMTK's reason (never patient data: nothing of
/// DICOM has been read yet).
class ListenerTlsLayer : public DcmTLSTransportLayer {
  public:
    using Refused = std::function<void(const std::string& host, const std::string& problem)>;
    /// Throws TlsError as prepareTls.
    ListenerTlsLayer(const TlsSettings& tls, Refused onRefused);
    DcmTransportConnection* createConnection(DcmNativeSocketType openSocket,
                                             OFBool useSecureLayer) override;

  private:
    Refused onRefused_;
};

}  // namespace vv::pacs::detail
