// SPDX-License-Identifier: GPL-3.0-or-later
// vv_fuzz_seeds OUTDIR: writes the seed inputs made by our own generators
// (scripts/fuzz copies them into build/fuzz/corpus/<target>/ together with
// tests/reliability's corrupt corpus, fuzz/seeds/ and pydicom's test files;
// the session seeds are files in fuzz/seeds/session/):
//   OUTDIR/dicom/    two slices of a small demo CT series (writeCtSeries)
//   OUTDIR/vtp/      a small demo vessel tree (writeVtp: binary, appended)
//   OUTDIR/pfm/      small grayscale PFMs (writePfm, plus a big-endian one)
#include <cmath>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <string>
#include <utility>

#include "vv/core/Image.h"
#include "vv/demo/DemoCtSeries.h"
#include "vv/demo/DemoTree.h"
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

}  // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        std::cerr << "usage: vv_fuzz_seeds OUTDIR\n";
        return 2;
    }
    try {
        const fs::path out = argv[1];
        for (const char* sub : {"dicom", "vtp", "pfm"}) {
            fs::create_directories(out / sub);
        }
        dicomSeeds(out / "dicom");
        vtpSeeds(out / "vtp");
        pfmSeeds(out / "pfm");
    } catch (const std::exception& e) {
        std::cerr << "vv_fuzz_seeds: " << e.what() << "\n";
        return 1;
    }
    return 0;
}
