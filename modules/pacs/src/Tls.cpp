// SPDX-License-Identifier: GPL-3.0-or-later
#include "Tls.h"

#include <dcmtk/dcmnet/dcmtrans.h>
#include <sys/socket.h>
#include <sys/time.h>

#include <algorithm>
#include <memory>
#include <utility>

#include "ForwardingConnection.h"
#include "Socket.h"
#include "vv/pacs/PacsError.h"

namespace vv::pacs::detail {

namespace {

void check(const OFCondition& cond, const std::string& what) {
    if (cond.bad()) {
        throw TlsError(what + ": " + cond.text());
    }
}

/// Passes everything to the TLS connection; bounds the handshakes and
/// reports a failed server handshake.
class TimedConnection : public ForwardingConnection {
  public:
    TimedConnection(DcmNativeSocketType socket, DcmTransportConnection* inner, int handshakeSeconds,
                    const TimedTlsLayer::Refused& onRefused)
        : ForwardingConnection(socket, inner),
          handshakeSeconds_(handshakeSeconds),
          onRefused_(onRefused) {}

    OFCondition serverSideHandshake() override {
        const OFCondition cond = timed([this] { return inner().serverSideHandshake(); });
        if (cond.bad() && onRefused_) {
            onRefused_(peerAddress(getSocket()),
                       cond.text() != nullptr ? cond.text() : "TLS failed");
        }
        return cond;
    }
    OFCondition clientSideHandshake() override {
        return timed([this] { return inner().clientSideHandshake(); });
    }

  private:
    /// Runs `handshake` with our receive timeout on the socket instead of
    /// DCMTK's (60 s), then DCMTK's again for the association.
    template <class Handshake>
    OFCondition timed(Handshake handshake) {
        timeval previous{};
        socklen_t length = sizeof previous;
        const bool known =
            ::getsockopt(getSocket(), SOL_SOCKET, SO_RCVTIMEO, &previous, &length) == 0;
        const timeval bound{handshakeSeconds_, 0};
        ::setsockopt(getSocket(), SOL_SOCKET, SO_RCVTIMEO, &bound, sizeof bound);
        const OFCondition cond = handshake();
        if (known) {
            ::setsockopt(getSocket(), SOL_SOCKET, SO_RCVTIMEO, &previous, sizeof previous);
        }
        return cond;
    }

    int handshakeSeconds_;
    const TimedTlsLayer::Refused& onRefused_;
};

}  // namespace

void prepareTls(DcmTLSTransportLayer& layer, const TlsSettings& tls, T_ASC_NetworkRole role) {
    if (tls.trustedCertificates.empty()) {
        throw TlsError("TLS needs the trusted (CA) certificates");
    }
    if (role == NET_ACCEPTOR && (tls.certificate.empty() || tls.privateKey.empty())) {
        throw TlsError("a TLS listener needs its certificate and private key");
    }
    check(layer.setTLSProfile(TSP_Profile_BCP195), "TLS profile");
    check(layer.activateCipherSuites(), "TLS cipher suites");
    check(layer.addTrustedCertificateFile(tls.trustedCertificates.c_str(), DCF_Filetype_PEM),
          tls.trustedCertificates.string());
    if (!tls.certificate.empty()) {
        check(layer.setPrivateKeyFile(tls.privateKey.c_str(), DCF_Filetype_PEM),
              tls.privateKey.string());
        check(layer.setCertificateFile(tls.certificate.c_str(), DCF_Filetype_PEM),
              tls.certificate.string());
        if (!layer.checkPrivateKeyMatchesCertificate()) {
            throw TlsError(tls.privateKey.string() + " is not the key of " +
                           tls.certificate.string());
        }
    }
    layer.setCertificateVerification(DCV_requireCertificate);
}

TimedTlsLayer::TimedTlsLayer(T_ASC_NetworkRole networkRole, const TlsSettings& tls,
                             int handshakeSeconds, Refused onRefused)
    : DcmTLSTransportLayer(networkRole, nullptr, OFTrue),
      handshakeSeconds_(std::max(1, handshakeSeconds)),
      onRefused_(std::move(onRefused)) {
    prepareTls(*this, tls, networkRole);
}

DcmTransportConnection* TimedTlsLayer::createConnection(DcmNativeSocketType openSocket,
                                                        OFBool useSecureLayer) {
    DcmTransportConnection* inner =
        DcmTLSTransportLayer::createConnection(openSocket, useSecureLayer);
    if (inner == nullptr || !useSecureLayer) {
        return inner;
    }
    return new TimedConnection(openSocket, inner, handshakeSeconds_, onRefused_);
}

}  // namespace vv::pacs::detail
