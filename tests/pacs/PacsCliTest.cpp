// SPDX-License-Identifier: GPL-3.0-or-later
// `vesselview-cli pacs echo|find|get|send|listen` against a real Orthanc
// (OrthancServer): outputs, the store it fills, and exit status 5 when the
// peer refuses or fails.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <future>
#include <iterator>
#include <memory>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "CliRun.h"
#include "ListenerPeers.h"
#include "OrthancServer.h"
#include "PacsTestUtil.h"
#include "vv/pacs/Echo.h"
#include "vv/pacs/Find.h"
#include "vv/pacs/LocalStore.h"
#include "vv/pacs/PacsError.h"
#include "vv/pacs/Send.h"
#include "vv/pacs/StorageScp.h"

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

/// Polls (bounded) until the listener at `listener` answers a C-ECHO from
/// `me`: it is listening, with no guess of how long that takes.
bool answersEcho(const vv::pacs::LocalAe& me, const vv::pacs::Node& listener) {
    return vv::test::waitUntil([&] {
        try {
            vv::pacs::echo(me, listener);
            return true;
        } catch (const vv::pacs::NetworkError&) {
            return false;
        }
    });
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

/// The listener's limits on `pacs listen` and `pacs get --move`: a value out
/// of its range, or limits that do not fit together, are usage errors naming
/// the options; only a listener takes them.
TEST(PacsCliTest, ListenerLimitsOutOfRangeOrNotFittingAreUsageErrorsNamingTheOption) {
    const std::vector<std::string> listen = {"pacs", "listen", "--store", "/tmp/s", "--port", "1"};
    const std::vector<std::vector<std::string>> bad = {
        {"--max-associations", "0"},   {"--max-associations", "257"},
        {"--max-associations", "two"}, {"--max-per-address", "0"},
        {"--max-per-address", "1025"}, {"--max-connections", "0"},
        {"--max-connections", "1025"}, {"--request-timeout", "0"},
        {"--request-timeout", "121"},  {"--request-timeout", "1.5"},
        {"--max-instance", "999"},     {"--max-instance", "1.5GB"},
        {"--max-instance", "1TB"},     {"--max-association", "GB"},
        {"--max-association", "-1"},   {"--max-association", "99999999999GB"},
    };
    for (const auto& option : bad) {
        auto args = listen;
        args.insert(args.end(), option.begin(), option.end());
        const auto run = runCli(args);
        EXPECT_EQ(run.code, 2) << option[0] << " " << option[1];
        EXPECT_NE(run.err.find(option[0]), std::string::npos) << run.err;
    }
    // Limits that do not fit together name both options, with the values in force.
    const std::vector<std::pair<std::vector<std::string>, std::vector<std::string>>> conflicts = {
        {{"--max-connections", "8"}, {"--max-connections (8)", "--max-associations (16)"}},
        {{"--max-associations", "100"}, {"--max-connections (64)", "--max-associations (100)"}},
        {{"--max-per-address", "65"}, {"--max-per-address (65)", "--max-connections (64)"}},
        {{"--max-association", "1GB"},
         {"--max-association (1000000000)", "--max-instance (4000000000)"}},
    };
    for (const auto& [options, named] : conflicts) {
        auto args = listen;
        args.insert(args.end(), options.begin(), options.end());
        const auto run = runCli(args);
        EXPECT_EQ(run.code, 2) << options[0];
        for (const std::string& text : named) {
            EXPECT_NE(run.err.find(text), std::string::npos) << run.err;
        }
    }
    // Valid limits pass to the listener of get --move, which starts; the node is not there.
    const auto valid = runCli({"pacs",
                               "get",
                               "--node",
                               "A@127.0.0.1:" + std::to_string(vv::test::freePort()),
                               "--study",
                               "1.2.3",
                               "--store",
                               (vv::test::processTestDir("pacs-cli") / "limits").string(),
                               "--move",
                               "--port",
                               std::to_string(vv::test::freePort()),
                               "--max-associations",
                               "4",
                               "--max-per-address",
                               "2",
                               "--max-connections",
                               "8",
                               "--request-timeout",
                               "30",
                               "--max-instance",
                               "500MB",
                               "--max-association",
                               "2GB"});
    EXPECT_EQ(valid.code, 5) << valid.err;
    EXPECT_NE(valid.err.find("cannot connect"), std::string::npos) << valid.err;
    // Only a listener has limits: get without --move, and send, refuse them.
    const auto get = runCli({"pacs", "get", "--node", "A@127.0.0.1:1", "--study", "1.2.3",
                             "--store", "/tmp/s", "--max-associations", "4"});
    EXPECT_EQ(get.code, 2);
    EXPECT_NE(get.err.find("--max-associations needs --move"), std::string::npos) << get.err;
    EXPECT_EQ(
        runCli({"pacs", "send", "--node", "A@127.0.0.1:1", "--max-instance", "1GB", "f.dcm"}).code,
        2);
    // The store limit's NGB no longer wraps around 2^64 either.
    const auto huge = runCli({"pacs", "get", "--node", "A@127.0.0.1:1", "--study", "1.2.3",
                              "--store", "/tmp/s", "--store-limit", "99999999999GB"});
    EXPECT_EQ(huge.code, 2);
    EXPECT_NE(huge.err.find("--store-limit"), std::string::npos) << huge.err;
}

/// --help gives each limit's default as pacs::ListenerLimits has it.
TEST(PacsCliTest, HelpGivesTheListenerLimitsDefaults) {
    const auto help = runCli({"--help"});
    const vv::pacs::ListenerLimits defaults;
    for (const std::string& text :
         {"--max-associations N (" + std::to_string(defaults.maxAssociations) + ")",
          "--max-per-address N (" + std::to_string(defaults.maxConnectionsPerAddress) + ")",
          "--max-connections N (" + std::to_string(defaults.maxConnections) + ")",
          "--request-timeout S (" + std::to_string(defaults.requestSeconds) + ")",
          "--max-instance BYTES|NMB|NGB (" +
              std::to_string(defaults.maxInstanceBytes / 1000000000) + "GB)",
          "--max-association SIZE (" + std::to_string(defaults.maxAssociationBytes / 1000000000) +
              "GB)",
          "other hosts: " +
              std::to_string(vv::pacs::ListenerLimits::kStrangerConnectionsPerAddress) + "\n"}) {
        EXPECT_NE(help.out.find(text), std::string::npos) << text;
    }
}

/// `pacs listen` as a program of its own: started with `args`, output into
/// `log`, stopped with SIGTERM (as a service manager stops it).
class ListenProcess {
  public:
    ListenProcess(std::vector<std::string> args, const fs::path& log)
        : pid_(spawn(std::move(args), log)) {}
    ~ListenProcess() { (void)stop(); }
    ListenProcess(const ListenProcess&) = delete;
    ListenProcess& operator=(const ListenProcess&) = delete;
    ListenProcess(ListenProcess&&) = delete;
    ListenProcess& operator=(ListenProcess&&) = delete;

    /// SIGTERM, and its exit status (-1 when it did not exit normally).
    int stop() {
        if (pid_ <= 0) {
            return -1;
        }
        ::kill(pid_, SIGTERM);
        int status = 0;
        ::waitpid(pid_, &status, 0);
        pid_ = -1;
        return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    }

  private:
    static pid_t spawn(std::vector<std::string> args, const fs::path& log) {
        args.insert(args.begin(), VV_CLI_EXE);
        std::vector<char*> argv;
        argv.reserve(args.size() + 1);
        for (std::string& arg : args) {
            argv.push_back(arg.data());
        }
        argv.push_back(nullptr);
        const pid_t pid = ::fork();
        if (pid == 0) {
            // NOLINTNEXTLINE(cppcoreguidelines-pro-type-vararg): POSIX open()
            const int out = ::open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
            ::dup2(out, 1);
            ::dup2(out, 2);
            ::execv(VV_CLI_EXE, argv.data());
            ::_exit(127);
        }
        return pid;
    }

    pid_t pid_;
};

/// A connection from 127.0.0.1 to `port`, polled for (bounded) until the
/// listener there accepts; nullopt when it never did.
std::optional<vv::bench::Connection> connectWhenListening(std::uint16_t port) {
    std::optional<vv::bench::Connection> connection;
    vv::test::waitUntil([&] {
        try {
            connection = vv::bench::Connection::open("127.0.0.1", port, 5);
            return true;
        } catch (const std::runtime_error&) {  // not listening yet
            return false;
        }
    });
    return connection;
}

/// Needs the listener core of issue 31 (the per-address cap).
TEST(PacsCliTest, ListenWithOneConnectionPerAddressClosesASecondOne) {
    const std::uint16_t port = vv::test::freePort();
    const fs::path folder = vv::test::processTestDir("pacs-cli") / "listen-limits";
    fs::remove_all(folder);
    fs::create_directories(folder);
    ListenProcess listening({"pacs",
                             "listen",
                             "--store",
                             (folder / "store").string(),
                             "--port",
                             std::to_string(port),
                             "--bind",
                             "127.0.0.1",
                             "--allow",
                             "SENDER@127.0.0.1",
                             "--for",
                             "120",
                             "--max-per-address",
                             "1",
                             "--max-associations",
                             "2",
                             "--max-connections",
                             "4",
                             "--request-timeout",
                             "60",
                             "--max-instance",
                             "500MB",
                             "--max-association",
                             "1GB"},
                            folder / "listen.log");
    const auto first = connectWhenListening(port);
    ASSERT_TRUE(first.has_value()) << "the listener never came up";
    // Started, not waited for: the listener may reset it before the connect
    // is seen to complete (open() would throw then), which is the refusal
    // this test wants; closedByPeer() sees both.
    const auto second = vv::bench::Connection::start("127.0.0.1", port);
    EXPECT_TRUE(second.closedByPeer(10))
        << "a second connection from 127.0.0.1 stays open over --max-per-address 1";
    EXPECT_FALSE(first->closedByPeer(0)) << "the connection within the cap was closed";
    EXPECT_EQ(listening.stop(), 0);
    std::ifstream log(folder / "listen.log");
    const std::string output{std::istreambuf_iterator<char>(log), {}};
    EXPECT_NE(output.find("stored 0 instance(s)"), std::string::npos) << output;
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
    const vv::pacs::Node listener{"VVLISTEN", "127.0.0.1", port, {}};
    ASSERT_TRUE(answersEcho(vv::pacs::LocalAe{"SENDER", {2, 5, 10}}, listener));
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
    const vv::pacs::Node trusted{
        "VVLISTEN",
        "127.0.0.1",
        port,
        {true, certificates.ca, certificates.clientCert, certificates.clientKey}};
    ASSERT_TRUE(answersEcho(vv::pacs::LocalAe{"SENDER", {2, 5, 10}}, trusted));
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
