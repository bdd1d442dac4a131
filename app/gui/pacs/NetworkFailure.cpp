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
        return {Kind::Refused, e.what()};
    } catch (const pacs::AssociationRejectedError& e) {
        return {Kind::AssociationRejected, e.what()};
    } catch (const pacs::TimeoutError& e) {
        return {Kind::Timeout, e.what()};
    } catch (const pacs::TlsError& e) {
        return {Kind::Tls, e.what()};
    } catch (const pacs::PeerFailedError& e) {
        return {Kind::PeerFailed, e.what()};
    } catch (const pacs::ResponseError& e) {
        return {Kind::Response, e.what()};
    } catch (const CancelledError& e) {
        return {Kind::Cancelled, e.what()};
    } catch (const InvalidArgumentError& e) {
        return {Kind::InvalidInput, e.what()};
    } catch (const std::exception& e) {
        return {Kind::Other, e.what()};
    } catch (...) {
        return {Kind::Other, "unknown error"};
    }
}

QString failureText(const NetworkFailure& failure, const pacs::Node& node) {
    using Kind = NetworkFailure::Kind;
    const QString peer = QString::fromStdString(pacs::describe(node));
    const QString detail = QString::fromStdString(failure.detail);
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
            return QCoreApplication::translate("vv::gui::NetworkFailure",
                                               "%1 stopped or failed during the transfer (%2).")
                .arg(peer, detail);
        case Kind::Response:
            return QCoreApplication::translate(
                       "vv::gui::NetworkFailure",
                       "The answer of %1 was refused (%2). Narrow the search.")
                .arg(peer, detail);
        case Kind::InvalidInput:
            return QCoreApplication::translate("vv::gui::NetworkFailure", "Invalid input: %1")
                .arg(detail);
        case Kind::Cancelled:
            return QCoreApplication::translate("vv::gui::NetworkFailure", "Cancelled.");
        case Kind::Other:
            break;
    }
    return QCoreApplication::translate("vv::gui::NetworkFailure", "Failed with %1: %2")
        .arg(peer, detail);
}

QString portText(int port) {
    QLocale locale;
    locale.setNumberOptions(QLocale::OmitGroupSeparator);
    return locale.toString(port);
}

}  // namespace vv::gui
