// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// A DCMTK transport connection that owns another one and passes every call to
// it: the base of the connections that change one or two calls of a layer's
// connection (bounded TLS handshakes, a socket a stop can shut down).

#include <dcmtk/config/osconfig.h>
#include <dcmtk/dcmnet/dcmtrans.h>

#include <memory>

namespace vv::pacs::detail {

class ForwardingConnection : public DcmTransportConnection {
  public:
    /// Takes `inner` (the connection made on `socket`) over.
    ForwardingConnection(DcmNativeSocketType socket, DcmTransportConnection* inner)
        : DcmTransportConnection(socket), inner_(inner) {}
    ForwardingConnection(const ForwardingConnection&) = delete;
    ForwardingConnection& operator=(const ForwardingConnection&) = delete;
    ForwardingConnection(ForwardingConnection&&) = delete;
    ForwardingConnection& operator=(ForwardingConnection&&) = delete;
    ~ForwardingConnection() override = default;

    OFCondition serverSideHandshake() override { return inner_->serverSideHandshake(); }
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

  protected:
    [[nodiscard]] DcmTransportConnection& inner() const { return *inner_; }
    /// Closes and deletes the inner connection now (a subclass' destructor).
    void dropInner() noexcept { inner_.reset(); }

  private:
    std::unique_ptr<DcmTransportConnection> inner_;
};

}  // namespace vv::pacs::detail
