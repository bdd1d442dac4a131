// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// What went wrong in a DICOM network operation, as the GUI tells the user:
// the typed errors of vv/pacs/PacsError.h (caught on a worker) become a kind
// and, on the GUI thread, one translated sentence that names the node
// (AE@host:port) and what to check. No patient data is ever part of it.

#include <QString>
#include <exception>
#include <string>
#include <type_traits>
#include <utility>

#include "vv/pacs/Node.h"

namespace vv::gui {

struct NetworkFailure {
    enum class Kind {
        None,                 ///< it worked
        Refused,              ///< ConnectionRefusedError: nobody listens / host unknown
        AssociationRejected,  ///< AssociationRejectedError: AE titles not known to the peer
        Timeout,              ///< TimeoutError
        Tls,                  ///< TlsError
        PeerFailed,           ///< PeerFailedError: aborted, closed, failure status
        Response,             ///< ResponseError: too many matches, malformed answer
        InvalidInput,         ///< InvalidArgumentError: a malformed key or node
        Cancelled,            ///< CancelledError: the user stopped it
        Other,                ///< anything else (IoError of the store, ...)
    };
    Kind kind = Kind::None;
    std::string detail;  ///< the exception's message (English, no patient data)
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

/// A port number as a person reads it: the UI locale's digits, no group separator.
[[nodiscard]] QString portText(int port);

}  // namespace vv::gui
