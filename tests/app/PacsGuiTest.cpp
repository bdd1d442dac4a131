// SPDX-License-Identifier: GPL-3.0-or-later
// The app's DICOM listener, the Local Studies browser and Send to PACS
// (issue 21) against a real Orthanc started by the test on free ports
// (tests/pacs/OrthancServer.h): what the user sees in the browser, the
// status bar and the Send dialog.
#include <arpa/inet.h>
#include <gtest/gtest.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <QAction>
#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QLineEdit>
#include <QMessageBox>
#include <QPlainTextEdit>
#include <QPointer>
#include <QProgressBar>
#include <QPushButton>
#include <QSettings>
#include <QTreeWidget>
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <memory>
#include <set>
#include <string>
#include <thread>

#include "ClippingCheck.h"
#include "GuiFixture.h"
#include "ListenerPeers.h"
#include "LocalStudiesGui.h"
#include "OrthancServer.h"
#include "ReportTestUtil.h"
#include "SyntheticCta.h"
#include "UiLanguage.h"
#include "gui/ExportWorker.h"
#include "gui/MainWindow.h"
#include "gui/ReportDialog.h"
#include "gui/SeriesDialog.h"
#include "gui/analysis/PlanningState.h"
#include "gui/pacs/ListenerService.h"
#include "gui/pacs/LocalStudiesBrowser.h"
#include "gui/pacs/PacsSettings.h"
#include "gui/pacs/SendDialog.h"
#include "gui/pacs/StoreLeases.h"
#include "gui/panels/AnalysisPanel.h"
#include "gui/panels/SegmentationPanel.h"
#include "vv/dicom/DicomSeg.h"
#include "vv/dicom/SeriesWriter.h"
#include "vv/pacs/Echo.h"
#include "vv/pacs/Find.h"
#include "vv/pacs/LocalStore.h"
#include "vv/pacs/PacsError.h"
#include "vv/pacs/Retrieve.h"
#include "vv/pacs/Send.h"

namespace pacs_gui_test {

namespace {

namespace fs = std::filesystem;
using vv::gui::ListenerService;
using vv::gui::LocalStudiesBrowser;
using vv::gui::MainWindow;
using vv::gui::PacsSettings;
using vv::gui::SendDialog;
using vv::test::OrthancServer;
using vv::test::waitUntil;

constexpr const char* kOurAe = "VVGUI";
constexpr const char* kPatientId = "VV-GUI-1";
constexpr int kSlices = 48;
constexpr const char* kNeckUid = "1.2.826.0.1.1";  ///< the study "Neck CTA" of the tests

vv::pacs::LocalAe me() {
    return vv::pacs::LocalAe{kOurAe, vv::pacs::Timeouts{2, 5, 10}};
}

fs::path testDir() {
    return vv::test::panelTestDir() / "pacs";
}

/// The synthetic CTA (64 x 64 x 48, a vessel tree) as a CT series in `folder`.
/// `description`: the Series Description (empty: the writer's default).
std::vector<fs::path> writeCta(const fs::path& folder, const std::string& patientId,
                               const std::string& description = {}) {
    fs::remove_all(folder);
    const auto cta = vv::test::makeSyntheticCta({64, 64, kSlices}, 3);
    vv::dicom::CtSeriesWriteOptions options;
    options.patientId = patientId;
    options.patientName = "Test^Vessel";
    options.studyDescription = "CTA run-off";
    if (!description.empty()) {
        options.seriesDescription = description;
    }
    vv::dicom::writeCtSeries(folder, cta.volume, options);
    std::vector<fs::path> files;
    for (const auto& entry : fs::directory_iterator(folder)) {
        files.push_back(entry.path());
    }
    return files;
}

/// A study "description" of 2 January 2024 with one instance of `bytes`
/// bytes committed to the store at `root` (not DICOM: the browser reads the
/// index).
void commitStudy(const fs::path& root, const std::string& uid, const std::string& description,
                 std::size_t bytes = 2000) {
    const vv::pacs::LocalStore store(root);
    vv::pacs::LocalStore::Transaction t = store.begin();
    const fs::path staged = t.stagingPath();
    std::ofstream(staged) << std::string(bytes, 'x');
    vv::pacs::InstanceFields f;
    f.studyInstanceUid = uid;
    f.seriesInstanceUid = uid + ".1";
    f.sopInstanceUid = uid + ".1.1";
    f.patientName = "Test^Store";
    f.studyDate = "20240102";
    f.studyDescription = description;
    f.modality = "CT";
    f.seriesNumber = 1;
    t.add(staged, f);
    t.commit();
}

/// The study row of `browser` described `description`, or nullptr.
QTreeWidgetItem* studyRow(const LocalStudiesBrowser& browser, const QString& description) {
    const auto rows = browser.tree()->findItems(description, Qt::MatchExactly, 3);
    return rows.isEmpty() ? nullptr : rows.front();
}

/// All texts of `item`'s columns, "|"-joined, for failure messages and checks.
/// A study date as both browsers show it: the UI locale's short format,
/// with the year in four digits (never "1/2/24").
/// A date as the English UI (no translation loaded here) writes it, the same
/// as the report: year, month, day.
QString shownDate(const QDate& date) {
    return date.toString(QStringLiteral("yyyy-MM-dd"));
}

std::string rowText(const QTreeWidgetItem* item) {
    QStringList texts;
    for (int c = 0; c < item->columnCount(); ++c) {
        texts << item->text(c);
    }
    return texts.join(QLatin1Char('|')).toStdString();
}

class PacsGuiTest : public vv::test::GuiFixture {
  protected:
    static void SetUpTestSuite() {
        GuiFixture::SetUpTestSuite();
        fs::remove_all(testDir());
        scpPort_ = vv::test::freePort();
        orthanc_ = std::make_unique<OrthancServer>(kOurAe, scpPort_);
        const auto statuses =
            vv::pacs::sendFiles(me(), orthanc_->node(), writeCta(testDir() / "cta", kPatientId));
        ASSERT_EQ(statuses.size(), static_cast<std::size_t>(kSlices));
        vv::pacs::StudyQuery query;
        query.patientId = kPatientId;
        const auto studies = vv::pacs::findStudies(me(), orthanc_->node(), query);
        ASSERT_EQ(studies.size(), 1U);
        studyUid_ = studies[0].studyInstanceUid;
    }
    static void TearDownTestSuite() {
        orthanc_.reset();
        std::error_code ec;
        fs::remove_all(testDir(), ec);
        GuiFixture::TearDownTestSuite();
    }

    /// Settings with our listener on scpPort_ (when `listen`), Orthanc as
    /// the one node (allowed to push when `allowPush`), a fresh store.
    PacsSettings settings(bool listen = true, bool allowPush = true) {
        PacsSettings s;
        s.me = me();
        s.listenerEnabled = listen;
        s.listenerPort = scpPort_;
        vv::gui::PacsNode node;
        node.name = "Orthanc";
        node.node = orthanc_->node();
        node.allowPush = allowPush;
        s.nodes.push_back(node);
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        s.storeFolder = testDir() / (std::string("store-") + info->name());
        return s;
    }

    /// A new main window (the old one closed) that starts with `s`.
    void restartWith(const PacsSettings& s) {
        window_.reset();
        QSettings store;
        vv::gui::writePacsSettings(s, store);
        store.sync();
        GuiFixture::SetUp();
    }

    void TearDown() override {
        GuiFixture::TearDown();
        QSettings().remove(QStringLiteral("pacs"));
    }

    [[nodiscard]] ListenerService* listener() const { return window_->listenerService(); }
    [[nodiscard]] QString indicatorText() const {
        return window_->findChild<QLabel*>(QStringLiteral("listenerIndicator"))->text();
    }

    /// DICOM > Local Studies…, as the user opens it.
    LocalStudiesBrowser* openBrowser() { return vv::test::openLocalStudies(*window_); }

    /// Refresh, and the wait (bounded) for its rows; false when they never came.
    static bool refreshAndRead(LocalStudiesBrowser& browser) {
        browser.refresh();
        return read(browser);
    }

    /// Waits (bounded) until the browser's read of the store is shown.
    static bool read(const LocalStudiesBrowser& browser) {
        return waitUntil([&] { return !browser.isReading(); }, 15000);
    }

    /// Orthanc pushes the study to our listener (C-MOVE with us as destination).
    static void orthancPushesTheStudy() {
        const auto result = vv::pacs::moveTo(kOurAe, me(), orthanc_->node(),
                                             vv::pacs::RetrieveRequest{studyUid_, ""});
        EXPECT_EQ(result.instances, static_cast<std::size_t>(kSlices));
    }

    /// Opens `folder` as the user does (the series chooser accepted); true
    /// once a scene is shown.
    bool openDicomAndAccept(const std::function<void()>& open) {
        QPointer<vv::gui::SeriesDialog> dialog;
        const vv::test::ScopedConnection keep1(
            QObject::connect(window_.get(), &MainWindow::seriesDialogShown, window_.get(),
                             [&dialog](vv::gui::SeriesDialog* d) { dialog = d; }));
        bool shown = false;
        const vv::test::ScopedConnection keep2(
            QObject::connect(window_.get(), &MainWindow::sceneShown, window_.get(),
                             [&shown, this] { shown = window_->viewer()->scene() != nullptr; }));
        open();
        if (!waitUntil([&] { return !dialog.isNull() || !window_->lastError().isEmpty(); })) {
            return false;
        }
        if (dialog.isNull()) {
            ADD_FAILURE() << window_->lastError().toStdString();
            return false;
        }
        dialog->accept();
        const bool ok =
            waitUntil([&] { return shown || !window_->lastError().isEmpty(); }, 50000) && shown;
        EXPECT_TRUE(ok) << window_->lastError().toStdString();
        return ok;
    }

    /// DICOM > Send to PACS…, `edit` on the dialog, Send, and the wait for the outcome.
    SendDialog* sendReport(const std::function<void(SendDialog&)>& edit = {}) {
        QAction* action = window_->findChild<QAction*>(QStringLiteral("sendToPacs"));
        EXPECT_TRUE(action->isEnabled());
        action->trigger();
        auto* dialog = window_->findChild<SendDialog*>();
        if (dialog == nullptr) {
            ADD_FAILURE() << "no Send dialog";
            return nullptr;
        }
        if (edit) {
            edit(*dialog);
        }
        EXPECT_TRUE(dialog->sendButton()->isEnabled());
        dialog->sendButton()->click();
        EXPECT_TRUE(dialog->isSending());
        EXPECT_TRUE(waitUntil([&] { return !dialog->isSending(); }, 55000)) << "the send hangs";
        return dialog;
    }

    /// The instance of the series of `modality` in Orthanc's study `studyUid`,
    /// retrieved (C-GET) into a store at `store`; empty after a test failure.
    fs::path retrievedInstance(const std::string& studyUid, const std::string& modality,
                               const fs::path& store) {
        std::string uid;
        for (const auto& series : vv::pacs::findSeries(me(), orthanc_->node(),
                                                       vv::pacs::SeriesQuery{studyUid, "", ""})) {
            uid = series.modality == modality ? series.seriesInstanceUid : uid;
        }
        vv::pacs::LocalStore retrieved(store);
        if (uid.empty()) {
            ADD_FAILURE() << "no " << modality << " series in Orthanc";
            return {};
        }
        (void)vv::pacs::getInto(retrieved, me(), orthanc_->node(),
                                vv::pacs::RetrieveRequest{studyUid, uid});
        const auto stored = retrieved.studies();
        if (stored.size() != 1 || stored[0].series.size() != 1) {
            ADD_FAILURE() << "the " << modality << " series was not retrieved";
            return {};
        }
        return fs::directory_iterator(stored[0].series[0].folder)->path();
    }

    /// The PDF of the Encapsulated PDF (DOC) in Orthanc's study `studyUid`,
    /// written to `pdf` (dcm2pdf); false after a test failure.
    bool retrievedPdf(const std::string& studyUid, const fs::path& pdf) {
        const fs::path document = retrievedInstance(
            studyUid, "DOC", pdf.parent_path() / (pdf.stem().string() + "-store"));
        std::string output;
        const bool ok =
            !document.empty() &&
            vv::report::test::runTool("dcm2pdf '" + document.string() + "' '" + pdf.string() + "'",
                                      output) == 0;
        EXPECT_TRUE(ok) << output;
        return ok;
    }

    /// The window restarted with `s` over a store holding the study "Neck
    /// CTA" (kNeckUid), and its Local Studies browser open.
    LocalStudiesBrowser* browserOverNeckStudy(const PacsSettings& s) {
        commitStudy(s.storeFolder, kNeckUid, "Neck CTA");
        restartWith(s);
        return openBrowser();
    }

    /// Delete… on `row`, and the Delete button of the confirmation; returns
    /// the confirmation's text.
    static QString deleteAndConfirm(LocalStudiesBrowser& browser, QTreeWidgetItem* row) {
        browser.tree()->setCurrentItem(row);
        EXPECT_TRUE(browser.deleteButton()->isEnabled());
        browser.deleteButton()->click();
        auto* box = browser.findChild<QMessageBox*>(QStringLiteral("deleteStudyBox"));
        if (box == nullptr) {
            ADD_FAILURE() << "no confirmation";
            return {};
        }
        EXPECT_TRUE(waitUntil([&] { return box->isVisible(); }, 5000));
        const QString text = box->text();
        QAbstractButton* remove = nullptr;
        for (QAbstractButton* button : box->buttons()) {
            remove = box->buttonRole(button) == QMessageBox::DestructiveRole ? button : remove;
        }
        EXPECT_NE(remove, nullptr);
        if (remove != nullptr) {
            EXPECT_EQ(remove->text(), QStringLiteral("Delete"));
            remove->click();
        }
        EXPECT_TRUE(waitUntil([&] { return !browser.isDeleting(); }, 20000));
        return text;
    }

    static inline std::unique_ptr<OrthancServer> orthanc_;
    static inline std::uint16_t scpPort_ = 0;
    static inline std::string studyUid_;
};

TEST_F(PacsGuiTest, StudyPushedByOrthancAppearsInLocalStudiesWithoutUserAction) {
    restartWith(settings());
    EXPECT_EQ(listener()->state(), ListenerService::State::Running);
    EXPECT_EQ(indicatorText(), QStringLiteral("DICOM listener: port %1").arg(scpPort_));
    LocalStudiesBrowser* browser = openBrowser();
    ASSERT_NE(browser, nullptr);
    EXPECT_EQ(browser->tree()->topLevelItemCount(), 0);

    orthancPushesTheStudy();
    ASSERT_TRUE(waitUntil([&] { return browser->tree()->topLevelItemCount() == 1; }, 20000))
        << "the pushed study never appeared";
    const QTreeWidgetItem* study = browser->tree()->topLevelItem(0);
    const auto stored = vv::pacs::LocalStore(listener()->storeFolder()).studies();
    ASSERT_EQ(stored.size(), 1U);
    const QDate date =
        QDate::fromString(QString::fromStdString(stored[0].studyDate), QStringLiteral("yyyyMMdd"));
    ASSERT_TRUE(date.isValid()) << stored[0].studyDate;
    EXPECT_EQ(rowText(study),
              "Test, Vessel|VV-GUI-1|" + shownDate(date).toStdString() + "|CTA run-off|CT|1");
    ASSERT_EQ(study->childCount(), 1);
    EXPECT_EQ(rowText(study->child(0)), "|||synthetic CTA|CT|48 images");
    EXPECT_NE(browser->statusLine()->text().indexOf(QStringLiteral("1 study")), -1)
        << browser->statusLine()->text().toStdString();
    browser->grab().save(QString::fromStdString((testDir() / "local-studies.png").string()));
    const auto problems = vv::test::ClippingCheck::problems(browser);
    EXPECT_TRUE(problems.empty()) << problems.front();

    // New settings (as Preferences applies them) with another store: it is listed.
    PacsSettings other = settings();
    other.storeFolder = testDir() / "store-other";
    listener()->apply(other);
    ASSERT_TRUE(read(*browser));
    EXPECT_EQ(browser->tree()->topLevelItemCount(), 0);
    listener()->apply(settings());
    ASSERT_TRUE(read(*browser));
    EXPECT_EQ(browser->tree()->topLevelItemCount(), 1);
}

TEST_F(PacsGuiTest, PushedStudyIsStillListedAfterARestartAndOpens) {
    const PacsSettings s = settings();
    restartWith(s);
    orthancPushesTheStudy();
    ASSERT_TRUE(waitUntil([&] { return listener()->committedInstances() == kSlices; }, 20000));

    restartWith(s);  // the app closed and started again
    LocalStudiesBrowser* browser = openBrowser();
    ASSERT_NE(browser, nullptr);
    ASSERT_EQ(browser->tree()->topLevelItemCount(), 1);
    QTreeWidgetItem* series = browser->tree()->topLevelItem(0)->child(0);
    ASSERT_NE(series, nullptr);
    browser->tree()->setCurrentItem(series);
    ASSERT_TRUE(browser->openButton()->isEnabled());
    ASSERT_TRUE(openDicomAndAccept([&] { browser->openButton()->click(); }));
    EXPECT_FALSE(window_->viewer()->scene()->meshes.empty());
    EXPECT_EQ(window_->volume()->dims().z, kSlices);
}

TEST_F(PacsGuiTest, UnknownNodePushingIsRefusedAndNothingAppears) {
    restartWith(settings());
    LocalStudiesBrowser* browser = openBrowser();
    ASSERT_NE(browser, nullptr);
    const vv::pacs::Node ourListener{kOurAe, "127.0.0.1", scpPort_, {}};
    const vv::pacs::LocalAe stranger{"STRANGER", vv::pacs::Timeouts{2, 5, 10}};
    EXPECT_THROW(
        vv::pacs::sendFiles(stranger, ourListener, writeCta(testDir() / "stranger", "VV-X")),
        vv::pacs::AssociationRejectedError);
    ASSERT_TRUE(waitUntil([&] { return listener()->refusedAssociations() == 1; }, 5000));
    waitUntil([] { return false; }, 1000);  // time for a refresh that must not come
    EXPECT_EQ(browser->tree()->topLevelItemCount(), 0);
    ASSERT_TRUE(refreshAndRead(*browser));
    EXPECT_EQ(browser->tree()->topLevelItemCount(), 0);
}

TEST_F(PacsGuiTest, UnderLoadTheWindowWorksOnAndLocalStudiesFillsInByItself) {
    // Three modalities may push; a host that is no node holds 200 silent
    // connections meanwhile; the three push a study each at the same time.
    PacsSettings s = settings();
    for (int i = 1; i <= 3; ++i) {
        vv::gui::PacsNode node;
        node.name = "Modality " + std::to_string(i);
        node.node = vv::pacs::Node{"LOAD" + std::to_string(i), "127.0.0.1", 104, {}};
        s.nodes.push_back(node);
    }
    restartWith(s);
    ASSERT_EQ(listener()->state(), ListenerService::State::Running);
    LocalStudiesBrowser* browser = openBrowser();
    ASSERT_NE(browser, nullptr);
    ASSERT_EQ(browser->tree()->topLevelItemCount(), 0);
    const auto idle = vv::bench::idleConnections("127.0.0.2", scpPort_, 200);
    std::vector<std::vector<fs::path>> studies;
    for (int i = 1; i <= 3; ++i) {
        studies.push_back(
            writeCta(testDir() / ("load" + std::to_string(i)), "VV-LOAD-" + std::to_string(i)));
    }
    std::vector<std::size_t> accepted(3, 0);
    std::vector<std::thread> senders;
    for (std::size_t i = 0; i < 3; ++i) {
        senders.emplace_back([&, i] {
            const vv::pacs::LocalAe modality{"LOAD" + std::to_string(i + 1),
                                             vv::pacs::Timeouts{5, 10, 20}};
            try {
                for (const auto& status : vv::pacs::sendFiles(
                         modality, vv::pacs::Node{kOurAe, "127.0.0.1", scpPort_, {}}, studies[i])) {
                    accepted[i] += status.accepted ? 1 : 0;
                }
            } catch (const std::exception&) {  // counted as nothing accepted
            }
        });
    }
    // The window's event loop runs all along (waitUntil turns it); the list
    // refreshes by itself as each study is committed.
    const bool listed = waitUntil([&] { return browser->tree()->topLevelItemCount() == 3; }, 60000);
    for (std::thread& sender : senders) {
        sender.join();
    }
    EXPECT_TRUE(listed) << browser->tree()->topLevelItemCount() << " studies listed";
    for (std::size_t i = 0; i < 3; ++i) {
        EXPECT_EQ(accepted[i], static_cast<std::size_t>(kSlices)) << "modality " << i + 1;
    }
    EXPECT_TRUE(waitUntil([&] { return listener()->committedInstances() == 3U * kSlices; }, 10000));
    EXPECT_EQ(listener()->state(), ListenerService::State::Running);
}

/// New limits (as Preferences applies them) restart the listener with them
/// (its counters start again); the same settings again keep it running.
TEST_F(PacsGuiTest, NewListenerLimitsRestartTheListener) {
    PacsSettings s = settings();
    listener()->apply(s);
    ASSERT_EQ(listener()->state(), ListenerService::State::Running);
    const vv::pacs::Node ourListener{kOurAe, "127.0.0.1", scpPort_, {}};
    const vv::pacs::LocalAe stranger{"STRANGER", vv::pacs::Timeouts{2, 5, 10}};
    EXPECT_THROW(vv::pacs::echo(stranger, ourListener), vv::pacs::AssociationRejectedError);
    ASSERT_TRUE(waitUntil([&] { return listener()->refusedAssociations() == 1; }, 5000));
    listener()->apply(s);
    EXPECT_EQ(listener()->refusedAssociations(), 1U) << "restarted without a change";
    s.listenerLimits.requestSeconds = 30;
    listener()->apply(s);
    EXPECT_EQ(listener()->state(), ListenerService::State::Running);
    EXPECT_EQ(listener()->refusedAssociations(), 0U) << "new limits, but the listener ran on";
    EXPECT_THROW(vv::pacs::echo(stranger, ourListener), vv::pacs::AssociationRejectedError);
    EXPECT_TRUE(waitUntil([&] { return listener()->refusedAssociations() == 1; }, 5000));
}

TEST_F(PacsGuiTest, NodeNotAllowedToPushIsRefused) {
    restartWith(settings(true, false));
    LocalStudiesBrowser* browser = openBrowser();
    ASSERT_NE(browser, nullptr);
    EXPECT_THROW(orthancPushesTheStudy(), vv::pacs::NetworkError);
    ASSERT_TRUE(waitUntil([&] { return listener()->refusedAssociations() >= 1; }, 5000));
    ASSERT_TRUE(refreshAndRead(*browser));
    EXPECT_EQ(browser->tree()->topLevelItemCount(), 0);
}

TEST_F(PacsGuiTest, PortInUseIsAClearStateAndTheAppKeepsWorking) {
    const PacsSettings s = settings();
    const int blocker = ::socket(AF_INET, SOCK_STREAM, 0);
    sockaddr_in where{};
    where.sin_family = AF_INET;
    where.sin_port = htons(s.listenerPort);
    where.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    // NOLINTNEXTLINE(cppcoreguidelines-pro-type-reinterpret-cast): the sockets API
    ASSERT_EQ(::bind(blocker, reinterpret_cast<const sockaddr*>(&where), sizeof where), 0);
    ASSERT_EQ(::listen(blocker, 1), 0);
    restartWith(s);
    EXPECT_EQ(listener()->state(), ListenerService::State::Failed);
    EXPECT_EQ(indicatorText(),
              QStringLiteral("DICOM listener failed: port %1 is in use by another program")
                  .arg(s.listenerPort));
    ::close(blocker);
    // The port is free again: applying the settings (as Preferences does) starts it.
    listener()->apply(s);
    EXPECT_EQ(listener()->state(), ListenerService::State::Running);
    EXPECT_EQ(indicatorText(), QStringLiteral("DICOM listener: port %1").arg(s.listenerPort));
    PacsSettings off = s;
    off.listenerEnabled = false;
    listener()->apply(off);
    EXPECT_EQ(indicatorText(), QStringLiteral("DICOM listener off"));
}

TEST_F(PacsGuiTest, ReportOfTheCtaSceneIsAcceptedByOrthancAndFoundThere) {
    restartWith(settings(false));
    // A folder named by a UID, as a study store names them.
    const std::string folderUid = "1.2.826.0.1.3680043.8.498.4711";
    const fs::path cta = testDir() / "cta-send" / folderUid;
    writeCta(cta, "VV-GUI-SEND", "Run-off CTA");
    ASSERT_TRUE(
        openDicomAndAccept([&] { window_->openDicom(QString::fromStdString(cta.string())); }));
    // The findings of an earlier Export Report of this series.
    window_->document()->setFindings(QStringLiteral("Occlusion of the left SFA."));
    const QString findings =
        QStringLiteral("Occlusion of the left SFA.\nCollaterals from the profunda.");
    SendDialog* dialog = sendReport([&](SendDialog& send) {
        // The series by its description, never the UID folder; the findings to review.
        EXPECT_TRUE(send.dataLabel()->text().contains(QStringLiteral("Run-off CTA")))
            << send.dataLabel()->text().toStdString();
        EXPECT_FALSE(send.dataLabel()->text().contains(QString::fromStdString(folderUid)));
        EXPECT_EQ(send.findingsEdit()->toPlainText(), QStringLiteral("Occlusion of the left SFA."));
        send.findingsEdit()->setPlainText(findings);
    });
    ASSERT_NE(dialog, nullptr);
    // What was sent is the data's findings from now on (the next report starts with them).
    EXPECT_EQ(window_->document()->findings(), findings);
    const QString peer = QString::fromStdString(vv::pacs::describe(orthanc_->node()));
    EXPECT_EQ(dialog->summaryLabel()->text(), QStringLiteral("3 of 3 accepted by %1").arg(peer));
    ASSERT_EQ(dialog->resultTable()->topLevelItemCount(), 3);
    EXPECT_EQ(dialog->resultTable()->topLevelItem(0)->text(0),
              QStringLiteral("Report image (Secondary Capture)"));
    EXPECT_EQ(dialog->resultTable()->topLevelItem(1)->text(0),
              QStringLiteral("Report PDF (Encapsulated PDF)"));
    EXPECT_EQ(dialog->resultTable()->topLevelItem(2)->text(0),
              QStringLiteral("Segmentation (DICOM SEG)"));
    for (int row = 0; row < 3; ++row) {
        EXPECT_EQ(dialog->resultTable()->topLevelItem(row)->text(1), QStringLiteral("Accepted"));
    }
    dialog->grab().save(QString::fromStdString((testDir() / "send.png").string()));
    const auto problems = vv::test::ClippingCheck::problems(dialog);
    EXPECT_TRUE(problems.empty()) << problems.front();

    // Orthanc has the report's series in the CTA's study.
    vv::pacs::StudyQuery query;
    query.patientId = "VV-GUI-SEND";
    const auto studies = vv::pacs::findStudies(me(), orthanc_->node(), query);
    ASSERT_EQ(studies.size(), 1U);
    std::set<std::string> modalities;
    for (const auto& series : vv::pacs::findSeries(
             me(), orthanc_->node(), vv::pacs::SeriesQuery{studies[0].studyInstanceUid, "", ""})) {
        modalities.insert(series.modality);
    }
    EXPECT_EQ(modalities, (std::set<std::string>{"DOC", "OT", "SEG"}))
        << "the report's Secondary Capture (OT), PDF (DOC) and the SEG are not in Orthanc";
    // The SEG in Orthanc holds the segmentation on screen: its voxels.
    const fs::path segFile =
        retrievedInstance(studies[0].studyInstanceUid, "SEG", testDir() / "seg-retrieved");
    ASSERT_FALSE(segFile.empty());
    std::size_t inPacs = 0;
    for (const auto& map : vv::dicom::loadDicomSegLabelMaps(segFile)) {
        inPacs += static_cast<std::size_t>(std::count_if(map.labels.begin(), map.labels.end(),
                                                         [](std::uint8_t l) { return l != 0; }));
    }
    const auto& shown = window_->document()->labelMap()->labels;
    EXPECT_EQ(inPacs, static_cast<std::size_t>(std::count_if(
                          shown.begin(), shown.end(), [](std::uint8_t l) { return l != 0; })));
    EXPECT_GT(inPacs, 0U);

    // The PDF in Orthanc has the findings entered and names the series, not its folder.
    const fs::path pdf = testDir() / "sent-report.pdf";
    ASSERT_TRUE(retrievedPdf(studies[0].studyInstanceUid, pdf));
    std::string text;
    ASSERT_EQ(vv::report::test::runTool("pdftotext '" + pdf.string() + "' -", text), 0) << text;
    text = vv::report::test::withoutLigatures(text);  // "Run-oﬀ" -> "Run-off"
    EXPECT_NE(text.find("Occlusion of the left SFA."), std::string::npos) << text;
    EXPECT_NE(text.find("Collaterals from the profunda."), std::string::npos) << text;
    EXPECT_EQ(text.find("No findings entered."), std::string::npos) << text;
    EXPECT_NE(text.find("Run-off CTA"), std::string::npos) << text;
    EXPECT_EQ(text.find(folderUid), std::string::npos) << text;
}

TEST_F(PacsGuiTest, TheAppliedSegmentationIsSentNeverAPreview) {
    restartWith(settings(false));
    const fs::path cta = testDir() / "cta-applied";
    writeCta(cta, "VV-GUI-APPLIED", "Applied CTA");
    ASSERT_TRUE(
        openDicomAndAccept([&] { window_->openDicom(QString::fromStdString(cta.string())); }));
    const auto voxels = [](const vv::scene::LabelMap& map) {
        return static_cast<std::size_t>(std::count_if(map.labels.begin(), map.labels.end(),
                                                      [](std::uint8_t l) { return l != 0; }));
    };
    const std::size_t loaded = voxels(*window_->document()->labelMap());

    // A higher lower threshold, previewed: nothing can be sent until it is applied.
    vv::gui::panels::SegmentationPanel* panel = window_->segmentationPanel();
    const int previews = panel->previewsShown();
    panel->lowerBox()->setValue(panel->lowerBox()->value() + 150.0);
    ASSERT_TRUE(waitUntil(
        [&] { return panel->previewsShown() > previews && !panel->isPreviewing(); }, 60000));
    QAction* send = window_->findChild<QAction*>(QStringLiteral("sendToPacs"));
    EXPECT_TRUE(window_->document()->showsPreview());
    EXPECT_FALSE(send->isEnabled());
    EXPECT_EQ(send->toolTip(), vv::gui::MainWindow::previewNotApplied());
    EXPECT_EQ(voxels(*window_->document()->labelMap()), loaded);  // still the loaded one

    // Applied: the document's segmentation from now on, and Send is back.
    panel->apply();
    ASSERT_TRUE(waitUntil([&] { return !panel->isApplying(); }, 60000));
    ASSERT_FALSE(window_->document()->showsPreview());
    const std::size_t applied = voxels(*window_->document()->labelMap());
    EXPECT_LT(applied, loaded);
    ASSERT_TRUE(send->isEnabled());
    SendDialog* dialog = sendReport();
    ASSERT_NE(dialog, nullptr);
    const QString peer = QString::fromStdString(vv::pacs::describe(orthanc_->node()));
    EXPECT_EQ(dialog->summaryLabel()->text(), QStringLiteral("3 of 3 accepted by %1").arg(peer));

    // The SEG in Orthanc is the applied segmentation, the PDF says how it was made.
    vv::pacs::StudyQuery query;
    query.patientId = "VV-GUI-APPLIED";
    const auto studies = vv::pacs::findStudies(me(), orthanc_->node(), query);
    ASSERT_EQ(studies.size(), 1U);
    const fs::path segFile =
        retrievedInstance(studies[0].studyInstanceUid, "SEG", testDir() / "applied-retrieved");
    ASSERT_FALSE(segFile.empty());
    std::size_t inPacs = 0;
    for (const auto& map : vv::dicom::loadDicomSegLabelMaps(segFile)) {
        inPacs += voxels(map);
    }
    EXPECT_EQ(inPacs, applied);
    const fs::path pdf = testDir() / "applied-report.pdf";
    ASSERT_TRUE(retrievedPdf(studies[0].studyInstanceUid, pdf));
    std::string text;
    ASSERT_EQ(vv::report::test::runTool("pdftotext '" + pdf.string() + "' -", text), 0) << text;
    EXPECT_NE(text.find("chosen in the Segmentation panel"), std::string::npos) << text;
}

TEST_F(PacsGuiTest, TheMeasurementsGoToThePacsAsAStructuredReportInTheSeriesStudy) {
    restartWith(settings(false));
    const fs::path cta = testDir() / "cta-measurements";
    writeCta(cta, "VV-GUI-SR", "Measured CTA");
    ASSERT_TRUE(
        openDicomAndAccept([&] { window_->openDicom(QString::fromStdString(cta.string())); }));
    // Without centrelines there is nothing to send as measurements.
    {
        auto* action = window_->findChild<QAction*>(QStringLiteral("sendToPacs"));
        action->trigger();
        auto* before = window_->findChild<SendDialog*>();
        ASSERT_NE(before, nullptr);
        EXPECT_FALSE(before->measurementsBox()->isEnabled());
        EXPECT_FALSE(before->measurementsBox()->isChecked());
        delete before;
    }
    vv::gui::panels::AnalysisPanel* analysis = window_->analysisPanel();
    analysis->findCenterlines();
    ASSERT_TRUE(waitUntil([&] { return !analysis->analysing(); }, 120000));
    ASSERT_TRUE(window_->planning()->hasAnalysis());
    window_->planning()->setCursorMm(window_->planning()->path().lengthMm() / 3.0);
    ASSERT_GE(window_->planning()->placeLandmarkAtCursor(vv::planning::LandmarkKind::Free,
                                                         QStringLiteral("Proximal landing")),
              0);
    SendDialog* dialog = sendReport([](SendDialog& send) {
        EXPECT_TRUE(send.measurementsBox()->isEnabled());
        EXPECT_TRUE(send.measurementsBox()->isChecked());
        send.secondaryCaptureBox()->setChecked(false);
        send.pdfBox()->setChecked(false);
        send.segmentationBox()->setChecked(false);
    });
    ASSERT_NE(dialog, nullptr);
    const QString peer = QString::fromStdString(vv::pacs::describe(orthanc_->node()));
    EXPECT_EQ(dialog->summaryLabel()->text(), QStringLiteral("1 of 1 accepted by %1").arg(peer));
    ASSERT_EQ(dialog->resultTable()->topLevelItemCount(), 1);
    EXPECT_EQ(dialog->resultTable()->topLevelItem(0)->text(0),
              QStringLiteral("Measurements (DICOM Structured Report)"));

    // Orthanc has it as an SR in the CTA's study, with the landmark's sizes.
    vv::pacs::StudyQuery query;
    query.patientId = "VV-GUI-SR";
    const auto studies = vv::pacs::findStudies(me(), orthanc_->node(), query);
    ASSERT_EQ(studies.size(), 1U);
    const fs::path srFile =
        retrievedInstance(studies[0].studyInstanceUid, "SR", testDir() / "sr-retrieved");
    ASSERT_FALSE(srFile.empty());
    std::string dump;
    ASSERT_EQ(vv::report::test::runTool("dsrdump +Pl '" + srFile.string() + "'", dump), 0) << dump;
    EXPECT_NE(dump.find("\"Proximal landing\""), std::string::npos) << dump;
    EXPECT_NE(dump.find("Equivalent diameter (2 sqrt(area / pi)), at Proximal landing"),
              std::string::npos)
        << dump;
}

TEST_F(PacsGuiTest, TheReportExportedLastIsSentAsItIs) {
    restartWith(settings(false));
    const fs::path cta = testDir() / "cta-exported";
    writeCta(cta, "VV-GUI-EXPORTED", "Carotid CTA");
    ASSERT_TRUE(
        openDicomAndAccept([&] { window_->openDicom(QString::fromStdString(cta.string())); }));
    // File > Export Report with findings and a second view.
    window_->exportReportAction()->trigger();
    auto* report = window_->findChild<vv::gui::ReportDialog*>();
    ASSERT_NE(report, nullptr);
    const fs::path exported = testDir() / "exported-report.pdf";
    fs::remove(exported);
    report->pdfEdit()->setText(QString::fromStdString(exported.string()));
    report->findingsEdit()->setPlainText(QStringLiteral("Stenosis of the right ICA, 70 %."));
    report->secondViewChooser()->setCurrentIndex(
        report->secondViewChooser()->findData(QStringLiteral("anterior")));
    bool written = false;
    QObject::connect(
        report, &vv::gui::ReportDialog::exportStarted, [&](vv::gui::ExportWorker* worker) {
            QObject::connect(worker, &vv::gui::ExportWorker::succeeded, [&] { written = true; });
        });
    report->accept();
    ASSERT_TRUE(waitUntil([&] { return written; }, 120000)) << "the export did not end";

    // Send to PACS offers it, chosen, with its findings shown read-only.
    SendDialog* dialog = sendReport([&](SendDialog& send) {
        EXPECT_EQ(send.reportChooser()->currentData().toString(),
                  QString::fromStdString(exported.string()));
        EXPECT_TRUE(send.findingsEdit()->isReadOnly());
        EXPECT_EQ(send.findingsEdit()->toPlainText(),
                  QStringLiteral("Stenosis of the right ICA, 70 %."));
        send.secondaryCaptureBox()->setChecked(false);
        send.segmentationBox()->setChecked(false);
    });
    ASSERT_NE(dialog, nullptr);
    const QString peer = QString::fromStdString(vv::pacs::describe(orthanc_->node()));
    EXPECT_EQ(dialog->summaryLabel()->text(), QStringLiteral("1 of 1 accepted by %1").arg(peer));
    // A new report can still be chosen, with editable findings.
    dialog->reportChooser()->setCurrentIndex(0);
    EXPECT_FALSE(dialog->findingsEdit()->isReadOnly());

    // Orthanc holds the exported PDF, byte for byte.
    vv::pacs::StudyQuery query;
    query.patientId = "VV-GUI-EXPORTED";
    const auto studies = vv::pacs::findStudies(me(), orthanc_->node(), query);
    ASSERT_EQ(studies.size(), 1U);
    const fs::path pdf = testDir() / "exported-from-pacs.pdf";
    ASSERT_TRUE(retrievedPdf(studies[0].studyInstanceUid, pdf));
    const auto bytes = [](const fs::path& file) {
        std::ifstream in(file, std::ios::binary);
        return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    };
    const std::string sent = bytes(pdf);
    const std::string original = bytes(exported);
    ASSERT_GT(original.size(), 1000U);
    // DICOM pads an odd length with one byte.
    EXPECT_EQ(sent.substr(0, original.size()), original);
    EXPECT_LE(sent.size(), original.size() + 1);
}

TEST_F(PacsGuiTest, TheSendDialogForgetsTheLastSendWhenOtherDataIsShown) {
    PacsSettings s = settings(false);
    s.nodes[0].node.port = vv::test::freePort();  // nobody listens there: a quick outcome
    restartWith(s);
    window_->setScene(vv::test::makeTubeScene(), QStringLiteral("tube"));
    window_->document()->setFindings(QStringLiteral("Findings of the tube."));
    SendDialog* dialog = sendReport();
    ASSERT_NE(dialog, nullptr);
    ASSERT_EQ(dialog->resultTable()->topLevelItemCount(), 2);
    ASSERT_FALSE(dialog->summaryLabel()->text().isEmpty());
    const QString before = dialog->dataLabel()->text();

    // Other data on screen: nothing of the last send or of the tube's findings.
    const fs::path cta = testDir() / "cta-other";
    writeCta(cta, "VV-GUI-OTHER", "Neck CTA");
    ASSERT_TRUE(
        openDicomAndAccept([&] { window_->openDicom(QString::fromStdString(cta.string())); }));
    EXPECT_EQ(dialog->resultTable()->topLevelItemCount(), 0);
    EXPECT_TRUE(dialog->summaryLabel()->text().isEmpty())
        << dialog->summaryLabel()->text().toStdString();
    EXPECT_EQ(dialog->dataLabel()->text(), QStringLiteral("Neck CTA"));
    EXPECT_NE(dialog->dataLabel()->text(), before);
    EXPECT_TRUE(dialog->findingsEdit()->toPlainText().isEmpty());
    // The new series' segmentation is offered.
    EXPECT_TRUE(dialog->segmentationBox()->isEnabled());
    EXPECT_TRUE(dialog->segmentationBox()->isChecked());
    EXPECT_TRUE(dialog->sendButton()->isEnabled());

    // Other data while a send runs: the send stops, its outcome is dropped.
    dialog->sendButton()->click();
    ASSERT_TRUE(dialog->isSending());
    window_->setScene(vv::test::makeTubeScene(), QStringLiteral("tube"));
    EXPECT_FALSE(dialog->isSending());
    EXPECT_EQ(dialog->resultTable()->topLevelItemCount(), 0);
    EXPECT_EQ(dialog->summaryLabel()->text(),
              QStringLiteral("Other data was opened: the send of Neck CTA was stopped; nothing "
                             "more was sent."));
    EXPECT_FALSE(dialog->segmentationBox()->isEnabled());  // meshes: no SEG
    EXPECT_TRUE(dialog->sendButton()->isEnabled());
}

/// A peer that accepts each TCP connection on 127.0.0.1 and closes it at
/// once (on a thread of its own): the association never gets an answer.
class ClosingPeer {
  public:
    ClosingPeer() : listener_(::socket(AF_INET, SOCK_STREAM, 0)) {
        sockaddr_in address{};
        address.sin_family = AF_INET;
        address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
        socklen_t length = sizeof address;
        if (listener_ < 0 ||
            ::bind(listener_, reinterpret_cast<sockaddr*>(&address), length) != 0 ||
            ::listen(listener_, 4) != 0 ||
            ::getsockname(listener_, reinterpret_cast<sockaddr*>(&address), &length) != 0) {
            ADD_FAILURE() << "cannot listen";
            return;
        }
        port_ = ntohs(address.sin_port);
        thread_ = std::thread([this] {
            for (int fd = ::accept(listener_, nullptr, nullptr); fd >= 0;
                 fd = ::accept(listener_, nullptr, nullptr)) {
                ::close(fd);
            }
        });
    }
    ClosingPeer(const ClosingPeer&) = delete;
    ClosingPeer& operator=(const ClosingPeer&) = delete;
    ClosingPeer(ClosingPeer&&) = delete;
    ClosingPeer& operator=(ClosingPeer&&) = delete;
    ~ClosingPeer() {
        ::shutdown(listener_, SHUT_RDWR);  // ends the blocked accept()
        if (thread_.joinable()) {
            thread_.join();
        }
        ::close(listener_);
    }
    [[nodiscard]] std::uint16_t port() const noexcept { return port_; }

  private:
    int listener_;
    std::uint16_t port_ = 0;
    std::thread thread_;
};

TEST_F(PacsGuiTest, ATransferThatFailsSaysSoInGermanNamingTheNodeWithTheDetailApart) {
    const ClosingPeer closing;
    PacsSettings s = settings(false);
    s.nodes[0].name = "Archiv Nord";
    s.nodes[0].node = {"CLOSER", "127.0.0.1", closing.port(), {}};
    ASSERT_TRUE(vv::test::installUiLanguage("de", VV_QM_DIR));
    restartWith(s);
    window_->setScene(vv::test::makeTubeScene(), QStringLiteral("tube"));
    SendDialog* dialog = sendReport();
    ASSERT_NE(dialog, nullptr);
    const QString shown = dialog->summaryLabel()->text();
    const QString tooltip = dialog->summaryLabel()->toolTip();
    vv::test::removeUiLanguage();
    // German, the node by its name and address, what to do.
    EXPECT_TRUE(
        shown.startsWith(QStringLiteral("Die Übertragung an Archiv Nord (CLOSER@127.0.0.1:")))
        << shown.toStdString();
    EXPECT_TRUE(shown.contains(QStringLiteral("Versuchen Sie es erneut"))) << shown.toStdString();
    // The module's English words apart, in the tooltip.
    ASSERT_TRUE(tooltip.startsWith(QStringLiteral("Details: CLOSER@127.0.0.1:")))
        << tooltip.toStdString();
    EXPECT_FALSE(shown.contains(tooltip.mid(9))) << shown.toStdString();
    for (const char* english : {" the ", "failed", "closed", "Peer", "association"}) {
        EXPECT_FALSE(shown.contains(QLatin1String(english)))
            << english << " in: " << shown.toStdString();
    }
    EXPECT_EQ(dialog->resultTable()->topLevelItem(0)->text(1), QStringLiteral("Nicht gesendet"));
}

TEST_F(PacsGuiTest, SendingToAClosedPortSaysRefusedAndTheAppKeepsWorking) {
    PacsSettings s = settings(false);
    s.nodes[0].node.port = vv::test::freePort();  // nobody listens there
    restartWith(s);
    window_->setScene(vv::test::makeTubeScene(), QStringLiteral("tube"));
    SendDialog* dialog = sendReport();
    ASSERT_NE(dialog, nullptr);
    const QString peer = QString::fromStdString(vv::pacs::describe(s.nodes[0].node));
    EXPECT_EQ(dialog->summaryLabel()->text(),
              QStringLiteral("Nothing was sent: Orthanc (%1) refused the connection. Nobody "
                             "listens at that host and port, or a firewall blocks it.")
                  .arg(peer));
    // The module's words apart, at hand.
    EXPECT_TRUE(dialog->summaryLabel()->toolTip().contains(QStringLiteral("cannot connect")))
        << dialog->summaryLabel()->toolTip().toStdString();
    ASSERT_EQ(dialog->resultTable()->topLevelItemCount(), 2);  // meshes: no SEG to send
    EXPECT_FALSE(dialog->segmentationBox()->isEnabled());
    EXPECT_EQ(dialog->resultTable()->topLevelItem(0)->text(1), QStringLiteral("Not sent"));
    // The app keeps working: the dialog can send again, the window renders.
    EXPECT_TRUE(dialog->sendButton()->isEnabled());
    EXPECT_TRUE(dialog->isVisible());
    EXPECT_TRUE(waitForFrames());
}

}  // namespace

TEST_F(PacsGuiTest, DeleteAsksNamingTheStudyThenItsRowAndFilesAreGone) {
    const PacsSettings s = settings(false);
    commitStudy(s.storeFolder, kNeckUid, "Neck CTA");
    commitStudy(s.storeFolder, "1.2.826.0.1.2", "Leg CTA");
    restartWith(s);
    LocalStudiesBrowser* browser = openBrowser();
    ASSERT_NE(browser, nullptr);
    ASSERT_EQ(browser->tree()->topLevelItemCount(), 2);
    QTreeWidgetItem* neck = studyRow(*browser, QStringLiteral("Neck CTA"));
    ASSERT_NE(neck, nullptr);
    EXPECT_FALSE(browser->deleteButton()->isEnabled()) << "nothing chosen yet";

    const QString date = shownDate(QDate(2024, 1, 2));
    // A series row deletes its study too.
    const QString asked = deleteAndConfirm(*browser, neck->child(0));
    EXPECT_EQ(asked, QStringLiteral("Delete the study “Neck CTA” of %1 from the local study "
                                    "store? Its files are deleted from this computer.")
                         .arg(date));
    ASSERT_TRUE(waitUntil([&] { return browser->tree()->topLevelItemCount() == 1; }, 5000));
    EXPECT_EQ(studyRow(*browser, QStringLiteral("Neck CTA")), nullptr);
    EXPECT_NE(studyRow(*browser, QStringLiteral("Leg CTA")), nullptr);
    EXPECT_FALSE(fs::exists(s.storeFolder / kNeckUid));
    EXPECT_TRUE(fs::exists(s.storeFolder / "1.2.826.0.1.2"));
    EXPECT_FALSE(browser->messageLine()->isVisible());
    EXPECT_EQ(vv::pacs::LocalStore(s.storeFolder).studies().size(), 1U);
}

TEST_F(PacsGuiTest, DeletingAnOpenStudyIsRefusedWithAMessageAndTheRowStays) {
    const PacsSettings s = settings(false);
    LocalStudiesBrowser* browser = browserOverNeckStudy(s);
    ASSERT_NE(browser, nullptr);
    {
        const auto lease = vv::pacs::LocalStore(s.storeFolder).open(kNeckUid);
        deleteAndConfirm(*browser, browser->tree()->topLevelItem(0));
        ASSERT_TRUE(waitUntil([&] { return browser->messageLine()->isVisible(); }, 5000));
        const QString date = shownDate(QDate(2024, 1, 2));
        EXPECT_EQ(browser->messageLine()->text(),
                  QStringLiteral("The study “Neck CTA” of %1 is open — in this window or in "
                                 "another program — and was not deleted. Close it (open other "
                                 "data) and try again.")
                      .arg(date));
        EXPECT_EQ(browser->tree()->topLevelItemCount(), 1);
        EXPECT_TRUE(fs::exists(s.storeFolder / kNeckUid));
        browser->grab().save(QString::fromStdString((testDir() / "delete-refused.png").string()));
        const auto problems = vv::test::ClippingCheck::problems(browser);
        EXPECT_TRUE(problems.empty()) << problems.front();
    }
    // Closed now: Delete removes it and the message goes.
    deleteAndConfirm(*browser, browser->tree()->topLevelItem(0));
    ASSERT_TRUE(waitUntil([&] { return browser->tree()->topLevelItemCount() == 0; }, 5000));
    EXPECT_FALSE(browser->messageLine()->isVisible());
    EXPECT_FALSE(fs::exists(s.storeFolder / kNeckUid));
}

TEST_F(PacsGuiTest, AStudyOpenedFromLocalStudiesStaysUntilOtherDataReplacesIt) {
    const PacsSettings s = settings(false);
    {
        vv::pacs::LocalStore store(s.storeFolder);
        (void)vv::pacs::getInto(store, me(), orthanc_->node(),
                                vv::pacs::RetrieveRequest{studyUid_, ""});
    }
    commitStudy(s.storeFolder, kNeckUid, "Neck CTA");
    restartWith(s);
    LocalStudiesBrowser* browser = openBrowser();
    ASSERT_NE(browser, nullptr);
    browser->tree()->setCurrentItem(studyRow(*browser, QStringLiteral("CTA run-off")));
    ASSERT_TRUE(openDicomAndAccept([&] { browser->openButton()->click(); }));
    auto* leases = window_->findChild<vv::gui::StoreLeases*>();
    ASSERT_NE(leases, nullptr);
    EXPECT_EQ(leases->heldStudies(), std::vector<std::string>{studyUid_});

    // A clean-up with a tiny limit removes only the other study; Delete refuses.
    vv::pacs::LocalStore store(s.storeFolder);
    store.setSizeLimit(1);
    EXPECT_EQ(store.cleanUp(), std::vector<std::string>{kNeckUid});
    EXPECT_THROW(store.remove(studyUid_), vv::pacs::StudyOpenError);
    EXPECT_TRUE(fs::exists(s.storeFolder / studyUid_));

    // Other data replaces the scene: the study is no longer held.
    const QString other = QString::fromStdString((testDir() / "cta").string());
    ASSERT_TRUE(openDicomAndAccept([&] { window_->openDicom(other); }));
    EXPECT_TRUE(leases->heldStudies().empty());
    EXPECT_EQ(store.cleanUp(), std::vector<std::string>{studyUid_});
    EXPECT_FALSE(fs::exists(s.storeFolder / studyUid_));
}

TEST_F(PacsGuiTest, AStudyBeingOpenedIsHeldUntilTheWindowCloses) {
    const PacsSettings s = settings(false);
    LocalStudiesBrowser* browser = browserOverNeckStudy(s);
    ASSERT_NE(browser, nullptr);
    browser->tree()->setCurrentItem(browser->tree()->topLevelItem(0));
    browser->openButton()->click();
    auto* leases = window_->findChild<vv::gui::StoreLeases*>();
    ASSERT_NE(leases, nullptr);
    ASSERT_TRUE(waitUntil([&] { return !leases->heldStudies().empty(); }, 15000));
    EXPECT_THROW(vv::pacs::LocalStore(s.storeFolder).remove(kNeckUid), vv::pacs::StudyOpenError);
    window_->close();
    EXPECT_TRUE(leases->heldStudies().empty());
    EXPECT_NO_THROW(vv::pacs::LocalStore(s.storeFolder).remove(kNeckUid));
}

TEST_F(PacsGuiTest, OpeningAStudyRemovedMeanwhileSaysSoAndItsRowGoes) {
    const PacsSettings s = settings(false);
    LocalStudiesBrowser* browser = browserOverNeckStudy(s);
    ASSERT_NE(browser, nullptr);
    ASSERT_EQ(browser->tree()->topLevelItemCount(), 1);
    vv::pacs::LocalStore(s.storeFolder).remove(kNeckUid);  // e.g. by another program
    browser->tree()->setCurrentItem(browser->tree()->topLevelItem(0));
    browser->openButton()->click();
    ASSERT_TRUE(waitUntil([&] { return browser->messageLine()->isVisible(); }, 15000));
    EXPECT_EQ(browser->messageLine()->text(),
              QStringLiteral("This study is no longer in the local study store."));
    ASSERT_TRUE(read(*browser));
    EXPECT_EQ(browser->tree()->topLevelItemCount(), 0);
    EXPECT_TRUE(window_->lastError().isEmpty()) << "nothing was opened";
}

TEST_F(PacsGuiTest, OverTheStoreLimitAPushedStudyMakesTheLeastRecentlyUsedStudyGo) {
    // Two studies of 2 MB, the "Leg CTA" stored first; the limit leaves room
    // for both and less than the pushed CTA (about 0.5 MB) on top.
    constexpr std::size_t kBig = 2000000;
    PacsSettings s = settings();
    s.storeLimitBytes = 2 * kBig + 200000;
    commitStudy(s.storeFolder, "1.2.826.0.1.2", "Leg CTA", kBig);
    commitStudy(s.storeFolder, "1.2.826.0.1.3", "Head CTA", kBig);
    restartWith(s);
    LocalStudiesBrowser* browser = openBrowser();
    ASSERT_NE(browser, nullptr);
    ASSERT_EQ(browser->tree()->topLevelItemCount(), 2);

    orthancPushesTheStudy();
    ASSERT_TRUE(waitUntil([&] { return studyRow(*browser, QStringLiteral("CTA run-off")); }, 20000))
        << "the pushed study never appeared";
    EXPECT_EQ(studyRow(*browser, QStringLiteral("Leg CTA")), nullptr)
        << "the least recently used study is still there";
    EXPECT_NE(studyRow(*browser, QStringLiteral("Head CTA")), nullptr);
    EXPECT_EQ(browser->tree()->topLevelItemCount(), 2);
    EXPECT_FALSE(fs::exists(s.storeFolder / "1.2.826.0.1.2"));
    EXPECT_LE(vv::pacs::LocalStore(s.storeFolder).sizeOnDisk(), s.storeLimitBytes);
}

TEST_F(PacsGuiTest, ListenerWithTlsFromTheSettingsReceivesAPushOverTlsAndRefusesPlainPeers) {
    const fs::path dir = testDir() / "tls";
    const vv::test::TestCertificates certificates =
        vv::test::makeCertificates(dir / "certificates");
    const std::uint16_t port = vv::test::freePort();
    const OrthancServer tlsOrthanc(kOurAe, port, &certificates);  // speaks TLS only
    ASSERT_EQ(
        vv::pacs::sendFiles(me(), tlsOrthanc.node(), writeCta(dir / "cta", "VV-GUI-TLS")).size(),
        static_cast<std::size_t>(kSlices));
    vv::pacs::StudyQuery query;
    query.patientId = "VV-GUI-TLS";
    const auto studies = vv::pacs::findStudies(me(), tlsOrthanc.node(), query);
    ASSERT_EQ(studies.size(), 1U);

    PacsSettings s = settings();
    s.listenerPort = port;
    s.nodes[0].node = tlsOrthanc.node();
    s.listenerTls = {true, certificates.ca, certificates.serverCert, certificates.serverKey};
    restartWith(s);
    ASSERT_EQ(listener()->state(), ListenerService::State::Running);
    EXPECT_EQ(indicatorText(), QStringLiteral("DICOM listener: port %1 (TLS)").arg(port));
    LocalStudiesBrowser* browser = openBrowser();
    ASSERT_NE(browser, nullptr);

    const auto moved = vv::pacs::moveTo(kOurAe, me(), tlsOrthanc.node(),
                                        vv::pacs::RetrieveRequest{studies[0].studyInstanceUid, ""});
    EXPECT_EQ(moved.instances, static_cast<std::size_t>(kSlices));
    ASSERT_TRUE(waitUntil([&] { return browser->tree()->topLevelItemCount() == 1; }, 20000))
        << "the study pushed over TLS never appeared";
    EXPECT_EQ(listener()->refusedAssociations(), 0U);

    // The allowed node's AE title from its host, but in plain TCP: refused.
    const vv::pacs::LocalAe orthancAe{"ORTHANC", vv::pacs::Timeouts{2, 5, 10}};
    EXPECT_THROW(vv::pacs::echo(orthancAe, vv::pacs::Node{kOurAe, "127.0.0.1", port, {}}),
                 vv::pacs::NetworkError);
    EXPECT_TRUE(waitUntil([&] { return listener()->refusedAssociations() == 1; }, 5000));
    EXPECT_EQ(browser->tree()->topLevelItemCount(), 1);
}

TEST_F(PacsGuiTest, ListenerTlsFilesThatCannotBeReadAreAClearStateNotPlainTcp) {
    PacsSettings s = settings();
    s.listenerTls = {true, testDir() / "missing-ca.pem", testDir() / "missing.pem",
                     testDir() / "missing.key"};
    restartWith(s);
    EXPECT_EQ(listener()->state(), ListenerService::State::Failed);
    EXPECT_EQ(indicatorText(),
              QStringLiteral("DICOM listener failed: TLS is on, but our certificate, its key or "
                             "the trusted CA certificates cannot be read or do not match"));
    // Nothing listens in plain TCP instead.
    const vv::pacs::LocalAe orthancAe{"ORTHANC", vv::pacs::Timeouts{2, 5, 10}};
    EXPECT_THROW(vv::pacs::echo(orthancAe, vv::pacs::Node{kOurAe, "127.0.0.1", scpPort_, {}}),
                 vv::pacs::ConnectionRefusedError);
}

}  // namespace pacs_gui_test
