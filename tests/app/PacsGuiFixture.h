// SPDX-License-Identifier: GPL-3.0-or-later
// The PACS GUI tests' fixture: one real Orthanc per process (tests/pacs/
// OrthancServer.h) holding the synthetic CTA series, the DICOM network
// settings pointing at it, a fresh local store per test, and helpers that
// drive the Preferences and the PACS browser as a user does.
#pragma once

#include <gtest/gtest.h>

#include <QDialogButtonBox>
#include <QLineEdit>
#include <QLocale>
#include <QPointer>
#include <QPushButton>
#include <QSettings>
#include <QSpinBox>
#include <QTableWidget>
#include <QTest>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "GuiFixture.h"
#include "OrthancServer.h"
#include "SyntheticCta.h"
#include "UiLanguage.h"
#include "gui/MainWindow.h"
#include "gui/SeriesDialog.h"
#include "gui/pacs/DicomMenu.h"
#include "gui/pacs/NetworkPreferencesDialog.h"
#include "gui/pacs/NodeEditDialog.h"
#include "gui/pacs/PacsBrowser.h"
#include "gui/pacs/PacsSettings.h"
#include "vv/dicom/SeriesWriter.h"
#include "vv/pacs/Send.h"

namespace vv::test {

namespace fs = std::filesystem;

inline constexpr const char* kOurAe = "VVGUITEST";
/// Every network wait of a test: C-ECHO / C-FIND / retrieve end well before.
inline constexpr int kNetworkWaitMs = 50000;

/// The synthetic CTA written by the test (its header: Study Date 20250101,
/// patient VesselView^Demo) and sent into Orthanc; returns the number of files.
inline int loadSeries(const OrthancServer& orthanc, const fs::path& folder,
                      const vv::dicom::CtSeriesWriteOptions& options, glm::ivec3 dims,
                      int generations) {
    fs::remove_all(folder);
    const auto cta = makeSyntheticCta(dims, generations, 0.0, 0.0);
    vv::dicom::writeCtSeries(folder, cta.volume, options);
    std::vector<fs::path> files;
    for (const auto& entry : fs::directory_iterator(folder)) {
        files.push_back(entry.path());
    }
    const vv::pacs::LocalAe me{kOurAe, {}};
    for (const auto& status : vv::pacs::sendFiles(me, orthanc.node(), files)) {
        EXPECT_TRUE(status.accepted) << status.file;
    }
    return static_cast<int>(files.size());
}

/// The texts of one table row, joined by " | ".
inline std::string rowText(const QTableWidget* table, int row) {
    QStringList cells;
    for (int column = 0; column < table->columnCount(); ++column) {
        const QTableWidgetItem* item = table->item(row, column);
        cells << (item != nullptr ? item->text() : QString());
    }
    return cells.join(QStringLiteral(" | ")).toStdString();
}

class PacsGuiFixture : public GuiFixture {
  protected:
    static void SetUpTestSuite() {
        GuiFixture::SetUpTestSuite();
        // Dates and numbers as the app in English shows them (a language test sets its own).
        QLocale::setDefault(QLocale(QLocale::English, QLocale::UnitedStates));
        listenerPort_ = freePort();
        orthanc_ = std::make_unique<OrthancServer>(kOurAe, listenerPort_);
        vv::dicom::CtSeriesWriteOptions options;
        options.patientId = "VV-GUI-1";
        options.seriesDescription = "GUI CTA";
        slices_ = loadSeries(*orthanc_, panelTestDir() / "pacs-cta", options, {64, 64, 48}, 3);
    }
    static void TearDownTestSuite() {
        orthanc_.reset();
        GuiFixture::TearDownTestSuite();
    }

    void SetUp() override {
        GuiFixture::SetUp();
        const std::string name = ::testing::UnitTest::GetInstance()->current_test_info()->name();
        store_ = panelTestDir() / ("store-" + name);
        fs::remove_all(store_);
        vv::gui::PacsSettings s;
        s.me.aeTitle = kOurAe;
        s.listenerPort = listenerPort_;
        s.storeFolder = store_;
        vv::gui::PacsNode node;
        node.name = "Orthanc";
        node.node = orthanc_->node();
        s.nodes.push_back(node);
        QSettings settings;
        vv::gui::writePacsSettings(s, settings);
    }

    void TearDown() override {
        if (browser_ != nullptr) {
            delete browser_.data();
        }
        GuiFixture::TearDown();
    }

    /// DICOM > Preferences… as the menu opens it.
    vv::gui::NetworkPreferencesDialog* preferences() {
        auto* dialog = window_->dicomMenu()->showPreferences();
        EXPECT_TRUE(waitUntil([dialog] { return dialog->isVisible(); }, 10000));
        return dialog;
    }

    /// DICOM > Query PACS… as the menu opens it.
    vv::gui::PacsBrowser* browser() {
        browser_ = window_->dicomMenu()->showBrowser();
        browser_->resize(1200, 720);
        EXPECT_TRUE(waitUntil([this] { return browser_->isVisible(); }, 10000));
        return browser_;
    }

    /// Clicks Test on row `row` and waits for the answer; returns what it says.
    static std::string testNode(vv::gui::NetworkPreferencesDialog* dialog, int row) {
        dialog->nodeTable()->selectRow(row);
        dialog->testButton()->click();
        EXPECT_TRUE(waitUntil([dialog] { return !dialog->testRunning(); }, kNetworkWaitMs))
            << "Test never ended";
        EXPECT_TRUE(dialog->testButton()->isEnabled());
        return dialog->testResult().toStdString();
    }

    /// Clicks `button` (Add… or Edit…) and returns the node dialog it opened.
    static QPointer<vv::gui::NodeEditDialog> openNodeDialog(
        vv::gui::NetworkPreferencesDialog* dialog, QPushButton* button) {
        QPointer<vv::gui::NodeEditDialog> edit;
        QObject::connect(
            dialog, &vv::gui::NetworkPreferencesDialog::nodeDialogShown, dialog,
            [&edit](QDialog* shown) { edit = qobject_cast<vv::gui::NodeEditDialog*>(shown); },
            Qt::SingleShotConnection);
        button->click();
        EXPECT_TRUE(edit != nullptr) << "no node dialog";
        return edit;
    }

    /// Clicks Add… and fills in the node dialog as a user would; returns it (open).
    static QPointer<vv::gui::NodeEditDialog> addNode(vv::gui::NetworkPreferencesDialog* dialog,
                                                     const QString& name, const QString& ae,
                                                     const QString& host, int port) {
        QPointer<vv::gui::NodeEditDialog> edit = openNodeDialog(dialog, dialog->addButton());
        if (edit == nullptr) {
            return edit;
        }
        QTest::keyClicks(edit->nameEdit(), name);
        QTest::keyClicks(edit->aeTitleEdit(), ae);
        QTest::keyClicks(edit->hostEdit(), host);
        edit->portBox()->setValue(port);
        clickOk(edit);
        return edit;
    }

    static void clickOk(QDialog* dialog) {
        auto* buttons = dialog->findChild<QDialogButtonBox*>();
        ASSERT_NE(buttons, nullptr);
        buttons->button(QDialogButtonBox::Ok)->click();
    }

    /// Types the patient ID, clicks Search and waits for the rows.
    static bool search(vv::gui::PacsBrowser* b, const QString& patientId) {
        b->patientIdEdit()->clear();
        QTest::keyClicks(b->patientIdEdit(), patientId);
        bool ok = false;
        bool done = false;
        QObject::connect(
            b, &vv::gui::PacsBrowser::searchFinished, b,
            [&](bool result) {
                ok = result;
                done = true;
            },
            Qt::SingleShotConnection);
        b->searchButton()->click();
        EXPECT_TRUE(waitUntil([&] { return done; }, kNetworkWaitMs)) << "the search never ended";
        return ok;
    }

    /// Selects study row 0 and waits for its series.
    static bool selectStudy(vv::gui::PacsBrowser* b) {
        bool done = false;
        QObject::connect(
            b, &vv::gui::PacsBrowser::seriesFinished, b, [&](bool) { done = true; },
            Qt::SingleShotConnection);
        b->studyTable()->selectRow(0);
        return waitUntil([&] { return done; }, kNetworkWaitMs) && b->seriesTable()->rowCount() > 0;
    }

    /// Clicks `button` and waits (bounded) for the retrieve to end; true when it succeeded.
    static bool retrieve(vv::gui::PacsBrowser* b, QPushButton* button) {
        bool ok = false;
        bool done = false;
        QObject::connect(
            b, &vv::gui::PacsBrowser::retrieveFinished, b,
            [&](bool result) {
                ok = result;
                done = true;
            },
            Qt::SingleShotConnection);
        button->click();
        EXPECT_TRUE(waitUntil([&] { return done; }, kNetworkWaitMs)) << "the retrieve never ended";
        return ok;
    }

    /// Clicks the browser's Open and waits for the series chooser; returns it
    /// (nullptr, with the window's error reported, when none came).
    QPointer<vv::gui::SeriesDialog> openRetrieved(vv::gui::PacsBrowser* b) {
        QPointer<vv::gui::SeriesDialog> chooser;
        const QMetaObject::Connection c =
            QObject::connect(window_.get(), &vv::gui::MainWindow::seriesDialogShown, window_.get(),
                             [&chooser](vv::gui::SeriesDialog* shown) { chooser = shown; });
        EXPECT_TRUE(b->openButton()->isEnabled());
        b->openButton()->click();
        EXPECT_TRUE(waitUntil([&] { return chooser != nullptr || !window_->lastError().isEmpty(); },
                              30000));
        QObject::disconnect(c);
        EXPECT_NE(chooser, nullptr) << window_->lastError().toStdString();
        return chooser;
    }

    /// Accepts `chooser` and waits until its scene is shown; false on an error.
    bool acceptAndShow(vv::gui::SeriesDialog* chooser) {
        bool shown = false;
        const QMetaObject::Connection c = QObject::connect(
            window_.get(), &vv::gui::MainWindow::sceneShown, [&shown] { shown = true; });
        chooser->accept();
        const bool ended =
            waitUntil([&] { return shown || !window_->lastError().isEmpty(); }, 50000);
        QObject::disconnect(c);
        EXPECT_TRUE(window_->lastError().isEmpty()) << window_->lastError().toStdString();
        return ended && shown;
    }

    inline static std::unique_ptr<OrthancServer> orthanc_;
    inline static std::uint16_t listenerPort_ = 0;
    inline static int slices_ = 0;
    fs::path store_;
    QPointer<vv::gui::PacsBrowser> browser_;
};

/// The fixture with the UI in the language of the test's parameter ("en",
/// "de"), installed as gui/Translations.cpp does before any widget exists,
/// and the window at 1280 x 800.
class PacsGuiInLanguage : public PacsGuiFixture, public ::testing::WithParamInterface<const char*> {
  protected:
    void SetUp() override {
        ASSERT_TRUE(installUiLanguage(GetParam(), VV_QM_DIR));
        PacsGuiFixture::SetUp();
        window_->resize(1280, 800);
    }
    void TearDown() override {
        PacsGuiFixture::TearDown();
        removeUiLanguage();
    }
};

}  // namespace vv::test
