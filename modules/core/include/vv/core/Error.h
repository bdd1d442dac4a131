// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <filesystem>
#include <stdexcept>
#include <string>

namespace vv {

/// Root of every exception VesselView throws on purpose. `what()` always names
/// the file (when there is one) and the problem: "<file>: <problem>".
class Error : public std::runtime_error {
  public:
    /// An error about `file` (may be empty when no file is involved).
    Error(const std::filesystem::path& file, const std::string& problem);
    explicit Error(const std::string& problem);

    /// The file the error is about; empty when none.
    [[nodiscard]] const std::filesystem::path& file() const noexcept { return file_; }
    /// The problem alone, without the file name.
    [[nodiscard]] const std::string& problem() const noexcept { return problem_; }

  private:
    std::filesystem::path file_;
    std::string problem_;
};

/// A file could not be opened, read or written (missing, permissions, disk full).
class IoError : public Error {
    using Error::Error;
};

/// A file was read but its content is not acceptable (corrupt, truncated,
/// empty, wrong type, non-finite coordinates, unknown format).
class FormatError : public Error {
    using Error::Error;
};

/// An argument or option given by the caller is out of its documented range.
class InvalidArgumentError : public Error {
    using Error::Error;
};

/// Long work was cancelled through its stop token.
class CancelledError : public Error {
  public:
    CancelledError() : Error("cancelled") {}
};

/// The GPU / OpenGL layer could not do what was asked (context, shaders, FBOs).
class RenderError : public Error {
    using Error::Error;
};

}  // namespace vv
