// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/core/Error.h"

namespace vv {

namespace {
std::string compose(const std::filesystem::path& file, const std::string& problem) {
    if (file.empty()) {
        return problem;
    }
    return file.string() + ": " + problem;
}
}  // namespace

Error::Error(const std::filesystem::path& file, const std::string& problem)
    : std::runtime_error(compose(file, problem)), file_(file), problem_(problem) {}

Error::Error(const std::string& problem) : std::runtime_error(problem), problem_(problem) {}

}  // namespace vv
