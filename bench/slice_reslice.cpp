// SPDX-License-Identifier: GPL-3.0-or-later
// slice_reslice: the time of a new slice of a big CT volume in the slice views
// (issue 20: "a new slice of a 512×512×600 CT within one frame"): reslicing
// (trilinear), the overlay's label reslice (nearest), window / level and the
// composed overlay image, per orientation, for an axis-aligned grid and an
// oblique, sheared one. Prints a Markdown table (docs/benchmarks/slices.md).
//
//   slice_reslice [--dims 512,512,600] [--slices N]
//
// Each row: N different slices spread over the stack (each a new slice, as
// when scrolling), median and worst wall time per step and for the whole.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <glm/gtc/matrix_transform.hpp>
#include <string>
#include <vector>

#include "BenchTiming.h"
#include "vv/core/Parallel.h"
#include "vv/scene/LabelMap.h"
#include "vv/scene/Volume.h"
#include "vv/slices/Reslice.h"
#include "vv/slices/SliceOverlay.h"
#include "vv/slices/SlicePlane.h"
#include "vv/slices/WindowLevel.h"

namespace {

using vv::slices::SliceOrientation;

glm::ivec3 parseDims(const std::string& text) {
    glm::ivec3 d{0};
    if (std::sscanf(text.c_str(), "%d,%d,%d", &d.x, &d.y, &d.z) != 3 || d.x < 2 || d.y < 2 ||
        d.z < 2) {
        std::fprintf(stderr, "--dims wants X,Y,Z (each >= 2)\n");
        std::exit(2);
    }
    return d;
}

// An Int16 CT-like volume: a smooth pattern of values in -1000..1000 HU
// (content does not change the reslicing cost), and a label map of a tube.
struct BenchVolume {
    vv::scene::Volume volume;
    vv::scene::LabelMap labels;
};

BenchVolume makeVolume(glm::ivec3 dims, const glm::dmat4& indexToWorld) {
    BenchVolume b{vv::scene::Volume(dims, vv::scene::VoxelType::Int16), {}};
    b.volume.setIndexToWorld(indexToWorld);
    b.volume.setModality("CT");
    auto voxels = b.volume.int16Voxels();
    b.labels.dims = dims;
    b.labels.indexToWorld = indexToWorld;
    b.labels.labels.assign(b.volume.voxelCount(), 0);
    vv::parallelFor(0, dims.z, 1, [&](long k0, long k1) {
        for (long k = k0; k < k1; ++k) {
            for (int j = 0; j < dims.y; ++j) {
                for (int i = 0; i < dims.x; ++i) {
                    const std::size_t n = b.volume.index(i, j, static_cast<int>(k));
                    voxels[n] = static_cast<std::int16_t>((i * 7 + j * 13 + k * 3) % 2000 - 1000);
                    const int di = i - dims.x / 2;
                    const int dj = j - dims.y / 2;
                    b.labels.labels[n] = di * di + dj * dj < 400 ? 1 : 0;
                }
            }
        }
    });
    return b;
}

struct Times {
    std::vector<double> reslice, labels, window, compose, total;
};

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}
double worst(const std::vector<double>& v) {
    return *std::max_element(v.begin(), v.end());
}

void runRow(const char* grid, const BenchVolume& b, SliceOrientation o, int slices) {
    const auto stack = vv::slices::sliceStack(b.volume, o);
    const vv::slices::Window window{300.0, 600.0};
    Times t;
    for (int s = 0; s < slices; ++s) {
        const int k = static_cast<int>((s + 0.5) / slices * stack.count);
        const auto plane = stack.planeAt(k);
        vv::Image<float> values;
        vv::Image<std::uint8_t> labels;
        vv::Image<std::uint8_t> gray;
        const double r =
            vv::bench::millisecondsOf([&] { values = vv::slices::reslice(b.volume, plane); });
        const double l =
            vv::bench::millisecondsOf([&] { labels = vv::slices::resliceLabels(b.labels, plane); });
        const double w = vv::bench::millisecondsOf(
            [&] { gray = vv::slices::applyWindow(values.view(), window); });
        const double c = vv::bench::millisecondsOf(
            [&] { (void)vv::slices::composeSlice(gray.view(), labels.view()); });
        t.reslice.push_back(r);
        t.labels.push_back(l);
        t.window.push_back(w);
        t.compose.push_back(c);
        t.total.push_back(r + l + w + c);
    }
    static const char* names[] = {"axial", "coronal", "sagittal"};
    std::printf(
        "| %s | %s | %d x %d | %.1f / %.1f | %.1f / %.1f | %.1f / %.1f | %.1f / %.1f | "
        "%.1f / %.1f |\n",
        grid, names[static_cast<int>(o)], stack.plane.width, stack.plane.height, median(t.reslice),
        worst(t.reslice), median(t.labels), worst(t.labels), median(t.window), worst(t.window),
        median(t.compose), worst(t.compose), median(t.total), worst(t.total));
}

}  // namespace

int main(int argc, char** argv) {
    glm::ivec3 dims{512, 512, 600};
    int slices = 15;
    for (int a = 1; a < argc; ++a) {
        const std::string arg = argv[a];
        if (arg == "--dims" && a + 1 < argc) {
            dims = parseDims(argv[++a]);
        } else if (arg == "--slices" && a + 1 < argc) {
            slices = std::max(1, std::atoi(argv[++a]));
        } else {
            std::fprintf(stderr, "usage: slice_reslice [--dims X,Y,Z] [--slices N]\n");
            return 2;
        }
    }
    const glm::dmat4 aligned = glm::scale(glm::dmat4(1.0), glm::dvec3(0.7, 0.7, 0.5));
    glm::dmat4 oblique = glm::rotate(glm::dmat4(1.0), glm::radians(20.0),
                                     glm::normalize(glm::dvec3(0.2, 0.1, 1.0))) *
                         aligned;
    oblique[2] += glm::dvec4(0.15, 0.0, 0.0, 0.0);  // gantry-tilt shear
    std::fprintf(stderr, "building %d x %d x %d volumes...\n", dims.x, dims.y, dims.z);
    std::printf(
        "%d x %d x %d Int16 volume, %d threads, %d new slices per row; "
        "ms median / worst\n\n",
        dims.x, dims.y, dims.z, vv::workerCount(), slices);
    std::printf("| grid | view | pixels | reslice | labels | window | overlay | total |\n");
    std::printf("|---|---|---|---|---|---|---|---|\n");
    for (const auto& [name, geometry] :
         {std::pair<const char*, glm::dmat4>{"axis-aligned", aligned},
          {"oblique+sheared", oblique}}) {
        const BenchVolume b = makeVolume(dims, geometry);
        for (const SliceOrientation o :
             {SliceOrientation::Axial, SliceOrientation::Coronal, SliceOrientation::Sagittal}) {
            runRow(name, b, o, slices);
        }
    }
    return 0;
}
