// SPDX-License-Identifier: GPL-3.0-or-later
// vv_fuzz_seeds OUTDIR: writes the seed inputs made by our own generators
// (scripts/fuzz copies them into build/fuzz/corpus/<target>/ together with
// tests/reliability's corrupt corpus, fuzz/seeds/ and pydicom's test files;
// the session seeds are files in fuzz/seeds/session/):
//   OUTDIR/dicom/    two slices of a small demo CT series (writeCtSeries)
//   OUTDIR/vtp/      a small demo vessel tree (writeVtp: binary, appended)
//   OUTDIR/pfm/      small grayscale PFMs (writePfm, plus a big-endian one)
//   OUTDIR/analysis/ small tube and bifurcation phantoms (~200 to ~1000
//                    triangles) as compact meshes (encodeAnalysisInput), one
//                    with a given source and target, two disjoint tubes, and
//                    a tube as an 'S' + binary STL and a 'P' + PLY input
#include <array>
#include <cmath>
#include <cstdint>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "FuzzBodies.h"
#include "vv/core/Image.h"
#include "vv/demo/BifurcationPhantom.h"
#include "vv/demo/DemoCtSeries.h"
#include "vv/demo/DemoTree.h"
#include "vv/demo/TubePhantom.h"
#include "vv/dicom/SeriesWriter.h"
#include "vv/meshio/MeshWriter.h"
#include "vv/vss/Pfm.h"

namespace fs = std::filesystem;

namespace {

void writeBytes(const fs::path& file, const std::string& bytes) {
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    if (!out) {
        throw std::runtime_error("cannot write " + file.string());
    }
}

void dicomSeeds(const fs::path& dir) {
    vv::demo::DemoCtOptions options;
    options.dims = {8, 8, 8};
    options.generations = 1;
    const vv::demo::DemoCt ct = vv::demo::generateDemoCt(options);
    const fs::path series = dir / "series";
    static_cast<void>(vv::dicom::writeCtSeries(series, ct.volume));
    // Two slices are enough: every slice has the same structure.
    fs::copy_file(series / "slice0.dcm", dir / "demo-slice0.dcm",
                  fs::copy_options::overwrite_existing);
    fs::copy_file(series / "slice4.dcm", dir / "demo-slice4.dcm",
                  fs::copy_options::overwrite_existing);
    fs::remove_all(series);
}

void vtpSeeds(const fs::path& dir) {
    vv::demo::DemoTreeOptions options;
    options.generations = 1;
    options.voxelSizeMm = 2.0;
    vv::meshio::writeVtp(vv::demo::generateDemoMesh(options), dir / "demo-tree.vtp");
}

void pfmSeeds(const fs::path& dir) {
    vv::Image<float> small(3, 2);
    for (int y = 0; y < 2; ++y) {
        for (int x = 0; x < 3; ++x) {
            small(x, y) = static_cast<float>(x + 10 * y);
        }
    }
    vv::vss::writePfm(dir / "small.pfm", std::as_const(small).view());
    vv::Image<float> odd(1, 4);
    odd(0, 0) = std::numeric_limits<float>::quiet_NaN();
    odd(0, 1) = std::numeric_limits<float>::infinity();
    odd(0, 2) = -0.0F;
    odd(0, 3) = 1e30F;
    vv::vss::writePfm(dir / "non-finite.pfm", std::as_const(odd).view());
    // Big endian (positive scale), 2 x 1: 1.0 and -2.0.
    writeBytes(dir / "big-endian.pfm",
               std::string("Pf\n2 1\n1.0\n") + std::string("\x3f\x80\x00\x00\xc0\x00\x00\x00", 8));
}

void writeBytes(const fs::path& file, const std::vector<std::uint8_t>& bytes) {
    writeBytes(file, std::string(bytes.begin(), bytes.end()));
}

vv::scene::Mesh tube(vv::demo::TubeShape shape, std::size_t triangles, bool capped) {
    vv::demo::TubePhantomOptions options;
    options.shape = shape;
    options.radiusMm = 2.0;
    options.lengthMm = 20.0;
    options.bendRadiusMm = 10.0;
    options.stenosisLengthMm = 8.0;
    options.targetTriangles = triangles;
    options.capped = capped;
    return vv::demo::makeTubePhantom(options).mesh;
}

/// `mesh` as a file of the type `extension` names, behind the selector byte.
void fileSeed(const vv::scene::Mesh& mesh, const fs::path& file, char selector) {
    const fs::path scratch = file.parent_path() / ("scratch" + file.extension().string());
    vv::meshio::writeMeshFile(mesh, scratch);
    std::ifstream in(scratch, std::ios::binary);
    const std::string content{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    in.close();
    fs::remove(scratch);
    writeBytes(file, selector + content);
}

void analysisSeeds(const fs::path& dir) {
    using vv::demo::TubeShape;
    using vv::fuzz::encodeAnalysisInput;
    const vv::scene::Mesh cylinder = tube(TubeShape::Cylinder, 200, false);
    writeBytes(dir / "cylinder-open.mesh", encodeAnalysisInput(cylinder));
    writeBytes(dir / "cylinder-capped.mesh",
               encodeAnalysisInput(tube(TubeShape::Cylinder, 300, true), {.step = 1}));
    writeBytes(dir / "bend.mesh", encodeAnalysisInput(tube(TubeShape::TorusSegment, 600, false)));
    writeBytes(dir / "stenosis.mesh",
               encodeAnalysisInput(tube(TubeShape::Stenosis, 1000, false), {.step = 3}));
    writeBytes(dir / "cylinder-given-ends.mesh",
               encodeAnalysisInput(cylinder, {.step = 1,
                                              .source = std::array{0.0F, 0.0F, 0.0F},
                                              .target = std::array{0.0F, 0.0F, 20.0F}}));
    vv::scene::Mesh twoTubes = cylinder;
    const auto offset = static_cast<std::uint32_t>(cylinder.positions.size());
    for (const glm::vec3& p : cylinder.positions) {
        twoTubes.positions.push_back(p + glm::vec3(10.0F, 0.0F, 0.0F));
    }
    for (const std::uint32_t i : cylinder.indices) {
        twoTubes.indices.push_back(i + offset);
    }
    writeBytes(dir / "two-disjoint-tubes.mesh", encodeAnalysisInput(twoTubes));
    vv::demo::BifurcationPhantomOptions y;
    y.parentRadiusMm = 2.0;
    y.parentLengthMm = 10.0;
    y.daughterLengthMm = 10.0;
    y.targetTriangles = 1000;
    writeBytes(dir / "bifurcation.mesh",
               encodeAnalysisInput(vv::demo::makeBifurcationPhantom(y).mesh));
    fileSeed(cylinder, dir / "cylinder.stl", 'S');
    fileSeed(cylinder, dir / "cylinder.ply", 'P');
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        std::cerr << "usage: vv_fuzz_seeds OUTDIR\n";
        return 2;
    }
    try {
        const fs::path out = argv[1];
        for (const char* sub : {"dicom", "vtp", "pfm", "analysis"}) {
            fs::create_directories(out / sub);
        }
        dicomSeeds(out / "dicom");
        vtpSeeds(out / "vtp");
        pfmSeeds(out / "pfm");
        analysisSeeds(out / "analysis");
    } catch (const std::exception& e) {
        std::cerr << "vv_fuzz_seeds: " << e.what() << "\n";
        return 1;
    }
    return 0;
}
