// SPDX-License-Identifier: GPL-3.0-or-later
#include "AbortableLayer.h"

#include <sys/socket.h>

#include <utility>

#include "ForwardingConnection.h"
#include "Socket.h"

namespace vv::pacs::detail {

namespace {

/// Passes everything to the connection it wraps; keeps its socket attached to
/// the switch until the socket is closed.
class AbortableConnection : public ForwardingConnection {
  public:
    AbortableConnection(DcmNativeSocketType socket, DcmTransportConnection* inner,
                        std::shared_ptr<AbortSwitch> abortSwitch)
        : ForwardingConnection(socket, inner), switch_(std::move(abortSwitch)) {
        switch_->attach(socket);
    }
    AbortableConnection(const AbortableConnection&) = delete;
    AbortableConnection& operator=(const AbortableConnection&) = delete;
    AbortableConnection(AbortableConnection&&) = delete;
    AbortableConnection& operator=(AbortableConnection&&) = delete;
    ~AbortableConnection() override {
        switch_->detach(getSocket());
        dropInner();  // closes the socket, now that a stop cannot reach it
    }

    void close() override {
        switch_->detach(getSocket());
        ForwardingConnection::close();
        setSocket(-1);
    }
    void closeTransportConnection() override {
        switch_->detach(getSocket());
        ForwardingConnection::closeTransportConnection();
    }

  private:
    std::shared_ptr<AbortSwitch> switch_;
};

}  // namespace

DcmTransportConnection* makeAbortableConnection(DcmNativeSocketType socket,
                                                DcmTransportConnection* inner,
                                                std::shared_ptr<AbortSwitch> abortSwitch) {
    return new AbortableConnection(socket, inner, std::move(abortSwitch));
}

void AbortSwitch::abort() noexcept {
    const std::lock_guard lock(mutex_);
    aborted_ = true;
    if (socket_ >= 0) {
        ::shutdown(socket_, SHUT_RDWR);
    }
}

bool AbortSwitch::aborted() const noexcept {
    const std::lock_guard lock(mutex_);
    return aborted_;
}

void AbortSwitch::attach(DcmNativeSocketType socket) noexcept {
    const std::lock_guard lock(mutex_);
    socket_ = socket;
    if (aborted_ && socket_ >= 0) {
        ::shutdown(socket_, SHUT_RDWR);
    }
}

void AbortSwitch::detach(DcmNativeSocketType socket) noexcept {
    const std::lock_guard lock(mutex_);
    if (socket_ == socket) {
        socket_ = -1;
    }
}

AbortableLayer::AbortableLayer(DcmTransportLayer* inner, const std::stop_token& stop, int ioSeconds)
    : inner_(inner), ioSeconds_(ioSeconds) {
    onStop_.emplace(stop, Trip{switch_});
}

DcmTransportConnection* AbortableLayer::createConnection(DcmNativeSocketType openSocket,
                                                         OFBool /*useSecureLayer*/) {
    sendAtOnce(openSocket);
    DcmTransportConnection* connection =
        inner_ != nullptr ? inner_->createConnection(openSocket, OFTrue)
                          : DcmTransportLayer::createConnection(openSocket, OFFalse);
    if (connection == nullptr) {
        return nullptr;
    }
    DcmTransportConnection* abortable = makeAbortableConnection(openSocket, connection, switch_);
    if (ioSeconds_ > 0) {
        boundEachReadAndWrite(openSocket, ioSeconds_);
    }
    return abortable;
}

}  // namespace vv::pacs::detail
