// SPDX-License-Identifier: GPL-3.0-or-later
#include "PacsSettings.h"

#include <QFile>
#include <QSettings>
#include <QStandardPaths>
#include <QString>
#include <functional>
#include <set>
#include <string>
#include <system_error>

#include "vv/core/Error.h"
#include "vv/pacs/StorageScp.h"

namespace vv::gui {
namespace {

std::string text(const QSettings& store, const QString& key, const std::string& fallback) {
    const QVariant value = store.value(key);
    return value.isValid() ? value.toString().toStdString() : fallback;
}

bool validPort(int port) {
    return port > 0 && port <= kMaxPort;
}

/// The whole number at `key` when it is one within lo..hi, else `fallback`.
int wholeNumber(const QSettings& store, const QString& key, int lo, int hi, int fallback) {
    bool ok = false;
    const int value = store.value(key).toString().toInt(&ok);
    return ok && value >= lo && value <= hi ? value : fallback;
}

/// The byte count at `key` when it is one of at least `least`, else `fallback`.
std::uint64_t byteCount(const QSettings& store, const QString& key, std::uint64_t least,
                        std::uint64_t fallback) {
    bool ok = false;
    const qulonglong value = store.value(key).toString().toULongLong(&ok);  // never "-1"
    return ok && value >= least ? value : fallback;
}

std::uint16_t port(const QSettings& store, const QString& key, std::uint16_t fallback) {
    return static_cast<std::uint16_t>(wholeNumber(store, key, 1, kMaxPort, fallback));
}

/// False when `check` throws InvalidArgumentError.
bool passes(const std::function<void()>& check) {
    try {
        check();
        return true;
    } catch (const InvalidArgumentError&) {
        return false;
    }
}

/// The listener's limits under "pacs/listener/": each out of its own range
/// skipped; limits that do not fit together skipped together, never one of
/// them guessed (first the connection limits, then the size caps).
pacs::ListenerLimits readLimits(const QSettings& store) {
    const pacs::ListenerLimits defaults;
    const auto key = [](const char* name) {
        return QStringLiteral("pacs/listener/") + QLatin1String(name);
    };
    pacs::ListenerLimits l;
    l.maxAssociations =
        wholeNumber(store, key("maxAssociations"), 1, pacs::ListenerLimits::kMaxAssociations,
                    defaults.maxAssociations);
    l.maxConnectionsPerAddress =
        wholeNumber(store, key("maxConnectionsPerAddress"), 1,
                    pacs::ListenerLimits::kMaxConnections, defaults.maxConnectionsPerAddress);
    l.maxConnections = wholeNumber(store, key("maxConnections"), 1,
                                   pacs::ListenerLimits::kMaxConnections, defaults.maxConnections);
    l.requestSeconds =
        wholeNumber(store, key("requestSeconds"), 1, pacs::ListenerLimits::kMaxRequestSeconds,
                    defaults.requestSeconds);
    l.maxInstanceBytes =
        byteCount(store, key("maxInstanceBytes"), pacs::ListenerLimits::kMinInstanceBytes,
                  defaults.maxInstanceBytes);
    l.maxAssociationBytes =
        byteCount(store, key("maxAssociationBytes"), pacs::ListenerLimits::kMinInstanceBytes,
                  defaults.maxAssociationBytes);
    pacs::ListenerLimits connections = l;
    connections.maxInstanceBytes = defaults.maxInstanceBytes;
    connections.maxAssociationBytes = defaults.maxAssociationBytes;
    if (!passes([&] { connections.validate(); })) {
        l.maxAssociations = defaults.maxAssociations;
        l.maxConnectionsPerAddress = defaults.maxConnectionsPerAddress;
        l.maxConnections = defaults.maxConnections;
    }
    if (!passes([&] { l.validate(); })) {
        l.maxInstanceBytes = defaults.maxInstanceBytes;
        l.maxAssociationBytes = defaults.maxAssociationBytes;
    }
    return passes([&] { l.validate(); }) ? l : defaults;  // a rule added to validate()
}

void writeLimits(const pacs::ListenerLimits& l, QSettings& store) {
    store.setValue(QStringLiteral("pacs/listener/maxAssociations"), l.maxAssociations);
    store.setValue(QStringLiteral("pacs/listener/maxConnectionsPerAddress"),
                   l.maxConnectionsPerAddress);
    store.setValue(QStringLiteral("pacs/listener/maxConnections"), l.maxConnections);
    store.setValue(QStringLiteral("pacs/listener/requestSeconds"), l.requestSeconds);
    store.setValue(QStringLiteral("pacs/listener/maxInstanceBytes"),
                   qulonglong{l.maxInstanceBytes});
    store.setValue(QStringLiteral("pacs/listener/maxAssociationBytes"),
                   qulonglong{l.maxAssociationBytes});
}

/// TLS settings under `prefix` ("…/tls/"): enabled, trusted, certificate, privateKey.
pacs::TlsSettings readTls(const QSettings& store, const QString& prefix) {
    pacs::TlsSettings tls;
    tls.enabled = store.value(prefix + QStringLiteral("enabled"), false).toBool();
    tls.trustedCertificates = text(store, prefix + QStringLiteral("trusted"), {});
    tls.certificate = text(store, prefix + QStringLiteral("certificate"), {});
    tls.privateKey = text(store, prefix + QStringLiteral("privateKey"), {});
    return tls;
}

void writeTls(const pacs::TlsSettings& tls, const QString& prefix, QSettings& store) {
    store.setValue(prefix + QStringLiteral("enabled"), tls.enabled);
    store.setValue(prefix + QStringLiteral("trusted"),
                   QString::fromStdString(tls.trustedCertificates.string()));
    store.setValue(prefix + QStringLiteral("certificate"),
                   QString::fromStdString(tls.certificate.string()));
    store.setValue(prefix + QStringLiteral("privateKey"),
                   QString::fromStdString(tls.privateKey.string()));
}

/// How long we wait for a node, under "pacs/timeouts/": each out of range skipped.
pacs::Timeouts readTimeouts(const QSettings& store) {
    pacs::Timeouts t;
    t.connectSeconds = wholeNumber(store, QStringLiteral("pacs/timeouts/connectSeconds"), 1,
                                   kMaxTimeoutSeconds, t.connectSeconds);
    t.associateSeconds = wholeNumber(store, QStringLiteral("pacs/timeouts/associateSeconds"), 1,
                                     kMaxTimeoutSeconds, t.associateSeconds);
    t.responseSeconds = wholeNumber(store, QStringLiteral("pacs/timeouts/responseSeconds"), 1,
                                    kMaxTimeoutSeconds, t.responseSeconds);
    return t;
}

void writeTimeouts(const pacs::Timeouts& t, QSettings& store) {
    store.setValue(QStringLiteral("pacs/timeouts/connectSeconds"), t.connectSeconds);
    store.setValue(QStringLiteral("pacs/timeouts/associateSeconds"), t.associateSeconds);
    store.setValue(QStringLiteral("pacs/timeouts/responseSeconds"), t.responseSeconds);
}

void checkBeforeWriting(const PacsSettings& settings) {
    using Setting = PacsSettingsError::Setting;
    try {
        pacs::validateAeTitle(settings.me.aeTitle);
    } catch (const InvalidArgumentError& e) {
        throw PacsSettingsError(Setting::OurAeTitle, {}, std::string("our AE title: ") + e.what());
    }
    if (settings.listenerPort == 0) {
        throw PacsSettingsError(Setting::ListenerPort, {}, "listener port: must be 1 to 65535");
    }
    const pacs::TlsSettings& tls = settings.listenerTls;
    if (tls.enabled &&
        (tls.certificate.empty() || tls.privateKey.empty() || tls.trustedCertificates.empty())) {
        throw PacsSettingsError(Setting::ListenerTls, {},
                                "listener TLS: needs our certificate, its private key and the "
                                "trusted CA certificate(s)");
    }
    try {
        settings.listenerLimits.validate();
    } catch (const InvalidArgumentError& e) {
        throw PacsSettingsError(Setting::ListenerLimits, {}, e.what());
    }
    const pacs::Timeouts& t = settings.me.timeouts;
    for (const int seconds : {t.connectSeconds, t.associateSeconds, t.responseSeconds}) {
        if (seconds < 1 || seconds > kMaxTimeoutSeconds) {
            throw PacsSettingsError(
                Setting::Timeouts, {},
                "timeouts: each must be 1 to " + std::to_string(kMaxTimeoutSeconds) + " s");
        }
    }
    std::set<std::string> names;
    for (const PacsNode& node : settings.nodes) {
        if (node.name.empty()) {
            throw PacsSettingsError(Setting::NodeName, {}, "a node has no name");
        }
        if (!names.insert(node.name).second) {
            throw PacsSettingsError(Setting::NodeName, node.name,
                                    "two nodes are called '" + node.name + "'");
        }
        try {
            pacs::validateNode(node.node);
        } catch (const InvalidArgumentError& e) {
            throw PacsSettingsError(Setting::Node, node.name,
                                    "node '" + node.name + "': " + e.what());
        }
    }
}

}  // namespace

std::filesystem::path defaultStoreFolder() {
    namespace fs = std::filesystem;
    // Not AppLocalDataLocation: it adds the organisation and the application
    // name, both "VesselView" (~/.local/share/VesselView/VesselView/studies).
    const fs::path generic =
        QFile::encodeName(QStandardPaths::writableLocation(QStandardPaths::GenericDataLocation))
            .toStdString();
    fs::path folder = generic / "VesselView" / "studies";
    // A store an earlier version made there keeps working where it is.
    fs::path earlier = fs::path(QFile::encodeName(QStandardPaths::writableLocation(
                                                      QStandardPaths::AppLocalDataLocation))
                                    .toStdString()) /
                       "studies";
    std::error_code ec;
    if (!fs::exists(folder, ec) && fs::is_directory(earlier, ec)) {
        return earlier;
    }
    return folder;
}

PacsSettings readPacsSettings(const QSettings& store) {
    PacsSettings s;
    const std::string ae = text(store, QStringLiteral("pacs/aeTitle"), s.me.aeTitle);
    if (passes([&] { pacs::validateAeTitle(ae); })) {
        s.me.aeTitle = ae;
    }
    s.me.timeouts = readTimeouts(store);
    s.listenerEnabled = store.value(QStringLiteral("pacs/listener/enabled"), false).toBool();
    s.listenerPort = port(store, QStringLiteral("pacs/listener/port"), s.listenerPort);
    s.listenerBindAddress =
        text(store, QStringLiteral("pacs/listener/bind"), s.listenerBindAddress);
    s.listenerTls = readTls(store, QStringLiteral("pacs/listener/tls/"));
    s.listenerLimits = readLimits(store);
    const std::string folder = text(store, QStringLiteral("pacs/store/folder"), {});
    s.storeFolder = folder.empty() ? defaultStoreFolder() : std::filesystem::path(folder);
    bool ok = false;
    const qulonglong limit = store.value(QStringLiteral("pacs/store/limitBytes")).toULongLong(&ok);
    s.storeLimitBytes = ok ? limit : 0;

    const int count = store.value(QStringLiteral("pacs/nodes/size"), 0).toInt();
    std::set<std::string> names;
    for (int i = 0; i < count; ++i) {
        const QString key = QStringLiteral("pacs/nodes/%1/").arg(i + 1);
        PacsNode n;
        n.name = text(store, key + QStringLiteral("name"), {});
        n.node.aeTitle = text(store, key + QStringLiteral("aeTitle"), {});
        n.node.host = text(store, key + QStringLiteral("host"), {});
        bool portOk = false;
        const int p = store.value(key + QStringLiteral("port")).toInt(&portOk);
        n.node.port = portOk && validPort(p) ? static_cast<std::uint16_t>(p) : 0;
        n.allowPush = store.value(key + QStringLiteral("allowPush"), true).toBool();
        n.node.tls = readTls(store, key + QStringLiteral("tls/"));
        if (!n.name.empty() && !names.contains(n.name) &&
            passes([&] { pacs::validateNode(n.node); })) {
            names.insert(n.name);
            s.nodes.push_back(std::move(n));
        }
    }
    return s;
}

void writePacsSettings(const PacsSettings& settings, QSettings& store) {
    checkBeforeWriting(settings);
    store.remove(QStringLiteral("pacs"));
    store.setValue(QStringLiteral("pacs/aeTitle"), QString::fromStdString(settings.me.aeTitle));
    writeTimeouts(settings.me.timeouts, store);
    store.setValue(QStringLiteral("pacs/listener/enabled"), settings.listenerEnabled);
    store.setValue(QStringLiteral("pacs/listener/port"), int{settings.listenerPort});
    store.setValue(QStringLiteral("pacs/listener/bind"),
                   QString::fromStdString(settings.listenerBindAddress));
    writeTls(settings.listenerTls, QStringLiteral("pacs/listener/tls/"), store);
    writeLimits(settings.listenerLimits, store);
    store.setValue(QStringLiteral("pacs/store/folder"),
                   QString::fromStdString(settings.storeFolder.string()));
    store.setValue(QStringLiteral("pacs/store/limitBytes"), qulonglong{settings.storeLimitBytes});
    store.setValue(QStringLiteral("pacs/nodes/size"), static_cast<int>(settings.nodes.size()));
    for (std::size_t i = 0; i < settings.nodes.size(); ++i) {
        const PacsNode& n = settings.nodes[i];
        const QString key = QStringLiteral("pacs/nodes/%1/").arg(i + 1);
        store.setValue(key + QStringLiteral("name"), QString::fromStdString(n.name));
        store.setValue(key + QStringLiteral("aeTitle"), QString::fromStdString(n.node.aeTitle));
        store.setValue(key + QStringLiteral("host"), QString::fromStdString(n.node.host));
        store.setValue(key + QStringLiteral("port"), int{n.node.port});
        store.setValue(key + QStringLiteral("allowPush"), n.allowPush);
        writeTls(n.node.tls, key + QStringLiteral("tls/"), store);
    }
}

pacs::LocalStore openStore(const PacsSettings& settings) {
    pacs::LocalStore store(settings.storeFolder);
    store.setSizeLimit(settings.storeLimitBytes);
    return store;
}

const PacsNode* findNode(const PacsSettings& settings, const std::string& name) {
    for (const PacsNode& n : settings.nodes) {
        if (n.name == name) {
            return &n;
        }
    }
    return nullptr;
}

}  // namespace vv::gui
