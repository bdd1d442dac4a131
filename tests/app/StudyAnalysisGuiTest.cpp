// SPDX-License-Identifier: GPL-3.0-or-later
// Study > Analyse Results…: two results files of simulated participants
// (one a guesser) analysed from the dialog as from the CLI: the outcome in
// the dialog names the participants, the exclusion, Friedman's test and
// the pairs that differ; the PDF says the same (read back with pdftotext);
// the tables are written; a bad file gets an error naming its line, and
// the window never waits for the work.
#include <gtest/gtest.h>

#include <QApplication>
#include <QMenuBar>
#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>

#include "SimulatedResults.h"
#include "WaitUntil.h"
#include "gui/MainWindow.h"
#include "gui/study/StudyAnalysisDialog.h"

namespace vv::gui {
namespace {

std::filesystem::path scratch() {
    auto dir = std::filesystem::path(VV_TEST_TMP) / "study-analysis-gui";
    std::filesystem::create_directories(dir);
    return dir;
}

bool waitFor(const std::function<bool()>& done) {
    return test::pollUntil(done, std::chrono::seconds(60), [] {
        QCoreApplication::processEvents(QEventLoop::WaitForMoreEvents, 20);
    });
}

std::string pdfText(const std::filesystem::path& pdf) {
    std::string text;
    const std::string command = "pdftotext -layout '" + pdf.string() + "' -";
    if (FILE* pipe = popen(command.c_str(), "r")) {
        std::array<char, 4096> buffer{};
        while (const std::size_t n = fread(buffer.data(), 1, buffer.size(), pipe)) {
            text.append(buffer.data(), n);
        }
        pclose(pipe);
    }
    return text;
}

StudyAnalysisDialog* openFromMenu(MainWindow& window) {
    for (QAction* menu : window.menuBar()->actions()) {
        if (menu->text().remove('&') == "Study") {
            for (QAction* item : menu->menu()->actions()) {
                if (item->text().remove('&').startsWith("Analyse")) {
                    item->trigger();
                }
            }
        }
    }
    return window.findChild<StudyAnalysisDialog*>();
}

TEST(StudyAnalysisGui, AnalysesTheResultsFilesIntoThePdfAndTheTables) {
    if (QApplication::instance() == nullptr) {
        static int argc = 1;
        static std::array<char, 22> name{"vv_gui_analysis_tests"};
        static std::array<char*, 2> argv{name.data(), nullptr};
        const auto config = scratch() / "config";
        std::filesystem::remove_all(config);
        qputenv("XDG_CONFIG_HOME", QByteArray::fromStdString(config.string()));
        new QApplication(argc, argv.data());  // kept for the whole process
    }
    const auto first = scratch() / "first.csv";
    const auto second = scratch() / "second.csv";
    study::test::writeSimulatedResults(first, 1, 6, false);
    study::test::writeSimulatedResults(second, 7, 12, true);
    const auto pdf = scratch() / "study.pdf";
    const auto tables = scratch() / "tables";
    std::filesystem::remove(pdf);
    std::filesystem::remove_all(tables);

    MainWindow window;
    window.show();
    StudyAnalysisDialog* dialog = openFromMenu(window);
    ASSERT_NE(dialog, nullptr) << "no Study > Analyse Results…";
    EXPECT_FALSE(dialog->analyse()) << "no files yet";
    EXPECT_TRUE(dialog->outcome().contains("Add the study's results files"));
    dialog->addResultsFile(QString::fromStdString(first.string()));
    dialog->addResultsFile(QString::fromStdString(second.string()));
    dialog->setPdfPath(QString::fromStdString(pdf.string()));
    dialog->setTablesFolder(QString::fromStdString(tables.string()));
    dialog->setCorrection(study::Correction::Holm);
    bool ok = false;
    bool ended = false;
    QObject::connect(dialog, &StudyAnalysisDialog::finished, [&](bool success) {
        ok = success;
        ended = true;
    });
    ASSERT_TRUE(dialog->analyse());
    // The outcome comes through the event loop from the worker, never
    // inside the call that started it (a synchronous analysis would end here).
    EXPECT_FALSE(ended) << "the work runs off the GUI thread";
    ASSERT_TRUE(waitFor([&] { return ended; }));
    ASSERT_TRUE(ok) << dialog->outcome().toStdString();

    const QString outcome = dialog->outcome();
    EXPECT_TRUE(outcome.contains("Participants: 13, Included: 12")) << outcome.toStdString();
    EXPECT_TRUE(outcome.contains("Excluded \u2014 guesser: at chance level"))
        << outcome.toStdString();
    EXPECT_TRUE(outcome.contains("Accuracy: Friedman's test: \u03c7\u00b2(2)"))
        << outcome.toStdString();
    EXPECT_TRUE(outcome.contains("VSS-CD \u2013 baseline")) << outcome.toStdString();

    const std::string text = pdfText(pdf);
    EXPECT_NE(text.find("guesser"), std::string::npos) << text.substr(0, 400);
    EXPECT_NE(text.find("Holm"), std::string::npos);
    EXPECT_NE(text.find("second.csv"), std::string::npos);  // ("first" is set with the fi ligature)
    for (const char* table : {"conditions.csv", "comparisons.csv", "participants.csv"}) {
        EXPECT_TRUE(std::filesystem::exists(tables / table)) << table;
    }

    // A damaged file: the error names it and its line; nothing is written.
    const auto bad = scratch() / "bad.csv";
    std::ofstream(bad) << study::resultsHeader() << "\nP1,main,x\n";
    std::filesystem::remove(pdf);
    dialog->addResultsFile(QString::fromStdString(bad.string()));
    ended = false;
    ASSERT_TRUE(dialog->analyse());
    ASSERT_TRUE(waitFor([&] { return ended; }));
    EXPECT_FALSE(ok);
    EXPECT_TRUE(dialog->outcome().contains("bad.csv")) << dialog->outcome().toStdString();
    EXPECT_TRUE(dialog->outcome().contains("line 2")) << dialog->outcome().toStdString();
    EXPECT_FALSE(std::filesystem::exists(pdf));
}

}  // namespace
}  // namespace vv::gui
