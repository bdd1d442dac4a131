// SPDX-License-Identifier: GPL-3.0-or-later
#include "gui/pacs/ListenerService.h"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <QLocale>
#include <cerrno>
#include <utility>

#include "vv/core/Error.h"
#include "vv/pacs/LocalStore.h"
#include "vv/pacs/PacsError.h"
#include "vv/pacs/StorageScp.h"

namespace vv::gui {
namespace {

constexpr int kPollMs = 250;

/// True when another socket holds `port` on `address` (IPv4): a bind fails
/// with EADDRINUSE. Only asked after the listener could not open the port.
bool portInUse(const std::string& address, std::uint16_t port) {
    const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
    if (fd < 0) {
        return false;
    }
    int reuse = 1;
    ::setsockopt(fd, SOL_SOCKET, SO_REUSEADDR, &reuse, sizeof reuse);
    sockaddr_in where{};
    where.sin_family = AF_INET;
    where.sin_port = htons(port);
    const bool parsed = ::inet_pton(AF_INET, address.c_str(), &where.sin_addr) == 1;
    // NOLINTNEXTLINE(cppcoreguidelines-pro-type-reinterpret-cast): the sockets API
    const bool inUse = parsed &&
                       ::bind(fd, reinterpret_cast<const sockaddr*>(&where), sizeof where) != 0 &&
                       errno == EADDRINUSE;
    ::close(fd);
    return inUse;
}

/// What the listener runs on, as one comparable string (no patient data).
std::string runKey(const PacsSettings& s) {
    std::string key = s.me.aeTitle + '\n' + s.listenerBindAddress + '\n' +
                      std::to_string(s.listenerPort) + '\n' + s.storeFolder.string();
    const pacs::ListenerLimits& l = s.listenerLimits;
    for (const std::uint64_t limit :
         {std::uint64_t(l.maxAssociations), std::uint64_t(l.maxConnectionsPerAddress),
          std::uint64_t(l.maxConnections), std::uint64_t(l.requestSeconds), l.maxInstanceBytes,
          l.maxAssociationBytes}) {
        key += ' ' + std::to_string(limit);
    }
    const pacs::TlsSettings& tls = s.listenerTls;
    if (tls.enabled) {
        key += "\ntls\n" + tls.certificate.string() + '\n' + tls.privateKey.string() + '\n' +
               tls.trustedCertificates.string();
    }
    for (const PacsNode& node : s.nodes) {
        if (node.allowPush) {
            key += '\n' + node.node.aeTitle + '@' + node.node.host;
        }
    }
    return key;
}

}  // namespace

ListenerService::ListenerService(QObject* parent) : QObject(parent) {
    poll_.setInterval(kPollMs);
    connect(&poll_, &QTimer::timeout, this, &ListenerService::poll);
}

ListenerService::~ListenerService() = default;

QString ListenerService::stateText() const {
    switch (state_) {
        case State::Running:
            return tr("DICOM listener: port %1").arg(detail_);
        case State::Failed:
            return tr("DICOM listener failed: %1").arg(detail_);
        case State::Stopped:
            break;
    }
    return tr("DICOM listener off");
}

void ListenerService::apply(const vv::gui::PacsSettings& settings) {
    const bool newStore = storeFolder_ != settings.storeFolder;
    storeFolder_ = settings.storeFolder;
    if (newStore) {
        emit storeChanged();
    }
    const std::string key = settings.listenerEnabled ? runKey(settings) : std::string();
    if (state_ == State::Running && key == runningKey_) {
        store_->setSizeLimit(settings.storeLimitBytes);  // from its next commit on
        return;
    }
    stop();
    if (settings.listenerEnabled) {
        start(settings);
    } else {
        setState(State::Stopped, QString());
    }
}

void ListenerService::stop() {
    poll_.stop();
    poll();  // what was committed before the stop still counts
    scp_.reset();
    store_.reset();
    runningKey_.clear();
    committed_ = 0;
    refused_ = 0;
}

void ListenerService::start(const PacsSettings& settings) {
    const QString where = QString::fromStdString(settings.listenerBindAddress);
    const QString port = QLocale::c().toString(settings.listenerPort);  // a port, not a number
    try {
        store_ = std::make_unique<pacs::LocalStore>(openStore(settings));
    } catch (const Error&) {
        setState(State::Failed, tr("the study store %1 cannot be opened")
                                    .arg(QString::fromStdString(settings.storeFolder.string())));
        return;
    }
    pacs::ListenerConfig config;
    config.aeTitle = settings.me.aeTitle;
    config.port = settings.listenerPort;
    config.bindAddress = settings.listenerBindAddress;
    config.timeouts = settings.me.timeouts;
    config.tls = settings.listenerTls;
    config.limits = settings.listenerLimits;
    for (const PacsNode& node : settings.nodes) {
        if (node.allowPush) {
            config.allowedPeers.push_back(node.node);
        }
    }
    try {
        scp_ = std::make_unique<pacs::StorageScp>(*store_, std::move(config));
    } catch (const pacs::TlsError&) {
        store_.reset();
        setState(State::Failed, tr("TLS is on, but our certificate, its key or the trusted CA "
                                   "certificates cannot be read or do not match"));
        return;
    } catch (const Error&) {
        store_.reset();
        setState(State::Failed, portInUse(settings.listenerBindAddress, settings.listenerPort)
                                    ? tr("port %1 is in use by another program").arg(port)
                                    : tr("cannot listen on %1, port %2").arg(where, port));
        return;
    }
    runningKey_ = runKey(settings);
    poll_.start();
    setState(State::Running, settings.listenerTls.enabled ? tr("%1 (TLS)").arg(port) : port);
}

void ListenerService::setState(State state, QString detail) {
    if (state == state_ && detail == detail_) {
        return;
    }
    state_ = state;
    detail_ = std::move(detail);
    emit stateChanged(state_, stateText());
}

void ListenerService::poll() {
    if (!scp_) {
        return;
    }
    const pacs::ListenerStats stats = scp_->stats();
    refused_ = stats.refusedAssociations;
    if (stats.committedInstances != committed_) {
        committed_ = stats.committedInstances;
        emit studiesChanged();
    }
}

}  // namespace vv::gui
