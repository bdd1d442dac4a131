// SPDX-License-Identifier: GPL-3.0-or-later
// DICOM > Local Studies over stores made with the real store API (no PACS):
// the list of a store of many studies is right; the index is read off the
// GUI thread (a writer holding the SQLite index keeps the read waiting, not
// the window) and a read that a newer one overtook is dropped; a series
// opened from the store is named by its description (or modality and
// number), never by its UID folder.
#include <gtest/gtest.h>

#include <QAction>
#include <QDate>
#include <QFile>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLabel>
#include <QLocale>
#include <QMenu>
#include <QPointer>
#include <QPushButton>
#include <QSettings>
#include <QSqlDatabase>
#include <QSqlQuery>
#include <QStatusBar>
#include <QTimer>
#include <QTreeWidget>
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "GuiFixture.h"
#include "LocalStudiesGui.h"
#include "SyntheticCta.h"
#include "gui/DocumentController.h"
#include "gui/MainWindow.h"
#include "gui/SeriesDialog.h"
#include "gui/pacs/ListenerService.h"
#include "gui/pacs/LocalStudiesBrowser.h"
#include "gui/pacs/PacsSettings.h"
#include "gui/pacs/PacsWidgets.h"
#include "vv/dicom/Dicom.h"
#include "vv/dicom/SeriesWriter.h"
#include "vv/pacs/LocalStore.h"

namespace pacs_local_studies_gui_test {

namespace {

namespace fs = std::filesystem;
using vv::gui::LocalStudiesBrowser;
using vv::test::waitUntil;

fs::path testDir() {
    return vv::test::panelTestDir() / "pacs-local";
}

/// One study of the tests' stores: what goes into the index.
struct Study {
    std::string uid;
    std::string date;  ///< YYYYMMDD
    std::string description;
};

/// `count` studies of one series and one (not DICOM) instance each, with
/// distinct dates and descriptions, committed to the store at `root` in one
/// transaction through the store's API.
std::vector<Study> commitStudies(const fs::path& root, int count, int first = 0) {
    const vv::pacs::LocalStore store(root);
    vv::pacs::LocalStore::Transaction t = store.begin();
    std::vector<Study> studies;
    for (int i = first; i < first + count; ++i) {
        Study s;
        s.uid = "2.25." + std::to_string(100000 + i);
        s.date = QDate(1990 + i % 30, 1 + i % 12, 1 + i % 28)
                     .toString(QStringLiteral("yyyyMMdd"))
                     .toStdString();
        s.description = "Study " + std::to_string(i);
        const fs::path staged = t.stagingPath();
        std::ofstream(staged) << "instance " << i;
        vv::pacs::InstanceFields f;
        f.studyInstanceUid = s.uid;
        f.seriesInstanceUid = s.uid + ".1";
        f.sopInstanceUid = s.uid + ".1.1";
        f.patientName = "Test^Store";
        f.studyDate = s.date;
        f.studyDescription = s.description;
        f.modality = "CT";
        f.seriesDescription = "Series of " + s.description;
        f.seriesNumber = 1;
        t.add(staged, f);
        studies.push_back(s);
    }
    t.commit();
    return studies;
}

/// The order the store lists studies in: newest first, then by UID.
void sortAsListed(std::vector<Study>& studies) {
    std::sort(studies.begin(), studies.end(), [](const Study& a, const Study& b) {
        return a.date != b.date ? a.date > b.date : a.uid < b.uid;
    });
}

/// Holds the store's SQLite index as a writer does (an exclusive
/// transaction through its own connection): readers wait until release().
class IndexWriter {
  public:
    explicit IndexWriter(const fs::path& root) {
        QSqlDatabase db = QSqlDatabase::addDatabase(QStringLiteral("QSQLITE"), name_);
        db.setDatabaseName(QString::fromStdString((root / "index.sqlite").string()));
        EXPECT_TRUE(db.open());
        EXPECT_TRUE(QSqlQuery(db).exec(QStringLiteral("BEGIN EXCLUSIVE")));
    }
    IndexWriter(const IndexWriter&) = delete;
    IndexWriter& operator=(const IndexWriter&) = delete;
    IndexWriter(IndexWriter&&) = delete;
    IndexWriter& operator=(IndexWriter&&) = delete;
    ~IndexWriter() {
        release();
        QSqlDatabase::removeDatabase(name_);
    }
    void release() {
        QSqlDatabase db = QSqlDatabase::database(name_, false);
        if (db.isOpen()) {
            QSqlQuery(db).exec(QStringLiteral("ROLLBACK"));
            db.close();
        }
    }

  private:
    QString name_ = QStringLiteral("test.index.writer");
};

class PacsLocalStudiesGuiTest : public vv::test::GuiFixture {
  protected:
    void SetUp() override {
        const std::string name = ::testing::UnitTest::GetInstance()->current_test_info()->name();
        store_ = testDir() / ("store-" + name);
        fs::remove_all(store_);
        GuiFixture::SetUp();
    }
    void TearDown() override {
        GuiFixture::TearDown();
        QSettings().remove(QStringLiteral("pacs"));
        std::error_code ec;
        fs::remove_all(store_, ec);
    }

    /// Settings with the store at `store` and no listener.
    [[nodiscard]] static vv::gui::PacsSettings settingsFor(const fs::path& store) {
        vv::gui::PacsSettings s;
        s.me.aeTitle = "VVLOCAL";
        s.listenerEnabled = false;
        s.storeFolder = store;
        return s;
    }

    /// A new main window over the store store_.
    void restart() {
        window_.reset();
        QSettings settings;
        vv::gui::writePacsSettings(settingsFor(store_), settings);
        settings.sync();
        GuiFixture::SetUp();
    }

    /// DICOM > Local Studies…, as the user opens it; waits for its rows.
    LocalStudiesBrowser* openBrowser() { return vv::test::openLocalStudies(*window_); }

    static QPushButton* refreshButton(LocalStudiesBrowser* browser) {
        for (QPushButton* button : browser->findChildren<QPushButton*>()) {
            if (button->text() == QStringLiteral("&Refresh")) {
                return button;
            }
        }
        ADD_FAILURE() << "no Refresh button";
        return nullptr;
    }

    fs::path store_;
};

TEST_F(PacsLocalStudiesGuiTest, AStoreOfManyStudiesIsListedRowByRowInItsOrder) {
    constexpr int kStudies = 1500;
    std::vector<Study> studies = commitStudies(store_, kStudies);
    sortAsListed(studies);
    restart();
    LocalStudiesBrowser* browser = openBrowser();
    ASSERT_NE(browser, nullptr);
    ASSERT_EQ(browser->tree()->topLevelItemCount(), kStudies);
    for (const int row : {0, 1, kStudies / 2, kStudies - 1}) {
        const QTreeWidgetItem* item = browser->tree()->topLevelItem(row);
        const Study& expected = studies[static_cast<std::size_t>(row)];
        EXPECT_EQ(item->text(3).toStdString(), expected.description) << "row " << row;
        EXPECT_EQ(item->text(2).toStdString(), vv::gui::studyDateText(expected.date).toStdString())
            << "row " << row;
        EXPECT_TRUE(item->text(2).contains(QString::fromStdString(expected.date.substr(0, 4))))
            << "row " << row;
        ASSERT_EQ(item->childCount(), 1);
        EXPECT_EQ(item->child(0)->text(3).toStdString(), "Series of " + expected.description);
        EXPECT_EQ(item->child(0)->text(5), QStringLiteral("1 image"));
    }
    EXPECT_TRUE(browser->statusLine()->text().startsWith(
        QStringLiteral("%1 studies in %2")
            .arg(QLocale().toString(kStudies), QString::fromStdString(store_.string()))))
        << browser->statusLine()->text().toStdString();
}

TEST_F(PacsLocalStudiesGuiTest, TheIndexIsReadOffTheGuiThreadWhichKeepsWorkingMeanwhile) {
    commitStudies(store_, 200);
    restart();
    LocalStudiesBrowser* browser = openBrowser();
    ASSERT_NE(browser, nullptr);
    ASSERT_EQ(browser->tree()->topLevelItemCount(), 200);
    browser->tree()->setCurrentItem(browser->tree()->topLevelItem(5));
    const QString chosen = browser->tree()->currentItem()->text(3);
    commitStudies(store_, 1, 200);  // a study more, then a writer holds the index
    IndexWriter writer(store_);

    refreshButton(browser)->click();
    // The click returned while the writer still holds the index: a read on
    // the GUI thread would have ended (read or failed) inside the click.
    EXPECT_TRUE(browser->isReading()) << "Refresh read the index on the GUI thread";
    EXPECT_TRUE(browser->statusLine()->text().startsWith(QStringLiteral("Reading the study store")))
        << browser->statusLine()->text().toStdString();
    // The GUI thread goes on: its timer ticks while the read waits.
    int ticks = 0;
    QTimer timer;
    QObject::connect(&timer, &QTimer::timeout, [&ticks] { ++ticks; });
    timer.start(50);
    EXPECT_TRUE(waitUntil([&] { return ticks >= 10; })) << "the GUI thread stood still";
    EXPECT_TRUE(browser->isReading()) << "the index is held: the read cannot have ended";
    EXPECT_EQ(browser->tree()->topLevelItemCount(), 200) << "the last read's rows stay meanwhile";
    browser->grab().save(QString::fromStdString((testDir() / "local-reading.png").string()));

    writer.release();
    ASSERT_TRUE(waitUntil([&] { return !browser->isReading(); }, 15000));
    EXPECT_EQ(browser->tree()->topLevelItemCount(), 201);
    EXPECT_TRUE(browser->statusLine()->text().startsWith(QStringLiteral("201 studies in")))
        << browser->statusLine()->text().toStdString();
    ASSERT_NE(browser->tree()->currentItem(), nullptr);
    EXPECT_EQ(browser->tree()->currentItem()->text(3), chosen) << "the choice stays";
}

TEST_F(PacsLocalStudiesGuiTest, AReadThatANewerOneOvertookIsDropped) {
    commitStudies(store_, 3);
    const fs::path other = store_.string() + "-other";
    fs::remove_all(other);
    commitStudies(other, 2, 50);
    restart();
    LocalStudiesBrowser* browser = openBrowser();
    ASSERT_NE(browser, nullptr);
    ASSERT_EQ(browser->tree()->topLevelItemCount(), 3);
    {
        IndexWriter writer(store_);
        refreshButton(browser)->click();  // waits on the held index
        ASSERT_TRUE(browser->isReading());
        // New settings name another store: its read overtakes the waiting one.
        window_->listenerService()->apply(settingsFor(other));
        ASSERT_TRUE(waitUntil([&] { return !browser->isReading(); }, 15000));
        EXPECT_EQ(browser->tree()->topLevelItemCount(), 2);
    }  // the index is free: the old read ends now, and must not show up
    waitUntil([] { return false; }, 1500);
    EXPECT_EQ(browser->tree()->topLevelItemCount(), 2);
    EXPECT_FALSE(browser->isReading());
    EXPECT_NE(browser->statusLine()->text().indexOf(QString::fromStdString(other.string())), -1)
        << browser->statusLine()->text().toStdString();
    std::error_code ec;
    fs::remove_all(other, ec);
}

/// A synthetic CTA written as a CT series described `description` (number 1)
/// and committed with its files into the store at `root`, as a retrieve
/// stores it; returns the Series Instance UID (its folder's name).
std::string commitCta(const fs::path& root, const std::string& description) {
    const fs::path folder = testDir() / "cta-written";
    fs::remove_all(folder);
    const auto cta = vv::test::makeSyntheticCta({64, 64, 40}, 3);
    vv::dicom::CtSeriesWriteOptions options;
    options.seriesDescription = description;
    vv::dicom::writeCtSeries(folder, cta.volume, options);
    const vv::dicom::DicomScanResult scan = vv::dicom::scanDicom(folder);
    EXPECT_EQ(scan.allSeries().size(), 1U);
    const vv::dicom::DicomSeries& series = *scan.allSeries().front();
    const vv::dicom::DicomStudy& study = scan.patients.front().studies.front();
    const vv::pacs::LocalStore store(root);
    vv::pacs::LocalStore::Transaction t = store.begin();
    int instance = 0;
    for (const fs::path& file : series.files) {
        const fs::path staged = t.stagingPath();
        fs::copy_file(file, staged);
        vv::pacs::InstanceFields f;
        f.studyInstanceUid = series.studyInstanceUid;
        f.seriesInstanceUid = series.seriesInstanceUid;
        f.sopInstanceUid = "2.25." + std::to_string(700 + ++instance);
        f.studyDate = study.date;
        f.studyDescription = study.description;
        f.modality = series.modality;
        f.seriesDescription = series.description;
        f.seriesNumber = series.seriesNumber.value_or(-1);
        t.add(staged, f);
    }
    t.commit();
    return series.seriesInstanceUid;
}

class PacsSeriesTitleGuiTest : public PacsLocalStudiesGuiTest {
  protected:
    /// Open on the first study's series in Local Studies, the series chooser
    /// accepted as it comes; true once the scene is shown.
    bool openFromLocalStudies() {
        LocalStudiesBrowser* browser = openBrowser();
        if (browser == nullptr || browser->tree()->topLevelItemCount() != 1) {
            ADD_FAILURE() << "the study is not listed";
            return false;
        }
        browser->tree()->setCurrentItem(browser->tree()->topLevelItem(0)->child(0));
        QPointer<vv::gui::SeriesDialog> chooser;
        const vv::test::ScopedConnection keep1(
            QObject::connect(window_.get(), &vv::gui::MainWindow::seriesDialogShown, window_.get(),
                             [&chooser](vv::gui::SeriesDialog* shown) { chooser = shown; }));
        bool shown = false;
        const vv::test::ScopedConnection keep2(
            QObject::connect(window_.get(), &vv::gui::MainWindow::sceneShown, window_.get(),
                             [&shown] { shown = true; }));
        browser->openButton()->click();
        if (!waitUntil([&] { return !chooser.isNull() || !window_->lastError().isEmpty(); })) {
            return false;
        }
        EXPECT_FALSE(chooser.isNull()) << window_->lastError().toStdString();
        if (chooser.isNull()) {
            return false;
        }
        chooser->accept();
        return waitUntil([&] { return shown || !window_->lastError().isEmpty(); }, 50000) && shown;
    }
};

TEST_F(PacsSeriesTitleGuiTest, ASeriesOpenedFromTheStoreIsTitledByItsDescription) {
    const std::string uid = commitCta(store_, "Run-off CTA 1.0 mm");
    restart();
    ASSERT_TRUE(openFromLocalStudies()) << window_->lastError().toStdString();
    EXPECT_EQ(window_->windowTitle().toStdString(), "Run-off CTA 1.0 mm — VesselView");
    EXPECT_FALSE(window_->windowTitle().contains(QString::fromStdString(uid)));
    EXPECT_EQ(window_->document()->title().toStdString(), "Run-off CTA 1.0 mm");
    window_->grab().save(QString::fromStdString((testDir() / "series-title.png").string()));
}

/// The entries of File > Open Recent ("&1 …", "&2 …"), in order.
QList<QAction*> recentMenuActions(const vv::gui::MainWindow& window) {
    QList<QAction*> entries;
    for (const QMenu* menu : window.findChildren<QMenu*>()) {
        if (menu->title() != vv::gui::MainWindow::tr("Open &Recent")) {
            continue;
        }
        for (QAction* action : menu->actions()) {
            const QString text = action->text();
            if (!action->isSeparator() && text.startsWith(QLatin1Char('&')) && text.size() > 3 &&
                text[1].isDigit()) {
                entries << action;
            }
        }
    }
    return entries;
}

QAction* recentMenuAction(const vv::gui::MainWindow& window, int index) {
    return recentMenuActions(window).value(index, nullptr);
}

/// The entries of File > Open Recent as shown (without the "&1 " prefix).
QStringList recentMenuTexts(const vv::gui::MainWindow& window) {
    QStringList texts;
    for (const QAction* action : recentMenuActions(window)) {
        texts << action->text().mid(3).replace(QStringLiteral("&&"), QStringLiteral("&"));
    }
    return texts;
}

TEST_F(PacsSeriesTitleGuiTest, OpenRecentNamesAStoreSeriesByItsDescriptionAndDate) {
    const std::string uid = commitCta(store_, "Run-off CTA 1.0 mm");
    restart();
    ASSERT_TRUE(openFromLocalStudies()) << window_->lastError().toStdString();
    const QStringList entries = recentMenuTexts(*window_);
    ASSERT_FALSE(entries.isEmpty());
    EXPECT_EQ(entries.front().toStdString(),
              (QStringLiteral("Run-off CTA 1.0 mm · ") + vv::gui::studyDateText("20250101"))
                  .toStdString());
    EXPECT_FALSE(entries.front().contains(QString::fromStdString(uid)));
    // The next start shows it the same, and opens it from there.
    restart();
    ASSERT_EQ(recentMenuTexts(*window_).value(0).toStdString(), entries.front().toStdString());
    EXPECT_EQ(vv::gui::MainWindow::recentFiles().value(0).section(QLatin1Char('/'), -1),
              QString::fromStdString(uid));
    QAction* entry = recentMenuAction(*window_, 0);
    ASSERT_NE(entry, nullptr);
    bool shown = false;
    QObject::connect(window_.get(), &vv::gui::MainWindow::sceneShown, window_.get(),
                     [&shown] { shown = true; });
    entry->trigger();
    ASSERT_TRUE(waitUntil([&] { return shown || !window_->lastError().isEmpty(); }, 50000));
    ASSERT_TRUE(window_->lastError().isEmpty()) << window_->lastError().toStdString();
    EXPECT_EQ(window_->windowTitle().toStdString(), "Run-off CTA 1.0 mm — VesselView");
    EXPECT_EQ(window_->document()->seriesUid(), uid);
}

TEST_F(PacsSeriesTitleGuiTest, ASeriesWithoutDescriptionIsTitledByModalityAndNumber) {
    const std::string uid = commitCta(store_, "");
    restart();
    ASSERT_TRUE(openFromLocalStudies()) << window_->lastError().toStdString();
    EXPECT_EQ(window_->windowTitle().toStdString(), "CT series 1 — VesselView");
    EXPECT_FALSE(window_->windowTitle().contains(QString::fromStdString(uid)));
}

/// The texts of the window's status bar as shown (its visible labels).
QString statusText(const vv::gui::MainWindow& window) {
    QStringList texts;
    for (const QLabel* label : window.statusBar()->findChildren<QLabel*>()) {
        if (label->isVisible() && !label->text().isEmpty()) {
            texts << label->text();
        }
    }
    return texts.join(QStringLiteral(" | "));
}

class PacsSessionTitleGuiTest : public PacsSeriesTitleGuiTest {
  protected:
    /// A series described `description` committed to the store, opened from
    /// Local Studies and saved as the session session(); returns the folder it
    /// was loaded from (named by its UID).
    QString openAndSave(const std::string& description) {
        uid_ = commitCta(store_, description);
        restart();
        if (!openFromLocalStudies()) {
            ADD_FAILURE() << "not opened: " << window_->lastError().toStdString();
            return {};
        }
        const QStringList files = window_->document()->shownFiles();
        EXPECT_EQ(files.size(), 1);
        // The folder is the UID: what the title must not be.
        EXPECT_TRUE(files.value(0).contains(QString::fromStdString(uid_)))
            << files.value(0).toStdString();
        EXPECT_TRUE(window_->saveSessionTo(session()));
        return files.value(0);
    }
    /// Opens session() in a fresh window (the store's settings as before),
    /// noting every text the status bar showed while it loaded; true once it
    /// was applied or failed.
    bool reopen() {
        restart();
        QObject::connect(window_->document(), &vv::gui::DocumentController::loadStarted,
                         window_.get(), [this] { shown_ << statusText(*window_); });
        QObject::connect(window_->document(), &vv::gui::DocumentController::loadProgress,
                         window_.get(), [this] { shown_ << statusText(*window_); });
        bool applied = false;
        const vv::test::ScopedConnection keep1(
            QObject::connect(window_.get(), &vv::gui::MainWindow::sessionApplied, window_.get(),
                             [&applied] { applied = true; }));
        return window_->openSession(session()) &&
               waitUntil([&] { return applied || !window_->lastError().isEmpty(); }, 60000);
    }
    [[nodiscard]] static QString session() {
        return QString::fromStdString((testDir() / "titled.vvs").string());
    }
    [[nodiscard]] QString uid() const { return QString::fromStdString(uid_); }

    std::string uid_;
    QStringList shown_;  ///< the status bar while the session loaded
};

TEST_F(PacsSessionTitleGuiTest, ASavedSessionReopensTheSeriesUnderItsTitle) {
    ASSERT_FALSE(openAndSave("Run-off CTA 1.0 mm").isEmpty());
    ASSERT_TRUE(reopen());
    ASSERT_TRUE(window_->lastError().isEmpty()) << window_->lastError().toStdString();
    EXPECT_EQ(window_->windowTitle().toStdString(), "Run-off CTA 1.0 mm — VesselView");
    EXPECT_EQ(window_->document()->title().toStdString(), "Run-off CTA 1.0 mm");
    const QString status = statusText(*window_);
    EXPECT_TRUE(status.contains(QStringLiteral("Run-off CTA 1.0 mm: 1 mesh, ")))
        << status.toStdString();
    EXPECT_TRUE(std::any_of(shown_.begin(), shown_.end(), [](const QString& text) {
        return text.contains(QStringLiteral("Loading Run-off CTA 1.0 mm…"));
    })) << shown_.join('\n').toStdString();
    for (const QString& text : shown_ + QStringList{status, window_->windowTitle()}) {
        EXPECT_FALSE(text.contains(uid())) << "a UID shown: " << text.toStdString();
    }
    window_->grab().save(QString::fromStdString((testDir() / "session-title.png").string()));
    // Saved again from the reopened window, the title stays.
    EXPECT_TRUE(window_->saveSessionTo(session()));
    ASSERT_TRUE(reopen());
    EXPECT_EQ(window_->windowTitle().toStdString(), "Run-off CTA 1.0 mm — VesselView");
}

TEST_F(PacsSessionTitleGuiTest, ASessionSavedInAnotherLanguageReopensInTheUiLanguage) {
    ASSERT_FALSE(openAndSave("").isEmpty());
    EXPECT_EQ(window_->windowTitle().toStdString(), "CT series 1 — VesselView");
    // The same session as a German window saved it.
    QFile file(session());
    ASSERT_TRUE(file.open(QIODevice::ReadOnly));
    QJsonObject root = QJsonDocument::fromJson(file.readAll()).object();
    file.close();
    QJsonObject dicom = root.value(QStringLiteral("dicom")).toObject();
    ASSERT_EQ(dicom.value(QStringLiteral("title")).toString(), QStringLiteral("CT series 1"));
    dicom.insert(QStringLiteral("title"), QStringLiteral("CT-Serie 1"));
    root.insert(QStringLiteral("dicom"), dicom);
    ASSERT_TRUE(file.open(QIODevice::WriteOnly | QIODevice::Truncate));
    file.write(QJsonDocument(root).toJson());
    file.close();
    ASSERT_TRUE(reopen());
    ASSERT_TRUE(window_->lastError().isEmpty()) << window_->lastError().toStdString();
    EXPECT_EQ(window_->windowTitle().toStdString(), "CT series 1 — VesselView");
    EXPECT_TRUE(statusText(*window_).contains(QStringLiteral("CT series 1: 1 mesh, ")))
        << statusText(*window_).toStdString();
}

TEST_F(PacsSessionTitleGuiTest, ASessionWhoseSeriesIsGoneNamesTheFolderButNoUidTitle) {
    const QString folder = openAndSave("Carotid CTA");
    ASSERT_FALSE(folder.isEmpty());
    restart();  // the series is no longer open when its files go
    fs::remove_all(fs::path(folder.toStdString()));
    ASSERT_TRUE(reopen());
    // As for any missing file: the error names it, the empty window stays.
    EXPECT_TRUE(window_->lastError().contains(folder)) << window_->lastError().toStdString();
    EXPECT_EQ(window_->windowTitle().toStdString(), "VesselView");
    EXPECT_EQ(window_->viewer()->scene(), nullptr);
}

TEST(PacsSeriesNameTest, ASeriesIsNamedByWhatItSaysNeverByItsUid) {
    vv::dicom::DicomSeries s;
    s.seriesInstanceUid = "1.2.3.4";
    s.description = "  Arterial  phase ";
    s.modality = "CT";
    s.seriesNumber = 4;
    EXPECT_EQ(vv::gui::SeriesDialog::seriesName(s), QStringLiteral("Arterial phase"));
    s.description = " ";
    EXPECT_EQ(vv::gui::SeriesDialog::seriesName(s), QStringLiteral("CT series 4"));
    s.seriesNumber.reset();
    EXPECT_EQ(vv::gui::SeriesDialog::seriesName(s), QStringLiteral("CT series"));
    s.modality.clear();
    EXPECT_EQ(vv::gui::SeriesDialog::seriesName(s), QStringLiteral("DICOM series"));
    s.seriesNumber = 7;
    EXPECT_EQ(vv::gui::SeriesDialog::seriesName(s), QStringLiteral("Series 7"));
    // A series number is an identifier: never grouped ("10.001" in German).
    const QLocale before;
    QLocale::setDefault(QLocale(QLocale::German, QLocale::Germany));
    s.modality = "CT";
    s.seriesNumber = 10001;
    EXPECT_EQ(vv::gui::SeriesDialog::seriesName(s).toStdString(), "CT series 10001");
    QLocale::setDefault(before);
}

class SeriesChooserTest : public vv::test::GuiFixture {};

TEST_F(SeriesChooserTest, ShowsStudyDatesAndSeriesNumbersAsTheBrowsersDo) {
    const QLocale before;
    QLocale::setDefault(QLocale(QLocale::German, QLocale::Germany));
    vv::dicom::DicomScanResult scan;
    vv::dicom::DicomSeries series;
    series.seriesInstanceUid = "1.2.3.4";
    series.modality = "CT";
    series.seriesNumber = 10001;
    series.imageCount = 3;
    vv::dicom::DicomStudy study;
    study.studyInstanceUid = "1.2.3";
    study.date = "20250307";
    study.series.push_back(series);
    vv::dicom::DicomPatient patient;
    patient.studies.push_back(study);
    scan.patients.push_back(patient);
    vv::gui::SeriesDialog dialog(scan);
    QLocale::setDefault(before);
    const QTreeWidgetItem* studyItem = dialog.tree()->topLevelItem(0)->child(0);
    // 7 March 2025 as the UI language writes dates (English here: the test
    // loads no translation; German is checked with its translation in
    // PacsGuiLanguageTest), as the study browsers, Open Recent and the report.
    EXPECT_EQ(studyItem->text(0).toStdString(),
              "Study " + vv::gui::studyDateText("20250307").toStdString());
    EXPECT_EQ(vv::gui::studyDateText("20250307").toStdString(), "2025-03-07");
    EXPECT_EQ(studyItem->child(0)->text(0).toStdString(), "Series 10001");
}

}  // namespace

}  // namespace pacs_local_studies_gui_test
