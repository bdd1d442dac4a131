// SPDX-License-Identifier: GPL-3.0-or-later
// The store's size limit: after a commit over the limit whole studies go,
// least recently stored or opened first; an open study stays, also when
// another process holds it open (vv_store_helper); the study just committed
// stays even when it alone is over the limit; a clean-up killed midway
// leaves no indexed study without files; and afterwards the index and the
// disk agree. Removing one study (Local Studies' Delete): it goes from the
// index and the disk, unless it is open (here or in another process).
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <QSqlDatabase>
#include <QSqlQuery>
#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <thread>

#include "WaitUntil.h"
#include "vv/core/Error.h"
#include "vv/pacs/LocalStore.h"

namespace store_limit_test {

namespace fs = std::filesystem;
using namespace vv::pacs;

namespace {

constexpr std::uint64_t kStudyBytes = 100000;

fs::path freshFolder(const std::string& name) {
    const fs::path folder =
        fs::path(VV_TEST_TMP) / ("store-limit-" + std::to_string(::getpid())) / name;
    fs::remove_all(folder);
    return folder;
}

/// Commits a study "1.2.<n>" of one instance of `bytes` bytes.
void commitStudy(const LocalStore& store, int n, std::uint64_t bytes = kStudyBytes) {
    LocalStore::Transaction t = store.begin();
    const fs::path staged = t.stagingPath();
    std::ofstream(staged) << std::string(bytes, 'x');
    InstanceFields f;
    f.studyInstanceUid = "1.2." + std::to_string(n);
    f.seriesInstanceUid = f.studyInstanceUid + ".1";
    f.sopInstanceUid = f.seriesInstanceUid + ".1";
    f.patientId = "P" + std::to_string(n);
    f.studyDate = "20240101";  // one date: the order is the time of use, not the study date
    t.add(staged, f);
    t.commit();
}

std::string uid(int n) {
    return "1.2." + std::to_string(n);
}

std::set<std::string> indexed(const LocalStore& store) {
    std::set<std::string> uids;
    for (const StoredStudy& s : store.studies()) {
        uids.insert(s.studyInstanceUid);
    }
    return uids;
}

/// Every indexed study has its files, and every study folder is indexed.
void expectIndexAndDiskAgree(const LocalStore& store) {
    const std::set<std::string> uids = indexed(store);
    for (const StoredStudy& s : store.studies()) {
        for (const StoredSeries& series : s.series) {
            int files = 0;
            for (const auto& e : fs::directory_iterator(series.folder)) {
                files += e.path().extension() == ".dcm" ? 1 : 0;
            }
            EXPECT_EQ(files, series.instances) << s.studyInstanceUid;
        }
    }
    std::set<std::string> folders;
    for (const auto& e : fs::directory_iterator(store.root())) {
        if (e.is_directory() && e.path().filename().string()[0] != '.') {
            folders.insert(e.path().filename().string());
        }
    }
    EXPECT_EQ(folders, uids);
    EXPECT_TRUE(fs::is_empty(store.root() / ".incoming"));
}

/// vv_store_helper MODE ROOT ARGUMENT in another process, talking through
/// pipes: its first line of output is read; stop() closes its input and waits.
class Helper {
  public:
    Helper(const std::string& mode, const fs::path& root, const std::string& argument) {
        int toChild[2];
        int fromChild[2];
        if (::pipe(toChild) != 0 || ::pipe(fromChild) != 0) {
            throw std::runtime_error("pipe");
        }
        pid_ = ::fork();
        if (pid_ == 0) {
            ::dup2(toChild[0], STDIN_FILENO);
            ::dup2(fromChild[1], STDOUT_FILENO);
            ::close(toChild[1]);
            ::close(fromChild[0]);
            ::execl(VV_STORE_HELPER, "vv_store_helper", mode.c_str(), root.c_str(),
                    argument.c_str(), static_cast<char*>(nullptr));
            ::_exit(127);
        }
        ::close(toChild[0]);
        ::close(fromChild[1]);
        toChild_ = toChild[1];
        char text[16] = {};
        const ssize_t n = ::read(fromChild[0], text, sizeof text - 1);
        ::close(fromChild[0]);
        said_ = n > 0 ? std::string(text, static_cast<std::size_t>(n)) : std::string();
    }
    ~Helper() { stop(); }
    Helper(const Helper&) = delete;
    Helper& operator=(const Helper&) = delete;
    /// Its first line of output ("leased\n", "cleaning\n").
    [[nodiscard]] const std::string& said() const { return said_; }
    void kill() const { ::kill(pid_, SIGKILL); }
    void stop() {
        if (pid_ > 0) {
            ::close(toChild_);
            ::waitpid(pid_, nullptr, 0);
            pid_ = -1;
        }
    }

  private:
    pid_t pid_ = -1;
    int toChild_ = -1;
    std::string said_;
};

/// Every indexed study has all its files (a crash may leave unindexed ones).
void expectEveryIndexedStudyComplete(const LocalStore& store) {
    for (const StoredStudy& s : store.studies()) {
        for (const StoredSeries& series : s.series) {
            std::error_code ec;
            int files = 0;
            for (const auto& e : fs::directory_iterator(series.folder, ec)) {
                files += e.path().extension() == ".dcm" ? 1 : 0;
            }
            EXPECT_EQ(files, series.instances) << s.studyInstanceUid << " is indexed";
        }
    }
}

}  // namespace

TEST(StoreLimitTest, LeastRecentlyStoredOrOpenedStudiesGoFirst) {
    LocalStore store(freshFolder("order"));
    store.setSizeLimit(kStudyBytes * 5 / 2);  // room for two studies
    commitStudy(store, 1);
    commitStudy(store, 2);
    EXPECT_EQ(indexed(store), (std::set<std::string>{uid(1), uid(2)}));
    commitStudy(store, 3);
    EXPECT_EQ(indexed(store), (std::set<std::string>{uid(2), uid(3)})) << "the oldest went";
    { const auto opened = store.open(uid(2)); }  // opened: now used more recently than 3
    commitStudy(store, 4);
    EXPECT_EQ(indexed(store), (std::set<std::string>{uid(2), uid(4)}));
    EXPECT_LE(store.sizeOnDisk(), store.sizeLimit());
    expectIndexAndDiskAgree(store);
}

TEST(StoreLimitTest, AnOpenStudyIsNeverRemoved) {
    LocalStore store(freshFolder("open"));
    store.setSizeLimit(kStudyBytes * 5 / 2);
    commitStudy(store, 1);
    const LocalStore::OpenLease lease = store.open(uid(1));
    EXPECT_EQ(lease.studyInstanceUid(), uid(1));
    commitStudy(store, 2);
    commitStudy(store, 3);
    commitStudy(store, 4);
    EXPECT_EQ(indexed(store), (std::set<std::string>{uid(1), uid(4)}));
    expectIndexAndDiskAgree(store);
}

TEST(StoreLimitTest, AStudyOpenInAnotherProcessIsNeverRemoved) {
    const fs::path root = freshFolder("other-process");
    LocalStore store(root);
    store.setSizeLimit(kStudyBytes * 5 / 2);
    commitStudy(store, 1);
    Helper other("lease", root, uid(1));
    ASSERT_EQ(other.said(), "leased\n");
    commitStudy(store, 2);
    commitStudy(store, 3);
    EXPECT_EQ(indexed(store), (std::set<std::string>{uid(1), uid(3)}));
    expectIndexAndDiskAgree(store);

    other.stop();  // the other process closes the study
    store.setSizeLimit(kStudyBytes * 3 / 2);
    EXPECT_EQ(store.cleanUp(), std::vector<std::string>{uid(1)});
    EXPECT_EQ(indexed(store), (std::set<std::string>{uid(3)}));
    expectIndexAndDiskAgree(store);
}

TEST(StoreLimitTest, TheStudyJustCommittedStaysEvenAloneOverTheLimit) {
    LocalStore store(freshFolder("alone"));
    store.setSizeLimit(kStudyBytes * 3);
    commitStudy(store, 1);
    commitStudy(store, 2);
    commitStudy(store, 3, kStudyBytes * 4);
    EXPECT_EQ(indexed(store), (std::set<std::string>{uid(3)}));
    EXPECT_GT(store.sizeOnDisk(), store.sizeLimit()) << "over its limit until it is removed";
    expectIndexAndDiskAgree(store);
    commitStudy(store, 4);  // now the big one is the least recently used
    EXPECT_EQ(indexed(store), (std::set<std::string>{uid(4)}));
    expectIndexAndDiskAgree(store);
}

TEST(StoreLimitTest, WithoutALimitNothingIsRemoved) {
    LocalStore store(freshFolder("unlimited"));
    for (int n = 1; n <= 4; ++n) {
        commitStudy(store, n);
    }
    EXPECT_TRUE(store.cleanUp().empty());
    EXPECT_EQ(indexed(store).size(), 4U);
    EXPECT_EQ(store.sizeOnDisk(), 4 * kStudyBytes);
}

TEST(StoreLimitTest, OpeningAStudyNotInTheStoreIsRefused) {
    LocalStore store(freshFolder("missing"));
    EXPECT_THROW((void)store.open("1.2.99"), vv::InvalidArgumentError);
    EXPECT_THROW((void)store.open("../etc"), vv::InvalidArgumentError);
    store.setSizeLimit(kStudyBytes / 2);
    commitStudy(store, 1);
    commitStudy(store, 2);  // removes 1
    EXPECT_THROW((void)store.open(uid(1)), vv::InvalidArgumentError);
}

TEST(StoreLimitTest, AnIndexFromBeforeTheLimitIsMigratedAndItsStudiesCountAsOldest) {
    // A store as the first version wrote it: no time of use in the index.
    const fs::path root = freshFolder("migrate");
    fs::create_directories(root / uid(1) / (uid(1) + ".1"));
    std::ofstream(root / uid(1) / (uid(1) + ".1") / (uid(1) + ".1.1.dcm"))
        << std::string(kStudyBytes, 'x');
    {
        QSqlDatabase db = QSqlDatabase::addDatabase(QStringLiteral("QSQLITE"), "old-index");
        db.setDatabaseName(QString::fromStdString((root / "index.sqlite").string()));
        ASSERT_TRUE(db.open());
        QSqlQuery q(db);
        ASSERT_TRUE(
            q.exec("CREATE TABLE studies (study_uid TEXT PRIMARY KEY, patient_name TEXT, "
                   "patient_id TEXT, study_date TEXT, study_description TEXT, "
                   "accession TEXT)"));
        ASSERT_TRUE(
            q.exec("CREATE TABLE series (series_uid TEXT PRIMARY KEY, study_uid TEXT NOT "
                   "NULL, modality TEXT, series_description TEXT, series_number INTEGER, "
                   "instances INTEGER)"));
        ASSERT_TRUE(q.exec("INSERT INTO studies VALUES ('1.2.1', '', 'P1', '20990101', '', '')"));
        ASSERT_TRUE(q.exec("INSERT INTO series VALUES ('1.2.1.1', '1.2.1', 'CT', '', 1, 1)"));
        db.close();
    }
    QSqlDatabase::removeDatabase("old-index");

    LocalStore store(root);
    EXPECT_EQ(indexed(store), (std::set<std::string>{uid(1)}));
    store.setSizeLimit(kStudyBytes * 5 / 2);
    commitStudy(store, 2);
    commitStudy(store, 3);
    EXPECT_EQ(indexed(store), (std::set<std::string>{uid(2), uid(3)}))
        << "the old study, never used since, went first (despite its later study date)";
    expectIndexAndDiskAgree(store);
}

TEST(StoreLimitTest, ACleanUpKilledMidwayLeavesNoIndexedStudyWithoutFiles) {
    const fs::path root = freshFolder("killed");
    LocalStore store(root);
    const auto studyFolders = [&root] {
        int n = 0;
        for (const auto& e : fs::directory_iterator(root)) {
            n += e.is_directory() && e.path().filename().string()[0] != '.' ? 1 : 0;
        }
        return n;
    };
    for (const int removedBeforeKill : {1, 8, 20}) {
        for (int n = 1; n <= 40; ++n) {
            commitStudy(store, n, 20000);
        }
        {
            Helper cleaner("clean-up", root, "1");  // removes every study, one at a time
            ASSERT_EQ(cleaner.said(), "cleaning\n");
            vv::test::pollUntil([&] { return studyFolders() <= 40 - removedBeforeKill; },
                                std::chrono::seconds(10),
                                [] {});  // a busy poll: the clean-up is fast
            cleaner.kill();
        }
        const std::size_t left = store.studies().size();
        EXPECT_GT(left, 0U) << "killed before the end";
        EXPECT_LE(left, static_cast<std::size_t>(40 - removedBeforeKill));
        expectEveryIndexedStudyComplete(store);
        // The next clean-up deletes what the killed one left.
        EXPECT_TRUE(store.cleanUp().empty());
        expectIndexAndDiskAgree(store);
    }
}

TEST(StoreLimitTest, RemoveTakesOneStudyOutOfTheIndexAndOffTheDisk) {
    LocalStore store(freshFolder("remove"));
    commitStudy(store, 1);
    commitStudy(store, 2);
    store.remove(uid(1));
    EXPECT_EQ(indexed(store), (std::set<std::string>{uid(2)}));
    EXPECT_FALSE(fs::exists(store.root() / uid(1)));
    EXPECT_EQ(store.sizeOnDisk(), kStudyBytes);
    expectIndexAndDiskAgree(store);
    EXPECT_THROW(store.remove(uid(1)), vv::InvalidArgumentError) << "already gone";
    EXPECT_THROW(store.remove("../" + uid(2)), vv::InvalidArgumentError);
    EXPECT_EQ(indexed(store), (std::set<std::string>{uid(2)}));
}

TEST(StoreLimitTest, RemovingAnOpenStudyIsRefusedAndRemovesNothing) {
    LocalStore store(freshFolder("remove-open"));
    commitStudy(store, 1);
    {
        const LocalStore::OpenLease lease = store.open(uid(1));
        EXPECT_THROW(store.remove(uid(1)), StudyOpenError);
        EXPECT_EQ(indexed(store), (std::set<std::string>{uid(1)}));
        expectIndexAndDiskAgree(store);
    }
    store.remove(uid(1));  // closed: it goes
    EXPECT_TRUE(indexed(store).empty());
    expectIndexAndDiskAgree(store);
}

TEST(StoreLimitTest, RemovingAStudyOpenInAnotherProcessIsRefused) {
    const fs::path root = freshFolder("remove-other-process");
    LocalStore store(root);
    commitStudy(store, 1);
    Helper other("lease", root, uid(1));
    ASSERT_EQ(other.said(), "leased\n");
    EXPECT_THROW(store.remove(uid(1)), StudyOpenError);
    EXPECT_EQ(indexed(store), (std::set<std::string>{uid(1)}));
    expectIndexAndDiskAgree(store);
    other.stop();  // the other process closes the study
    store.remove(uid(1));
    EXPECT_TRUE(indexed(store).empty());
    expectIndexAndDiskAgree(store);
}

}  // namespace store_limit_test
