// SPDX-License-Identifier: GPL-3.0-or-later
// What the DICOM network GUI says when a call fails, in German (issue 30
// item 11): a sentence in the UI language that names the node by its name,
// says what happened and what to do; the module's English detail apart (the
// line's tooltip), never inside the sentence. Provoked against the tests'
// real Orthanc and a closed port; the kinds no peer here can be made to
// produce go through classifyFailure(). Every text is also laid out in
// English and German in the lines that show it, with nothing cut off.
#include <gtest/gtest.h>

#include <QCoreApplication>
#include <QLabel>
#include <QLayout>
#include <QLineEdit>
#include <QPushButton>
#include <QTableWidget>
#include <QWindow>
#include <exception>
#include <string>
#include <vector>

#include "ClippingCheck.h"
#include "PacsGuiFixture.h"
#include "UiLanguage.h"
#include "gui/pacs/NetworkFailure.h"
#include "vv/core/Error.h"
#include "vv/pacs/PacsError.h"

namespace {

using vv::test::listed;

using vv::test::waitUntil;

/// The summary `shown` is a German sentence that names `name` and holds no
/// English of `details` (the tooltip "Details: …", which must be there).
void expectGermanWithTheDetailApart(const QString& shown, const QString& tooltip,
                                    const QString& name) {
    EXPECT_TRUE(shown.contains(name)) << shown.toStdString();
    EXPECT_TRUE(tooltip.startsWith(QStringLiteral("Details: "))) << tooltip.toStdString();
    const QString details = tooltip.mid(9);
    EXPECT_GT(details.size(), 10) << tooltip.toStdString();
    EXPECT_FALSE(shown.contains(details)) << shown.toStdString();
    for (const char* english : {" the ", " failed", " cannot ", " must ", "Failed", "Invalid"}) {
        EXPECT_FALSE(shown.contains(QLatin1String(english)))
            << english << " in: " << shown.toStdString();
    }
    for (const char* german : {" Sie "}) {
        EXPECT_TRUE(shown.contains(QLatin1String(german)))
            << "no German \"" << german << "\" in: " << shown.toStdString();
    }
}

class PacsFailureGermanTest : public vv::test::PacsGuiFixture {
  protected:
    void SetUp() override {
        ASSERT_TRUE(vv::test::installUiLanguage("de", VV_QM_DIR));
        PacsGuiFixture::SetUp();
    }
    void TearDown() override {
        PacsGuiFixture::TearDown();
        vv::test::removeUiLanguage();
    }
    [[nodiscard]] QLabel* browserStatus() const {
        return browser_->findChild<QLabel*>(QStringLiteral("pacsStatus"));
    }
};

TEST_F(PacsFailureGermanTest, TestOnAClosedPortNamesTheNodeInGermanWithTheDetailApart) {
    auto* dialog = preferences();
    addNode(dialog, QStringLiteral("Archiv Nord"), QStringLiteral("NOBODY"),
            QStringLiteral("127.0.0.1"), vv::test::freePort());
    ASSERT_EQ(dialog->nodeTable()->rowCount(), 2);
    const QString shown = QString::fromStdString(testNode(dialog, 1));
    EXPECT_TRUE(shown.contains(QStringLiteral("Verbindung"))) << shown.toStdString();
    expectGermanWithTheDetailApart(
        shown, dialog->findChild<QLabel*>(QStringLiteral("testResult"))->toolTip(),
        QStringLiteral("Archiv Nord"));
}

TEST_F(PacsFailureGermanTest, ASearchKeyDicomForbidsSaysInGermanWhatToCorrect) {
    auto* b = browser();
    EXPECT_FALSE(search(b, QStringLiteral("VV\\GUI")));
    const QString shown = b->status();
    EXPECT_TRUE(shown.contains(QStringLiteral("Korrigieren"))) << shown.toStdString();
    expectGermanWithTheDetailApart(shown, browserStatus()->toolTip(), QStringLiteral("Orthanc"));
    EXPECT_TRUE(browserStatus()->toolTip().contains(QStringLiteral("backslash")))
        << browserStatus()->toolTip().toStdString();
}

TEST_F(PacsFailureGermanTest, TheOtherKindsAreGermanNameTheNodeAndKeepTheDetailApart) {
    const vv::pacs::Node node{"PACS1", "pacs.example", 4242, {}};
    const std::string detail = "PACS1@pacs.example:4242: C-FIND failed with status 0xc001";
    const std::exception_ptr errors[] = {
        std::make_exception_ptr(vv::pacs::PeerFailedError(detail)),
        std::make_exception_ptr(vv::pacs::ResponseError(detail)),
        std::make_exception_ptr(vv::pacs::TooManyMatchesError(detail, 2000)),
        std::make_exception_ptr(vv::InvalidArgumentError(detail)),
        std::make_exception_ptr(std::runtime_error(detail)),
    };
    for (const std::exception_ptr& error : errors) {
        const vv::gui::ProblemText problem =
            vv::gui::failureText(vv::gui::classifyFailure(error), QStringLiteral("Archiv"), node);
        expectGermanWithTheDetailApart(problem.summary,
                                       QStringLiteral("Details: ") + problem.details,
                                       QStringLiteral("Archiv (PACS1@pacs.example:4242)"));
        EXPECT_EQ(problem.details.toStdString(), detail);
    }
    // Too many matches: the limit in the UI locale's digits, and what to do.
    const QString tooMany =
        vv::gui::failureText(vv::gui::classifyFailure(errors[2]), QStringLiteral("Archiv"), node)
            .summary;
    EXPECT_TRUE(tooMany.contains(QStringLiteral("mehr als 2.000 Treffer")))
        << tooMany.toStdString();
    EXPECT_TRUE(tooMany.contains(QStringLiteral("Grenzen Sie die Suche ein")))
        << tooMany.toStdString();
}

class PacsFailureClippingTest : public vv::test::PacsGuiInLanguage {
  protected:
    /// Every failure's summary, for a node with a long name.
    static std::vector<QString> everySummary() {
        using Kind = vv::gui::NetworkFailure::Kind;
        const vv::pacs::Node node{"RADIOLOGY_PACS", "pacs.radiology.example.org", 11112, {}};
        std::vector<QString> texts;
        for (const Kind kind : {Kind::Refused, Kind::AssociationRejected, Kind::Timeout, Kind::Tls,
                                Kind::PeerFailed, Kind::ConnectionClosed, Kind::TooManyMatches,
                                Kind::Response, Kind::InvalidInput, Kind::Other}) {
            vv::gui::NetworkFailure failure{kind, "detail", std::nullopt};
            failure.matchLimit = 2000;
            texts.push_back(
                vv::gui::failureText(failure, QStringLiteral("Radiologie Haus B"), node).summary);
        }
        return texts;
    }

    /// Shows each text in `label` of `window` and expects nothing cut off.
    void expectWhole(QWidget& window, QLabel* label, const std::string& name) {
        ASSERT_NE(label, nullptr) << name;
        EXPECT_TRUE(waitUntil(
            [&] { return window.windowHandle() != nullptr && window.windowHandle()->isExposed(); },
            10000));
        for (const QString& text : everySummary()) {
            label->setText(text);
            window.layout()->activate();
            for (int i = 0; i < 5; ++i) {
                QCoreApplication::processEvents(QEventLoop::AllEvents, 20);
            }
            const std::vector<std::string> problems = vv::test::ClippingCheck::problems(&window);
            EXPECT_TRUE(problems.empty()) << "cut off in " << name << " showing \""
                                          << text.toStdString() << "\":" << listed(problems);
        }
    }
};

TEST_P(PacsFailureClippingTest, EveryFailureFitsTheBrowsersStatusAndTheTestLine) {
    auto* b = browser();
    expectWhole(*b, b->findChild<QLabel*>(QStringLiteral("pacsStatus")), "browser status");
    auto* dialog = preferences();
    dialog->nodeTable()->selectRow(0);
    expectWhole(*dialog, dialog->findChild<QLabel*>(QStringLiteral("testResult")), "test line");
}

INSTANTIATE_TEST_SUITE_P(Languages, PacsFailureClippingTest, ::testing::Values("en", "de"),
                         [](const ::testing::TestParamInfo<const char*>& param) {
                             return std::string(param.param);
                         });

}  // namespace
