// SPDX-License-Identifier: GPL-3.0-or-later
// The local study store without a network: staged instances become complete
// only on commit; folders are private; the index survives reopening.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "vv/core/Error.h"
#include "vv/pacs/LocalStore.h"

namespace store_test {

namespace fs = std::filesystem;
using namespace vv::pacs;

namespace {

fs::path freshFolder(const std::string& name) {
    // Per process: ctest runs the tests of this file in parallel processes.
    const fs::path folder = fs::path(VV_TEST_TMP) / ("store-" + std::to_string(::getpid())) / name;
    fs::remove_all(folder);
    return folder;
}

InstanceFields fields(const std::string& sop) {
    InstanceFields f;
    f.sopInstanceUid = sop;
    f.studyInstanceUid = "1.2.3";
    f.seriesInstanceUid = "1.2.3.4";
    f.patientName = "Test^Patient";
    f.patientId = "P1";
    f.studyDate = "20240102";
    f.modality = "CT";
    f.seriesNumber = 3;
    return f;
}

fs::path stage(LocalStore::Transaction& t) {
    const fs::path p = t.stagingPath();
    std::ofstream(p) << "not really DICOM";
    return p;
}

unsigned mode(const fs::path& p) {
    struct stat st {};
    ::stat(p.c_str(), &st);
    return st.st_mode & 0777U;
}

}  // namespace

TEST(LocalStoreTest, CommitMakesTheStudyCompleteInPrivateFolders) {
    const fs::path root = freshFolder("commit");
    LocalStore store(root);
    {
        LocalStore::Transaction t = store.begin();
        t.add(stage(t), fields("1.2.3.4.1"));
        t.add(stage(t), fields("1.2.3.4.2"));
        EXPECT_TRUE(store.studies().empty()) << "nothing is complete before commit";
        t.commit();
    }
    const LocalStore reopened(root);
    const auto studies = reopened.studies();
    ASSERT_EQ(studies.size(), 1U);
    EXPECT_EQ(studies[0].studyInstanceUid, "1.2.3");
    EXPECT_EQ(studies[0].patientId, "P1");
    ASSERT_EQ(studies[0].series.size(), 1U);
    EXPECT_EQ(studies[0].series[0].instances, 2);
    EXPECT_EQ(studies[0].series[0].seriesNumber, 3);
    EXPECT_TRUE(fs::exists(studies[0].series[0].folder / "1.2.3.4.1.dcm"));
    EXPECT_EQ(mode(root), 0700U);
    EXPECT_EQ(mode(studies[0].folder), 0700U);
    EXPECT_EQ(mode(studies[0].series[0].folder), 0700U);
    EXPECT_TRUE(fs::is_empty(root / ".incoming")) << "the staging folder is cleaned up";
}

TEST(LocalStoreTest, DiscardedTransactionLeavesNothing) {
    const fs::path root = freshFolder("discard");
    LocalStore store(root);
    {
        LocalStore::Transaction t = store.begin();
        t.add(stage(t), fields("1.2.3.4.1"));
    }  // destroyed without commit, as a failed transfer
    EXPECT_TRUE(store.studies().empty());
    EXPECT_FALSE(fs::exists(root / "1.2.3"));
    EXPECT_TRUE(fs::is_empty(root / ".incoming"));
}

TEST(LocalStoreTest, MalformedUidIsRefusedAndItsFileRemoved) {
    LocalStore store(freshFolder("baduid"));
    LocalStore::Transaction t = store.begin();
    const fs::path staged = stage(t);
    InstanceFields bad = fields("1.2.3.4.1");
    bad.studyInstanceUid = "../../etc";
    EXPECT_THROW(t.add(staged, bad), vv::InvalidArgumentError);
    EXPECT_FALSE(fs::exists(staged));
}

}  // namespace store_test
