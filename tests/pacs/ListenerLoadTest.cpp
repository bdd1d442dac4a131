// SPDX-License-Identifier: GPL-3.0-or-later
// The listener (storage SCP) under load and abuse, black-box through real
// sockets (issue 31): 200 idle connections from an address that is no
// configured node while a node stores; ten nodes storing at once; a node
// that stalls while another stores; an instance over the size cap; a sender
// killed (vv_send_helper, SIGKILL) or frozen (SIGSTOP) in the middle of a
// dataset; a truncated PDU after a real DCMTK association request; garbage
// bytes; a silent connection; the listener destroyed while busy. Each time:
// nothing half-written in the store, an empty staging folder, and the next
// association is served. Connections from 127.0.0.2 come from "another host"
// (loopback: a client socket bound to 127.0.0.2 reaches a listener on
// 127.0.0.1 and is seen as coming from there).
#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <cstdint>
#include <filesystem>
#include <future>
#include <map>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "ListenerPeers.h"
#include "OrthancServer.h"
#include "PacsTestUtil.h"
#include "vv/pacs/Echo.h"
#include "vv/pacs/PacsError.h"
#include "vv/pacs/Send.h"
#include "vv/pacs/StorageScp.h"

namespace listener_load_test {

namespace fs = std::filesystem;
using namespace vv::pacs;
using vv::bench::Bytes;
using vv::bench::ChildProcess;
using vv::bench::Connection;
using vv::bench::storedInstances;
using vv::test::waitUntil;

namespace {

constexpr const char* kListenerAe = "VVLISTEN";
constexpr const char* kSenderAe = "SENDER";
constexpr const char* kStranger = "127.0.0.2";  ///< no configured node's host
constexpr std::uint16_t kOutOfResources = 0xA700;

fs::path freshFolder(const std::string& name) {
    fs::path folder =
        fs::path(VV_TEST_TMP) / ("listener-load-" + std::to_string(::getpid())) / name;
    fs::remove_all(folder);
    return folder;
}

/// A listener on 127.0.0.1 that lets SENDER@127.0.0.1 in; connections have
/// 2 s to present their association request.
ListenerConfig listenerConfig() {
    ListenerConfig config;
    config.aeTitle = kListenerAe;
    config.port = vv::test::freePort();
    config.allowedPeers = {Node{kSenderAe, "127.0.0.1", 104, {}}};
    config.limits.requestSeconds = 2;
    return config;
}

Node nodeOf(const ListenerConfig& config) {
    return Node{kListenerAe, "127.0.0.1", config.port, {}};
}

/// A sender with generous timeouts: the listener, not the sender, must be quick.
LocalAe sender(const std::string& aeTitle = kSenderAe) {
    return LocalAe{aeTitle, Timeouts{10, 30, 30}};
}

bool stagingEmpty(const LocalStore& store) {
    const fs::path incoming = store.root() / ".incoming";
    return !fs::exists(incoming) || fs::is_empty(incoming);
}

/// Sends `files` and expects every one accepted; a failed association is a
/// test failure, not an exception.
void expectStored(const ListenerConfig& config, const std::vector<fs::path>& files,
                  const LocalAe& me = sender()) {
    try {
        const auto statuses = sendFiles(me, nodeOf(config), files);
        ASSERT_EQ(statuses.size(), files.size());
        for (const SendStatus& s : statuses) {
            EXPECT_TRUE(s.accepted) << s.file << " status " << s.status;
        }
    } catch (const std::exception& e) {
        ADD_FAILURE() << me.aeTitle << " could not store: " << e.what();
    }
}

/// The listener of `config` serves the next association: a new series of 8
/// instances from SENDER arrives in `store` in full.
void expectNextStoreServed(const ListenerConfig& config, const LocalStore& store,
                           const std::string& name) {
    const std::size_t before = storedInstances(store);
    const auto next =
        vv::test::writeCtaFiles(freshFolder(name + "/next"), "VV-LOAD-" + name + "-NEXT", 8);
    expectStored(config, next);
    EXPECT_TRUE(waitUntil([&] { return storedInstances(store) == before + next.size(); }));
    EXPECT_TRUE(waitUntil([&] { return stagingEmpty(store); }));
}

/// The one association the listener had is broken off: counted as
/// discarded, nothing of it in the store or the staging folder.
void expectBrokenOffAndGone(const StorageScp& listener, const LocalStore& store) {
    EXPECT_TRUE(waitUntil([&] { return listener.stats().discardedAssociations == 1; }));
    EXPECT_TRUE(store.studies().empty());
    EXPECT_EQ(listener.stats().committedInstances, 0U);
    EXPECT_TRUE(waitUntil([&] { return stagingEmpty(store); }));
}

/// A synthetic CTA series of `slices` small images, the last of them
/// replaced by one of `bigSide` x `bigSide` pixels (same series).
std::vector<fs::path> seriesWithABigLast(const std::string& name, int slices, int bigSide) {
    auto files = vv::test::writeCtaFiles(freshFolder(name), "VV-LOAD-" + name, slices);
    vv::bench::writeLargeImage(files.back(), files.back(), bigSide);
    return files;
}

/// vv_send_helper sending `files` as SENDER to the listener of `config`,
/// stalling in the middle of the last file's dataset: after all bytes of the
/// files before it (their datasets and commands are about as long as the
/// files) and half of the last one's.
std::unique_ptr<ChildProcess> senderStallingInTheLast(const ListenerConfig& config,
                                                      const std::vector<fs::path>& files) {
    std::uint64_t stall = fs::file_size(files.back()) / 2;
    for (std::size_t i = 0; i + 1 < files.size(); ++i) {
        stall += fs::file_size(files[i]);
    }
    std::vector<std::string> arguments = {std::to_string(config.port), kListenerAe, kSenderAe,
                                          std::to_string(stall)};
    for (const fs::path& f : files) {
        arguments.push_back(f.string());
    }
    return std::make_unique<ChildProcess>(VV_SEND_HELPER, arguments);
}

/// The A-ASSOCIATE-RQ PDU that a real DCMTK SCU (vv::pacs::echo as SENDER)
/// sends to VVLISTEN, as a plain server socket of ours receives it.
Bytes recordedAssociationRequest() {
    vv::bench::RawServer server;
    std::thread scu([port = server.port()] {
        try {
            echo(LocalAe{kSenderAe, Timeouts{5, 5, 5}}, Node{kListenerAe, "127.0.0.1", port, {}});
        } catch (const std::exception&) {  // we never answer
        }
    });
    Bytes pdu;
    {
        Connection c = server.accept(10);
        // PDU header: type, reserved, 32-bit big-endian length.
        const auto header = c.receive(6, 10);
        if (header) {
            const std::size_t length = (std::size_t{(*header)[2]} << 24U) |
                                       (std::size_t{(*header)[3]} << 16U) |
                                       (std::size_t{(*header)[4]} << 8U) | (*header)[5];
            const auto body = c.receive(length, 10);
            if (body) {
                pdu = *header;
                pdu.insert(pdu.end(), body->begin(), body->end());
            }
        }
    }  // closed: the SCU's association fails at once
    scu.join();
    return pdu;
}

/// A connection that has replayed the recorded association request to the
/// listener of `config` and read its A-ASSOCIATE-AC.
Connection associatedByReplay(const ListenerConfig& config) {
    const Bytes request = recordedAssociationRequest();
    EXPECT_FALSE(request.empty()) << "no association request recorded";
    EXPECT_TRUE(!request.empty() && request[0] == 0x01) << "not an A-ASSOCIATE-RQ";
    Connection c = Connection::open("127.0.0.1", config.port, 10);
    c.send(request);
    const auto header = c.receive(6, 10);
    EXPECT_TRUE(header.has_value()) << "no answer to the association request";
    EXPECT_TRUE(header && (*header)[0] == 0x02) << "not an A-ASSOCIATE-AC";
    return c;
}

/// A P-DATA-TF PDU that claims 1000 bytes and brings 10.
Bytes truncatedPdu() {
    Bytes pdu = {0x04, 0x00, 0x00, 0x00, 0x03, 0xE8};
    pdu.resize(pdu.size() + 10, 0x00);
    return pdu;
}

}  // namespace

TEST(ListenerLoadTest, ANodeStoresWhile200IdleConnectionsFromAStrangerAreHeldOpen) {
    LocalStore store(freshFolder("idle/store"));
    const auto files = vv::test::writeCtaFiles(freshFolder("idle/series"), "VV-LOAD-IDLE", 34);
    const ListenerConfig config = listenerConfig();
    StorageScp listener(store, config);
    constexpr int kIdle = 200;
    std::vector<Connection> idle = vv::bench::idleConnections(kStranger, config.port, kIdle);
    // A stranger keeps 2 connections at the most (until their request
    // deadline): every other one is closed at once.
    const auto kept = static_cast<std::size_t>(ListenerLimits::kStrangerConnectionsPerAddress);
    EXPECT_TRUE(waitUntil([&] {
        const ListenerStats s = listener.stats();
        return s.refusedConnections + s.droppedConnections >= kIdle - kept;
    })) << "refused "
        << listener.stats().refusedConnections;
    const ListenerStats during = listener.stats();
    // A few more than 198 may have got in when the first ones' 2 s were over.
    EXPECT_GE(during.refusedConnections, 190U);
    EXPECT_LE(during.openConnections, kept);

    expectStored(config, files);  // the strangers' connections still open
    EXPECT_TRUE(waitUntil([&] { return storedInstances(store) == files.size(); }));
    const auto studies = store.studies();
    ASSERT_EQ(studies.size(), 1U);
    ASSERT_EQ(studies[0].series.size(), 1U);
    EXPECT_EQ(studies[0].series[0].instances, 34);

    idle.clear();
    // Every stranger's connection counted, none served.
    EXPECT_TRUE(waitUntil([&] {
        const ListenerStats s = listener.stats();
        return s.refusedConnections + s.droppedConnections == kIdle && s.openConnections == 0;
    }));
    EXPECT_EQ(listener.stats().acceptedAssociations, 1U);
    EXPECT_TRUE(stagingEmpty(store));
}

TEST(ListenerLoadTest, TenNodesStoringAtOnceEachArriveOnce) {
    constexpr int kNodes = 10;
    constexpr int kSlices = 12;
    LocalStore store(freshFolder("ten/store"));
    ListenerConfig config = listenerConfig();
    config.allowedPeers.clear();
    std::vector<std::vector<fs::path>> series;
    for (int i = 0; i < kNodes; ++i) {
        const std::string n = std::to_string(i);
        config.allowedPeers.push_back(Node{"NODE" + n, "127.0.0.1", 104, {}});
        series.push_back(
            vv::test::writeCtaFiles(freshFolder("ten/series" + n), "VV-LOAD-NODE" + n, kSlices));
    }
    config.limits.maxConnectionsPerAddress = 2 * kNodes;  // all nodes share 127.0.0.1
    StorageScp listener(store, config);

    std::vector<std::thread> nodes;
    nodes.reserve(kNodes);
    for (int i = 0; i < kNodes; ++i) {
        nodes.emplace_back([&, i] {
            expectStored(config, series[static_cast<std::size_t>(i)],
                         sender("NODE" + std::to_string(i)));
        });
    }
    for (std::thread& t : nodes) {
        t.join();
    }

    const std::size_t all = std::size_t{kNodes} * kSlices;
    EXPECT_TRUE(waitUntil([&] { return storedInstances(store) == all; }))
        << storedInstances(store) << " of " << all;
    std::map<std::string, int> studiesOfPatient;
    for (const StoredStudy& study : store.studies()) {
        ++studiesOfPatient[study.patientId];
        ASSERT_EQ(study.series.size(), 1U) << study.patientId;
        EXPECT_EQ(study.series[0].instances, kSlices) << study.patientId;
    }
    EXPECT_EQ(studiesOfPatient.size(), static_cast<std::size_t>(kNodes));
    for (const auto& [patient, count] : studiesOfPatient) {
        EXPECT_EQ(count, 1) << patient;
    }
    const ListenerStats s = listener.stats();
    EXPECT_EQ(s.committedInstances, all);
    EXPECT_EQ(s.discardedAssociations, 0U);
    EXPECT_TRUE(waitUntil([&] { return stagingEmpty(store); }));
}

TEST(ListenerLoadTest, ANodeStuckInADatasetDoesNotHoldUpAnother) {
    LocalStore store(freshFolder("stuck/store"));
    ListenerConfig config = listenerConfig();
    config.allowedPeers.push_back(Node{"OTHER", "127.0.0.1", 104, {}});
    config.timeouts.responseSeconds = 60;  // the stuck sender keeps its association
    StorageScp listener(store, config);
    const auto stuckFiles = seriesWithABigLast("stuck-series", 8, 1024);
    const auto helper = senderStallingInTheLast(config, stuckFiles);
    ASSERT_EQ(helper->readLine(30), "stalled");

    const auto files = vv::test::writeCtaFiles(freshFolder("stuck/other"), "VV-LOAD-OTHER", 12);
    expectStored(config, files, LocalAe{"OTHER", Timeouts{5, 10, 10}});
    EXPECT_TRUE(waitUntil([&] { return storedInstances(store) == files.size(); }));

    EXPECT_TRUE(helper->end(SIGKILL, 10));
    EXPECT_TRUE(waitUntil([&] { return listener.stats().discardedAssociations == 1; }));
    ASSERT_EQ(store.studies().size(), 1U);
    EXPECT_EQ(store.studies()[0].patientId, "VV-LOAD-OTHER");
    EXPECT_TRUE(waitUntil([&] { return stagingEmpty(store); }));
}

TEST(ListenerLoadTest, WithEveryWorkerBusyTheNextAssociationIsRejectedAsTransientAndServedLater) {
    LocalStore store(freshFolder("busy/store"));
    ListenerConfig config = listenerConfig();
    config.allowedPeers.push_back(Node{"OTHER", "127.0.0.1", 104, {}});
    config.limits.maxAssociations = 1;
    config.timeouts.responseSeconds = 60;  // the stuck sender keeps the one worker
    StorageScp listener(store, config);
    const auto stuckFiles = seriesWithABigLast("busy-series", 8, 1024);
    const auto helper = senderStallingInTheLast(config, stuckFiles);
    ASSERT_EQ(helper->readLine(30), "stalled");
    ASSERT_EQ(listener.stats().activeAssociations, 1U);

    // What a peer receives: A-ASSOCIATE-RJ (type 3), result 2 (rejected,
    // transient: try again later), source 3 (service provider, presentation
    // related), reason 2 (local limit exceeded) — PS3.8 9.3.4.
    const Bytes request = recordedAssociationRequest();
    ASSERT_FALSE(request.empty());
    const Connection peer = Connection::open("127.0.0.1", config.port, 10);
    peer.send(request);
    const auto answer = peer.receive(10, 10);
    ASSERT_TRUE(answer.has_value()) << "no answer to the association request";
    EXPECT_EQ((*answer)[0], 0x03) << "not an A-ASSOCIATE-RJ";
    EXPECT_EQ((*answer)[7], 0x02) << "not transient";
    EXPECT_EQ((*answer)[8], 0x03) << "not from the service provider (presentation)";
    EXPECT_EQ((*answer)[9], 0x02) << "not \"local limit exceeded\"";
    const LocalAe other{"OTHER", Timeouts{5, 10, 10}};
    EXPECT_THROW(echo(other, nodeOf(config)), AssociationRejectedError);
    EXPECT_EQ(listener.stats().refusedAssociations, 2U);

    EXPECT_TRUE(helper->end(SIGKILL, 10));
    ASSERT_TRUE(waitUntil([&] { return listener.stats().activeAssociations == 0; }));
    EXPECT_NO_THROW(echo(other, nodeOf(config))) << "the freed worker serves the next one";
}

TEST(ListenerLoadTest, AnInstanceOverTheSizeCapIsRefusedAndTheRestStored) {
    LocalStore store(freshFolder("cap/store"));
    auto files = vv::test::writeCtaFiles(freshFolder("cap/series"), "VV-LOAD-CAP", 8);
    constexpr std::size_t kBig = 3;  // in the middle: the association goes on after it
    vv::bench::writeLargeImage(files[kBig], files[kBig], 256);
    ListenerConfig config = listenerConfig();
    config.limits.maxInstanceBytes = 4 * fs::file_size(files[0]);
    ASSERT_GT(fs::file_size(files[kBig]), 2 * config.limits.maxInstanceBytes);
    StorageScp listener(store, config);

    std::vector<SendStatus> statuses;
    try {
        statuses = sendFiles(sender(), nodeOf(config), files);
    } catch (const std::exception& e) {
        ADD_FAILURE() << e.what();
    }
    ASSERT_EQ(statuses.size(), files.size());
    for (std::size_t i = 0; i < files.size(); ++i) {
        if (i == kBig) {
            EXPECT_FALSE(statuses[i].accepted);
            EXPECT_EQ(statuses[i].status, kOutOfResources);
        } else {
            EXPECT_TRUE(statuses[i].accepted) << i << " status " << statuses[i].status;
        }
    }
    EXPECT_TRUE(waitUntil([&] { return storedInstances(store) == files.size() - 1; }));
    ASSERT_EQ(store.studies().size(), 1U);
    EXPECT_EQ(store.studies()[0].series[0].instances, static_cast<int>(files.size()) - 1);
    EXPECT_EQ(listener.stats().refusedInstances, 1U);
    EXPECT_EQ(listener.stats().committedInstances, files.size() - 1);
    EXPECT_EQ(listener.stats().discardedAssociations, 0U);

    expectNextStoreServed(config, store, "cap");
    EXPECT_EQ(store.studies().size(), 2U);
}

TEST(ListenerLoadTest, ASenderKilledInADatasetLeavesNothingBehind) {
    LocalStore store(freshFolder("kill/store"));
    const ListenerConfig config = listenerConfig();
    StorageScp listener(store, config);
    const auto files = seriesWithABigLast("kill-series", 8, 1024);
    const auto helper = senderStallingInTheLast(config, files);
    ASSERT_EQ(helper->readLine(30), "stalled");
    EXPECT_TRUE(helper->end(SIGKILL, 10));
    expectBrokenOffAndGone(listener, store);
    expectNextStoreServed(config, store, "kill");
}

TEST(ListenerLoadTest, ASenderFrozenInADatasetIsDroppedAfterTheResponseTimeout) {
    LocalStore store(freshFolder("frozen/store"));
    ListenerConfig config = listenerConfig();
    config.timeouts.responseSeconds = 2;
    StorageScp listener(store, config);
    const auto files = seriesWithABigLast("frozen-series", 8, 1024);
    const auto helper = senderStallingInTheLast(config, files);
    ASSERT_EQ(helper->readLine(30), "stalled");
    helper->signal(SIGSTOP);
    expectBrokenOffAndGone(listener, store);
    expectNextStoreServed(config, store, "frozen");
    EXPECT_TRUE(helper->end(SIGKILL, 10));
}

TEST(ListenerLoadTest, ATruncatedPduEndsOnlyItsOwnAssociation) {
    LocalStore store(freshFolder("truncated/store"));
    const ListenerConfig config = listenerConfig();
    StorageScp listener(store, config);
    {
        Connection c = associatedByReplay(config);
        c.send(truncatedPdu());
    }  // and closed
    EXPECT_NO_THROW(echo(sender(), nodeOf(config)));
    expectNextStoreServed(config, store, "truncated");
    EXPECT_EQ(store.studies().size(), 1U);
}

// The same PDU, but the peer stays connected and silent: the rest of the PDU
// is waited for no longer than the response timeout, and meanwhile the
// others are served.
TEST(ListenerLoadTest, ATruncatedPduLeftOpenIsDroppedAfterTheResponseTimeout) {
    LocalStore store(freshFolder("truncated-open/store"));
    ListenerConfig config = listenerConfig();
    config.timeouts.responseSeconds = 2;
    StorageScp listener(store, config);
    Connection c = associatedByReplay(config);
    c.send(truncatedPdu());
    EXPECT_NO_THROW(echo(LocalAe{kSenderAe, Timeouts{5, 5, 5}}, nodeOf(config)));
    EXPECT_TRUE(c.closedByPeer(15)) << "the listener still waits for the rest of the PDU";
    EXPECT_TRUE(store.studies().empty());
    EXPECT_TRUE(waitUntil([&] { return stagingEmpty(store); }));
}

TEST(ListenerLoadTest, GarbageBytesAreDroppedAndCounted) {
    LocalStore store(freshFolder("garbage/store"));
    const ListenerConfig config = listenerConfig();
    StorageScp listener(store, config);
    Connection c = Connection::open(kStranger, config.port, 10);
    const std::string http = "GET / HTTP/1.1\r\nHost: vesselview\r\n\r\n";
    c.send(Bytes(http.begin(), http.end()));
    EXPECT_TRUE(c.closedByPeer(10));
    EXPECT_TRUE(waitUntil([&] { return listener.stats().droppedConnections == 1; }));
    EXPECT_EQ(listener.stats().refusedAssociations, 0U) << "no association was asked for";
    EXPECT_NO_THROW(echo(sender(), nodeOf(config)));
}

TEST(ListenerLoadTest, ASilentConnectionIsDroppedWhileANodeIsServed) {
    LocalStore store(freshFolder("silent/store"));
    ListenerConfig config = listenerConfig();
    config.timeouts.associateSeconds = 30;  // the request deadline, not this, must end it
    StorageScp listener(store, config);
    Connection silent = Connection::open(kStranger, config.port, 10);
    EXPECT_NO_THROW(echo(LocalAe{kSenderAe, Timeouts{5, 5, 5}}, nodeOf(config)));
    EXPECT_TRUE(silent.closedByPeer(15)) << "the silent connection was not dropped";
    EXPECT_TRUE(waitUntil([&] { return listener.stats().droppedConnections == 1; }));
    EXPECT_EQ(listener.stats().acceptedAssociations, 1U);
}

TEST(ListenerLoadTest, DestroyingABusyListenerReturnsAndLeavesNothingBehind) {
    LocalStore store(freshFolder("stop/store"));
    ListenerConfig config = listenerConfig();
    config.limits.maxConnectionsPerAddress = 64;
    config.limits.maxConnections = 128;
    config.limits.requestSeconds = 60;     // the idle ones stay
    config.timeouts.responseSeconds = 60;  // and so does the stuck sender
    auto listener = std::make_unique<StorageScp>(store, config);
    const auto files = seriesWithABigLast("stop-series", 8, 1024);
    auto helper = senderStallingInTheLast(config, files);
    ASSERT_EQ(helper->readLine(30), "stalled");
    constexpr int kIdle = 50;
    std::vector<Connection> idle = vv::bench::idleConnections("127.0.0.1", config.port, kIdle);
    EXPECT_TRUE(waitUntil(
        [&] { return listener->stats().openConnections == static_cast<std::size_t>(kIdle) + 1; },
        std::chrono::seconds(10)));

    auto stopped = std::async(std::launch::async, [&listener] { listener.reset(); });
    const bool returned = stopped.wait_for(std::chrono::seconds(30)) == std::future_status::ready;
    EXPECT_TRUE(returned) << "the listener's destructor did not return in 30 s";
    if (!returned) {  // let it end, so that this test does
        helper.reset();
        idle.clear();
    }
    stopped.get();
    EXPECT_TRUE(store.studies().empty());
    EXPECT_TRUE(stagingEmpty(store));
}

}  // namespace listener_load_test
