// SPDX-License-Identifier: GPL-3.0-or-later
// The DICOM network settings kept in QSettings (app/gui/pacs/PacsSettings.h).
#include <gtest/gtest.h>

#include <QCoreApplication>
#include <QSettings>
#include <QTemporaryDir>
#include <filesystem>
#include <functional>
#include <memory>
#include <string>

#include "gui/pacs/PacsSettings.h"
#include "vv/core/Error.h"
#include "vv/pacs/StorageScp.h"

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

/// The six limits as one comparable text.
std::string limitsText(const pacs::ListenerLimits& l) {
    return std::to_string(l.maxAssociations) + " associations, " +
           std::to_string(l.maxConnectionsPerAddress) + " per address, " +
           std::to_string(l.maxConnections) + " in all, " + std::to_string(l.requestSeconds) +
           " s, " + std::to_string(l.maxInstanceBytes) + " B per instance, " +
           std::to_string(l.maxAssociationBytes) + " B per association";
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

TEST_F(PacsSettingsTest, ListenerLimitsAreWrittenAndReadBack) {
    PacsSettings s;
    s.listenerLimits.maxAssociations = 4;
    s.listenerLimits.maxConnectionsPerAddress = 1;
    s.listenerLimits.maxConnections = 12;
    s.listenerLimits.requestSeconds = 60;
    s.listenerLimits.maxInstanceBytes = 500'000'000;
    s.listenerLimits.maxAssociationBytes = 123'000'000'000ULL;  // beyond 32 bits
    writePacsSettings(s, store_);
    store_.sync();
    // As the next start reads them: from the file.
    const QSettings again(store_.fileName(), QSettings::IniFormat);
    EXPECT_EQ(limitsText(readPacsSettings(again).listenerLimits), limitsText(s.listenerLimits));
    EXPECT_EQ(again.value(QStringLiteral("pacs/listener/maxConnectionsPerAddress")).toInt(), 1);
}

TEST_F(PacsSettingsTest, MissingListenerLimitsTakeTheDefaults) {
    EXPECT_EQ(limitsText(readPacsSettings(store_).listenerLimits),
              limitsText(pacs::ListenerLimits{}));
    store_.setValue(QStringLiteral("pacs/listener/maxAssociations"), 32);
    store_.setValue(QStringLiteral("pacs/listener/maxInstanceBytes"), 2'000'000'000ULL);
    pacs::ListenerLimits expected;
    expected.maxAssociations = 32;
    expected.maxInstanceBytes = 2'000'000'000ULL;
    EXPECT_EQ(limitsText(readPacsSettings(store_).listenerLimits), limitsText(expected));
}

TEST_F(PacsSettingsTest, InvalidListenerLimitsWrittenByHandAreSkippedNotGuessed) {
    const pacs::ListenerLimits defaults;
    const auto readWith = [this](const char* name, const QVariant& value) {
        store_.remove(QStringLiteral("pacs"));
        store_.setValue(QStringLiteral("pacs/listener/requestSeconds"), 30);  // valid: kept
        store_.setValue(QStringLiteral("pacs/listener/") + QLatin1String(name), value);
        return readPacsSettings(store_).listenerLimits;
    };
    for (const QVariant& bad : {QVariant(0), QVariant(257), QVariant(QStringLiteral("abc")),
                                QVariant(QStringLiteral("8.5")), QVariant(-3)}) {
        const pacs::ListenerLimits l = readWith("maxAssociations", bad);
        EXPECT_EQ(l.maxAssociations, defaults.maxAssociations) << bad.toString().toStdString();
        EXPECT_EQ(l.requestSeconds, 30);
    }
    EXPECT_EQ(readWith("maxConnections", 1025).maxConnections, defaults.maxConnections);
    EXPECT_EQ(readWith("maxConnectionsPerAddress", 0).maxConnectionsPerAddress,
              defaults.maxConnectionsPerAddress);
    EXPECT_EQ(readWith("requestSeconds", 121).requestSeconds, defaults.requestSeconds);
    for (const QVariant& bad :
         {QVariant(999), QVariant(QStringLiteral("-5")), QVariant(QStringLiteral("4GB"))}) {
        const pacs::ListenerLimits l = readWith("maxInstanceBytes", bad);
        EXPECT_EQ(l.maxInstanceBytes, defaults.maxInstanceBytes) << bad.toString().toStdString();
        EXPECT_EQ(l.requestSeconds, 30);
    }

    // Limits that do not fit together: those skipped together, the others kept.
    store_.remove(QStringLiteral("pacs"));
    store_.setValue(QStringLiteral("pacs/listener/maxAssociations"), 32);
    store_.setValue(QStringLiteral("pacs/listener/maxConnections"), 20);  // below 32
    store_.setValue(QStringLiteral("pacs/listener/maxConnectionsPerAddress"), 2);
    store_.setValue(QStringLiteral("pacs/listener/maxInstanceBytes"), 1'000'000'000ULL);
    pacs::ListenerLimits expected;
    expected.maxInstanceBytes = 1'000'000'000ULL;
    EXPECT_EQ(limitsText(readPacsSettings(store_).listenerLimits), limitsText(expected));
    store_.setValue(QStringLiteral("pacs/listener/maxConnections"), 40);  // now they fit
    store_.setValue(QStringLiteral("pacs/listener/maxAssociationBytes"), 900'000'000ULL);
    expected = {};
    expected.maxAssociations = 32;
    expected.maxConnections = 40;
    expected.maxConnectionsPerAddress = 2;
    EXPECT_EQ(limitsText(readPacsSettings(store_).listenerLimits), limitsText(expected))
        << "the largest association below the largest instance: both sizes are the defaults";
}

TEST_F(PacsSettingsTest, WritingRefusesListenerLimitsThatDoNotFitTogether) {
    PacsSettings good;
    good.listenerLimits.maxAssociations = 4;
    writePacsSettings(good, store_);
    const auto refusal = [this](const PacsSettings& bad) -> std::string {
        try {
            writePacsSettings(bad, store_);
        } catch (const PacsSettingsError& e) {
            EXPECT_EQ(e.setting(), PacsSettingsError::Setting::ListenerLimits) << e.what();
            return e.what();
        }
        return "written";
    };
    PacsSettings bad = good;
    bad.listenerLimits.maxConnections = 3;  // below the 4 associations
    EXPECT_NE(refusal(bad).find("connections in all"), std::string::npos) << refusal(bad);
    bad = good;
    bad.listenerLimits.maxConnectionsPerAddress = 65;  // above the 64 in all
    EXPECT_NE(refusal(bad).find("per address"), std::string::npos) << refusal(bad);
    bad = good;
    bad.listenerLimits.maxAssociationBytes = bad.listenerLimits.maxInstanceBytes - 1;
    EXPECT_NE(refusal(bad).find("largest association"), std::string::npos) << refusal(bad);
    bad = good;
    bad.listenerLimits.requestSeconds = 0;
    EXPECT_NE(refusal(bad).find("deadline"), std::string::npos) << refusal(bad);
    EXPECT_EQ(readPacsSettings(store_).listenerLimits.maxAssociations, 4) << "nothing written";
}

TEST_F(PacsSettingsTest, TimeoutsAreWrittenAndReadBackAndInvalidOnesSkipped) {
    EXPECT_EQ(readPacsSettings(store_).me.timeouts.responseSeconds,
              pacs::Timeouts{}.responseSeconds);
    PacsSettings s;
    s.me.timeouts = {7, 1, kMaxTimeoutSeconds};
    writePacsSettings(s, store_);
    store_.sync();
    const QSettings again(store_.fileName(), QSettings::IniFormat);
    const pacs::Timeouts read = readPacsSettings(again).me.timeouts;
    EXPECT_EQ(read.connectSeconds, 7);
    EXPECT_EQ(read.associateSeconds, 1);
    EXPECT_EQ(read.responseSeconds, kMaxTimeoutSeconds);

    // Written by hand out of range, or not a number: that one takes its default.
    const pacs::Timeouts defaults;
    store_.setValue(QStringLiteral("pacs/timeouts/connectSeconds"), 0);
    store_.setValue(QStringLiteral("pacs/timeouts/associateSeconds"), kMaxTimeoutSeconds + 1);
    store_.setValue(QStringLiteral("pacs/timeouts/responseSeconds"), QStringLiteral("soon"));
    const pacs::Timeouts skipped = readPacsSettings(store_).me.timeouts;
    EXPECT_EQ(skipped.connectSeconds, defaults.connectSeconds);
    EXPECT_EQ(skipped.associateSeconds, defaults.associateSeconds);
    EXPECT_EQ(skipped.responseSeconds, defaults.responseSeconds);
    store_.setValue(QStringLiteral("pacs/timeouts/responseSeconds"), 45);
    EXPECT_EQ(readPacsSettings(store_).me.timeouts.responseSeconds, 45);

    // Out of range is refused when written, naming the setting; nothing is written.
    writePacsSettings(s, store_);
    for (const pacs::Timeouts bad : {pacs::Timeouts{0, 10, 30}, pacs::Timeouts{5, 10, -1},
                                     pacs::Timeouts{5, kMaxTimeoutSeconds + 1, 30}}) {
        PacsSettings wrong = s;
        wrong.me.timeouts = bad;
        try {
            writePacsSettings(wrong, store_);
            ADD_FAILURE() << "timeouts " << bad.connectSeconds << "/" << bad.associateSeconds << "/"
                          << bad.responseSeconds << " written";
        } catch (const PacsSettingsError& e) {
            EXPECT_EQ(e.setting(), PacsSettingsError::Setting::Timeouts) << e.what();
        }
    }
    EXPECT_EQ(readPacsSettings(store_).me.timeouts.connectSeconds, 7) << "nothing written";
}

/// What the front ends offer limit by limit (ListenerLimits::kMax… / kMin…) is what
/// ListenerLimits::validate() allows: its ends pass, one beyond is refused.
TEST_F(PacsSettingsTest, TheListenerLimitRangesOfTheFrontEndsAreThoseValidateAllows) {
    const auto passes = [](const std::function<void(pacs::ListenerLimits&)>& set) {
        pacs::ListenerLimits l;
        l.maxConnections = pacs::ListenerLimits::kMaxConnections;  // room for the others
        set(l);
        try {
            l.validate();
            return true;
        } catch (const InvalidArgumentError&) {
            return false;
        }
    };
    for (const int n : {1, pacs::ListenerLimits::kMaxAssociations}) {
        EXPECT_TRUE(passes([n](auto& l) { l.maxAssociations = n; })) << n;
    }
    EXPECT_FALSE(passes([](auto& l) { l.maxAssociations = 0; }));
    EXPECT_FALSE(
        passes([](auto& l) { l.maxAssociations = pacs::ListenerLimits::kMaxAssociations + 1; }));
    for (const int n : {1, pacs::ListenerLimits::kMaxConnections}) {
        EXPECT_TRUE(passes([n](auto& l) { l.maxConnectionsPerAddress = n; })) << n;
    }
    EXPECT_FALSE(passes([](auto& l) { l.maxConnectionsPerAddress = 0; }));
    EXPECT_FALSE(
        passes([](auto& l) { l.maxConnections = pacs::ListenerLimits::kMaxConnections + 1; }));
    for (const int n : {1, pacs::ListenerLimits::kMaxRequestSeconds}) {
        EXPECT_TRUE(passes([n](auto& l) { l.requestSeconds = n; })) << n;
    }
    EXPECT_FALSE(passes([](auto& l) { l.requestSeconds = 0; }));
    EXPECT_FALSE(
        passes([](auto& l) { l.requestSeconds = pacs::ListenerLimits::kMaxRequestSeconds + 1; }));
    EXPECT_TRUE(
        passes([](auto& l) { l.maxInstanceBytes = pacs::ListenerLimits::kMinInstanceBytes; }));
    EXPECT_FALSE(
        passes([](auto& l) { l.maxInstanceBytes = pacs::ListenerLimits::kMinInstanceBytes - 1; }));
}

}  // namespace
}  // namespace vv::gui
