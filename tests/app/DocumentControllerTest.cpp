// SPDX-License-Identifier: GPL-3.0-or-later
// The document controller on its own (no window, no display): the recent
// files' rules, the order of its signals, a session applied once its files
// are shown and never to other data, cancelled and failed loads keeping the
// shown document, drops, and what a saved session names.
#include <gtest/gtest.h>

#include <QCoreApplication>
#include <QDir>
#include <QSettings>
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "GuiFixture.h"
#include "SyntheticCta.h"
#include "common/ResourcePaths.h"
#include "gui/DocumentController.h"
#include "gui/RecentFiles.h"
#include "gui/pacs/PacsWidgets.h"
#include "vv/dicom/SeriesWriter.h"
#include "vv/meshio/MeshWriter.h"

namespace vv::test {
namespace {

namespace fs = std::filesystem;
using gui::DocumentController;

fs::path documentTestDir() {
    const fs::path dir = fs::path(VV_TEST_TMP) / "document-controller" /
                         ("run-" + std::to_string(QCoreApplication::applicationPid()));
    fs::create_directories(dir);
    return dir;
}

QString qpath(const fs::path& path) {
    return QString::fromStdString(path.string());
}

/// A tube mesh written as `name` (VTP) in the test folder.
fs::path writeTube(const std::string& name, float length = 30.0F) {
    const fs::path file = documentTestDir() / name;
    scene::Mesh mesh = vv::test::tube(
        {.radius = 2.0F, .start = glm::vec3(0.0F), .length = length, .segments = 16, .rings = 8});
    meshio::writeVtp(mesh, file);
    return file;
}

/// Every signal of a controller, by name, in the order emitted.
struct Recorder {
    std::vector<std::string> events;
    std::vector<app::Session> sessions;  ///< what sessionReady() handed over
    QStringList failures;                ///< failed() messages

    explicit Recorder(DocumentController& document) {
        const auto note = [this](const char* name) {
            return [this, name] { events.push_back(name); };
        };
        QObject::connect(&document, &DocumentController::loadStarted, note("loadStarted"));
        QObject::connect(&document, &DocumentController::loadEnded, note("loadEnded"));
        QObject::connect(&document, &DocumentController::loadCancelled, note("loadCancelled"));
        QObject::connect(&document, &DocumentController::failed,
                         [this](const QString&, const gui::ProblemText& problem) {
                             events.emplace_back("failed");
                             failures << problem.line();
                         });
        QObject::connect(&document, &DocumentController::seriesScanned, note("seriesScanned"));
        QObject::connect(&document, &DocumentController::sceneChanged, note("sceneChanged"));
        QObject::connect(&document, &DocumentController::sessionReady,
                         [this](const app::Session& session) {
                             events.emplace_back("sessionReady");
                             sessions.push_back(session);
                         });
        QObject::connect(&document, &DocumentController::sceneShown, note("sceneShown"));
        QObject::connect(&document, &DocumentController::sessionApplied, note("sessionApplied"));
        QObject::connect(&document, &DocumentController::volumeChanged, note("volumeChanged"));
        QObject::connect(&document, &DocumentController::recentFilesChanged,
                         note("recentFilesChanged"));
    }

    [[nodiscard]] int count(const std::string& name) const {
        return static_cast<int>(std::count(events.begin(), events.end(), name));
    }
    /// The position of the first `name`; -1 when absent.
    [[nodiscard]] long first(const std::string& name) const {
        const auto it = std::find(events.begin(), events.end(), name);
        return it == events.end() ? -1 : it - events.begin();
    }
    [[nodiscard]] std::string joined() const {
        std::string text;
        for (const auto& e : events) {
            text += e + " ";
        }
        return text;
    }
};

class DocumentControllerTest : public ::testing::Test {
  protected:
    static void SetUpTestSuite() {
        if (QCoreApplication::instance() != nullptr) {
            return;
        }
        // Recent files go to a throw-away folder, not the user's settings.
        const QString config = qpath(documentTestDir() / "config");
        QDir(config).removeRecursively();
        qputenv("XDG_CONFIG_HOME", config.toUtf8());
        qunsetenv("VV_DEMO_FILE");
        static int argc = 1;
        static char name[] = "vv_gui_document_tests";
        static char* argv[] = {name, nullptr};
        new QCoreApplication(argc, argv);  // kept for the whole process
        QCoreApplication::setOrganizationName(QStringLiteral("VesselViewDocumentTest"));
        QCoreApplication::setApplicationName(QStringLiteral("VesselViewDocumentTest"));
    }

    void SetUp() override { gui::recent::clear(); }

    /// Loads `file` and waits until it is shown.
    void show(const fs::path& file) {
        document_.openFiles({qpath(file)});
        ASSERT_TRUE(waitUntil([&] { return !document_.isLoading(); }))
            << document_.lastError().toStdString();
        ASSERT_NE(document_.scene(), nullptr) << document_.lastError().toStdString();
    }

    /// A small synthetic CT series described `description` written into
    /// `folder`; returns its Series Instance UID.
    static std::string writeCta(const fs::path& folder, const std::string& description) {
        static const auto cta = test::makeSyntheticCta({40, 40, 24}, 3);
        dicom::CtSeriesWriteOptions options;
        options.seriesDescription = description;
        return dicom::writeCtSeries(folder, cta.volume, options);
    }

    /// Waits until `document` has loaded; true when it shows a scene.
    static bool loaded(const DocumentController& document) {
        EXPECT_TRUE(waitUntil([&] { return !document.isLoading(); }, 60000));
        EXPECT_TRUE(document.lastError().isEmpty()) << document.lastError().toStdString();
        return document.scene() != nullptr;
    }

    /// A session file showing `files` with power p = 4 and a layout.
    static fs::path writeSession(const std::string& name, const QStringList& files) {
        app::Session session;
        session.files = files;
        session.vss.solver.p = 4.0;
        session.layout = QByteArray("layout bytes");
        const fs::path path = documentTestDir() / name;
        app::saveSession(path, session);
        return path;
    }

    DocumentController document_;
};

TEST(RecentFiles, TheOpenedFilesGoFirstInTheirOrderWithoutRepeats) {
    const QStringList recent{QStringLiteral("/a.vtp"), QStringLiteral("/b.vtp"),
                             QStringLiteral("/c.vtp")};
    EXPECT_EQ(gui::recent::merged(recent, {QStringLiteral("/c.vtp"), QStringLiteral("/d.vtp")}),
              (QStringList{QStringLiteral("/c.vtp"), QStringLiteral("/d.vtp"),
                           QStringLiteral("/a.vtp"), QStringLiteral("/b.vtp")}));
    EXPECT_EQ(gui::recent::merged(recent, {}), recent);
    // Relative names are remembered absolute, so they reopen from anywhere.
    EXPECT_EQ(gui::recent::merged({}, {QStringLiteral("tree.vtp")}),
              QStringList{QDir::current().absoluteFilePath(QStringLiteral("tree.vtp"))});
    QStringList many;
    for (int i = 0; i < 12; ++i) {
        many << QStringLiteral("/file-%1.vtp").arg(i);
    }
    const QStringList kept = gui::recent::merged({}, many);
    ASSERT_EQ(kept.size(), gui::recent::kMaxFiles);
    EXPECT_EQ(kept.front(), QStringLiteral("/file-0.vtp"));
    EXPECT_EQ(kept.back(), QStringLiteral("/file-7.vtp"));
}

TEST_F(DocumentControllerTest, RecentFilesAreStoredAndCleared) {
    QSettings().setValue(QStringLiteral("recentFiles"),
                         QStringList{QString(), QStringLiteral("/old.vtp")});
    EXPECT_EQ(DocumentController::recentFiles(), QStringList{QStringLiteral("/old.vtp")});
    const fs::path tube = writeTube("recent.vtp");
    Recorder record(document_);
    show(tube);
    EXPECT_EQ(DocumentController::recentFiles(),
              (QStringList{qpath(fs::absolute(tube)), QStringLiteral("/old.vtp")}));
    EXPECT_EQ(record.count("recentFilesChanged"), 1);
    document_.clearRecentFiles();
    EXPECT_TRUE(DocumentController::recentFiles().isEmpty());
    EXPECT_EQ(record.count("recentFilesChanged"), 2);
}

TEST_F(DocumentControllerTest, ARecentSeriesIsLabelledByWhatItSaysNeverByItsFolder) {
    const QString folder = QStringLiteral("/store/1.2.840.99/1.2.840.99.7");
    gui::SeriesIdentity cta;
    cta.description = QStringLiteral("Run-off & CTA");
    cta.modality = QStringLiteral("CT");
    cta.number = 3;
    cta.studyDate = QStringLiteral("20250101");
    gui::recent::add({QStringLiteral("/meshes/tree.vtp")});
    gui::recent::add({folder}, cta);
    EXPECT_EQ(gui::recent::series(folder), cta);
    const QString label = gui::recent::label(folder);
    EXPECT_TRUE(label.startsWith(QStringLiteral("Run-off & CTA · "))) << label.toStdString();
    EXPECT_TRUE(label.contains(QStringLiteral("2025"))) << label.toStdString();
    EXPECT_FALSE(label.contains(QStringLiteral("1.2.840"))) << label.toStdString();
    EXPECT_EQ(gui::recent::label(QStringLiteral("/meshes/tree.vtp")), QStringLiteral("tree.vtp"));
    // Without a description: modality and number, in the UI language.
    cta.description.clear();
    cta.studyDate.clear();
    gui::recent::add({folder}, cta);
    EXPECT_EQ(gui::recent::label(folder), QStringLiteral("CT series 3"));
    // Opened again as plain files (or with others), it is a file again.
    gui::recent::add({folder, QStringLiteral("/meshes/tree.vtp")}, cta);
    EXPECT_FALSE(gui::recent::series(folder).has_value());
    EXPECT_EQ(gui::recent::label(folder), QStringLiteral("1.2.840.99.7"));
    // A series that drops off the list is forgotten with it.
    gui::recent::add({folder}, cta);
    for (int i = 0; i < gui::recent::kMaxFiles; ++i) {
        gui::recent::add({QStringLiteral("/meshes/m%1.vtp").arg(i)});
    }
    EXPECT_FALSE(gui::recent::files().contains(folder));
    EXPECT_FALSE(QSettings().contains(QStringLiteral("recentSeries/size")));
    // Kept readable in the settings file; an entry that is not one (edited
    // by hand) names the file.
    gui::recent::add({folder}, cta);
    {
        QSettings settings;
        EXPECT_EQ(settings.value(QStringLiteral("recentSeries/1/modality")).toString(),
                  QStringLiteral("CT"));
        EXPECT_EQ(settings.value(QStringLiteral("recentSeries/1/file")).toString(), folder);
        settings.setValue(QStringLiteral("recentSeries/1/number"), QStringLiteral("three"));
    }
    EXPECT_FALSE(gui::recent::series(folder).has_value());
    EXPECT_EQ(gui::recent::label(folder), QStringLiteral("1.2.840.99.7"));
    // Clearing forgets both.
    gui::recent::clear();
    EXPECT_TRUE(gui::recent::files().isEmpty());
    EXPECT_FALSE(QSettings().contains(QStringLiteral("recentSeries/size")));
}

TEST_F(DocumentControllerTest, OneSeriesOpenedFromTwoPlacesIsListedOnce) {
    // The study's folder on a CD and its copy in the local study store: one
    // series (one Series Instance UID), one entry, the place opened last.
    const fs::path cd = documentTestDir() / "cd-copy";
    const fs::path store = documentTestDir() / "store" / "1.2.826.0.1.3680043.9.7777.8";
    fs::remove_all(cd);
    fs::remove_all(store);
    (void)writeCta(cd, "Run-off");
    fs::create_directories(store);
    for (const auto& file : fs::directory_iterator(cd)) {
        fs::copy_file(file.path(), store / file.path().filename());
    }
    const fs::path tube = writeTube("between.vtp");
    show(cd);
    show(tube);
    show(store);
    const QStringList files = DocumentController::recentFiles();
    EXPECT_EQ(files, (QStringList{qpath(fs::absolute(store)), qpath(fs::absolute(tube))}))
        << files.join(QStringLiteral(", ")).toStdString();
    // Back on the CD: the store's entry goes instead.
    show(cd);
    EXPECT_EQ(DocumentController::recentFiles(),
              (QStringList{qpath(fs::absolute(cd)), qpath(fs::absolute(tube))}));
    EXPECT_FALSE(gui::recent::series(qpath(fs::absolute(store))).has_value());
    // Another series in another folder stays beside it.
    const fs::path other = documentTestDir() / "other-series";
    fs::remove_all(other);
    (void)writeCta(other, "Venous");
    show(other);
    EXPECT_EQ(DocumentController::recentFiles().size(), 3);
}

TEST_F(DocumentControllerTest, ADicomFolderIsNamedByItsSeriesAndWithOtherFilesByTheirCount) {
    // A folder named by its UID, as in a study store.
    const fs::path folder = documentTestDir() / "1.2.826.0.1.3680043.9.7777.5";
    fs::remove_all(folder);
    (void)writeCta(folder, "Arterial  phase");
    show(folder);
    EXPECT_EQ(document_.title().toStdString(), "Arterial phase");
    EXPECT_EQ(document_.seriesTitle().toStdString(), "Arterial phase");
    EXPECT_EQ(gui::recent::label(qpath(fs::absolute(folder))).toStdString(),
              "Arterial phase · " + gui::studyDateText("20250101").toStdString());
    // With a mesh beside it the window shows two sources: not one series' name.
    const fs::path tube = writeTube("beside.vtp");
    document_.openFiles({qpath(folder), qpath(tube)});
    ASSERT_TRUE(loaded(document_));
    EXPECT_EQ(document_.title().toStdString(), "2 files");
    // Opened together, neither is a series in Open Recent.
    EXPECT_FALSE(gui::recent::series(qpath(fs::absolute(folder))).has_value());
}

TEST_F(DocumentControllerTest, ASeriesChosenInAFolderOfSeveralReopensFromTheRecentFiles) {
    // A patient CD's folder: two series, the second chosen in the chooser.
    const fs::path folder = documentTestDir() / "cd";
    fs::remove_all(folder);
    (void)writeCta(folder / "s1", "Venous");
    const std::string arterial = writeCta(folder / "s2", "Arterial");
    segmentation::SceneSourceOptions chosen;
    chosen.seriesInstanceUid = arterial;
    document_.openSeries(qpath(folder), chosen, QStringLiteral("Arterial"));
    ASSERT_TRUE(loaded(document_));
    const QString entry = qpath(fs::absolute(folder));
    ASSERT_EQ(DocumentController::recentFiles().value(0), entry);

    // Opened as a plain folder it is ambiguous: that is an error.
    DocumentController other;
    other.openFiles({entry});
    ASSERT_TRUE(waitUntil([&] { return !other.isLoading(); }, 60000));
    EXPECT_FALSE(other.lastError().isEmpty());

    // From the recent files: the same series again, without asking.
    DocumentController again;
    again.openRecent(entry);
    ASSERT_TRUE(loaded(again));
    EXPECT_EQ(again.seriesUid(), arterial);
    EXPECT_EQ(again.title().toStdString(), "Arterial");

    // The series gone from the folder: an error naming the folder, nothing shown.
    fs::remove_all(folder / "s2");
    DocumentController gone;
    gone.openRecent(entry);
    ASSERT_TRUE(waitUntil([&] { return !gone.isLoading(); }, 60000));
    EXPECT_EQ(gone.scene(), nullptr);
    EXPECT_TRUE(gone.lastError().contains(entry)) << gone.lastError().toStdString();
}

TEST_F(DocumentControllerTest, ALoadSignalsInOrderAndNamesItsFiles) {
    const fs::path tube = writeTube("tube.vtp");
    Recorder record(document_);
    document_.openFiles({qpath(tube)});
    EXPECT_TRUE(document_.isLoading());
    EXPECT_EQ(record.joined(), "loadStarted ");  // the rest arrives from the worker
    ASSERT_TRUE(waitUntil([&] { return !document_.isLoading(); }));
    EXPECT_EQ(record.joined(),
              "loadStarted volumeChanged sceneChanged sceneShown recentFilesChanged loadEnded ");
    EXPECT_EQ(document_.title(), QStringLiteral("tube.vtp"));
    EXPECT_EQ(document_.shownFiles(), QStringList{qpath(fs::absolute(tube))});
    EXPECT_EQ(document_.openedFiles(), QStringList{qpath(tube)});
    ASSERT_EQ(document_.reportSource().files.size(), 1U);
    EXPECT_TRUE(document_.reportSource().dicomPath.empty());
    EXPECT_EQ(document_.volume(), nullptr);
}

TEST_F(DocumentControllerTest, TheDemoIsSyntheticInTheReportEvenWhenGenerated) {
    // No demo file here (VV_DEMO_FILE unset, no data folder next to the test):
    // the demo is generated in memory and names no file, yet it is the demo.
    ASSERT_FALSE(app::findDemoFile().has_value());
    document_.openDemo();
    ASSERT_TRUE(waitUntil([&] { return !document_.isLoading(); }, 180000));
    ASSERT_TRUE(document_.showsDemo());
    EXPECT_TRUE(document_.reportSource().syntheticDemo);
    // Another file afterwards is patient data again.
    document_.openFiles({qpath(writeTube("after-demo.vtp"))});
    ASSERT_TRUE(waitUntil([&] { return !document_.isLoading(); }));
    EXPECT_FALSE(document_.reportSource().syntheticDemo);
}

TEST_F(DocumentControllerTest, ASessionIsAppliedOnceItsFilesAreShown) {
    const fs::path tube = writeTube("session-tube.vtp");
    const fs::path session = writeSession("apply.vvs", {qpath(tube)});
    Recorder record(document_);
    ASSERT_TRUE(document_.openSession(qpath(session)));
    EXPECT_EQ(record.count("sessionReady"), 0);  // its files load first
    ASSERT_TRUE(waitUntil([&] { return record.count("sessionApplied") > 0; }))
        << record.joined() << document_.lastError().toStdString();
    // The data, then the session's camera and settings on it, then "shown";
    // "applied" comes from the event loop once all of that was handled.
    const long changed = record.first("sceneChanged");
    const long ready = record.first("sessionReady");
    const long shown = record.first("sceneShown");
    const long applied = record.first("sessionApplied");
    EXPECT_TRUE(changed >= 0 && changed < ready && ready < shown && shown < applied)
        << record.joined();
    ASSERT_EQ(record.sessions.size(), 1U);
    EXPECT_DOUBLE_EQ(record.sessions.front().vss.solver.p, 4.0);
    EXPECT_EQ(record.sessions.front().layout, QByteArray("layout bytes"));
    EXPECT_EQ(document_.shownFiles(), QStringList{qpath(fs::absolute(tube))});

    // Once: the next load shows its data without the session.
    show(writeTube("after-session.vtp"));
    EXPECT_EQ(record.count("sessionReady"), 1) << record.joined();
}

TEST_F(DocumentControllerTest, ASessionIsNeverAppliedToOtherData) {
    const fs::path tube = writeTube("replaced-session-tube.vtp");
    const fs::path other = writeTube("other.vtp", 12.0F);
    const fs::path session = writeSession("replaced.vvs", {qpath(tube)});
    Recorder record(document_);

    // Another load replaces the session's load before its files arrive.
    ASSERT_TRUE(document_.openSession(qpath(session)));
    show(other);
    // Its cancelled load: the session goes with it.
    ASSERT_TRUE(document_.openSession(qpath(session)));
    EXPECT_TRUE(document_.cancelLoad());
    ASSERT_TRUE(waitUntil([&] { return !document_.isLoading(); }));
    EXPECT_EQ(record.count("loadCancelled"), 1) << record.joined();
    show(other);
    // Its failed load: the session goes with it.
    const fs::path missing = documentTestDir() / "missing.vtp";
    const fs::path broken = writeSession("broken-files.vvs", {qpath(missing)});
    ASSERT_TRUE(document_.openSession(qpath(broken)));
    ASSERT_TRUE(waitUntil([&] { return !document_.isLoading(); }));
    EXPECT_EQ(record.count("failed"), 1) << record.joined();
    show(other);

    waitUntil([] { return false; }, 300);  // a stray sessionApplied would arrive now
    EXPECT_EQ(record.count("sessionReady"), 0) << record.joined();
    EXPECT_EQ(record.count("sessionApplied"), 0) << record.joined();
    EXPECT_EQ(document_.shownFiles(), QStringList{qpath(fs::absolute(other))});
}

TEST_F(DocumentControllerTest, ACancelledLoadKeepsTheShownDocument) {
    const fs::path tube = writeTube("kept.vtp");
    show(tube);
    const auto scene = document_.scene();
    Recorder record(document_);
    document_.openFiles({qpath(writeTube("cancelled.vtp"))});
    EXPECT_TRUE(document_.cancelLoad());
    ASSERT_TRUE(waitUntil([&] { return !document_.isLoading(); }));
    // The worker may well have finished: a cancelled result is discarded.
    EXPECT_EQ(record.joined(), "loadStarted loadCancelled loadEnded ");
    EXPECT_EQ(document_.scene(), scene);
    EXPECT_EQ(document_.title(), QStringLiteral("kept.vtp"));
    EXPECT_EQ(document_.shownFiles(), QStringList{qpath(fs::absolute(tube))});
    EXPECT_TRUE(document_.lastError().isEmpty());
    EXPECT_FALSE(document_.cancelLoad());  // nothing to cancel now
}

TEST_F(DocumentControllerTest, AFailedLoadNamesTheFileAndKeepsTheShownDocument) {
    const fs::path tube = writeTube("shown.vtp");
    show(tube);
    const auto scene = document_.scene();
    Recorder record(document_);
    const fs::path missing = documentTestDir() / "no-such-file.stl";
    document_.openFiles({qpath(missing)});
    ASSERT_TRUE(waitUntil([&] { return !document_.isLoading(); }));
    ASSERT_EQ(record.failures.size(), 1) << record.joined();
    EXPECT_TRUE(record.failures.front().contains(QStringLiteral("no-such-file.stl")))
        << record.failures.front().toStdString();
    EXPECT_EQ(document_.lastError(), record.failures.front());
    EXPECT_EQ(record.count("sceneChanged"), 0);
    EXPECT_EQ(document_.scene(), scene);
    EXPECT_EQ(document_.shownFiles(), QStringList{qpath(fs::absolute(tube))});
    EXPECT_FALSE(DocumentController::recentFiles().contains(qpath(missing)));

    show(tube);  // the next scene shown clears the error
    EXPECT_TRUE(document_.lastError().isEmpty());
}

TEST_F(DocumentControllerTest, ASceneFromElsewhereIsADocumentWithoutFiles) {
    show(writeTube("replaced-by-scene.vtp"));
    Recorder record(document_);
    document_.setScene(makeTubeScene(), QStringLiteral("built"));
    // At once, without a worker.
    EXPECT_EQ(record.joined(), "volumeChanged sceneChanged sceneShown ");
    EXPECT_EQ(document_.title(), QStringLiteral("built"));
    EXPECT_TRUE(document_.shownFiles().isEmpty());
    EXPECT_TRUE(document_.reportSource().files.empty());
    const fs::path saved = documentTestDir() / "built.vvs";
    ASSERT_TRUE(document_.saveSession(qpath(saved), {}));
    EXPECT_TRUE(app::loadSession(saved).files.isEmpty());
}

TEST_F(DocumentControllerTest, ASavedSessionNamesTheShownFilesAndKeepsTheView) {
    const fs::path tube = writeTube("saved.vtp");
    show(tube);
    app::Session view;
    view.vss.solver.p = 5.0;
    view.files = {QStringLiteral("/not/what/is/shown.vtp")};  // the document's files win
    const fs::path path = documentTestDir() / "saved.vvs";
    ASSERT_TRUE(document_.saveSession(qpath(path), view));
    const app::Session saved = app::loadSession(path);
    EXPECT_EQ(saved.files, QStringList{qpath(fs::absolute(tube))});
    EXPECT_DOUBLE_EQ(saved.vss.solver.p, 5.0);
    EXPECT_FALSE(saved.dicom.has_value());

    Recorder record(document_);
    EXPECT_FALSE(document_.saveSession(qpath(documentTestDir() / "no-dir" / "x.vvs"), view));
    EXPECT_EQ(record.count("failed"), 1);
    EXPECT_TRUE(document_.lastError().contains(QStringLiteral("x.vvs")))
        << document_.lastError().toStdString();
}

TEST_F(DocumentControllerTest, DropsOpenSessionsFirstThenMeshesThenFolders) {
    const fs::path tube = writeTube("dropped.vtp");
    const fs::path session = writeSession("dropped.vvs", {qpath(tube)});
    const QString notes = qpath(documentTestDir() / "notes.txt");
    EXPECT_FALSE(DocumentController::canOpen({notes}));
    EXPECT_TRUE(DocumentController::canOpen({notes, qpath(tube)}));
    EXPECT_TRUE(DocumentController::canOpen({qpath(documentTestDir())}));  // a DICOM folder?
    EXPECT_FALSE(document_.openDropped({notes}));

    Recorder record(document_);
    ASSERT_TRUE(document_.openDropped({notes, qpath(tube), qpath(session)}));
    ASSERT_TRUE(waitUntil([&] { return record.count("sessionApplied") > 0; })) << record.joined();
    ASSERT_TRUE(document_.openDropped({qpath(documentTestDir()), qpath(tube)}));
    EXPECT_TRUE(waitUntil([&] { return !document_.isLoading(); }));
    EXPECT_EQ(record.count("seriesScanned"), 0);  // the mesh, not the folder
    EXPECT_EQ(record.count("sceneChanged"), 2);
}

TEST_F(DocumentControllerTest, AFolderWithoutDicomImagesFailsNamingIt) {
    const fs::path empty = documentTestDir() / "no-dicom";
    fs::create_directories(empty);
    std::ofstream(empty / "readme.txt") << "not DICOM\n";
    Recorder record(document_);
    document_.openDicom(qpath(empty));
    ASSERT_TRUE(waitUntil([&] { return !document_.isLoading(); }));
    EXPECT_EQ(record.count("seriesScanned"), 0) << record.joined();
    ASSERT_EQ(record.failures.size(), 1) << record.joined();
    EXPECT_TRUE(record.failures.front().contains(QStringLiteral("no DICOM images found")));
    EXPECT_TRUE(record.failures.front().contains(qpath(empty)));
}

}  // namespace
}  // namespace vv::test
