// SPDX-License-Identifier: GPL-3.0-or-later
// `vesselview-cli pacs echo|find|get|send|listen` against a real Orthanc
// (OrthancServer): outputs, the store it fills, and exit status 5 when the
// peer refuses or fails.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <future>
#include <thread>

#include "CliRun.h"
#include "OrthancServer.h"
#include "PacsTestUtil.h"
#include "vv/pacs/Find.h"
#include "vv/pacs/LocalStore.h"
#include "vv/pacs/Send.h"

namespace fs = std::filesystem;
using vv::test::runCli;

namespace {

constexpr const char* kOurAe = "VVCLI";

std::string nodeText(const vv::pacs::Node& n) {
    return n.aeTitle + "@" + n.host + ":" + std::to_string(n.port);
}

/// The synthetic CTA series in the folder `name`; returns its files.
std::vector<std::string> writeSeries(const std::string& name) {
    std::vector<std::string> files;
    for (const fs::path& f :
         vv::test::writeCtaFiles(vv::test::processTestDir("pacs-cli") / name, "VV-CLI-1", 8)) {
        files.push_back(f.string());
    }
    return files;
}

/// Commits a study "1.2.3" of one file of `bytes` bytes into the store at `root`.
void commitDummyStudy(const fs::path& root, std::size_t bytes) {
    const vv::pacs::LocalStore store(root);
    auto t = store.begin();
    const fs::path staged = t.stagingPath();
    std::ofstream(staged) << std::string(bytes, 'x');
    vv::pacs::InstanceFields f;
    f.studyInstanceUid = "1.2.3";
    f.seriesInstanceUid = "1.2.3.1";
    f.sopInstanceUid = "1.2.3.1.1";
    t.add(staged, f);
    t.commit();
}

}  // namespace

TEST(PacsCliTest, SendFindGetAndEcho) {
    const std::uint16_t ourPort = vv::test::freePort();
    vv::test::OrthancServer orthanc(kOurAe, ourPort);
    const std::string node = nodeText(orthanc.node());

    auto echo = runCli({"pacs", "echo", "--node", node, "--aet", kOurAe});
    EXPECT_EQ(echo.code, 0) << echo.err;
    EXPECT_NE(echo.out.find("ok"), std::string::npos);

    std::vector<std::string> send = {"pacs", "send", "--node", node, "--aet", kOurAe};
    const auto files = writeSeries("send");
    send.insert(send.end(), files.begin(), files.end());
    const auto sent = runCli(send);
    EXPECT_EQ(sent.code, 0) << sent.err;
    EXPECT_EQ(std::count(sent.out.begin(), sent.out.end(), '\n'), 8) << sent.out;
    EXPECT_EQ(sent.out.find("refused"), std::string::npos) << sent.out;

    const auto found = runCli({"pacs", "find", "--node", node, "--aet", kOurAe, "--patient-id",
                               "VV-CLI-1", "--modality", "CT"});
    EXPECT_EQ(found.code, 0) << found.err;
    EXPECT_NE(found.out.find("\"patientId\": \"VV-CLI-1\""), std::string::npos) << found.out;
    const auto uidAt = found.out.find("\"studyInstanceUid\": \"");
    ASSERT_NE(uidAt, std::string::npos);
    const auto uidStart = uidAt + std::string("\"studyInstanceUid\": \"").size();
    const std::string studyUid =
        found.out.substr(uidStart, found.out.find('"', uidStart) - uidStart);

    const auto series =
        runCli({"pacs", "find", "--node", node, "--aet", kOurAe, "--study", studyUid});
    EXPECT_EQ(series.code, 0) << series.err;
    EXPECT_NE(series.out.find("\"instances\": 8"), std::string::npos) << series.out;

    // The store holds an older study of 1.5 MB; with --store-limit 1MB it
    // makes room for the retrieved one.
    const fs::path store = vv::test::processTestDir("pacs-cli") / "store-get";
    fs::remove_all(store);
    commitDummyStudy(store, 1500000);
    const auto got = runCli({"pacs", "get", "--node", node, "--aet", kOurAe, "--study", studyUid,
                             "--store", store.string(), "--store-limit", "1MB"});
    EXPECT_EQ(got.code, 0) << got.err;
    const auto studies = vv::pacs::LocalStore(store).studies();
    ASSERT_EQ(studies.size(), 1U);
    EXPECT_EQ(studies[0].studyInstanceUid, studyUid);
    EXPECT_EQ(studies[0].series.at(0).instances, 8);

    const fs::path moved = vv::test::processTestDir("pacs-cli") / "store-move";
    fs::remove_all(moved);
    const auto move =
        runCli({"pacs", "get", "--node", node, "--aet", kOurAe, "--study", studyUid, "--store",
                moved.string(), "--move", "--port", std::to_string(ourPort)});
    EXPECT_EQ(move.code, 0) << move.err;
    EXPECT_EQ(vv::pacs::LocalStore(moved).studies().size(), 1U);

    // Refusals are exit status 5 with the peer named.
    auto wrongAe =
        runCli({"pacs", "echo", "--node", "WRONG@127.0.0.1:" + std::to_string(orthanc.node().port),
                "--aet", kOurAe});
    EXPECT_EQ(wrongAe.code, 5);
    EXPECT_NE(wrongAe.err.find("WRONG@127.0.0.1"), std::string::npos) << wrongAe.err;
}

TEST(PacsCliTest, RefusedConnectionIsExitStatusFive) {
    const auto run = runCli(
        {"pacs", "echo", "--node", "NOBODY@127.0.0.1:" + std::to_string(vv::test::freePort())});
    EXPECT_EQ(run.code, 5);
    EXPECT_NE(run.err.find("cannot connect"), std::string::npos) << run.err;
}

TEST(PacsCliTest, BadNodeIsUsageError) {
    EXPECT_EQ(runCli({"pacs", "echo", "--node", "no-port"}).code, 2);
    EXPECT_EQ(runCli({"pacs", "frobnicate"}).code, 2);
    EXPECT_EQ(runCli({"pacs", "get", "--node", "A@h:1"}).code, 2);
    const std::vector<std::string> get = {"pacs",    "get",   "--node",  "A@127.0.0.1:1",
                                          "--study", "1.2.3", "--store", "/tmp/s"};
    for (const std::string bad : {"100", "1TB", "GB", "-5GB", "1.5GB", "9999999999999GB"}) {
        auto args = get;
        args.insert(args.end(), {"--store-limit", bad});
        const auto run = runCli(args);
        EXPECT_EQ(run.code, 2) << bad;
        EXPECT_NE(run.err.find("--store-limit"), std::string::npos) << run.err;
    }
    EXPECT_EQ(
        runCli({"pacs", "send", "--node", "A@127.0.0.1:1", "--store-limit", "1GB", "f.dcm"}).code,
        2)
        << "only get and listen keep a store";
    EXPECT_EQ(
        runCli({"pacs", "listen", "--store", "/tmp/s", "--port", "1", "--tls-ca", "ca.pem"}).code,
        2)
        << "a TLS listener needs its certificate";
}

TEST(PacsCliTest, ListenReceivesFromAllowedNodeOnly) {
    const std::uint16_t port = vv::test::freePort();
    const fs::path store = vv::test::processTestDir("pacs-cli") / "store-listen";
    fs::remove_all(store);
    commitDummyStudy(store, 1500000);  // goes to make room: --store-limit 1MB
    auto listening = std::async(std::launch::async, [&] {
        return runCli({"pacs", "listen", "--store", store.string(), "--port", std::to_string(port),
                       "--aet", "VVLISTEN", "--allow", "SENDER@127.0.0.1", "--for", "4",
                       "--store-limit", "1MB"});
    });
    std::this_thread::sleep_for(std::chrono::milliseconds(500));
    const vv::pacs::Node listener{"VVLISTEN", "127.0.0.1", port, {}};
    std::vector<fs::path> files;
    for (const auto& f : writeSeries("listen")) {
        files.emplace_back(f);
    }
    const vv::pacs::LocalAe stranger{"STRANGER", {2, 5, 10}};
    EXPECT_ANY_THROW(vv::pacs::sendFiles(stranger, listener, files));
    const vv::pacs::LocalAe sender{"SENDER", {2, 5, 10}};
    const auto statuses = vv::pacs::sendFiles(sender, listener, files);
    EXPECT_TRUE(std::all_of(statuses.begin(), statuses.end(),
                            [](const vv::pacs::SendStatus& s) { return s.accepted; }));
    const auto result = listening.get();
    EXPECT_EQ(result.code, 0) << result.err;
    EXPECT_NE(result.out.find("stored 8 instance(s)"), std::string::npos) << result.out;
    const auto studies = vv::pacs::LocalStore(store).studies();
    ASSERT_EQ(studies.size(), 1U);
    EXPECT_NE(studies[0].studyInstanceUid, "1.2.3") << "the older study made room";
    EXPECT_FALSE(fs::exists(store / "1.2.3"));
}

TEST(PacsCliTest, ListenOverTlsLetsInOnlyPeersOfTheTrustedCa) {
    const fs::path folder = vv::test::processTestDir("pacs-cli") / "listen-tls";
    fs::remove_all(folder);
    const auto certificates = vv::test::makeCertificates(folder / "certificates");
    const std::uint16_t port = vv::test::freePort();
    const fs::path store = folder / "store";
    auto listening = std::async(std::launch::async, [&] {
        return runCli({"pacs", "listen", "--store", store.string(), "--port", std::to_string(port),
                       "--aet", "VVLISTEN", "--allow", "SENDER@127.0.0.1", "--for", "5", "--tls-ca",
                       certificates.ca.string(), "--tls-cert", certificates.serverCert.string(),
                       "--tls-key", certificates.serverKey.string()});
    });
    std::this_thread::sleep_for(std::chrono::milliseconds(500));
    std::vector<fs::path> files;
    for (const auto& f : writeSeries("listen-tls-series")) {
        files.emplace_back(f);
    }
    const vv::pacs::LocalAe sender{"SENDER", {2, 5, 10}};
    fs::path otherKey = certificates.otherCa;
    otherKey.replace_extension(".key");
    const vv::pacs::Node untrusted{
        "VVLISTEN", "127.0.0.1", port, {true, certificates.ca, certificates.otherCa, otherKey}};
    EXPECT_ANY_THROW(vv::pacs::sendFiles(sender, untrusted, files));
    const vv::pacs::Node trusted{
        "VVLISTEN",
        "127.0.0.1",
        port,
        {true, certificates.ca, certificates.clientCert, certificates.clientKey}};
    const auto statuses = vv::pacs::sendFiles(sender, trusted, files);
    EXPECT_TRUE(std::all_of(statuses.begin(), statuses.end(),
                            [](const vv::pacs::SendStatus& s) { return s.accepted; }));
    const auto result = listening.get();
    EXPECT_EQ(result.code, 0) << result.err;
    EXPECT_NE(result.out.find("stored 8 instance(s)"), std::string::npos) << result.out;
    EXPECT_EQ(vv::pacs::LocalStore(store).studies().size(), 1U);
}

TEST(PacsCliTest, EchoOverTls) {
    const fs::path folder = vv::test::processTestDir("pacs-cli") / "tls";
    fs::remove_all(folder);
    const auto certificates = vv::test::makeCertificates(folder);
    vv::test::OrthancServer orthanc(kOurAe, vv::test::freePort(), &certificates);
    const std::string node = nodeText(orthanc.node());
    const auto ok =
        runCli({"pacs", "echo", "--node", node, "--aet", kOurAe, "--tls-ca",
                certificates.ca.string(), "--tls-cert", certificates.clientCert.string(),
                "--tls-key", certificates.clientKey.string()});
    EXPECT_EQ(ok.code, 0) << ok.err;
    const auto untrusted =
        runCli({"pacs", "echo", "--node", node, "--aet", kOurAe, "--tls-ca",
                certificates.otherCa.string(), "--tls-cert", certificates.clientCert.string(),
                "--tls-key", certificates.clientKey.string()});
    EXPECT_EQ(untrusted.code, 5);
    EXPECT_NE(untrusted.err.find("TLS"), std::string::npos) << untrusted.err;
    EXPECT_EQ(runCli({"pacs", "echo", "--node", node, "--tls-cert", "c.pem"}).code, 2);
}
