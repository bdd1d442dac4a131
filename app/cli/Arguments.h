// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <climits>
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

/// Reading a command's arguments: one walker for every command, and the
/// parsers of the values they share. Errors are UsageErrors (Cli.h) whose
/// message starts with the command ("bench: --runs needs a value").
namespace vv::cli {

/// Walks the arguments of `command` one by one. An option's value is the
/// next argument, or follows an equals sign ("--p=4").
///
///     for (Arguments a("render", args); a.next();) {
///         if (a.name() == "-o") { output = a.path(); } ...
///     }
class Arguments {
  public:
    /// Starts before args[first].
    Arguments(std::string command, const std::vector<std::string>& args, std::size_t first = 0);

    /// Moves to the next argument; false after the last.
    bool next();
    /// The argument next() moved to, as given.
    [[nodiscard]] const std::string& current() const { return args_[at_]; }
    /// The option it names: "--p" for "--p=4"; else the argument as given.
    [[nodiscard]] const std::string& name() const noexcept { return name_; }
    /// Its index in the arguments.
    [[nodiscard]] std::size_t position() const noexcept { return at_; }
    /// True when the current argument looks like an option ("-x", "--x"; not "-").
    [[nodiscard]] bool isOption() const;
    [[nodiscard]] const std::string& command() const noexcept { return command_; }

    /// The current option's value: what follows its equals sign, else the
    /// next argument, taken. Throws UsageError "<command>: <option> needs a
    /// value" at the end.
    const std::string& value();
    /// A value that names a file or folder: as value(), and not empty
    /// ("<command>: <option> needs a file name").
    std::filesystem::path path();
    /// What value() would give, without taking it; "" when there is none
    /// (for parsers that decide themselves whether the option is theirs).
    [[nodiscard]] const std::string& peekValue() const;
    /// Takes the value peekValue() showed.
    void takeValue() noexcept;

    /// The current argument, which no option of the command took: the one
    /// positional input when it is not an option and `have` is false (then
    /// stored in `input`, `have` set). Throws UsageError for an unknown
    /// option or a second input, naming it.
    void takeOneInput(std::filesystem::path& input, bool& have) const;

    /// Throws UsageError "<command>: <problem>".
    [[noreturn]] void fail(const std::string& problem) const;

  private:
    std::string command_;
    const std::vector<std::string>& args_;
    std::size_t at_;
    bool started_ = false;
    std::string name_;
    std::optional<std::string> inlineValue_;
};

/// `text` as a finite number (C locale). Throws UsageError "<what> must be a
/// number, got '<text>'".
[[nodiscard]] double parseNumber(std::string_view text, const std::string& what);

/// `text` as a whole number within lo..hi. Throws UsageError "<what> must be
/// a whole number[ within lo..hi], got '<text>'".
[[nodiscard]] int parseWholeNumber(std::string_view text, const std::string& what, int lo = INT_MIN,
                                   int hi = INT_MAX);

/// "WIDTHxHEIGHT" (or "WxH" with a capital X), each side within
/// minSide..maxSide. Throws UsageError naming `what` ("--size").
[[nodiscard]] std::pair<int, int> parseSize(std::string_view text, const std::string& what,
                                            int minSide, int maxSide);

/// "a,b,c" as its items. Throws UsageError naming `what` for an empty item.
[[nodiscard]] std::vector<std::string> splitList(std::string_view text, const std::string& what);

}  // namespace vv::cli
