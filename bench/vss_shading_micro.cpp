// SPDX-License-Identifier: GPL-3.0-or-later
// Micro-benchmark of the exact solve path of a viewer frame (issue 4): the
// fast VSS solve of a depth image, then the lighting slopes
// (vss::fittedSlopes) and the normal coherence (vss::addNormalCoherence),
// each timed separately (median of runs). The depth comes from
// `vesselview-cli render ... --depth-out DEPTH.pfm`. Also prints a hash of
// the slopes with their coherence, to check a faster computation against
// the one before it bit for bit.
//
//   vss_shading_micro DEPTH.pfm [--runs N] [--pixel-scale S]
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <string>
#include <vector>

#include "BenchTiming.h"
#include "vv/core/Hash.h"
#include "vv/vss/DepthNormalization.h"
#include "vv/vss/Pfm.h"
#include "vv/vss/Shading.h"
#include "vv/vss/Vss.h"

namespace {

using vv::bench::millisecondsOf;

/// "median (min)" of v: the minimum is the steadier figure on a noisy machine.
std::string summary(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    char text[64];
    std::snprintf(text, sizeof text, "%.1f (%.1f)", v[v.size() / 2], v.front());
    return text;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 2) {
        std::fprintf(stderr, "usage: vss_shading_micro DEPTH.pfm [--runs N] [--pixel-scale S]\n");
        return 2;
    }
    int runs = 7;
    double pixelScale = 2.0 * std::tan(0.5 * 30.0 * 3.14159265358979 / 180.0) / 720.0;
    for (int i = 2; i + 1 < argc; i += 2) {
        if (std::strcmp(argv[i], "--runs") == 0) {
            runs = std::max(1, std::atoi(argv[i + 1]));
        } else if (std::strcmp(argv[i], "--pixel-scale") == 0) {
            pixelScale = std::atof(argv[i + 1]);
        }
    }
    try {
        const vv::Image<float> depth = vv::vss::readPfm(argv[1]);
        const vv::Image<std::uint8_t> mask = vv::vss::maskFromFiniteDepth(depth.view());
        std::vector<double> solveMs;
        std::vector<double> slopeMs;
        std::vector<double> coherenceMs;
        std::uint64_t hash = 0;
        for (int r = 0; r < runs; ++r) {
            vv::vss::VssResult result;
            solveMs.push_back(millisecondsOf([&] {
                result = vv::vss::solve(depth.view(), mask.view(), vv::vss::VssOptions{});
            }));
            vv::Image<glm::vec4> slopes;
            slopeMs.push_back(millisecondsOf(
                [&] { slopes = vv::vss::fittedSlopes(result.height.view(), mask.view()); }));
            coherenceMs.push_back(millisecondsOf([&] {
                vv::vss::addNormalCoherence(
                    slopes, result.height.view(), mask.view(),
                    vv::vss::SlopeScale{result.dmin, result.dmax, pixelScale});
            }));
            hash =
                vv::Hasher().bulk(slopes.data(), slopes.pixelCount() * sizeof(glm::vec4)).result();
        }
        std::printf(
            "| image | runs | solve ms | slopes ms | coherence ms |\n|---|---:|---:|---:|---:|\n");
        std::printf("| %dx%d | %d | %s | %s | %s |\n", depth.width(), depth.height(), runs,
                    summary(solveMs).c_str(), summary(slopeMs).c_str(),
                    summary(coherenceMs).c_str());
        // The same bits before and after a change of how they are computed.
        std::printf("slopes + coherence FNV: %016llx\n", static_cast<unsigned long long>(hash));
    } catch (const std::exception& e) {
        std::fprintf(stderr, "vss_shading_micro: %s\n", e.what());
        return 1;
    }
    return 0;
}
