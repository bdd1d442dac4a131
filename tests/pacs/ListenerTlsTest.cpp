// SPDX-License-Identifier: GPL-3.0-or-later
// The listener over TLS: Orthanc (speaking TLS only) pushes a study to it
// with C-MOVE; a peer whose certificate does not chain to our trusted CA
// (DCMTK's storescu, and our own SCU), a peer without a certificate and a
// peer speaking plain TCP are refused with a log line naming the peer's
// address and nothing stored, and the listener keeps working; a peer that
// connects and stays silent holds it only for the association timeout.
#include <arpa/inet.h>
#include <gtest/gtest.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "OrthancServer.h"
#include "PacsTestUtil.h"
#include "vv/core/Log.h"
#include "vv/pacs/Echo.h"
#include "vv/pacs/Find.h"
#include "vv/pacs/PacsError.h"
#include "vv/pacs/Retrieve.h"
#include "vv/pacs/Send.h"
#include "vv/pacs/StorageScp.h"

namespace listener_tls_test {

namespace fs = std::filesystem;
using namespace vv::pacs;

namespace {

constexpr const char* kOurAe = "VVTLSSCP";
constexpr const char* kPatientId = "VV-TLS-SECRET-ID";
constexpr int kSlices = 8;

fs::path testFolder() {
    return fs::path(VV_TEST_TMP) / ("pacs-listener-tls-" + std::to_string(::getpid()));
}

LocalAe me(const std::string& ae = kOurAe) {
    return LocalAe{ae, Timeouts{2, 5, 10}};
}

std::vector<fs::path> ctaFiles() {
    return vv::test::writeCtaFiles(testFolder() / "series", kPatientId, kSlices);
}

/// The "vv.pacs" log lines written while the test runs.
struct Logs {
    static std::mutex mutex;
    static std::vector<std::string> lines;
    static void collect(vv::log::Level, std::string_view category, std::string_view message) {
        const std::lock_guard lock(mutex);
        lines.emplace_back(std::string(category) + ": " + std::string(message));
    }
    static std::string all() {
        const std::lock_guard lock(mutex);
        std::string text;
        for (const std::string& line : lines) {
            text += line + "\n";
        }
        return text;
    }
};
std::mutex Logs::mutex;
std::vector<std::string> Logs::lines;

/// The listener's refusals once there are `expected` (or the wait's bound passed): with
/// TLS 1.3 a client may fail before the listener has counted the refusal.
std::size_t refusals(const StorageScp& listener, std::size_t expected) {
    vv::test::waitUntil([&] { return listener.stats().refusedAssociations >= expected; });
    return listener.stats().refusedAssociations;
}

class ListenerTlsTest : public ::testing::Test {
  protected:
    static void SetUpTestSuite() {
        fs::remove_all(testFolder());
        certificates_ = vv::test::makeCertificates(testFolder() / "certificates");
        scpPort_ = vv::test::freePort();
        orthanc_ = std::make_unique<vv::test::OrthancServer>(kOurAe, scpPort_, &certificates_);
    }
    static void TearDownTestSuite() { orthanc_.reset(); }
    void SetUp() override {
        Logs::lines.clear();
        vv::log::setSink(&Logs::collect);
    }
    void TearDown() override { vv::log::setSink(nullptr); }

    /// A TLS listener with our server certificate, trusting the test CA,
    /// letting in `allowed`.
    static ListenerConfig tlsConfig(std::uint16_t port, std::vector<Node> allowed) {
        ListenerConfig config;
        config.aeTitle = kOurAe;
        config.port = port;
        config.allowedPeers = std::move(allowed);
        config.timeouts = Timeouts{2, 5, 10};
        config.tls = {true, certificates_.ca, certificates_.serverCert, certificates_.serverKey};
        return config;
    }
    static fs::path freshStore(const std::string& name) {
        const fs::path folder = testFolder() / name;
        fs::remove_all(folder);
        return folder;
    }

    static vv::test::TestCertificates certificates_;
    static std::uint16_t scpPort_;
    static std::unique_ptr<vv::test::OrthancServer> orthanc_;
};

vv::test::TestCertificates ListenerTlsTest::certificates_;
std::uint16_t ListenerTlsTest::scpPort_ = 0;
std::unique_ptr<vv::test::OrthancServer> ListenerTlsTest::orthanc_;

}  // namespace

TEST_F(ListenerTlsTest, OrthancPushesAStudyOverTls) {
    const auto statuses = sendFiles(me(), orthanc_->node(), ctaFiles());
    ASSERT_EQ(statuses.size(), static_cast<std::size_t>(kSlices));
    StudyQuery query;
    query.patientId = kPatientId;
    const auto studies = findStudies(me(), orthanc_->node(), query);
    ASSERT_EQ(studies.size(), 1U);

    LocalStore store(freshStore("push"));
    const StorageScp listener(store, tlsConfig(scpPort_, {orthanc_->node()}));
    const RetrieveResult moved =
        moveTo(kOurAe, me(), orthanc_->node(), RetrieveRequest{studies[0].studyInstanceUid, ""});
    EXPECT_EQ(moved.instances, static_cast<std::size_t>(kSlices));
    vv::test::waitUntil([&] { return listener.stats().committedInstances >= moved.instances; });
    const auto stored = store.studies();
    ASSERT_EQ(stored.size(), 1U);
    EXPECT_EQ(stored[0].studyInstanceUid, studies[0].studyInstanceUid);
    ASSERT_EQ(stored[0].series.size(), 1U);
    EXPECT_EQ(stored[0].series[0].instances, kSlices);
    EXPECT_EQ(listener.stats().refusedAssociations, 0U);
}

TEST_F(ListenerTlsTest, PeerWithACertificateOfAnotherCaIsRefusedAndNothingStored) {
    LocalStore store(freshStore("wrong-ca"));
    const std::uint16_t port = vv::test::freePort();
    const Node sender{"SENDER", "127.0.0.1", 104, {}};
    const StorageScp listener(store, tlsConfig(port, {sender}));
    const auto files = ctaFiles();

    // DCMTK's storescu showing the other CA's (self-signed) certificate.
    fs::path otherKey = certificates_.otherCa;
    otherKey.replace_extension(".key");
    // Its waits are longer than `timeout` allows: only a refusal ends it before (124 after).
    const std::string command = "timeout 200 storescu -to 600 -ta 600 -td 600 +tls " +
                                otherKey.string() + " " + certificates_.otherCa.string() + " +cf " +
                                certificates_.ca.string() + " -aet SENDER -aec " + kOurAe +
                                " 127.0.0.1 " + std::to_string(port) + " " + files[0].string() +
                                " >/dev/null 2>&1";
    const int status = std::system(command.c_str());
    ASSERT_TRUE(WIFEXITED(status)) << command;
    EXPECT_NE(WEXITSTATUS(status), 0) << "storescu with an untrusted certificate got in";
    EXPECT_NE(WEXITSTATUS(status), 124) << "the listener neither refused nor answered";

    // Our own SCU with the same certificate.
    Node ours{kOurAe, "127.0.0.1", port, {true, certificates_.ca, certificates_.otherCa, otherKey}};
    EXPECT_THROW(sendFiles(me("SENDER"), ours, files), NetworkError);

    EXPECT_TRUE(store.studies().empty());
    EXPECT_TRUE(fs::is_empty(store.root() / ".incoming"));
    EXPECT_EQ(refusals(listener, 2), 2U);
    EXPECT_EQ(listener.stats().acceptedAssociations, 0U);
    const std::string logs = Logs::all();
    EXPECT_NE(logs.find("refused a connection from 127.0.0.1: TLS"), std::string::npos) << logs;
    EXPECT_EQ(logs.find(kPatientId), std::string::npos) << logs;
    EXPECT_EQ(logs.find("VesselView^"), std::string::npos) << logs;
}

TEST_F(ListenerTlsTest, PlainAndCertificateLessPeersAreRefusedAndTheListenerKeepsWorking) {
    LocalStore store(freshStore("plain"));
    const std::uint16_t port = vv::test::freePort();
    const StorageScp listener(store, tlsConfig(port, {Node{"SENDER", "127.0.0.1", 104, {}}}));
    // Waits longer than ctest lets the test run: only the refusals end these.
    const LocalAe patient{"SENDER", Timeouts{5, 3600, 3600}};
    EXPECT_THROW(echo(patient, Node{kOurAe, "127.0.0.1", port, {}}), NetworkError);
    const Node noCertificate{kOurAe, "127.0.0.1", port, {true, certificates_.ca, {}, {}}};
    EXPECT_THROW(echo(patient, noCertificate), NetworkError);
    EXPECT_EQ(refusals(listener, 2), 2U);

    const Node good{kOurAe,
                    "127.0.0.1",
                    port,
                    {true, certificates_.ca, certificates_.clientCert, certificates_.clientKey}};
    EXPECT_NO_THROW(echo(me("SENDER"), good)) << "the listener still answers";
    EXPECT_EQ(listener.stats().acceptedAssociations, 1U);
}

TEST_F(ListenerTlsTest, ASilentConnectionHoldsNothingAndIsDroppedAtTheRequestDeadline) {
    LocalStore store(freshStore("silent"));
    const std::uint16_t port = vv::test::freePort();
    ListenerConfig config = tlsConfig(port, {Node{"SENDER", "127.0.0.1", 104, {}}});
    config.limits.requestSeconds = 1;
    const StorageScp listener(store, config);
    // Connects and never says a word (no TLS handshake).
    const int silent = ::socket(AF_INET, SOCK_STREAM, 0);
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    address.sin_port = htons(port);
    ASSERT_EQ(::connect(silent, reinterpret_cast<sockaddr*>(&address), sizeof address), 0);
    ASSERT_TRUE(vv::test::waitUntil([&] { return listener.stats().openConnections == 1; }));

    const Node good{kOurAe,
                    "127.0.0.1",
                    port,
                    {true, certificates_.ca, certificates_.clientCert, certificates_.clientKey}};
    EXPECT_NO_THROW(echo(LocalAe{"SENDER", Timeouts{2, 10, 10}}, good));
    EXPECT_TRUE(vv::test::waitUntil([&] { return listener.stats().droppedConnections == 1; }));
    ::close(silent);
    EXPECT_NE(Logs::all().find("dropped a connection from 127.0.0.1: no association request "
                               "within 1 s"),
              std::string::npos)
        << Logs::all();
}

TEST_F(ListenerTlsTest, MissingOrUnreadableFilesAreTlsErrors) {
    LocalStore store(freshStore("files"));
    ListenerConfig config = tlsConfig(vv::test::freePort(), {});
    config.tls.privateKey.clear();
    EXPECT_THROW(StorageScp(store, config), TlsError);
    config = tlsConfig(vv::test::freePort(), {});
    config.tls.certificate = "/nonexistent/server.pem";
    EXPECT_THROW(StorageScp(store, config), TlsError);
    config = tlsConfig(vv::test::freePort(), {});
    config.tls.privateKey = certificates_.clientKey;  // not the key of the server certificate
    EXPECT_THROW(StorageScp(store, config), TlsError);
}

}  // namespace listener_tls_test
