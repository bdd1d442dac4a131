// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// What went wrong in a DICOM network operation, as the GUI tells the user:
// the typed errors of vv/pacs/PacsError.h (caught on a worker) become a kind
// and, on the GUI thread, a ProblemText: one sentence in the UI language that
// says what happened, names the node (as the user named it, and its
// AE@host:port) and what to do; the module's English detail apart (a
// tooltip, a message box's Details). No patient data is ever part of it.

#include <QString>
#include <cstddef>
#include <exception>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>

#include "gui/EngineTexts.h"
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
        TooManyMatches,       ///< TooManyMatchesError: more matches than matchLimit
        Response,             ///< ResponseError: a malformed or oversized answer
        InvalidInput,         ///< InvalidArgumentError: a malformed key or node
        Cancelled,            ///< CancelledError: the user stopped it
        Other,                ///< anything else (IoError of the store, ...)
    };
    Kind kind = Kind::None;
    std::string detail;  ///< the exception's message (English, no patient data)
    /// A retrieve that failed once its transfer began: how far it had come.
    std::optional<pacs::TransferProgress> transfer;
    std::size_t matchLimit = 0;  ///< Kind::TooManyMatches: the limit exceeded
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

/// The node as the messages name it: "Radiology PACS (PACS1@pacs.example:4242)";
/// its AE@host:port alone when `nodeName` is empty.
[[nodiscard]] QString nodeText(const QString& nodeName, const pacs::Node& node);

/// `failure` of a call to the node the user calls `nodeName` (`node`): as
/// summary, what failed, naming the node (nodeText()), and what to check or
/// do, in the UI language ("more than 2,000 matches" with the UI locale's
/// digits); as details, the module's English message (empty for None and
/// Cancelled). Never one English sentence inside the summary.
[[nodiscard]] ProblemText failureText(const NetworkFailure& failure, const QString& nodeName,
                                      const pacs::Node& node);

/// `failure` of a retrieve from the node the user calls `nodeName`. Once its
/// transfer had begun (failure.transfer), the summary is one plain
/// statement: what happened and how far it came ("The transfer from ORTHANC
/// stopped after 60 of 400 images: the PACS closed the connection."), what
/// the local study store kept of it (`kept` images: "Nothing was kept.";
/// nullopt: unknown, not said), and what to do. Before that (no
/// connection, a rejected association, …): failureText(). The details are
/// the module's English message.
[[nodiscard]] ProblemText retrieveFailureText(const NetworkFailure& failure,
                                              const QString& nodeName, const pacs::Node& node,
                                              std::optional<std::size_t> kept);

/// A port number as a person reads it: the UI locale's digits, no group separator.
[[nodiscard]] QString portText(int port);

}  // namespace vv::gui
