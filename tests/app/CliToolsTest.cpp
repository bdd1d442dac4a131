// SPDX-License-Identifier: GPL-3.0-or-later
// The command line's shared tools (app/cli): the argument walker and value
// parsers every command uses, the one output check and the one JSON writer.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "CliRun.h"
#include "cli/Arguments.h"
#include "cli/Cli.h"
#include "cli/JsonWriter.h"
#include "cli/OutputFiles.h"
#include "cli/RenderOptions.h"

namespace vv::test {
namespace {

using cli::Arguments;
using cli::UsageError;

/// The UsageError's message of `f` ("" when it threw none).
template <typename F>
std::string usageError(F f) {
    try {
        f();
    } catch (const UsageError& e) {
        return e.what();
    }
    return {};
}

TEST(CliArguments, WalksOptionsValuesAndInlineValues) {
    const std::vector<std::string> args{"in.vtp", "--p", "4", "--size=640x480", "-o", "", "--x"};
    Arguments a("render", args);
    ASSERT_TRUE(a.next());
    EXPECT_FALSE(a.isOption());
    EXPECT_EQ(a.current(), "in.vtp");
    ASSERT_TRUE(a.next());
    EXPECT_TRUE(a.isOption());
    EXPECT_EQ(a.name(), "--p");
    EXPECT_EQ(a.value(), "4");
    ASSERT_TRUE(a.next());
    EXPECT_EQ(a.name(), "--size");
    EXPECT_EQ(a.peekValue(), "640x480");
    EXPECT_EQ(a.value(), "640x480");
    ASSERT_TRUE(a.next());
    EXPECT_EQ(a.name(), "-o");
    EXPECT_EQ(usageError([&] { static_cast<void>(a.path()); }), "render: -o needs a file name");
    ASSERT_TRUE(a.next());
    EXPECT_EQ(usageError([&] { static_cast<void>(a.value()); }), "render: --x needs a value");
    EXPECT_FALSE(a.next());
}

TEST(CliArguments, OnePositionalInputThenUnknownOptionsAndSecondInputsAreRefused) {
    const std::vector<std::string> args{"a.vtp", "b.vtp", "--bogus"};
    Arguments a("report", args);
    std::filesystem::path input;
    bool have = false;
    ASSERT_TRUE(a.next());
    a.takeOneInput(input, have);
    EXPECT_TRUE(have);
    EXPECT_EQ(input, "a.vtp");
    ASSERT_TRUE(a.next());
    EXPECT_EQ(usageError([&] { a.takeOneInput(input, have); }),
              "report: takes one input file, got a second one 'b.vtp'");
    EXPECT_EQ(input, "a.vtp");
    ASSERT_TRUE(a.next());
    have = false;
    EXPECT_EQ(usageError([&] { a.takeOneInput(input, have); }), "report: unknown option '--bogus'");
    EXPECT_FALSE(have);
}

TEST(CliArguments, ParsersNameWhatIsWrong) {
    EXPECT_EQ(cli::parseNumber("2.5", "--p"), 2.5);
    EXPECT_EQ(usageError([] { static_cast<void>(cli::parseNumber("2,5", "--p")); }),
              "--p must be a number, got '2,5'");
    EXPECT_EQ(usageError([] { static_cast<void>(cli::parseNumber("nan", "--p")); }),
              "--p must be a number, got 'nan'");
    EXPECT_EQ(cli::parseWholeNumber("12", "--runs", 1, 1000), 12);
    EXPECT_EQ(usageError([] { static_cast<void>(cli::parseWholeNumber("0", "--runs", 1, 9)); }),
              "--runs must be a whole number within 1..9, got '0'");
    EXPECT_EQ(usageError([] { static_cast<void>(cli::parseWholeNumber("8", "--tile", 64)); }),
              "--tile must be a whole number of at least 64, got '8'");
    EXPECT_EQ(cli::parseSize("640X480", "--size", 1, 4096), std::make_pair(640, 480));
    EXPECT_NE(usageError([] { static_cast<void>(cli::parseSize("640", "--size", 1, 99)); }), "");
    EXPECT_NE(usageError([] {
                  static_cast<void>(cli::parseSize("100x100", "--size", 1, 99));
              }).find("--size width"),
              std::string::npos);
    EXPECT_EQ(cli::splitList("a,b", "--views"), (std::vector<std::string>{"a", "b"}));
    EXPECT_NE(usageError([] { static_cast<void>(cli::splitList("a,,b", "--views")); }), "");
}

TEST(CliArguments, SchemaOptionsAreParsedFromTheTable) {
    // An option the schema added (no hand-written parser): range and value from the table.
    const std::vector<std::string> good{"--ao-radius", "5.5"};
    std::size_t i = 0;
    cli::RenderOptionValues values;
    ASSERT_TRUE(cli::parseRenderOption(good, i, values, "render"));
    EXPECT_EQ(i, 1U);
    EXPECT_FLOAT_EQ(values.ao.radius, 5.5F);
    const std::vector<std::string> bad{"--ao-radius", "5000"};
    i = 0;
    EXPECT_NE(usageError([&] {
                  cli::parseRenderOption(bad, i, values, "render");
              }).find("--ao-radius must be a number within 0.01..1000"),
              std::string::npos);
    const std::vector<std::string> other{"--nonsense", "1"};
    i = 0;
    EXPECT_FALSE(cli::parseRenderOption(other, i, values, "render"));
    EXPECT_EQ(i, 0U);
}

TEST(CliOutputFiles, OneCheckForEveryCommand) {
    const std::filesystem::path dir = processTestDir("cli-tools");
    std::filesystem::create_directories(dir);
    EXPECT_NO_THROW(cli::checkOutputPath(dir / "new.png"));
    EXPECT_THROW(cli::checkOutputPath(dir / "missing" / "new.png"), cli::OutputError);
    EXPECT_THROW(cli::checkOutputPath(dir), cli::OutputError);
    EXPECT_NO_THROW(cli::ensureOutputFolder(dir / "made" / "here"));
    EXPECT_TRUE(std::filesystem::is_directory(dir / "made" / "here"));
    // The same check behind every command: a missing folder is exit code 4.
    const auto vss = runCli({"vss", "--depth", "in.pfm", "-o", (dir / "no" / "o.pfm").string()});
    const auto render = runCli({"render", "in.vtp", "-o", (dir / "no" / "o.png").string()});
    EXPECT_EQ(vss.code, cli::kCannotWrite) << vss.err;
    EXPECT_EQ(render.code, cli::kCannotWrite) << render.err;
}

TEST(CliJsonWriter, OneLineAndIndentedWithOneNumberFormat) {
    std::ostringstream line;
    cli::JsonWriter json(line, cli::JsonWriter::Layout::OneLine);
    json.beginObject();
    json.key("f");
    json.number(0.1F);
    json.key("d");
    json.number(0.1);
    json.key("whole");
    json.number(40.0);
    json.key("nan");
    json.number(std::numeric_limits<double>::quiet_NaN());
    json.key("list");
    json.beginArray();
    json.integer(1);
    json.integer(std::size_t{2});
    json.endArray();
    json.key("s");
    json.string("a\"b\x01");
    json.key("empty");
    json.beginObject();
    json.endObject();
    json.endObject();
    json.finish();
    EXPECT_EQ(line.str(),
              "{\"f\": 0.1, \"d\": 0.1, \"whole\": 40, \"nan\": null, \"list\": [1, 2], "
              "\"s\": \"a\\\"b\\u0001\", \"empty\": {}}\n");

    std::ostringstream indented;
    cli::JsonWriter pretty(indented);
    pretty.beginObject();
    pretty.key("a");
    pretty.beginArray();
    pretty.number(1.0 / 3.0);
    pretty.endArray();
    pretty.endObject();
    pretty.finish();
    EXPECT_EQ(indented.str(), "{\n  \"a\": [\n    0.3333333333333333\n  ]\n}\n");
}

TEST(CliJsonWriter, InvalidUtf8BecomesReplacementCharacters) {
    EXPECT_EQ(cli::jsonString("\xC3\xA9"), "\"\xC3\xA9\"");
    EXPECT_EQ(cli::jsonString("\xC3"), "\"\\ufffd\"");
    EXPECT_EQ(cli::jsonString("\xED\xA0\x80"), "\"\\ufffd\\ufffd\\ufffd\"");  // a surrogate
}

}  // namespace
}  // namespace vv::test
