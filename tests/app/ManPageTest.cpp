// SPDX-License-Identifier: GPL-3.0-or-later
// The man pages (resources/man/) and --help say the same: every option of
// `vesselview-cli --help` is in vesselview-cli.1 and the page names no other;
// each display setting's range and default reads as --help gives them (from
// the settings schema); the page describes every form of every command; and
// vesselview.1 names every option of `vesselview --help`.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <iterator>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "CliRun.h"

namespace vv::test {
namespace {

std::string readFile(const std::string& path) {
    std::ifstream in(path);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
    for (std::size_t at = text.find(from); at != std::string::npos;
         at = text.find(from, at + to.size())) {
        text.replace(at, from.size(), to);
    }
    return text;
}

/// The words of a font macro's arguments (".BI \-\-p " X"" -> "\-\-p", " X"),
/// joined as man prints them: without spaces between alternating fonts.
std::string macroText(const std::string& arguments) {
    std::string text;
    bool quoted = false;
    for (const char c : arguments) {
        if (c == '"') {
            quoted = !quoted;
        } else if (c != ' ' || quoted) {
            text += c;
        }
    }
    return text;
}

/// The page as text, roughly as man shows it: comments and layout macros
/// dropped, font macros' words joined, escapes resolved, white space single.
std::string pageText(const std::string& roff) {
    std::istringstream in(roff);
    std::string text;
    for (std::string line; std::getline(in, line);) {
        if (line.rfind(".\\\"", 0) == 0) {
            continue;
        }
        if (!line.empty() && line.front() == '.') {
            const std::size_t space = line.find(' ');
            const std::string macro =
                line.substr(1, space == std::string::npos ? space : space - 1);
            const std::string arguments = space == std::string::npos ? "" : line.substr(space + 1);
            if (macro == "B" || macro == "I" || macro == "SH" || macro == "TH") {
                line = arguments;
            } else if (macro.size() == 2 &&
                       std::string("BIR").find(macro[0]) != std::string::npos &&
                       std::string("BIR").find(macro[1]) != std::string::npos) {
                line = macroText(arguments);
            } else {
                line.clear();  // .TP, .PP, .RS, .br, ...
            }
        }
        text += line + " ";
    }
    for (const char* font : {"\\fB", "\\fI", "\\fR", "\\fP"}) {
        text = replaced(text, font, "");
    }
    text = replaced(text, "\\-", "-");
    text = replaced(text, "\\(de", "°");
    text = replaced(text, "\\(em", "—");
    text = replaced(text, "\\e", "\\");
    return std::regex_replace(text, std::regex("\\s+"), " ");
}

std::set<std::string> optionsIn(const std::string& text) {
    std::set<std::string> options;
    const std::regex option("--[a-z][a-z0-9-]*[a-z0-9]");
    for (auto it = std::sregex_iterator(text.begin(), text.end(), option);
         it != std::sregex_iterator(); ++it) {
        options.insert(it->str());
    }
    return options;
}

std::string cliHelp() {
    const auto run = runCli({"--help"});
    EXPECT_EQ(run.code, 0);
    return run.out;
}

const std::string& cliPage() {
    static const std::string text =
        pageText(readFile(VV_SOURCE_DIR "/resources/man/vesselview-cli.1"));
    return text;
}

TEST(ManPage, NamesEveryOptionOfHelpAndNoOther) {
    ASSERT_GT(cliPage().size(), 1000U);
    const std::set<std::string> help = optionsIn(cliHelp());
    const std::set<std::string> page = optionsIn(cliPage());
    for (const std::string& option : help) {
        EXPECT_TRUE(page.count(option) == 1) << option << " is not in vesselview-cli.1";
    }
    for (const std::string& option : page) {
        EXPECT_TRUE(help.count(option) == 1) << option << " is in vesselview-cli.1, not in --help";
    }
}

TEST(ManPage, GivesEveryDisplaySettingAsHelpDoes) {
    // --help's last block: "  --p X     Power p: 0.25..64, default 2".
    const std::string help = cliHelp();
    const std::size_t block = help.find("\ndisplay settings");
    ASSERT_NE(block, std::string::npos);
    std::istringstream lines(help.substr(block + 1));
    std::string line;
    std::getline(lines, line);  // the heading
    int settings = 0;
    const std::regex entry(R"(^  (--\S+) (\S+)\s*(.*)$)");
    std::string option;
    while (std::getline(lines, line)) {
        std::smatch m;
        std::string summary;
        if (std::regex_match(line, m, entry)) {
            option = m[1].str() + " " + m[2].str();
            summary = m[3].str();
            EXPECT_NE(cliPage().find(option), std::string::npos) << option;
        } else {
            summary = std::regex_replace(line, std::regex("^\\s+"), "");
        }
        if (!summary.empty()) {
            ++settings;
            EXPECT_NE(cliPage().find(summary), std::string::npos)
                << option << ": the page does not say \"" << summary << "\"";
        }
    }
    EXPECT_GE(settings, 25);
}

TEST(ManPage, DescribesEveryFormOfEveryCommand) {
    for (const char* form :
         {"info FILE...", "demo -o FILE.vtp", "demo --dicom DIR", "render FILE -o IMAGE.png",
          "render --session F.vvs -o IMAGE.png", "report FILE -o REPORT.pdf",
          "report --session F.vvs -o REPORT.pdf", "report --batch LIST.txt --out-dir DIR",
          "vss --depth IN.pfm -o OUT.pfm", "bench", "centerline FILE -o CENTERLINES.vtp",
          "pacs echo|find|get|send|listen"}) {
        // In SYNOPSIS (vesselview-cli FORM) and in COMMANDS.
        const std::string text = cliPage();
        const std::size_t commands = text.find(" COMMANDS ");
        ASSERT_NE(commands, std::string::npos);
        EXPECT_NE(text.find(form, commands), std::string::npos) << form << " is not described";
        EXPECT_LT(text.find(std::string("vesselview-cli ") + form), commands)
            << form << " is not in the synopsis";
    }
}

#ifdef VV_GUI_EXE
TEST(ManPage, TheGuiPageNamesEveryOptionOfItsHelp) {
    std::FILE* pipe =
        ::popen("env QT_QPA_PLATFORM=offscreen '" VV_GUI_EXE "' --help 2>/dev/null", "r");
    ASSERT_NE(pipe, nullptr);
    std::string help;
    for (int c = std::fgetc(pipe); c != EOF; c = std::fgetc(pipe)) {
        help += static_cast<char>(c);
    }
    ::pclose(pipe);
    const std::set<std::string> options = optionsIn(help);
    ASSERT_TRUE(options.count("--screenshot") == 1) << help;
    const std::string page = pageText(readFile(VV_SOURCE_DIR "/resources/man/vesselview.1"));
    for (const std::string& option : options) {
        EXPECT_NE(page.find(option), std::string::npos) << option << " is not in vesselview.1";
    }
    EXPECT_NE(page.find(".vvs"), std::string::npos);  // a session file as the argument
}
#endif

}  // namespace
}  // namespace vv::test
