// SPDX-License-Identifier: GPL-3.0-or-later
#include "AcceptorNetwork.h"

#include <dcmtk/dcmnet/dcmtrans.h>
#include <dcmtk/dcmnet/dul.h>

#include <algorithm>
#include <mutex>
#include <utility>

#include "vv/core/Error.h"

namespace vv::pacs::detail {

namespace {

/// Serialises every use of dcmExternalSocketHandle in the process.
std::mutex& handOverMutex() {
    static std::mutex mutex;
    return mutex;
}

/// The hand-over under way on this thread: what createConnection() needs.
struct HandOver {
    std::unique_lock<std::mutex>* lock = nullptr;
    std::shared_ptr<AbortSwitch> abortSwitch;
    bool taken = false;  ///< DCMTK made its connection: it owns the socket now

    /// DCMTK has read the global: withdraw it and let the next hand-over go.
    void end() const {
        if (lock != nullptr && lock->owns_lock()) {
            dcmExternalSocketHandle.set(-1);
            lock->unlock();
        }
    }
};

// NOLINTNEXTLINE(cppcoreguidelines-avoid-non-const-global-variables): per thread, by design
thread_local HandOver* tHandOver = nullptr;

}  // namespace

/// Our connections: the TLS layer's (or plain TCP), each attached to the
/// hand-over's abort switch; making one ends the hand-over.
class AcceptorNetwork::Layer : public DcmTransportLayer {
  public:
    Layer(DcmTransportLayer* tls, int ioSeconds) : tls_(tls), ioSeconds_(ioSeconds) {}

    DcmTransportConnection* createConnection(DcmNativeSocketType openSocket,
                                             OFBool /*useSecureLayer*/) override {
        HandOver* handOver = tHandOver;
        std::shared_ptr<AbortSwitch> abortSwitch =
            handOver != nullptr ? handOver->abortSwitch : std::make_shared<AbortSwitch>();
        if (handOver != nullptr) {
            handOver->taken = true;
            handOver->end();
        }
        DcmTransportConnection* inner =
            tls_ != nullptr ? tls_->createConnection(openSocket, OFTrue)
                            : DcmTransportLayer::createConnection(openSocket, OFFalse);
        if (inner == nullptr) {
            return nullptr;  // DCMTK closes the socket
        }
        DcmTransportConnection* connection =
            makeAbortableConnection(openSocket, inner, std::move(abortSwitch));
        boundEachReadAndWrite(openSocket, ioSeconds_);
        return connection;
    }

  private:
    DcmTransportLayer* tls_;
    int ioSeconds_;
};

AcceptorNetwork::AcceptorNetwork(int requestSeconds, int ioSeconds, DcmTransportLayer* tls)
    : layer_(std::make_unique<Layer>(tls, std::max(1, ioSeconds))), tls_(tls != nullptr) {
    dcmDisableGethostbyaddr.set(OFTrue);  // the peer is known by its address; never wait on DNS
    OFCondition cond;
    {
        // With a socket "handed over", DCMTK opens no listen socket of its own.
        const std::lock_guard lock(handOverMutex());
        dcmExternalSocketHandle.set(1);
        cond = ASC_initializeNetwork(NET_ACCEPTOR, 0, requestSeconds, &network_);
        dcmExternalSocketHandle.set(-1);
    }
    if (cond.good()) {
        cond = ASC_setTransportLayer(network_, layer_.get(), 0);
    }
    if (cond.bad()) {
        ASC_dropNetwork(&network_);
        throw IoError(std::string("cannot start the listener: ") + cond.text());
    }
}

AcceptorNetwork::~AcceptorNetwork() {
    ASC_dropNetwork(&network_);
}

OFCondition AcceptorNetwork::adopt(OwnedSocket socket, std::shared_ptr<AbortSwitch> abortSwitch,
                                   long maxPdu, T_ASC_Association*& association) {
    association = nullptr;
    if (abortSwitch->aborted()) {
        return DUL_NETWORKCLOSED;
    }
    std::unique_lock lock(handOverMutex());
    HandOver handOver{&lock, std::move(abortSwitch)};
    tHandOver = &handOver;
    const int fd = socket.get();
    dcmExternalSocketHandle.set(fd);
    const OFCondition cond = ASC_receiveAssociation(
        network_, &association, maxPdu, nullptr, nullptr, tls_ ? OFTrue : OFFalse, DUL_NOBLOCK, 1);
    handOver.end();  // when DCMTK failed before it made a connection
    tHandOver = nullptr;
    if (handOver.taken) {
        [[maybe_unused]] const int owned = socket.release();  // DCMTK's now (or closed by it)
    }
    if (cond.bad() && association != nullptr) {
        ASC_dropAssociation(association);
        ASC_destroyAssociation(&association);
        association = nullptr;
    }
    return cond;
}

}  // namespace vv::pacs::detail
