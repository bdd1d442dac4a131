// SPDX-License-Identifier: GPL-3.0-or-later
#include "PacsSettings.h"

#include <QFile>
#include <QSettings>
#include <QStandardPaths>
#include <QString>
#include <set>
#include <system_error>

#include "vv/core/Error.h"

namespace vv::gui {
namespace {

constexpr int kMaxPort = 65535;

std::string text(const QSettings& store, const QString& key, const std::string& fallback) {
    const QVariant value = store.value(key);
    return value.isValid() ? value.toString().toStdString() : fallback;
}

bool validPort(int port) {
    return port > 0 && port <= kMaxPort;
}

std::uint16_t port(const QSettings& store, const QString& key, std::uint16_t fallback) {
    bool ok = false;
    const int value = store.value(key).toInt(&ok);
    return ok && validPort(value) ? static_cast<std::uint16_t>(value) : fallback;
}

bool validAeTitle(const std::string& aeTitle) {
    try {
        pacs::validateAeTitle(aeTitle);
        return true;
    } catch (const InvalidArgumentError&) {
        return false;
    }
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
    if (validAeTitle(ae)) {
        s.me.aeTitle = ae;
    }
    s.listenerEnabled = store.value(QStringLiteral("pacs/listener/enabled"), false).toBool();
    s.listenerPort = port(store, QStringLiteral("pacs/listener/port"), s.listenerPort);
    s.listenerBindAddress =
        text(store, QStringLiteral("pacs/listener/bind"), s.listenerBindAddress);
    s.listenerTls = readTls(store, QStringLiteral("pacs/listener/tls/"));
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
        bool valid = !n.name.empty() && !names.contains(n.name);
        try {
            pacs::validateNode(n.node);
        } catch (const InvalidArgumentError&) {
            valid = false;
        }
        if (valid) {
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
    store.setValue(QStringLiteral("pacs/listener/enabled"), settings.listenerEnabled);
    store.setValue(QStringLiteral("pacs/listener/port"), int{settings.listenerPort});
    store.setValue(QStringLiteral("pacs/listener/bind"),
                   QString::fromStdString(settings.listenerBindAddress));
    writeTls(settings.listenerTls, QStringLiteral("pacs/listener/tls/"), store);
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
