// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <iosfwd>
#include <string>
#include <vector>

namespace vv::cli {

/// Exit codes of vesselview-cli; scripts rely on them.
enum ExitCode : int {
    kOk = 0,
    kInternalError = 1,  ///< a bug or an unexpected failure
    kUsage = 2,          ///< bad command line
    kInvalidInput = 3,   ///< input missing, unreadable or invalid
    kCannotWrite = 4,    ///< output could not be written
    kPeerFailed = 5,     ///< a DICOM peer refused, failed or did not answer in time
};

/// Thrown by commands for a bad command line; main() maps it to kUsage.
class UsageError : public std::exception {
  public:
    explicit UsageError(std::string message) : message_(std::move(message)) {}
    [[nodiscard]] const char* what() const noexcept override { return message_.c_str(); }

  private:
    std::string message_;
};

/// Runs vesselview-cli with `args` (args[0] is the subcommand), writing normal
/// output to `out` and messages to `err`. Returns the exit code; never throws.
int run(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

// The subcommands. Each parses its own arguments (throwing UsageError) and
// lets vv::Error exceptions pass to run(), which maps them to exit codes:
// IoError on an output path -> kCannotWrite; IoError/FormatError on input -> kInvalidInput.
int infoCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);
int demoCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);
int renderCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);
int vssCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);
int benchCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);
int artefactsCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);
int pacsCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);
int segmentCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);
int centerlineCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);
int studyCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

/// Thrown when an output file cannot be written; maps to kCannotWrite.
class OutputError : public std::exception {
  public:
    explicit OutputError(std::string message) : message_(std::move(message)) {}
    [[nodiscard]] const char* what() const noexcept override { return message_.c_str(); }

  private:
    std::string message_;
};

}  // namespace vv::cli
