// SPDX-License-Identifier: GPL-3.0-or-later
#include "gui/pacs/NetworkFailure.h"

#include <QCoreApplication>
#include <QLocale>

#include "vv/core/Error.h"
#include "vv/pacs/PacsError.h"

namespace vv::gui {

NetworkFailure classifyFailure(const std::exception_ptr& error) noexcept {
    using Kind = NetworkFailure::Kind;
    if (!error) {
        return {};
    }
    try {
        std::rethrow_exception(error);
    } catch (const pacs::ConnectionRefusedError& e) {
        return {Kind::Refused, e.what(), std::nullopt};
    } catch (const pacs::AssociationRejectedError& e) {
        return {Kind::AssociationRejected, e.what(), std::nullopt};
    } catch (const pacs::TimeoutError& e) {
        return {Kind::Timeout, e.what(), e.transfer()};
    } catch (const pacs::TlsError& e) {
        return {Kind::Tls, e.what(), e.transfer()};
    } catch (const pacs::ConnectionClosedError& e) {
        return {Kind::ConnectionClosed, e.what(), e.transfer()};
    } catch (const pacs::PeerFailedError& e) {
        return {Kind::PeerFailed, e.what(), e.transfer()};
    } catch (const pacs::TooManyMatchesError& e) {
        NetworkFailure failure{Kind::TooManyMatches, e.what(), e.transfer()};
        failure.matchLimit = e.limit();
        return failure;
    } catch (const pacs::ResponseError& e) {
        return {Kind::Response, e.what(), e.transfer()};
    } catch (const CancelledError& e) {
        return {Kind::Cancelled, e.what(), std::nullopt};
    } catch (const InvalidArgumentError& e) {
        return {Kind::InvalidInput, e.what(), std::nullopt};
    } catch (const std::exception& e) {
        return {Kind::Other, e.what(), std::nullopt};
    } catch (...) {
        return {Kind::Other, "unknown error", std::nullopt};
    }
}

QString nodeText(const QString& nodeName, const pacs::Node& node) {
    const QString address = QString::fromStdString(pacs::describe(node));
    return nodeName.isEmpty() ? address
                              : QCoreApplication::translate("vv::gui::NetworkFailure", "%1 (%2)",
                                                            "node name (AE@host:port)")
                                    .arg(nodeName, address);
}

namespace {

/// The summary of failureText(): `peer` is nodeText().
QString failureSummary(const NetworkFailure& failure, const QString& peer) {
    using Kind = NetworkFailure::Kind;
    switch (failure.kind) {
        case Kind::None:
            return QCoreApplication::translate("vv::gui::NetworkFailure", "%1 answered.").arg(peer);
        case Kind::Refused:
            return QCoreApplication::translate(
                       "vv::gui::NetworkFailure",
                       "%1 refused the connection: nobody listens there. Check the host name and "
                       "port, and that the PACS is running and the firewall lets the port through.")
                .arg(peer);
        case Kind::AssociationRejected:
            return QCoreApplication::translate(
                       "vv::gui::NetworkFailure",
                       "%1 rejected the association. Check the node's AE title, and that the PACS "
                       "knows our AE title, host and port.")
                .arg(peer);
        case Kind::Timeout:
            return QCoreApplication::translate(
                       "vv::gui::NetworkFailure",
                       "%1 did not answer in time. Check the host and port, the network and the "
                       "firewall; the PACS may be overloaded.")
                .arg(peer);
        case Kind::Tls:
            return QCoreApplication::translate(
                       "vv::gui::NetworkFailure",
                       "The TLS connection to %1 failed. Check that the node speaks TLS on this "
                       "port, the trusted CA certificate and our certificate and key files.")
                .arg(peer);
        case Kind::PeerFailed:
            return QCoreApplication::translate(
                       "vv::gui::NetworkFailure",
                       "%1 reported a failure and did not complete the request. Try again; if "
                       "it keeps happening, ask the PACS administrator.")
                .arg(peer);
        case Kind::ConnectionClosed:
            return QCoreApplication::translate(
                       "vv::gui::NetworkFailure",
                       "%1 closed the connection. Try again; if it keeps happening, check that "
                       "the PACS knows our AE title, host and port, or ask the PACS "
                       "administrator.")
                .arg(peer);
        case Kind::TooManyMatches:
            return QCoreApplication::translate(
                       "vv::gui::NetworkFailure",
                       "%1 has more than %2 matches for this search. Narrow the search (patient "
                       "name or ID, study date).")
                .arg(peer, QLocale().toString(static_cast<qulonglong>(failure.matchLimit)));
        case Kind::Response:
            return QCoreApplication::translate(
                       "vv::gui::NetworkFailure",
                       "The answer of %1 was refused: it breaks the DICOM standard or holds "
                       "oversized values. Narrow the search; if it keeps happening, ask the PACS "
                       "administrator.")
                .arg(peer);
        case Kind::InvalidInput:
            return QCoreApplication::translate(
                       "vv::gui::NetworkFailure",
                       "Nothing was asked of %1: a value is not valid in DICOM (a search field "
                       "holds a backslash or more than 64 characters, or a date is not valid). "
                       "Correct it and try again.")
                .arg(peer);
        case Kind::Cancelled:
            return QCoreApplication::translate("vv::gui::NetworkFailure", "Cancelled.");
        case Kind::Other:
            break;
    }
    return QCoreApplication::translate(
               "vv::gui::NetworkFailure",
               "The request to %1 failed unexpectedly. Try again; if it keeps happening, give "
               "the details to the administrator.")
        .arg(peer);
}

}  // namespace

ProblemText failureText(const NetworkFailure& failure, const QString& nodeName,
                        const pacs::Node& node) {
    ProblemText text;
    text.summary = failureSummary(failure, nodeText(nodeName, node));
    if (failure.kind != NetworkFailure::Kind::None &&
        failure.kind != NetworkFailure::Kind::Cancelled) {
        text.details = QString::fromStdString(failure.detail);
    }
    return text;
}

namespace {

/// What ended a transfer, as the end of "The transfer … stopped …: <cause>."
/// (empty: a kind that does not come from a transfer).
QString transferCause(NetworkFailure::Kind kind) {
    using Kind = NetworkFailure::Kind;
    switch (kind) {
        case Kind::ConnectionClosed:
            return QCoreApplication::translate("vv::gui::NetworkFailure",
                                               "the PACS closed the connection");
        case Kind::Timeout:
            return QCoreApplication::translate("vv::gui::NetworkFailure",
                                               "the PACS stopped answering");
        case Kind::PeerFailed:
            return QCoreApplication::translate("vv::gui::NetworkFailure",
                                               "the PACS reported images it could not send");
        case Kind::Tls:
            return QCoreApplication::translate("vv::gui::NetworkFailure",
                                               "the secure connection failed");
        case Kind::Response:
        case Kind::TooManyMatches:
            return QCoreApplication::translate(
                "vv::gui::NetworkFailure",
                "the PACS sent an answer that breaks the DICOM standard");
        case Kind::None:
        case Kind::Refused:
        case Kind::AssociationRejected:
        case Kind::InvalidInput:
        case Kind::Cancelled:
        case Kind::Other:
            break;
    }
    return {};
}

}  // namespace

ProblemText retrieveFailureText(const NetworkFailure& failure, const QString& nodeName,
                                const pacs::Node& node, std::optional<std::size_t> kept) {
    const QString cause = transferCause(failure.kind);
    if (!failure.transfer || cause.isEmpty()) {
        return failureText(failure, nodeName, node);
    }
    const pacs::TransferProgress& transfer = *failure.transfer;
    const QLocale locale;
    const int received = static_cast<int>(transfer.received);  // plain ints for lupdate's %n
    const int keptCount = static_cast<int>(kept.value_or(0));
    const QString when =
        transfer.received == 0 ? QCoreApplication::translate("vv::gui::NetworkFailure",
                                                             "before the first image arrived")
        : transfer.expected && *transfer.expected >= transfer.received
            ? QCoreApplication::translate("vv::gui::NetworkFailure", "after %1 of %2 images")
                  .arg(locale.toString(static_cast<qulonglong>(transfer.received)),
                       locale.toString(static_cast<qulonglong>(*transfer.expected)))
            : QCoreApplication::translate("vv::gui::NetworkFailure", "after %n image(s)", nullptr,
                                          received);
    const QString name =
        nodeName.isEmpty() ? QString::fromStdString(pacs::describe(node)) : nodeName;
    QString keptText;
    if (kept) {
        keptText =
            *kept == 0
                ? QCoreApplication::translate("vv::gui::NetworkFailure", "Nothing was kept.") +
                      QLatin1Char(' ')
                : QCoreApplication::translate(
                      "vv::gui::NetworkFailure",
                      "%n image(s) of it were kept in the local study store.", nullptr, keptCount) +
                      QLatin1Char(' ');
    }
    ProblemText text;
    text.summary = QCoreApplication::translate(
                       "vv::gui::NetworkFailure",
                       "The transfer from %1 stopped %2: %3. %4Try again, or ask the PACS "
                       "administrator if it keeps happening.")
                       .arg(name, when, cause, keptText);
    text.details = QString::fromStdString(failure.detail);
    return text;
}

QString portText(int port) {
    QLocale locale;
    locale.setNumberOptions(QLocale::OmitGroupSeparator);
    return locale.toString(port);
}

}  // namespace vv::gui
