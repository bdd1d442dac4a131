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

#include <array>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace vv::scene {
struct Mesh;
}  // namespace vv::scene

namespace vv::fuzz {

using Bytes = std::span<const std::uint8_t>;

/// What one input did.
struct Outcome {
    bool loaded = false;         ///< the API returned normally
    std::string error;           ///< else: the vv::Error's what() (names the file)
    std::filesystem::path file;  ///< the scratch file the input was written to (empty: none)
};

/// The fuzz targets by name: dicom, stl, obj, ply, vtp, vtk, pfm, session,
/// analysis, study.
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

/// analysis: the bytes become a surface, which goes through the vessel
/// analysis as the application runs it: vv::analysis::computeCenterlines,
/// computeSections, findBifurcations, gradeStenosis for every branch (each
/// reference kind) and surfaceBranchIds (defined in AnalysisBody.cpp, which
/// needs vv::analysis). The first byte says how the surface is made:
/// - 'S' / 'P': the rest is an STL / PLY file, loaded with
///   vv::meshio::loadMesh (a file a user opens);
/// - anything else: the compact mesh of encodeAnalysisInput() (the analysis
///   itself explored: NaN, huge, repeated and degenerate points and
///   triangles, indices out of range, several pieces).
/// Surfaces above kAnalysisMaxTriangles triangles are loaded, not analysed.
/// The analysis runs with a stop request after kAnalysisBudgetSeconds
/// (a cancelled run is a refusal naming the input). A result that breaks
/// the analysis' documented invariants (a non-finite or negative centreline
/// value, abscissae going back, not one section per point, a branch id out
/// of range, ...) aborts: the fuzzer reports it. After computeCenterlines
/// and computeSections, which may refuse with a vv::Error, the later steps
/// must not throw at all (their arguments are in range).
[[nodiscard]] Outcome feedAnalysis(Bytes bytes);

/// study: the depth-judgement study's files (defined in StudyBody.cpp,
/// which needs vv::study). First byte 'M': the rest is a study folder's
/// manifest.json (the folder holds stimuli/a.png ... h.png), read with
/// readManifest, planned for three participants (each plan must be the
/// main block's images, each once) and, up to 40 main images, run through
/// StudyRun to the end with every answer saved. Anything else: the rest
/// is a results file through analyseResultsFiles (accuracies in [0, 1],
/// p values in [0, 1], corrected ones not below their p). A broken
/// promise aborts.
[[nodiscard]] Outcome feedStudy(Bytes bytes);

/// At most this many vertices and triangles of a compact mesh are read.
inline constexpr std::size_t kAnalysisMaxVertices = 2048;
inline constexpr std::size_t kAnalysisMaxTriangles = 4096;
inline constexpr double kAnalysisBudgetSeconds = 5.0;

/// The compact mesh of the analysis target, little endian:
///   byte 0   not 'S' or 'P' (encodeAnalysisInput writes 'M')
///   byte 1   options: bits 0-2 the step (kAnalysisSteps), bit 3 a source
///            point follows, bit 4 a target point follows
///   u16      vertex count V, u16 triangle count T
///   [3 x f32 source] [3 x f32 target]
///   V x 3 x f32    vertex positions
///   T x 3 x u16    triangle indices (not checked against V)
/// Counts above the kAnalysis* limits, or above what the bytes hold, are cut.
/// The centreline options of a compact input (CenterlineOptions' stepMm,
/// source and one target).
struct AnalysisInput {
    std::uint8_t step = 0;  ///< index into kAnalysisSteps
    std::optional<std::array<float, 3>> source;
    std::optional<std::array<float, 3>> target;
};
/// The steps (mm) option bits 0-2 choose.
inline constexpr std::array<double, 8> kAnalysisSteps{0.5, 1.0, 2.0, 0.25, 5.0, 0.1, 10.0, 0.05};

/// `mesh` (positions and indices only) and `input` as a compact analysis
/// input (the seeds). Throws InvalidArgumentError for a mesh above the
/// kAnalysis* limits or a step index out of range.
[[nodiscard]] std::vector<std::uint8_t> encodeAnalysisInput(const scene::Mesh& mesh,
                                                            const AnalysisInput& input = {});

}  // namespace vv::fuzz
