// SPDX-License-Identifier: GPL-3.0-or-later
// The DICOM Preferences and the PACS browser in English and German at
// 1280 x 800: the study's date in the UI language's format, the texts
// translated, and nothing cut off (ClippingCheck) with a node listed and a
// search's results shown. Screenshots go to the test folder.
#include <gtest/gtest.h>

#include <QCoreApplication>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QLayout>
#include <QLineEdit>
#include <QPushButton>
#include <QTableWidget>
#include <QWindow>
#include <string>
#include <vector>

#include "ClippingCheck.h"
#include "PacsGuiFixture.h"
#include "UiLanguage.h"
#include "gui/pacs/ListenerLimitsBox.h"

namespace {

using vv::test::listed;

using vv::test::waitUntil;

class PacsGuiLanguageTest : public vv::test::PacsGuiInLanguage {
  protected:
    /// Lays `widget` out as shown, saves it as `name`-<language>.png and
    /// expects nothing cut off.
    void expectWhole(QWidget& widget, const std::string& name) {
        EXPECT_TRUE(waitUntil(
            [&] { return widget.windowHandle() != nullptr && widget.windowHandle()->isExposed(); },
            10000))
            << name << " never appeared";
        widget.layout()->activate();
        for (int i = 0; i < 10; ++i) {
            QCoreApplication::processEvents(QEventLoop::AllEvents, 20);
        }
        EXPECT_LE(widget.frameGeometry().width(), 1280) << name;
        EXPECT_LE(widget.frameGeometry().height(), 800) << name;
        widget.grab().save(QString::fromStdString(
            (vv::test::panelTestDir() / (name + "-" + GetParam() + ".png")).string()));
        const std::vector<std::string> problems = vv::test::ClippingCheck::problems(&widget);
        EXPECT_TRUE(problems.empty()) << "cut off in " << name << ":" << listed(problems);
    }
};

TEST_P(PacsGuiLanguageTest, PreferencesShowEveryTextInFull) {
    auto* dialog = preferences();
    dialog->nodeTable()->selectRow(0);
    expectWhole(*dialog, "pacs-preferences");
    // It can also be made small enough for a 1280 x 720 screen, with room for
    // a title bar and a panel (60 px).
    EXPECT_LE(dialog->minimumSizeHint().height(), 720 - 60);
    EXPECT_LE(dialog->minimumSizeHint().width(), 1280);
    // The listener limits among them: in the UI language, numbers in its locale.
    const bool german = QLatin1String(GetParam()) == QLatin1String("de");
    const vv::gui::ListenerLimitsBox* limits = dialog->listenerLimitsBox();
    EXPECT_TRUE(limits->isVisible());
    EXPECT_EQ(limits->title(), german ? QStringLiteral("Grenzen des Empfangsdienstes")
                                      : QStringLiteral("Listener limits"));
    EXPECT_EQ(limits->associationBox()->text(),
              german ? QStringLiteral("50,00 GB") : QStringLiteral("50.00 GB"));
    EXPECT_TRUE(limits->defaultsLabel()->text().startsWith(
        german ? QStringLiteral("Standardwerte: 16 Assoziationen")
               : QStringLiteral("Defaults: 16 associations")))
        << limits->defaultsLabel()->text().toStdString();
    QPointer<vv::gui::NodeEditDialog> edit = openNodeDialog(dialog, dialog->editButton());
    ASSERT_NE(edit, nullptr);
    expectWhole(*edit, "pacs-node");
    edit->reject();
}

TEST_P(PacsGuiLanguageTest, BrowserShowsTheStudyInTheUiLanguage) {
    auto* b = browser();
    b->resize(1200, 700);
    ASSERT_TRUE(search(b, QStringLiteral("VV-GUI-1"))) << b->status().toStdString();
    ASSERT_EQ(b->studyTable()->rowCount(), 1);
    ASSERT_TRUE(selectStudy(b));
    // Study Date 20250101 as the UI language and the report write dates: never "1/1/2025".
    const bool german = QLatin1String(GetParam()) == QLatin1String("de");
    EXPECT_EQ(b->studyTable()->item(0, 2)->text(),
              german ? QStringLiteral("01.01.2025") : QStringLiteral("2025-01-01"));
    EXPECT_EQ(b->status(), german ? QStringLiteral("Gefundene Studien: 1.")
                                  : QStringLiteral("Studies found: 1."));
    EXPECT_EQ(b->searchButton()->text(),
              german ? QStringLiteral("&Suchen") : QStringLiteral("&Search"));
    expectWhole(*b, "pacs-browser");
}

TEST_P(PacsGuiLanguageTest, TheNameHintFitsTheBrowserAtItsDefaultSize) {
    // As Query PACS… opens it: not resized.
    browser_ = window_->dicomMenu()->showBrowser();
    ASSERT_TRUE(waitUntil(
        [this] {
            return browser_->windowHandle() != nullptr && browser_->windowHandle()->isExposed();
        },
        10000));
    browser_->layout()->activate();
    QCoreApplication::processEvents();
    QLineEdit* name = browser_->patientNameEdit();
    ASSERT_TRUE(name->text().isEmpty());
    ASSERT_FALSE(name->placeholderText().isEmpty());
    const std::vector<std::string> problems = vv::test::ClippingCheck::problems(name);
    EXPECT_TRUE(problems.empty()) << "at " << browser_->width() << " px:" << listed(problems);
    // The whole hint is in the tooltip: both wildcards and what they match.
    const bool german = QLatin1String(GetParam()) == QLatin1String("de");
    const QString tip = name->toolTip();
    EXPECT_TRUE(tip.contains(QLatin1Char('*')) && tip.contains(QLatin1Char('?')))
        << tip.toStdString();
    EXPECT_TRUE(tip.contains(german ? QStringLiteral("beliebig") : QStringLiteral("any")))
        << tip.toStdString();
}

INSTANTIATE_TEST_SUITE_P(Languages, PacsGuiLanguageTest, ::testing::Values("en", "de"),
                         [](const ::testing::TestParamInfo<const char*>& param) {
                             return std::string(param.param);
                         });

}  // namespace
