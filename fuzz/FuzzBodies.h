// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The fuzz targets' bodies (docs/reliability.md, "Fuzzing"):
// each feeds one input, as bytes, into the API the application uses for that
// file type. The libFuzzer wrappers (<target>_fuzz.cpp) and the regression
// test (tests/fuzz/FuzzRegressionTest.cpp) call the same functions.
//
// Contract: an expected refusal is a vv::Error, returned as `error`; every
// other outcome — a crash, an abort, a sanitizer report, an exception that is
// not a vv::Error, a hang — is a finding and is NOT caught here.

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace vv::fuzz {

using Bytes = std::span<const std::uint8_t>;

/// What one input did.
struct Outcome {
    bool loaded = false;         ///< the API returned normally
    std::string error;           ///< else: the vv::Error's what() (names the file)
    std::filesystem::path file;  ///< the scratch file the input was written to (empty: none)
};

/// The fuzz targets by name: dicom, stl, obj, ply, vtp, vtk, pfm, session.
[[nodiscard]] const std::vector<std::string>& targetNames();

/// A scratch file called `name` in this process's scratch folder
/// (/dev/shm/vv-fuzz-<pid>/, or the temporary folder when /dev/shm is
/// missing), created on first use and removed at exit; `bytes` written to it,
/// replacing what it held.
[[nodiscard]] std::filesystem::path writeScratch(std::string_view name, Bytes bytes);

/// Mesh targets: the bytes as a file with `extension` (".stl", ".obj",
/// ".ply", ".vtp", ".vtk") through vv::meshio::loadMesh (the preflight checks,
/// then the VTK reader and the conversion), as the application loads it.
[[nodiscard]] Outcome feedMesh(Bytes bytes, std::string_view extension);

/// dicom: the bytes as a .dcm file through vv::dicom::loadDicomVolume (scan the
/// headers, then decode the pixels of its series) with a 256 MiB memory limit.
[[nodiscard]] Outcome feedDicom(Bytes bytes);

/// pfm: the bytes as a .pfm file through vv::vss::readPfm.
[[nodiscard]] Outcome feedPfm(Bytes bytes);

/// session: the bytes as the content of a .vvs file through
/// vv::gui::sessionFromJson (defined in SessionBody.cpp, which needs the GUI
/// library).
[[nodiscard]] Outcome feedSession(Bytes bytes);

}  // namespace vv::fuzz
