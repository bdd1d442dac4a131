// SPDX-License-Identifier: GPL-3.0-or-later
// The DICOM network settings kept in QSettings (app/gui/pacs/PacsSettings.h).
#include <gtest/gtest.h>

#include <QCoreApplication>
#include <QSettings>
#include <QTemporaryDir>
#include <filesystem>
#include <memory>

#include "gui/pacs/PacsSettings.h"
#include "vv/core/Error.h"

namespace vv::gui {
namespace {

PacsNode node(std::string name, std::string ae, std::string host, std::uint16_t port) {
    PacsNode n;
    n.name = std::move(name);
    n.node.aeTitle = std::move(ae);
    n.node.host = std::move(host);
    n.node.port = port;
    return n;
}

class PacsSettingsTest : public ::testing::Test {
  protected:
    QTemporaryDir dir_;
    QSettings store_{dir_.filePath(QStringLiteral("settings.ini")), QSettings::IniFormat};
};

TEST_F(PacsSettingsTest, AnEmptyStoreGivesTheDefaults) {
    const PacsSettings s = readPacsSettings(store_);
    EXPECT_FALSE(s.listenerTls.enabled);
    EXPECT_EQ(s.me.aeTitle, "VESSELVIEW");
    EXPECT_FALSE(s.listenerEnabled);
    EXPECT_EQ(s.listenerPort, 11112);
    EXPECT_EQ(s.listenerBindAddress, "127.0.0.1");
    EXPECT_TRUE(s.nodes.empty());
    EXPECT_EQ(s.storeFolder, defaultStoreFolder());
    EXPECT_EQ(s.storeLimitBytes, 0U);
}

/// The default store folder names VesselView once (QStandardPaths'
/// AppLocalDataLocation adds the organisation and the application name,
/// both "VesselView"); a store an earlier version made at that old place is
/// kept in use, never left behind.
TEST(PacsStoreFolderTest, TheDefaultNamesVesselViewOnceAndKeepsAnEarlierStore) {
    QTemporaryDir data;
    const QByteArray before = qgetenv("XDG_DATA_HOME");
    qputenv("XDG_DATA_HOME", data.path().toUtf8());
    const QString organisation = QCoreApplication::organizationName();
    const QString application = QCoreApplication::applicationName();
    QCoreApplication::setOrganizationName(QStringLiteral("VesselView"));  // as main() sets them
    QCoreApplication::setApplicationName(QStringLiteral("VesselView"));
    const std::shared_ptr<void> restore(nullptr, [&](void*) {
        QCoreApplication::setOrganizationName(organisation);
        QCoreApplication::setApplicationName(application);
        qputenv("XDG_DATA_HOME", before);
    });
    const std::filesystem::path root = data.path().toStdString();
    const std::filesystem::path folder = defaultStoreFolder();
    EXPECT_EQ(folder, root / "VesselView" / "studies");
    EXPECT_EQ(folder.string().find("VesselView/VesselView"), std::string::npos) << folder;

    // An earlier version's store: used where it is.
    const std::filesystem::path earlier = root / "VesselView" / "VesselView" / "studies";
    std::filesystem::create_directories(earlier);
    EXPECT_EQ(defaultStoreFolder(), earlier);
    QTemporaryDir dir;
    QSettings store(dir.filePath(QStringLiteral("settings.ini")), QSettings::IniFormat);
    EXPECT_EQ(readPacsSettings(store).storeFolder, earlier);
    // Once the new place holds a store, that one.
    std::filesystem::create_directories(folder);
    EXPECT_EQ(defaultStoreFolder(), folder);
}

TEST_F(PacsSettingsTest, WhatIsWrittenIsReadBack) {
    PacsSettings s;
    s.me.aeTitle = "VV_WS1";
    s.listenerEnabled = true;
    s.listenerPort = 4242;
    s.listenerBindAddress = "0.0.0.0";
    s.storeFolder = "/data/studies";
    s.storeLimitBytes = 5ULL << 30;
    s.nodes.push_back(node("Radiology PACS", "ORTHANC", "pacs.example", 4243));
    PacsNode tls = node("Remote", "REMOTE", "10.0.0.9", 2762);
    tls.allowPush = false;
    tls.node.tls.enabled = true;
    tls.node.tls.trustedCertificates = "/etc/ca.pem";
    s.nodes.push_back(tls);
    s.listenerTls = {true, "/etc/vv/ca.pem", "/etc/vv/listener.pem", "/etc/vv/listener.key"};
    writePacsSettings(s, store_);

    const PacsSettings r = readPacsSettings(store_);
    EXPECT_EQ(r.me.aeTitle, "VV_WS1");
    EXPECT_TRUE(r.listenerEnabled);
    EXPECT_EQ(r.listenerPort, 4242);
    EXPECT_EQ(r.listenerBindAddress, "0.0.0.0");
    EXPECT_EQ(r.storeFolder, std::filesystem::path("/data/studies"));
    EXPECT_EQ(r.storeLimitBytes, 5ULL << 30);
    EXPECT_TRUE(r.listenerTls.enabled);
    EXPECT_EQ(r.listenerTls.trustedCertificates, std::filesystem::path("/etc/vv/ca.pem"));
    EXPECT_EQ(r.listenerTls.certificate, std::filesystem::path("/etc/vv/listener.pem"));
    EXPECT_EQ(r.listenerTls.privateKey, std::filesystem::path("/etc/vv/listener.key"));
    ASSERT_EQ(r.nodes.size(), 2U);
    EXPECT_EQ(r.nodes[0].name, "Radiology PACS");
    EXPECT_EQ(r.nodes[0].node.aeTitle, "ORTHANC");
    EXPECT_EQ(r.nodes[0].node.host, "pacs.example");
    EXPECT_EQ(r.nodes[0].node.port, 4243);
    EXPECT_TRUE(r.nodes[0].allowPush);
    EXPECT_FALSE(r.nodes[1].allowPush);
    EXPECT_TRUE(r.nodes[1].node.tls.enabled);
    EXPECT_EQ(r.nodes[1].node.tls.trustedCertificates, std::filesystem::path("/etc/ca.pem"));
    ASSERT_NE(findNode(r, "Remote"), nullptr);
    EXPECT_EQ(findNode(r, "Remote")->node.port, 2762);
    EXPECT_EQ(findNode(r, "nobody"), nullptr);

    // Fewer nodes written later leave none of the old ones behind.
    s.nodes.pop_back();
    writePacsSettings(s, store_);
    EXPECT_EQ(readPacsSettings(store_).nodes.size(), 1U);
}

TEST_F(PacsSettingsTest, InvalidSettingsAreRefusedNamingTheFieldAndNothingIsWritten) {
    PacsSettings good;
    good.nodes.push_back(node("PACS", "ORTHANC", "localhost", 4242));
    writePacsSettings(good, store_);

    PacsSettings bad = good;
    bad.me.aeTitle = "MUCH_TOO_LONG_AE_TITLE";
    EXPECT_THROW(
        {
            try {
                writePacsSettings(bad, store_);
            } catch (const InvalidArgumentError& e) {
                EXPECT_NE(std::string(e.what()).find("our AE title"), std::string::npos);
                throw;
            }
        },
        InvalidArgumentError);
    bad = good;
    bad.nodes.push_back(node("PACS", "OTHER", "h", 1));
    EXPECT_THROW(writePacsSettings(bad, store_), InvalidArgumentError);
    bad = good;
    bad.nodes.push_back(node("No host", "OTHER", "", 104));
    try {
        writePacsSettings(bad, store_);
        ADD_FAILURE() << "a node without host was written";
    } catch (const InvalidArgumentError& e) {
        EXPECT_NE(std::string(e.what()).find("No host"), std::string::npos) << e.what();
    }
    bad = good;
    bad.listenerTls = {true, "/etc/vv/ca.pem", "/etc/vv/listener.pem", {}};  // no key
    try {
        writePacsSettings(bad, store_);
        ADD_FAILURE() << "listener TLS without its key was written";
    } catch (const InvalidArgumentError& e) {
        EXPECT_NE(std::string(e.what()).find("listener TLS"), std::string::npos) << e.what();
    }
    const PacsSettings r = readPacsSettings(store_);
    EXPECT_EQ(r.me.aeTitle, "VESSELVIEW");
    ASSERT_EQ(r.nodes.size(), 1U);
    EXPECT_EQ(r.nodes[0].name, "PACS");
    EXPECT_FALSE(r.listenerTls.enabled);
}

TEST_F(PacsSettingsTest, InvalidEntriesWrittenByHandAreSkippedNotGuessed) {
    store_.setValue(QStringLiteral("pacs/aeTitle"), QStringLiteral("BAD\\AE"));
    store_.setValue(QStringLiteral("pacs/listener/port"), 70000);
    store_.setValue(QStringLiteral("pacs/nodes/size"), 3);
    store_.setValue(QStringLiteral("pacs/nodes/1/name"), QStringLiteral("ok"));
    store_.setValue(QStringLiteral("pacs/nodes/1/aeTitle"), QStringLiteral("OK"));
    store_.setValue(QStringLiteral("pacs/nodes/1/host"), QStringLiteral("h"));
    store_.setValue(QStringLiteral("pacs/nodes/1/port"), 104);
    store_.setValue(QStringLiteral("pacs/nodes/2/name"), QStringLiteral("no port"));
    store_.setValue(QStringLiteral("pacs/nodes/2/aeTitle"), QStringLiteral("X"));
    store_.setValue(QStringLiteral("pacs/nodes/2/host"), QStringLiteral("h"));
    store_.setValue(QStringLiteral("pacs/nodes/2/port"), QStringLiteral("abc"));
    store_.setValue(QStringLiteral("pacs/nodes/3/name"), QStringLiteral("ok"));  // duplicate
    store_.setValue(QStringLiteral("pacs/nodes/3/aeTitle"), QStringLiteral("Y"));
    store_.setValue(QStringLiteral("pacs/nodes/3/host"), QStringLiteral("h"));
    store_.setValue(QStringLiteral("pacs/nodes/3/port"), 105);
    const PacsSettings r = readPacsSettings(store_);
    EXPECT_EQ(r.me.aeTitle, "VESSELVIEW");
    EXPECT_EQ(r.listenerPort, 11112);
    ASSERT_EQ(r.nodes.size(), 1U);
    EXPECT_EQ(r.nodes[0].node.aeTitle, "OK");
}

TEST_F(PacsSettingsTest, TheStoreOfTheSettingsHasTheirSizeLimit) {
    PacsSettings s;
    s.storeFolder = dir_.filePath(QStringLiteral("studies")).toStdString();
    s.storeLimitBytes = 123456789;
    const pacs::LocalStore store = openStore(s);
    EXPECT_EQ(store.root(), s.storeFolder);
    EXPECT_EQ(store.sizeLimit(), 123456789U);
    EXPECT_TRUE(std::filesystem::is_directory(s.storeFolder));
    s.storeLimitBytes = 0;
    EXPECT_EQ(openStore(s).sizeLimit(), 0U);
}

}  // namespace
}  // namespace vv::gui
