// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// What went wrong in a DICOM network operation, as the GUI tells the user:
// the typed errors of vv/pacs/PacsError.h (caught on a worker) become a kind
// and, on the GUI thread, one translated sentence that names the node
// (AE@host:port) and what to check. No patient data is ever part of it.

#include <QString>
#include <cstddef>
#include <exception>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>

#include "vv/pacs/Node.h"
#include "vv/pacs/PacsError.h"

namespace vv::gui {

struct NetworkFailure {
    enum class Kind {
        None,                 ///< it worked
        Refused,              ///< ConnectionRefusedError: nobody listens / host unknown
        AssociationRejected,  ///< AssociationRejectedError: AE titles not known to the peer
        Timeout,              ///< TimeoutError
        Tls,                  ///< TlsError
        PeerFailed,           ///< PeerFailedError: a failure status, no final answer
        ConnectionClosed,     ///< ConnectionClosedError: the peer aborted or closed
        Response,             ///< ResponseError: too many matches, malformed answer
        InvalidInput,         ///< InvalidArgumentError: a malformed key or node
        Cancelled,            ///< CancelledError: the user stopped it
        Other,                ///< anything else (IoError of the store, ...)
    };
    Kind kind = Kind::None;
    std::string detail;  ///< the exception's message (English, no patient data)
    /// A retrieve that failed once its transfer began: how far it had come.
    std::optional<pacs::TransferProgress> transfer;
};

/// Classifies the exception `error` (call it inside a catch block or with a
/// stored exception_ptr); never throws.
[[nodiscard]] NetworkFailure classifyFailure(const std::exception_ptr& error) noexcept;

/// Runs `call()` (on a worker): for a call returning void, the failure
/// (Kind::None when it worked); else the result and the failure, the result
/// value-initialised when it failed. Never throws.
template <typename Call>
[[nodiscard]] auto tryNetwork(Call call) noexcept {
    using Result = std::invoke_result_t<Call>;
    if constexpr (std::is_void_v<Result>) {
        try {
            call();
            return NetworkFailure{};
        } catch (...) {
            return classifyFailure(std::current_exception());
        }
    } else {
        std::pair<Result, NetworkFailure> answer;
        try {
            answer.first = call();
        } catch (...) {
            answer.second = classifyFailure(std::current_exception());
        }
        return answer;
    }
}

/// The translated message for `failure` with `node` ("Radiology PACS"'s
/// AE@host:port): what failed and what to check.
[[nodiscard]] QString failureText(const NetworkFailure& failure, const pacs::Node& node);

/// The translated message for a retrieve from the node the user calls
/// `nodeName` that failed with `failure`. Once its transfer had begun
/// (failure.transfer), one plain statement: what happened and how far it
/// came ("The transfer from ORTHANC stopped after 60 of 400 images: the PACS
/// closed the connection."), what the local study store kept of it (`kept`
/// images: "Nothing was kept."; nullopt: unknown, not said), and what to
/// do; the technical detail is
/// left to the caller (a tooltip, the log). Before that (no connection, a
/// rejected association, …): failureText(failure, node).
[[nodiscard]] QString retrieveFailureText(const NetworkFailure& failure, const QString& nodeName,
                                          const pacs::Node& node, std::optional<std::size_t> kept);

/// A port number as a person reads it: the UI locale's digits, no group separator.
[[nodiscard]] QString portText(int port);

}  // namespace vv::gui
