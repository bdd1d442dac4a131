// SPDX-License-Identifier: GPL-3.0-or-later
// Help > About names the versions of Qt, VTK and DCMTK; the German
// translation reaches the main window's menus.
#include <QAction>
#include <QCoreApplication>
#include <QMenuBar>
#include <QRegularExpression>
#include <QSettings>
#include <QTranslator>

#include "GuiFixture.h"
#include "gui/ReportDialog.h"
#include "gui/Translations.h"
#include "vv/dicom/Versions.h"
#include "vv/meshio/Versions.h"

namespace vv::test {
namespace {

const QRegularExpression kVersion(QStringLiteral("^\\d+\\.\\d+"));

TEST(LibraryVersions, ReportRealVersions) {
    for (const std::string& version : {meshio::vtkVersion(), dicom::dcmtkVersion()}) {
        EXPECT_TRUE(kVersion.match(QString::fromStdString(version)).hasMatch()) << version;
    }
}

TEST(Languages, CommandLineBeatsSettingsBeatsSystem) {
    const fs::path file = panelTestDir() / "language.ini";
    std::error_code ec;
    fs::remove(file, ec);
    QSettings settings(QString::fromStdString(file.string()), QSettings::IniFormat);
    EXPECT_EQ(gui::chooseLanguage(QString(), settings), QString());  // the system's
    settings.setValue(QLatin1String(gui::kLanguageKey), QStringLiteral("de"));
    EXPECT_EQ(gui::chooseLanguage(QString(), settings), QStringLiteral("de"));
    EXPECT_EQ(gui::chooseLanguage(QStringLiteral("en"), settings), QStringLiteral("en"));
    EXPECT_TRUE(gui::availableLanguages().contains(QStringLiteral("en")));
    EXPECT_EQ(gui::languageName(QStringLiteral("de")), QStringLiteral("Deutsch"));
    EXPECT_EQ(gui::languageName(QStringLiteral("en")), QStringLiteral("English"));
}

class AboutTest : public GuiFixture {};

TEST_F(AboutTest, AboutBoxNamesTheLibraries) {
    const QString about = window_->aboutText();
    EXPECT_TRUE(about.contains(QStringLiteral("Qt ") + QString::fromLatin1(qVersion())))
        << about.toStdString();
    EXPECT_TRUE(
        about.contains(QStringLiteral("VTK ") + QString::fromStdString(meshio::vtkVersion())))
        << about.toStdString();
    EXPECT_TRUE(
        about.contains(QStringLiteral("DCMTK ") + QString::fromStdString(dicom::dcmtkVersion())))
        << about.toStdString();
}

TEST_F(AboutTest, AboutBoxShowsTheReportsDisclaimer) {
    QSettings settings;
    const QLatin1String key(gui::ReportDialog::kDisclaimerKey);
    settings.remove(key);
    EXPECT_TRUE(window_->aboutText().contains(QStringLiteral("Not for diagnostic use.")))
        << window_->aboutText().toStdString();
    settings.setValue(key, QStringLiteral("Research use only & <b>not</b> validated."));
    const QString about = window_->aboutText();
    settings.remove(key);
    EXPECT_TRUE(about.contains(QStringLiteral("Research use only &amp; &lt;b&gt;not&lt;/b&gt;")))
        << about.toStdString();
    EXPECT_FALSE(about.contains(QStringLiteral("Not for diagnostic use.")));
}

TEST_F(AboutTest, GermanTranslationReachesTheMenus) {
    QTranslator german;
    ASSERT_TRUE(german.load(QStringLiteral("vesselview_de"), QStringLiteral(VV_QM_DIR)));
    QCoreApplication::installTranslator(&german);
    auto window = std::make_unique<gui::MainWindow>();
    QStringList menus;
    for (const QAction* action : window->menuBar()->actions()) {
        menus << action->text();
    }
    const QString about = window->aboutText();
    window.reset();
    QCoreApplication::removeTranslator(&german);
    EXPECT_TRUE(menus.contains(QStringLiteral("&Datei"))) << menus.join(' ').toStdString();
    EXPECT_TRUE(menus.contains(QStringLiteral("&Ansicht"))) << menus.join(' ').toStdString();
    EXPECT_TRUE(about.contains(QStringLiteral("Bibliotheken"))) << about.toStdString();
    EXPECT_TRUE(about.contains(QStringLiteral("Nicht für diagnostische Zwecke.")))
        << about.toStdString();
}

}  // namespace
}  // namespace vv::test
