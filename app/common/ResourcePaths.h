// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <filesystem>
#include <optional>
#include <string_view>
#include <vector>

/// Where the installed program finds its data: always relative to its own
/// executable, never through a path fixed at build time.
///
///   build tree   <build>/app/vesselview      data in <build>/resources/
///   installed    <prefix>/bin/vesselview     data in <prefix>/share/vesselview/
///   macOS bundle X.app/Contents/MacOS/...    data in X.app/Contents/Resources/
///
/// Data layout below a data folder: demo/vessel-tree.vtp, translations/*.qm.
namespace vv::app {

/// Folder of the running executable (absolute, symlinks resolved); empty when
/// the platform cannot tell.
[[nodiscard]] std::filesystem::path executableDir();

/// The candidate data folders for an executable in `exeDir`, most specific
/// first; they need not exist.
[[nodiscard]] std::vector<std::filesystem::path> dataDirCandidates(
    const std::filesystem::path& exeDir);

/// The first existing `relative` path (file or folder) below one of the data
/// folders of `exeDir`, or nothing.
[[nodiscard]] std::optional<std::filesystem::path> findData(std::string_view relative,
                                                            const std::filesystem::path& exeDir);

/// findData() for the running executable.
[[nodiscard]] std::optional<std::filesystem::path> findData(std::string_view relative);

/// The bundled demo vessel tree: $VV_DEMO_FILE when set, else
/// demo/vessel-tree.vtp below a data folder of the running executable.
[[nodiscard]] std::optional<std::filesystem::path> findDemoFile();

/// True when `file` is the bundled demo tree that findDemoFile() finds (the
/// same file, however named): VesselView's synthetic data, not patient data.
[[nodiscard]] bool isDemoFile(const std::filesystem::path& file);

/// The folder of the compiled translations (*.qm), if there is one.
[[nodiscard]] std::optional<std::filesystem::path> findTranslationsDir();

}  // namespace vv::app
