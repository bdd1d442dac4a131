// SPDX-License-Identifier: GPL-3.0-or-later
#include "Association.h"

#include <dcmtk/dcmnet/cond.h>
#include <dcmtk/dcmnet/dimse.h>
#include <dcmtk/dcmnet/dul.h>
#include <dcmtk/dcmtls/tlslayer.h>
#include <dcmtk/oflog/oflog.h>

#include <cstdio>
#include <mutex>

#include "Tls.h"
#include "vv/core/Error.h"
#include "vv/pacs/PacsError.h"

namespace vv::pacs::detail {

namespace {

bool contains(const std::string& text, const char* part) {
    return text.find(part) != std::string::npos;
}

std::string hex(Uint16 value) {
    char text[8];
    std::snprintf(text, sizeof text, "0x%04X", value);
    return text;
}

}  // namespace

void quietDcmtk() {
    static std::once_flag once;
    std::call_once(once, [] { OFLog::configure(OFLogger::OFF_LOG_LEVEL); });
}

void Scu::secure(const TlsSettings& tls, int handshakeSeconds) {
    tlsLayer = std::make_unique<TimedTlsLayer>(NET_REQUESTOR, tls, handshakeSeconds);
}

void Scu::abortOn(std::stop_token stop) {
    stop_ = std::move(stop);
}

void Scu::attachLayers() {
    // Always our layer: it sets TCP_NODELAY, bounds each read and write by
    // the response timeout, and a stop (when one can come) shuts the socket down.
    abortableLayer = std::make_unique<AbortableLayer>(tlsLayer.get(), stop_,
                                                      static_cast<int>(getDIMSETimeout()));
    const OFCondition cond = useSecureConnection(abortableLayer.get());
    if (cond.bad()) {
        throw TlsError(std::string("TLS: ") + cond.text());
    }
}

void Scu::throwIfStopped() const {
    if (stop_.stop_requested()) {
        throw CancelledError();
    }
}

void configure(Scu& scu, const LocalAe& me, const Node& peer) {
    quietDcmtk();
    if (peer.tls.enabled) {
        scu.secure(peer.tls, me.timeouts.associateSeconds);
    }
    validateAeTitle(me.aeTitle);
    validateNode(peer);
    scu.setAETitle(me.aeTitle.c_str());
    scu.setPeerAETitle(peer.aeTitle.c_str());
    scu.setPeerHostName(peer.host.c_str());
    scu.setPeerPort(peer.port);
    scu.setConnectionTimeout(me.timeouts.connectSeconds);
    scu.setACSETimeout(static_cast<Uint32>(me.timeouts.associateSeconds));
    scu.setDIMSEBlockingMode(DIMSE_NONBLOCKING);
    scu.setDIMSETimeout(static_cast<Uint32>(me.timeouts.responseSeconds));
    scu.setMaxReceivePDULength(ASC_DEFAULTMAXPDU);
}

void propose(DcmSCU& scu, const char* abstractSyntax, T_ASC_SC_ROLE role) {
    OFList<OFString> syntaxes;
    syntaxes.push_back(UID_LittleEndianExplicitTransferSyntax);
    syntaxes.push_back(UID_LittleEndianImplicitTransferSyntax);
    scu.addPresentationContext(abstractSyntax, syntaxes, role);
}

void open(Scu& scu, const Node& peer) {
    OFCondition cond = scu.initNetwork();
    if (cond.bad()) {
        fail(cond, peer, "network setup");
    }
    scu.attachLayers();
    scu.throwIfStopped();
    cond = scu.negotiateAssociation();
    if (cond.bad()) {
        scu.throwIfStopped();
        fail(cond, peer, "association");
    }
}

T_ASC_PresentationContextID contextFor(DcmSCU& scu, const Node& peer, const char* abstractSyntax) {
    const T_ASC_PresentationContextID id = scu.findAnyPresentationContextID(abstractSyntax, "");
    if (id == 0) {
        const char* name = dcmFindNameOfUID(abstractSyntax, abstractSyntax);
        throw AssociationRejectedError(describe(peer) + " does not accept " + name);
    }
    return id;
}

void fail(const OFCondition& cond, const Node& peer, const std::string& what) {
    const std::string text = cond.text() != nullptr ? cond.text() : "unknown error";
    const std::string where = describe(peer) + ": " + what + " failed: ";
    // A TLS read or write that did not complete within the socket's timeout
    // (OpenSSL's WANT_READ / WANT_WRITE on a blocking socket): the peer did
    // not answer, which says nothing about certificates.
    if (contains(text, "SSL_ERROR_WANT_READ") || contains(text, "SSL_ERROR_WANT_WRITE")) {
        throw TimeoutError(where + "no answer in time (" + text + ")");
    }
    if (cond.module() == OFM_dcmtls || contains(text, "TLS") || contains(text, "SSL") ||
        contains(text, "certificate")) {
        throw TlsError(where + "TLS failed (" + text + ")");
    }
    if (cond == DUL_ASSOCIATIONREJECTED) {
        throw AssociationRejectedError(
            where +
            "the peer rejected the association (is our AE title known to it, "
            "and is its called AE title right?)");
    }
    if (cond == NET_EC_NoAcceptablePresentationContexts) {
        throw AssociationRejectedError(where + "the peer accepts none of the proposed services");
    }
    if (cond == DUL_READTIMEOUT || cond == DIMSE_NODATAAVAILABLE || contains(text, "timed out") ||
        contains(text, "Timeout") || contains(text, "timeout")) {
        throw TimeoutError(where + "no answer in time (" + text + ")");
    }
    if (cond.code() == DULC_TCPINITERROR || contains(text, "refused") ||
        contains(text, "Unknown Host") || contains(text, "unreachable")) {
        throw ConnectionRefusedError(where + "cannot connect (" + text + ")");
    }
    // The connection went in the middle of a message too (a killed peer
    // shows as a failed send of our response as often as an abort).
    if (cond == DUL_PEERABORTEDASSOCIATION || cond == DUL_NETWORKCLOSED ||
        cond == DUL_PEERREQUESTEDRELEASE || cond == DIMSE_SENDFAILED ||
        cond == DIMSE_RECEIVEFAILED || cond == DIMSE_READPDVFAILED) {
        throw ConnectionClosedError(where + "the peer closed the connection (" + text + ")");
    }
    throw PeerFailedError(where + text);
}

void release(DcmSCU& scu) noexcept {
    if (scu.isConnected()) {
        scu.releaseAssociation();
    }
}

void checkStatus(Uint16 status, const Node& peer, const std::string& what) {
    const bool ok = status == STATUS_Success || status == STATUS_Pending ||
                    status == STATUS_FIND_Pending_WarningUnsupportedOptionalKeys ||
                    (status & 0xF000) == 0xB000;
    if (!ok) {
        throw PeerFailedError(describe(peer) + ": " + what + " failed with status " + hex(status));
    }
}

}  // namespace vv::pacs::detail
