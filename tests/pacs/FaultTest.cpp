// SPDX-License-Identifier: GPL-3.0-or-later
// Faults of the peer against a real Orthanc, beyond PacsTest's: a C-FIND
// answer with a malformed Study Instance UID (from an instance Orthanc
// accepted as it was; Orthanc drops over-long values from its answers, so
// PacsTest.TooManyMatchesAreAClearError checks the value limit with a lowered
// limit), Orthanc killed in the middle of a C-MOVE to our
// listener, and Orthanc frozen (SIGSTOP) in the middle of a C-GET so that it
// never answers. Each is a clear typed error, nothing half-written is marked
// complete, and the next request works.
#include <dcmtk/config/osconfig.h>
#include <dcmtk/dcmdata/dcdeftag.h>
#include <dcmtk/dcmdata/dcfilefo.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <string>
#include <thread>
#include <vector>

#include "OrthancServer.h"
#include "PacsTestUtil.h"
#include "vv/core/Progress.h"
#include "vv/pacs/Echo.h"
#include "vv/pacs/Find.h"
#include "vv/pacs/PacsError.h"
#include "vv/pacs/Retrieve.h"
#include "vv/pacs/Send.h"
#include "vv/pacs/StorageScp.h"

namespace fault_test {

namespace fs = std::filesystem;
using namespace vv::pacs;
using vv::test::OrthancServer;

namespace {

constexpr const char* kOurAe = "VVFAULT";

LocalAe me(int responseSeconds = 10) {
    return LocalAe{kOurAe, Timeouts{2, 5, responseSeconds}};
}

fs::path freshFolder(const std::string& name) {
    const fs::path folder =
        fs::path(VV_TEST_TMP) / ("pacs-fault-" + std::to_string(::getpid())) / name;
    fs::remove_all(folder);
    return folder;
}

/// A synthetic CTA series of `slices` (at least 8) files for patient `patientId`.
std::vector<fs::path> series(const std::string& patientId, int slices) {
    return vv::test::writeCtaFiles(freshFolder("series-" + patientId), patientId, slices);
}

void sendAll(const OrthancServer& orthanc, const std::vector<fs::path>& files) {
    for (const SendStatus& s : sendFiles(me(), orthanc.node(), files)) {
        ASSERT_TRUE(s.accepted) << s.file << " status " << s.status;
    }
}

std::string studyOf(const OrthancServer& orthanc, const std::string& patientId) {
    StudyQuery query;
    query.patientId = patientId;
    const auto studies = findStudies(me(), orthanc.node(), query);
    return studies.size() == 1 ? studies[0].studyInstanceUid : std::string();
}

void expectMessage(const std::function<void()>& call, const std::string& part) {
    try {
        call();
        ADD_FAILURE() << "no ResponseError (" << part << ")";
    } catch (const ResponseError& e) {
        EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("ORTHANC@127.0.0.1"), std::string::npos) << e.what();
    }
}

}  // namespace

TEST(PacsFaultTest, AMalformedFindAnswerIsAClearError) {
    OrthancServer orthanc(kOurAe, vv::test::freePort());
    sendAll(orthanc, series("VV-GOOD", 8));
    // A Study Instance UID that is no UID.
    auto bad = series("VV-MALFORMED", 8);
    bad.resize(1);
    DcmFileFormat file;
    ASSERT_TRUE(file.loadFile(bad[0].c_str()).good());
    file.getDataset()->putAndInsertString(DCM_StudyInstanceUID, "1.2.X9/../../etc");
    ASSERT_TRUE(file.saveFile(bad[0].c_str(), EXS_LittleEndianExplicit).good());
    sendAll(orthanc, bad);

    StudyQuery malformed;
    malformed.patientId = "VV-MALFORMED";
    expectMessage([&] { findStudies(me(), orthanc.node(), malformed); },
                  "without a valid StudyInstanceUID");
    EXPECT_THROW(findStudies(me(), orthanc.node(), StudyQuery{}), ResponseError);
    // The peer and we keep working.
    EXPECT_FALSE(studyOf(orthanc, "VV-GOOD").empty());
}

TEST(PacsFaultTest, OrthancKilledDuringAMoveLeavesNothingComplete) {
    const std::uint16_t scpPort = vv::test::freePort();
    OrthancServer orthanc(kOurAe, scpPort);
    sendAll(orthanc, series("VV-MOVE-KILL", 24));
    const std::string study = studyOf(orthanc, "VV-MOVE-KILL");
    ASSERT_FALSE(study.empty());
    LocalStore store(freshFolder("move-kill"));
    ListenerConfig config;
    config.aeTitle = kOurAe;
    config.port = scpPort;
    config.allowedPeers = {orthanc.node()};
    const StorageScp listener(store, config);
    bool killed = false;
    const vv::Progress progress = vv::test::atFirstReport(&killed, [&] { orthanc.kill(); });
    // Waits longer than ctest lets the test run: only the dead connection can end the move.
    EXPECT_THROW(moveTo(kOurAe, me(3600), orthanc.node(), RetrieveRequest{study, ""}, progress),
                 NetworkError);
    EXPECT_TRUE(killed);
    // The listener's association from the dead peer ends without a release.
    vv::test::waitUntil([&] {
        return listener.stats().acceptedAssociations <= listener.stats().discardedAssociations;
    });
    EXPECT_TRUE(store.studies().empty());
    EXPECT_EQ(listener.stats().committedInstances, 0U);
    EXPECT_TRUE(fs::is_empty(store.root() / ".incoming"));
    // Our listener still works.
    EXPECT_NO_THROW(
        echo(LocalAe{"ORTHANC", Timeouts{2, 5, 10}}, Node{kOurAe, "127.0.0.1", scpPort, {}}));
}

TEST(PacsFaultTest, APeerThatStopsAnsweringDuringAGetTimesOut) {
    OrthancServer orthanc(kOurAe, vv::test::freePort());
    sendAll(orthanc, series("VV-FROZEN", 12));
    const std::string study = studyOf(orthanc, "VV-FROZEN");
    ASSERT_FALSE(study.empty());
    LocalStore store(freshFolder("frozen"));
    bool paused = false;
    const vv::Progress progress = vv::test::atFirstReport(&paused, [&] { orthanc.pause(); });
    EXPECT_THROW(getInto(store, me(3), orthanc.node(), RetrieveRequest{study, ""}, progress),
                 TimeoutError);
    EXPECT_TRUE(paused);
    EXPECT_TRUE(store.studies().empty());
    EXPECT_TRUE(fs::is_empty(store.root() / ".incoming"));
    orthanc.resume();
    EXPECT_NO_THROW(getInto(store, me(), orthanc.node(), RetrieveRequest{study, ""}));
    EXPECT_EQ(store.studies().size(), 1U) << "the same retrieve works once the peer answers";
}

}  // namespace fault_test
