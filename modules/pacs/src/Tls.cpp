// SPDX-License-Identifier: GPL-3.0-or-later
#include "Tls.h"

#include <arpa/inet.h>
#include <dcmtk/dcmnet/dcmtrans.h>
#include <netinet/in.h>
#include <sys/socket.h>

#include <memory>
#include <utility>

#include "vv/pacs/PacsError.h"

namespace vv::pacs::detail {

namespace {

void check(const OFCondition& cond, const std::string& what) {
    if (cond.bad()) {
        throw TlsError(what + ": " + cond.text());
    }
}

/// The IPv4 address of the peer of `socket`, or "an unknown host".
std::string peerOf(DcmNativeSocketType socket) {
    sockaddr_in address{};
    socklen_t length = sizeof address;
    char text[INET_ADDRSTRLEN] = {};
    if (::getpeername(socket, reinterpret_cast<sockaddr*>(&address), &length) != 0 ||
        address.sin_family != AF_INET ||
        ::inet_ntop(AF_INET, &address.sin_addr, text, sizeof text) == nullptr) {
        return "an unknown host";
    }
    return text;
}

/// Passes everything to the TLS connection and reports a failed server handshake.
class WatchedConnection : public DcmTransportConnection {
  public:
    WatchedConnection(DcmNativeSocketType socket, DcmTransportConnection* inner,
                      const ListenerTlsLayer::Refused& onRefused)
        : DcmTransportConnection(socket), inner_(inner), onRefused_(onRefused) {}

    OFCondition serverSideHandshake() override {
        const OFCondition cond = inner_->serverSideHandshake();
        if (cond.bad() && onRefused_) {
            onRefused_(peerOf(getSocket()), cond.text() != nullptr ? cond.text() : "TLS failed");
        }
        return cond;
    }
    OFCondition clientSideHandshake() override { return inner_->clientSideHandshake(); }
    OFCondition renegotiate(const char* suite) override { return inner_->renegotiate(suite); }
    ssize_t read(void* buf, size_t n) override { return inner_->read(buf, n); }
    ssize_t write(void* buf, size_t n) override { return inner_->write(buf, n); }
    void close() override { inner_->close(); }
    void closeTransportConnection() override { inner_->closeTransportConnection(); }
    unsigned long getPeerCertificateLength() override { return inner_->getPeerCertificateLength(); }
    unsigned long getPeerCertificate(void* buf, unsigned long length) override {
        return inner_->getPeerCertificate(buf, length);
    }
    OFBool networkDataAvailable(int timeout) override {
        return inner_->networkDataAvailable(timeout);
    }
    OFBool isTransparentConnection() override { return inner_->isTransparentConnection(); }
    OFString& dumpConnectionParameters(OFString& str) override {
        return inner_->dumpConnectionParameters(str);
    }

  private:
    std::unique_ptr<DcmTransportConnection> inner_;
    const ListenerTlsLayer::Refused& onRefused_;
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

ListenerTlsLayer::ListenerTlsLayer(const TlsSettings& tls, Refused onRefused)
    : DcmTLSTransportLayer(NET_ACCEPTOR, nullptr, OFTrue), onRefused_(std::move(onRefused)) {
    prepareTls(*this, tls, NET_ACCEPTOR);
}

DcmTransportConnection* ListenerTlsLayer::createConnection(DcmNativeSocketType openSocket,
                                                           OFBool useSecureLayer) {
    DcmTransportConnection* inner =
        DcmTLSTransportLayer::createConnection(openSocket, useSecureLayer);
    if (inner == nullptr || !useSecureLayer) {
        return inner;
    }
    return new WatchedConnection(openSocket, inner, onRefused_);
}

}  // namespace vv::pacs::detail
