// SPDX-License-Identifier: GPL-3.0-or-later
// DICOM networking against a real Orthanc started by the test (OrthancServer):
// C-ECHO and its failures, C-STORE of the synthetic CTA series, C-FIND at
// study and series level, C-GET into the local store, C-MOVE to our own
// storage SCP, and the faults (unknown node pushing, Orthanc killed in the
// middle of a retrieve, cancel, a too-big C-FIND answer).
#include <gtest/gtest.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <future>
#include <memory>
#include <optional>
#include <set>
#include <stop_token>
#include <thread>

#include "FileLock.h"
#include "ListenerPeers.h"
#include "OrthancServer.h"
#include "PacsTestUtil.h"
#include "TcpTable.h"
#include "vv/core/Error.h"
#include "vv/pacs/Echo.h"
#include "vv/pacs/Find.h"
#include "vv/pacs/PacsError.h"
#include "vv/pacs/Retrieve.h"
#include "vv/pacs/Send.h"
#include "vv/pacs/StorageScp.h"

namespace fs = std::filesystem;
using namespace vv::pacs;
using vv::test::OrthancServer;

namespace {

constexpr const char* kOurAe = "VVTEST";
constexpr int kSlices = 12;

LocalAe me() {
    return LocalAe{kOurAe, Timeouts{2, 5, 10}};
}

fs::path freshFolder(const std::string& name) {
    // Per process: ctest runs the tests of this file in parallel processes.
    const fs::path folder = fs::path(VV_TEST_TMP) / ("pacs-" + std::to_string(::getpid())) / name;
    fs::remove_all(folder);
    return folder;
}

/// The synthetic CTA series of `patientId`; returns its files.
std::vector<fs::path> ctaFiles(const std::string& patientId = "VV-PACS-1") {
    return vv::test::writeCtaFiles(freshFolder("series-" + patientId), patientId, kSlices, 24);
}

/// Stores the series into `orthanc` and returns its Study Instance UID.
std::string load(const OrthancServer& orthanc, const std::string& patientId = "VV-PACS-1") {
    const auto statuses = sendFiles(me(), orthanc.node(), ctaFiles(patientId));
    EXPECT_EQ(statuses.size(), static_cast<std::size_t>(kSlices));
    for (const SendStatus& s : statuses) {
        EXPECT_TRUE(s.accepted) << s.file << " status " << s.status;
    }
    StudyQuery query;
    query.patientId = patientId;
    const auto studies = findStudies(me(), orthanc.node(), query);
    EXPECT_EQ(studies.size(), 1U);
    return studies.empty() ? std::string() : studies[0].studyInstanceUid;
}

/// Waits (bounded) until `store` lists a study.
std::vector<StoredStudy> waitForStudies(const LocalStore& store) {
    vv::test::waitUntil([&] { return !store.studies().empty(); });
    return store.studies();
}

class PacsTest : public ::testing::Test {
  protected:
    static void SetUpTestSuite() {
        scpPort_ = vv::test::freePort();
        orthanc_ = std::make_unique<OrthancServer>(kOurAe, scpPort_);
        studyUid_ = load(*orthanc_);
    }
    static void TearDownTestSuite() { orthanc_.reset(); }

    static std::unique_ptr<OrthancServer> orthanc_;
    static std::uint16_t scpPort_;
    static std::string studyUid_;
};

std::unique_ptr<OrthancServer> PacsTest::orthanc_;
std::uint16_t PacsTest::scpPort_ = 0;
std::string PacsTest::studyUid_;

}  // namespace

TEST_F(PacsTest, EchoSucceeds) {
    EXPECT_NO_THROW(echo(me(), orthanc_->node()));
}

TEST_F(PacsTest, WrongCalledAeTitleIsRejected) {
    Node wrong = orthanc_->node();
    wrong.aeTitle = "NOTORTHANC";
    EXPECT_THROW(echo(me(), wrong), AssociationRejectedError);
}

TEST_F(PacsTest, UnknownCallingAeTitleIsRejected) {
    const LocalAe stranger{"STRANGER", Timeouts{2, 5, 10}};
    EXPECT_THROW(echo(stranger, orthanc_->node()), AssociationRejectedError);
}

// The ports the tests' listeners take (a connection made meanwhile took one
// from under a listener in CI: "Address already in use").
TEST(TestPortsTest, AreOutsideTheEphemeralRangeUnusedAndReservedUntilTheProcessEnds) {
    const auto [first, last] = vv::test::ephemeralPorts();
    const bool roomOutside = first > 11000 || last < 64535;
    std::set<std::uint16_t> seen;
    for (int i = 0; i < 20; ++i) {
        const std::uint16_t port = vv::test::freePort();
        EXPECT_TRUE(seen.insert(port).second) << port << " given twice";
        if (roomOutside) {
            EXPECT_TRUE(port < first || port > last)
                << port << " lies in the ephemeral range " << first << "-" << last;
        }
        // Another process (a new open file description) cannot reserve it.
        EXPECT_FALSE(vv::pacs::detail::FileLock::tryExclusive(vv::test::portLockFile(port)))
            << port << " is not reserved";
        // And a listener can take it.
        const int listener = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
        sockaddr_in address{};
        address.sin_family = AF_INET;
        address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
        address.sin_port = htons(port);
        EXPECT_EQ(::bind(listener, reinterpret_cast<sockaddr*>(&address), sizeof address), 0)
            << port;
        EXPECT_EQ(::listen(listener, 1), 0) << port;
        ::close(listener);
    }
}

TEST(PacsFaultTest, RefusedPortIsConnectionRefused) {
    const Node nobody{"NOBODY", "127.0.0.1", vv::test::freePort(), {}};
    try {
        echo(me(), nobody);
        FAIL() << "echo to a closed port succeeded";
    } catch (const ConnectionRefusedError& e) {
        EXPECT_NE(std::string(e.what()).find("NOBODY@127.0.0.1"), std::string::npos) << e.what();
    }
}

TEST(PacsFaultTest, SilentPeerTimesOut) {
    const vv::test::SilentPeer peer;
    const Node silent{"SILENT", "127.0.0.1", peer.port(), {}};
    // Without the timeout the echo would wait for ever (ctest's limit ends the test).
    EXPECT_THROW(echo(LocalAe{kOurAe, Timeouts{2, 2, 2}}, silent), TimeoutError);
}

TEST(PacsFaultTest, APeerThatStallsInTheMiddleOfItsAnswerIsDroppedAfterTheResponseTimeout) {
    // The peer starts an A-ASSOCIATE-AC (a PDU header announcing 100 bytes),
    // sends 10 of them and goes silent without closing. DCMTK reads the rest
    // of a begun PDU with blocking reads bounded only by its global 60 s; our
    // layer bounds each read by the response timeout (2 s here).
    const vv::bench::RawServer server;
    auto answered = std::async(std::launch::async, [&] {
        try {
            echo(LocalAe{kOurAe, Timeouts{2, 2, 2}},
                 Node{"STALLS", "127.0.0.1", server.port(), {}});
        } catch (const NetworkError&) {
            return true;
        }
        return false;
    });
    const vv::bench::Connection peer = server.accept(10);
    ASSERT_TRUE(peer.receive(6, 10).has_value()) << "no association request came";
    peer.send({0x02, 0x00, 0x00, 0x00, 0x00, 100, 0x00, 0x01, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,
               0x00, 0x00});
    // A bound for a broken program only (the stall is 2 s; DCMTK's own, 60 s).
    ASSERT_EQ(answered.wait_for(std::chrono::seconds(30)), std::future_status::ready)
        << "the echo still waits on the stalled peer";
    EXPECT_TRUE(answered.get()) << "the echo did not fail";
}

/// Timeouts far beyond ctest's limit on a test (300 s): a call against a
/// silent peer with these ends only when something else ends it, so no test
/// needs to time it.
const Timeouts kLongerThanTheTest{5, 3600, 3600};

/// Runs `call(stop token)` against `peer` (which never answers), requests
/// the stop from another thread once the call's request waits at the peer,
/// and expects `call` to throw CancelledError. The callers' waits are
/// kLongerThanTheTest: a stop that only took effect when a wait ran out
/// would leave the test to ctest's limit.
template <typename Call>
void expectTheStopAbortsIt(const vv::test::SilentPeer& peer, Call call) {
    std::stop_source stop;
    std::thread canceller([&] {
        EXPECT_TRUE(vv::test::waitUntil([&] { return vv::test::unreadBytesAt(peer.port()) > 0; }))
            << "no request reached the peer";
        stop.request_stop();
    });
    bool cancelled = false;
    try {
        call(stop.get_token());
    } catch (const vv::CancelledError&) {
        cancelled = true;
    } catch (const std::exception& e) {
        ADD_FAILURE() << "not cancelled: " << e.what();
    }
    canceller.join();
    EXPECT_TRUE(cancelled);
}

TEST(PacsFaultTest, AStopAbortsAnEchoWaitingForASilentPeerAtOnce) {
    const vv::test::SilentPeer peer;
    const Node silent{"SILENT", "127.0.0.1", peer.port(), {}};
    const LocalAe patient{kOurAe, kLongerThanTheTest};
    expectTheStopAbortsIt(peer,
                          [&](std::stop_token stop) { echo(patient, silent, std::move(stop)); });
}

TEST(PacsFaultTest, AStopAbortsAFindWaitingForASilentPeerAtOnce) {
    const vv::test::SilentPeer peer;
    const Node silent{"SILENT", "127.0.0.1", peer.port(), {}};
    const LocalAe patient{kOurAe, kLongerThanTheTest};
    expectTheStopAbortsIt(peer, [&](std::stop_token stop) {
        (void)findStudies(patient, silent, StudyQuery{}, {}, std::move(stop));
    });
}

TEST(PacsFaultTest, AStopRequestedBeforeTheCallCancelsIt) {
    const vv::test::SilentPeer peer;
    const Node silent{"SILENT", "127.0.0.1", peer.port(), {}};
    std::stop_source stop;
    stop.request_stop();
    // Not connected at all: the waits are longer than the test may take.
    EXPECT_THROW(echo(LocalAe{kOurAe, kLongerThanTheTest}, silent, stop.get_token()),
                 vv::CancelledError);
}

TEST_F(PacsTest, FindsTheStudyByItsKeys) {
    StudyQuery byName;
    byName.patientName = "VesselView*";
    byName.modality = "CT";
    byName.studyDateFrom = "19000101";
    const auto studies = findStudies(me(), orthanc_->node(), byName);
    ASSERT_EQ(studies.size(), 1U);
    EXPECT_EQ(studies[0].studyInstanceUid, studyUid_);
    EXPECT_EQ(studies[0].patientId, "VV-PACS-1");
    EXPECT_EQ(studies[0].studyDescription, "VesselView demo");
    EXPECT_EQ(studies[0].numberOfSeries, 1);

    StudyQuery none;
    none.patientId = "SOMEONE-ELSE";
    EXPECT_TRUE(findStudies(me(), orthanc_->node(), none).empty());
    StudyQuery future;
    future.studyDateFrom = "29990101";
    EXPECT_TRUE(findStudies(me(), orthanc_->node(), future).empty());
}

TEST_F(PacsTest, FindAndEchoThatCanBeStoppedWorkAsUsualWhenNotStopped) {
    const std::stop_source stop;  // never requested: the abortable transport is in place
    StudyQuery byId;
    byId.patientId = "VV-PACS-1";
    const auto studies = findStudies(me(), orthanc_->node(), byId, {}, stop.get_token());
    ASSERT_EQ(studies.size(), 1U);
    EXPECT_EQ(studies[0].studyInstanceUid, studyUid_);
    EXPECT_NO_THROW(echo(me(), orthanc_->node(), stop.get_token()));
}

TEST_F(PacsTest, FindsTheSeriesOfTheStudy) {
    const auto series = findSeries(me(), orthanc_->node(), SeriesQuery{studyUid_, "", ""});
    ASSERT_EQ(series.size(), 1U);
    EXPECT_EQ(series[0].modality, "CT");
    EXPECT_EQ(series[0].seriesDescription, "synthetic CTA");
    EXPECT_EQ(series[0].numberOfInstances, kSlices);
}

TEST_F(PacsTest, TooManyMatchesAreAClearError) {
    FindLimits limits;
    limits.maxResults = 0;
    // Typed, with the limit it exceeded (the GUI says the number).
    try {
        (void)findStudies(me(), orthanc_->node(), StudyQuery{}, limits);
        ADD_FAILURE() << "no TooManyMatchesError";
    } catch (const TooManyMatchesError& e) {
        EXPECT_EQ(e.limit(), 0U);
    }
    FindLimits shortValues;
    shortValues.maxValueLength = 4;
    try {
        (void)findStudies(me(), orthanc_->node(), StudyQuery{}, shortValues);
        ADD_FAILURE() << "no ResponseError";
    } catch (const TooManyMatchesError&) {
        ADD_FAILURE() << "an oversized value is not too many matches";
    } catch (const ResponseError&) {
    }
    // The association is still usable afterwards.
    EXPECT_EQ(findStudies(me(), orthanc_->node(), StudyQuery{}).size(), 1U);
}

TEST_F(PacsTest, MalformedQueryKeysAreRefusedBeforeConnecting) {
    StudyQuery bad;
    bad.patientId = "A\\B";
    EXPECT_THROW(findStudies(me(), orthanc_->node(), bad), vv::InvalidArgumentError);
    StudyQuery badDate;
    badDate.studyDateFrom = "2024-01-01";
    EXPECT_THROW(findStudies(me(), orthanc_->node(), badDate), vv::InvalidArgumentError);
}

TEST_F(PacsTest, GetRetrievesTheStudyIntoTheStore) {
    LocalStore store(freshFolder("get"));
    double lastFraction = -1.0;
    const vv::Progress progress([&](double f, std::string_view) { lastFraction = f; }, {});
    const RetrieveResult result =
        getInto(store, me(), orthanc_->node(), RetrieveRequest{studyUid_, ""}, progress);
    EXPECT_EQ(result.instances, static_cast<std::size_t>(kSlices));
    const auto studies = store.studies();
    ASSERT_EQ(studies.size(), 1U);
    EXPECT_EQ(studies[0].studyInstanceUid, studyUid_);
    ASSERT_EQ(studies[0].series.size(), 1U);
    EXPECT_EQ(studies[0].series[0].instances, kSlices);
    EXPECT_EQ(std::distance(fs::directory_iterator(studies[0].series[0].folder),
                            fs::directory_iterator()),
              kSlices);
    EXPECT_DOUBLE_EQ(lastFraction, 1.0);
}

TEST_F(PacsTest, CancelledGetLeavesNothingComplete) {
    LocalStore store(freshFolder("cancel"));
    std::stop_source stop;
    const vv::Progress progress([&](double, std::string_view) { stop.request_stop(); },
                                stop.get_token());
    EXPECT_THROW(getInto(store, me(), orthanc_->node(), RetrieveRequest{studyUid_, ""}, progress),
                 vv::CancelledError);
    EXPECT_TRUE(store.studies().empty());
    EXPECT_TRUE(fs::is_empty(store.root() / ".incoming"));
    EXPECT_NO_THROW(echo(me(), orthanc_->node())) << "the peer still answers";
}

TEST_F(PacsTest, MoveToOurListenerStoresTheStudy) {
    LocalStore store(freshFolder("move"));
    ListenerConfig config;
    config.aeTitle = kOurAe;
    config.port = scpPort_;
    config.allowedPeers = {orthanc_->node()};
    StorageScp listener(store, config);
    const RetrieveResult result =
        moveTo(kOurAe, me(), orthanc_->node(), RetrieveRequest{studyUid_, ""});
    EXPECT_EQ(result.instances, static_cast<std::size_t>(kSlices));
    const auto studies = waitForStudies(store);
    ASSERT_EQ(studies.size(), 1U);
    ASSERT_EQ(studies[0].series.size(), 1U);
    EXPECT_EQ(studies[0].series[0].instances, kSlices);
    EXPECT_EQ(listener.stats().committedInstances, static_cast<std::size_t>(kSlices));
}

TEST_F(PacsTest, UnknownNodePushingIsRefusedAndNothingStored) {
    LocalStore store(freshFolder("refuse"));
    ListenerConfig config;
    config.aeTitle = "VVLISTEN";
    config.port = vv::test::freePort();
    config.allowedPeers = {orthanc_->node()};
    StorageScp listener(store, config);
    const Node ourListener{"VVLISTEN", "127.0.0.1", config.port, {}};
    const LocalAe stranger{"STRANGER", Timeouts{2, 5, 10}};
    EXPECT_THROW(sendFiles(stranger, ourListener, ctaFiles("VV-PACS-STRANGER")),
                 AssociationRejectedError);
    EXPECT_EQ(listener.stats().refusedAssociations, 1U);
    EXPECT_TRUE(store.studies().empty());
    EXPECT_TRUE(fs::is_empty(store.root() / ".incoming"));
}

TEST(PacsFaultTest, OrthancKilledDuringRetrieveLeavesNothingComplete) {
    OrthancServer orthanc(kOurAe, vv::test::freePort());
    const std::string studyUid = load(orthanc, "VV-PACS-KILL");
    LocalStore store(freshFolder("kill"));
    bool killed = false;
    const vv::Progress progress = vv::test::atFirstReport(&killed, [&] { orthanc.kill(); });
    std::optional<TransferProgress> transfer;
    try {
        (void)getInto(store, me(), orthanc.node(), RetrieveRequest{studyUid, ""}, progress);
        ADD_FAILURE() << "the retrieve from a killed peer succeeded";
    } catch (const NetworkError& e) {
        transfer = e.transfer();
    }
    EXPECT_TRUE(killed);
    // The error says how far it came: some of the series' images, not all.
    ASSERT_TRUE(transfer.has_value());
    EXPECT_GT(transfer->received, 0U);
    ASSERT_TRUE(transfer->expected.has_value());
    EXPECT_LT(transfer->received, *transfer->expected);
    EXPECT_TRUE(store.studies().empty());
    EXPECT_TRUE(fs::is_empty(store.root() / ".incoming"));
}

TEST(PacsListenerTest, AssociationOverTheSizeCapIsRefusedAndDiscarded) {
    LocalStore store(freshFolder("cap"));
    const auto files = ctaFiles("VV-PACS-CAP");
    ListenerConfig config;
    config.aeTitle = "VVLISTEN";
    config.port = vv::test::freePort();
    config.allowedPeers = {Node{"SENDER", "127.0.0.1", 104, {}}};
    config.limits.maxInstanceBytes = fs::file_size(files[0]) * 2;
    config.limits.maxAssociationBytes = fs::file_size(files[0]) * 5 / 2;  // room for two instances
    StorageScp listener(store, config);
    const auto statuses = sendFiles(LocalAe{"SENDER", Timeouts{2, 5, 10}},
                                    Node{"VVLISTEN", "127.0.0.1", config.port, {}}, files);
    ASSERT_EQ(statuses.size(), files.size());
    EXPECT_TRUE(statuses[0].accepted);
    EXPECT_TRUE(statuses[1].accepted);
    for (std::size_t i = 2; i < statuses.size(); ++i) {
        EXPECT_FALSE(statuses[i].accepted) << i;
    }
    EXPECT_TRUE(store.studies().empty()) << "an association over the cap stores nothing";
    EXPECT_EQ(listener.stats().discardedAssociations, 1U);
}

TEST(PacsListenerTest, KnownAeTitleFromAnotherHostIsRefused) {
    LocalStore store(freshFolder("host"));
    ListenerConfig config;
    config.aeTitle = "VVLISTEN";
    config.port = vv::test::freePort();
    config.allowedPeers = {Node{"SENDER", "127.0.0.2", 104, {}}};  // we call from 127.0.0.1
    StorageScp listener(store, config);
    EXPECT_THROW(
        sendFiles(LocalAe{"SENDER", Timeouts{2, 5, 10}},
                  Node{"VVLISTEN", "127.0.0.1", config.port, {}}, ctaFiles("VV-PACS-HOST")),
        AssociationRejectedError);
    EXPECT_EQ(listener.stats().refusedAssociations, 1U);
    EXPECT_TRUE(store.studies().empty());
}

TEST(PacsListenerTest, ListensOnTheConfiguredInterfaceOnly) {
    LocalStore store(freshFolder("bind"));
    ListenerConfig config;
    config.aeTitle = "VVLISTEN";
    config.port = vv::test::freePort();
    config.bindAddress = "127.0.0.2";
    config.allowedPeers = {Node{"SENDER", "127.0.0.1", 104, {}}};
    const StorageScp listener(store, config);
    const LocalAe sender{"SENDER", Timeouts{2, 5, 10}};
    EXPECT_NO_THROW(echo(sender, Node{"VVLISTEN", "127.0.0.2", config.port, {}}));
    EXPECT_THROW(echo(sender, Node{"VVLISTEN", "127.0.0.1", config.port, {}}),
                 ConnectionRefusedError);
}

TEST(PacsListenerTest, AnAddressNotOfThisHostIsAClearError) {
    LocalStore store(freshFolder("bind-bad"));
    ListenerConfig config;
    config.port = vv::test::freePort();
    config.bindAddress = "192.0.2.1";  // TEST-NET-1: not an address of this machine
    EXPECT_THROW(StorageScp(store, config), vv::IoError);
    config.bindAddress = "localhost";
    EXPECT_THROW(StorageScp(store, config), vv::InvalidArgumentError);
}

TEST(PacsListenerTest, WrongCalledAeTitleIsRefused) {
    LocalStore store(freshFolder("called"));
    ListenerConfig config;
    config.aeTitle = "VVLISTEN";
    config.port = vv::test::freePort();
    config.allowedPeers = {Node{"SENDER", "127.0.0.1", 104, {}}};
    const StorageScp listener(store, config);
    const LocalAe sender{"SENDER", Timeouts{2, 5, 10}};
    EXPECT_NO_THROW(echo(sender, Node{"VVLISTEN", "127.0.0.1", config.port, {}}));
    EXPECT_THROW(echo(sender, Node{"NOTUS", "127.0.0.1", config.port, {}}),
                 AssociationRejectedError);
    EXPECT_EQ(listener.stats().refusedAssociations, 1U);
}
