// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// The typed failures of DICOM networking. Every one names the peer
// ("AE@host:port") and what failed; none carries patient data.

#include <cstddef>
#include <optional>
#include <string>

#include "vv/core/Error.h"

namespace vv::pacs {

/// How far a transfer had come when it failed.
struct TransferProgress {
    /// Instances received: C-GET: those in the store transaction (which the
    /// failure discards); C-MOVE: the sub-operations the peer reported done.
    std::size_t received = 0;
    /// All instances of the transfer, when the peer said (its last pending
    /// response's completed + failed + warning + remaining sub-operations).
    std::optional<std::size_t> expected;
};

/// Root of the networking failures: the peer refused or failed
/// (`vesselview-cli pacs` exits with 5 for every one of them).
class NetworkError : public Error {
  public:
    using Error::Error;
    /// A retrieve (getInto, moveTo) that failed once its request was sent:
    /// how far it had come. Nullopt for every other failure.
    [[nodiscard]] const std::optional<TransferProgress>& transfer() const noexcept {
        return transfer_;
    }
    void setTransfer(const TransferProgress& transfer) noexcept { transfer_ = transfer; }

  private:
    std::optional<TransferProgress> transfer_;
};

/// Nobody listens at host:port (TCP connection refused), or the host is unknown
/// or unreachable.
class ConnectionRefusedError : public NetworkError {
    using NetworkError::NetworkError;
};

/// The peer answered but rejected the association: our AE title is not known
/// to it, the called AE title is wrong, or it accepts none of the proposed
/// presentation contexts. The message gives the peer's reason when it sent one.
class AssociationRejectedError : public NetworkError {
    using NetworkError::NetworkError;
};

/// A network wait ran out (connect, association, a response).
class TimeoutError : public NetworkError {
    using NetworkError::NetworkError;
};

/// TLS failed: our certificate files cannot be read, the handshake failed, or
/// the peer's certificate does not chain to the trusted certificates.
class TlsError : public NetworkError {
    using NetworkError::NetworkError;
};

/// The peer aborted, closed the connection or answered with a failure status.
class PeerFailedError : public NetworkError {
    using NetworkError::NetworkError;
};

/// The peer aborted the association or the connection closed while we
/// waited for it (DCMTK says "Peer aborted Association (or never connected)"
/// even after many messages): a PeerFailedError without a status.
class ConnectionClosedError : public PeerFailedError {
    using PeerFailedError::PeerFailedError;
};

/// A response broke our limits or the standard: too many results, an
/// oversized or malformed attribute.
class ResponseError : public NetworkError {
    using NetworkError::NetworkError;
};

/// A C-FIND matched more than our limit (FindLimits::maxResults): the
/// search was cancelled; a narrower one may succeed.
class TooManyMatchesError : public ResponseError {
  public:
    TooManyMatchesError(const std::string& message, std::size_t limit)
        : ResponseError(message), limit_(limit) {}
    /// The limit the matches exceeded.
    [[nodiscard]] std::size_t limit() const noexcept { return limit_; }

  private:
    std::size_t limit_;
};

}  // namespace vv::pacs
