// SPDX-License-Identifier: GPL-3.0-or-later
// Cancel of the network waits that have no progress of their own: Search in
// DICOM > Query PACS (C-FIND) and Test in DICOM > Preferences (C-ECHO),
// against a peer that accepts the TCP connection and never answers (without
// Cancel the wait runs into the 10 s association timeout). Cancel is clicked
// as a user clicks it; the dialog must be usable again at once, say
// "cancelled" (not an error, not "nothing found"), and the worker must have
// closed its connection before the association timeout could have closed it
// (so the close is the cancel's, however loaded the machine). Orthanc still
// answers afterwards.
#include <arpa/inet.h>
#include <gtest/gtest.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <QComboBox>
#include <QImage>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSocketNotifier>
#include <QTableWidget>
#include <QTest>
#include <array>
#include <cerrno>
#include <cstdint>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "PacsGuiFixture.h"
#include "TcpTable.h"
#include "gui/pacs/BackgroundCall.h"
#include "gui/pacs/NetworkPreferencesDialog.h"
#include "gui/pacs/PacsBrowser.h"
#include "gui/pacs/TlsFilesBox.h"
#include "vv/pacs/Node.h"

namespace {

using vv::test::waitUntil;

/// A DICOM peer that never answers: accepts each TCP connection on
/// 127.0.0.1, reads what comes and writes nothing; notes when the other side
/// closed it. Runs on the GUI thread's event loop (the tests' waits).
class StallingPeer {
  public:
    StallingPeer() : listener_(::socket(AF_INET, SOCK_STREAM, 0)) {
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
        auto* accepting = new QSocketNotifier(listener_, QSocketNotifier::Read, &context_);
        QObject::connect(accepting, &QSocketNotifier::activated, &context_, [this] { accept(); });
    }
    StallingPeer(const StallingPeer&) = delete;
    StallingPeer& operator=(const StallingPeer&) = delete;
    StallingPeer(StallingPeer&&) = delete;
    StallingPeer& operator=(StallingPeer&&) = delete;
    ~StallingPeer() {
        for (QSocketNotifier* n : context_.findChildren<QSocketNotifier*>()) {
            n->setEnabled(false);
        }
        for (const int fd : open_) {
            ::close(fd);
        }
        ::close(listener_);
    }
    [[nodiscard]] std::uint16_t port() const noexcept { return port_; }
    [[nodiscard]] int accepted() const noexcept { return accepted_; }
    [[nodiscard]] int closed() const noexcept { return closed_; }
    /// Bytes read from all connections (the A-ASSOCIATE-RQ, once sent).
    [[nodiscard]] std::size_t received() const noexcept { return received_; }

  private:
    void accept() {
        const int fd = ::accept(listener_, nullptr, nullptr);
        if (fd < 0) {
            return;
        }
        ++accepted_;
        open_.insert(fd);
        auto* reading = new QSocketNotifier(fd, QSocketNotifier::Read, &context_);
        QObject::connect(reading, &QSocketNotifier::activated, &context_, [this, fd, reading] {
            std::array<char, 4096> buffer{};
            const ssize_t got = ::recv(fd, buffer.data(), buffer.size(), MSG_DONTWAIT);
            if (got > 0 || (got < 0 && errno == EAGAIN)) {
                received_ += got > 0 ? static_cast<std::size_t>(got) : 0U;
                return;  // read and dropped: nobody answers
            }
            reading->setEnabled(false);  // closed by the caller (or failed)
            ++closed_;
            open_.erase(fd);
            ::close(fd);
        });
    }

    int listener_;
    std::uint16_t port_ = 0;
    QObject context_;
    std::set<int> open_;
    int accepted_ = 0;
    int closed_ = 0;
    std::size_t received_ = 0;
};

/// True when `label` shows its text in the red of problems (PacsWidgets'
/// showAsProblem), judged by its pixels.
bool showsRed(QLabel* label) {
    const QImage image = label->grab().toImage();
    for (int y = 0; y < image.height(); ++y) {
        for (int x = 0; x < image.width(); ++x) {
            const QColor c = image.pixelColor(x, y);
            if (c.red() > 120 && c.green() < 80 && c.blue() < 90) {
                return true;
            }
        }
    }
    return false;
}

/// deliverLater (app/gui/pacs/BackgroundCall.h), under the series' detail
/// query: a call that has already ended by the time its answer is wired up
/// (a refused connection ends in microseconds) still answers later, through
/// the event queue: else "Searching…", set just after starting the call,
/// stayed on screen over the answer (a CI failure of PacsBrowserGuiKillTest).
/// The same for LatestRun: tests/app/LatestRunTest.cpp.
class BackgroundCallTest : public vv::test::GuiFixture {};

TEST_F(BackgroundCallTest, AnAnswerThatIsAlreadyThereArrivesLaterNeverInsideTheCall) {
    QObject owner;
    std::vector<int> answers;
    vv::gui::deliverLater(QtFuture::makeReadyFuture(7), &owner,
                          [&answers](const int& answer) { answers.push_back(answer); });
    EXPECT_TRUE(answers.empty()) << "the answer was handed over inside the call";
    ASSERT_TRUE(waitUntil([&] { return !answers.empty(); }, 2000));
    EXPECT_EQ(answers, std::vector<int>{7});

    // An owner destroyed before the event queue runs gets nothing.
    bool called = false;
    {
        QObject gone;
        vv::gui::deliverLater(QtFuture::makeReadyFuture(8), &gone,
                              [&called](const int&) { called = true; });
    }
    static_cast<void>(waitUntil([] { return false; }, 200));
    EXPECT_FALSE(called);
}

class PacsCancelGuiTest : public vv::test::PacsGuiFixture {
  protected:
    /// The stalling peer added as a second node ("Stalling") to the settings,
    /// with the longest timeouts the settings take: a stalled call then ends
    /// before the test's waits do only when the cancel ends it.
    void addStallingNode() {
        QSettings settings;
        vv::gui::PacsSettings s = vv::gui::readPacsSettings(settings);
        s.me.timeouts.associateSeconds = vv::gui::kMaxTimeoutSeconds;
        s.me.timeouts.responseSeconds = vv::gui::kMaxTimeoutSeconds;
        vv::gui::PacsNode node;
        node.name = "Stalling";
        node.node = {"STALL", "127.0.0.1", peer_.port(), {}};
        s.nodes.push_back(node);
        vv::gui::writePacsSettings(s, settings);
    }

    StallingPeer peer_;
};

TEST_F(PacsCancelGuiTest, CancelSearchAbortsTheFindAtOnceAndSaysCancelled) {
    addStallingNode();
    vv::gui::PacsBrowser* b = browser();
    EXPECT_FALSE(b->cancelSearchButton()->isEnabled()) << "nothing to cancel yet";
    // A search whose rows then stand for an earlier answer.
    ASSERT_TRUE(search(b, QStringLiteral("VV-GUI-1")));
    ASSERT_EQ(b->studyTable()->rowCount(), 1);

    b->nodeBox()->setCurrentIndex(b->nodeBox()->findText(QStringLiteral("Stalling")));
    QTest::mouseClick(b->searchButton(), Qt::LeftButton);
    // The worker sent its A-ASSOCIATE-RQ and waits for the answer.
    ASSERT_TRUE(waitUntil([&] { return peer_.accepted() == 1 && peer_.received() > 0; }))
        << "no association request";
    EXPECT_TRUE(b->searching());
    EXPECT_FALSE(b->searchButton()->isEnabled());
    ASSERT_TRUE(b->cancelSearchButton()->isEnabled());
    ASSERT_TRUE(b->cancelSearchButton()->isVisible());
    b->grab().save(
        QString::fromStdString((vv::test::panelTestDir() / "search-running.png").string()));

    QTest::mouseClick(b->cancelSearchButton(), Qt::LeftButton);
    // Usable again at once, and saying so: cancelled, not failed, not "0 found".
    ASSERT_TRUE(waitUntil([&] { return b->searchButton()->isEnabled(); }));
    EXPECT_FALSE(b->searching());
    EXPECT_FALSE(b->cancelSearchButton()->isEnabled());
    EXPECT_EQ(b->status(), QStringLiteral("Search cancelled."));
    EXPECT_FALSE(showsRed(b->findChild<QLabel*>(QStringLiteral("pacsStatus"))));
    EXPECT_EQ(b->studyTable()->rowCount(), 0) << "the earlier answer is not this search's";
    // The worker aborted its association: the peer saw the connection close.
    ASSERT_TRUE(waitUntil([&] { return peer_.closed() == 1; })) << "the association stays open";
    b->grab().save(
        QString::fromStdString((vv::test::panelTestDir() / "search-cancelled.png").string()));
    waitUntil([] { return false; }, 500);  // no late answer of the aborted worker shows up
    EXPECT_EQ(b->status(), QStringLiteral("Search cancelled."));

    // Orthanc still answers a search.
    b->nodeBox()->setCurrentIndex(b->nodeBox()->findText(QStringLiteral("Orthanc")));
    ASSERT_TRUE(search(b, QStringLiteral("VV-GUI-1")));
    EXPECT_EQ(b->studyTable()->rowCount(), 1);
    EXPECT_EQ(b->status(), QStringLiteral("Studies found: 1."));
}

TEST_F(PacsCancelGuiTest, CancelTestAbortsTheEchoAtOnceAndSaysCancelled) {
    addStallingNode();
    auto* dialog = preferences();
    ASSERT_EQ(dialog->nodeTable()->rowCount(), 2);
    EXPECT_FALSE(dialog->cancelTestButton()->isEnabled()) << "nothing to cancel yet";
    dialog->nodeTable()->selectRow(1);
    QTest::mouseClick(dialog->testButton(), Qt::LeftButton);
    ASSERT_TRUE(waitUntil([&] { return peer_.accepted() == 1 && peer_.received() > 0; }))
        << "no association request";
    EXPECT_TRUE(dialog->testRunning());
    EXPECT_FALSE(dialog->testButton()->isEnabled());
    ASSERT_TRUE(dialog->cancelTestButton()->isEnabled());
    // The "Testing…" line takes room without squeezing the fields above it.
    for (QLineEdit* edit : {dialog->aeTitleEdit(), dialog->listenerTlsBox()->trustedEdit(),
                            dialog->listenerTlsBox()->keyEdit(), dialog->storeFolderEdit()}) {
        EXPECT_GE(edit->height(), edit->sizeHint().height()) << edit->objectName().toStdString();
    }
    dialog->grab().save(
        QString::fromStdString((vv::test::panelTestDir() / "test-running.png").string()));

    QTest::mouseClick(dialog->cancelTestButton(), Qt::LeftButton);
    ASSERT_TRUE(waitUntil([&] { return dialog->testButton()->isEnabled(); }));
    EXPECT_FALSE(dialog->testRunning());
    EXPECT_EQ(dialog->testButton()->text(), QStringLiteral("&Test"));
    EXPECT_FALSE(dialog->cancelTestButton()->isEnabled());
    EXPECT_EQ(dialog->testResult(), QStringLiteral("Test cancelled."));
    ASSERT_TRUE(waitUntil([&] { return peer_.closed() == 1; })) << "the association stays open";
    waitUntil([] { return false; }, 500);
    EXPECT_EQ(dialog->testResult(), QStringLiteral("Test cancelled."));

    // Orthanc still answers C-ECHO.
    const std::string result = testNode(dialog, 0);
    EXPECT_NE(result.find("Success"), std::string::npos) << result;
    dialog->reject();
}

TEST_F(PacsCancelGuiTest, CancelWhileTheSeriesAreSearchedAbortsThatFind) {
    vv::gui::PacsBrowser* b = browser();
    ASSERT_TRUE(search(b, QStringLiteral("VV-GUI-1")));
    ASSERT_EQ(b->studyTable()->rowCount(), 1);
    // Orthanc frozen: the series search waits for its answer.
    orthanc_->pause();
    const std::unique_ptr<void, void (*)(void*)> resume(
        this, [](void*) { orthanc_->resume(); });  // also when a check fails
    bool ended = false;
    QObject::connect(
        b, &vv::gui::PacsBrowser::seriesFinished, b, [&](bool) { ended = true; },
        Qt::SingleShotConnection);
    b->studyTable()->selectRow(0);
    ASSERT_TRUE(b->cancelSearchButton()->isEnabled());
    // The worker's request waits, unread, at the frozen Orthanc.
    ASSERT_TRUE(waitUntil([&] { return vv::test::unreadBytesAt(orthanc_->node().port) > 0; }))
        << "the series search sent no request";
    QTest::mouseClick(b->cancelSearchButton(), Qt::LeftButton);
    EXPECT_TRUE(waitUntil([&] { return ended; }));
    EXPECT_EQ(b->status(), QStringLiteral("Search cancelled."));
    EXPECT_FALSE(b->cancelSearchButton()->isEnabled());
    EXPECT_TRUE(b->searchButton()->isEnabled());
    EXPECT_EQ(b->seriesTable()->rowCount(), 0);
    orthanc_->resume();
    // The study's series come when it is chosen again.
    b->studyTable()->clearSelection();
    EXPECT_TRUE(selectStudy(b));
}

}  // namespace
