// SPDX-License-Identifier: GPL-3.0-or-later
// The settle path of a view (issue 19): what happens between the camera
// stopping and the frame with the exact VSS and its AO, stage by stage, at
// several frame sizes side by side (sizes interleaved within each run).
//
// Per run and size: a fresh offscreen frame of the mesh (default view, VSS
// and AO on) with VV_PASS_FINISH=1, so each pass's time is its whole cost on
// llvmpipe (GlPassObserver), then the CPU stages of the exact solve on the
// frame's read-back depth, each timed alone: vss::solve, vss::fittedSlopes,
// vss::addNormalCoherence. Prints a Markdown table: median (min-max) ms.
//
//   xvfb-run -a settle_path MESH [--runs N] [--sizes 1280x720,1920x1080,3840x2160]
//                                [--ao-full-resolution 1]
// (--ao-full-resolution 1: the AO at full resolution at every size, as before
// issue 19, for an A/B in one build.)
#include <QGuiApplication>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <fstream>
#include <limits>
#include <map>
#include <string>
#include <vector>

#include "BenchTiming.h"
#include "vv/core/Parallel.h"
#include "vv/meshio/MeshLoader.h"
#include "vv/render/OffscreenRenderer.h"
#include "vv/vss/DepthNormalization.h"
#include "vv/vss/Shading.h"
#include "vv/vss/Vss.h"

namespace {

using vv::bench::millisecondsOf;

struct Size {
    int width = 0;
    int height = 0;
};

std::vector<Size> parseSizes(const std::string& text) {
    std::vector<Size> sizes;
    std::size_t at = 0;
    while (at < text.size()) {
        const std::size_t comma = std::min(text.find(',', at), text.size());
        Size s;
        if (std::sscanf(text.substr(at, comma - at).c_str(), "%dx%d", &s.width, &s.height) != 2 ||
            s.width < 1 || s.height < 1) {
            throw std::runtime_error("bad size list: " + text);
        }
        sizes.push_back(s);
        at = comma + 1;
    }
    return sizes;
}

/// "median (min-max)"
std::string summary(std::vector<double> v) {
    if (v.empty()) {
        return "-";
    }
    std::sort(v.begin(), v.end());
    char text[64];
    std::snprintf(text, sizeof text, "%.0f (%.0f-%.0f)", v[v.size() / 2], v.front(), v.back());
    return text;
}

std::string loadAverage() {
    std::ifstream in("/proc/loadavg");
    std::string a;
    std::string b;
    std::string c;
    in >> a >> b >> c;
    return a + " " + b + " " + c;
}

/// Stage name -> times, per size.
using Samples = std::map<std::string, std::vector<double>>;

void runOnce(const vv::scene::Scene& scene, const Size& size, bool aoFull, Samples& samples) {
    vv::render::OffscreenRenderer renderer;
    vv::render::OffscreenOptions options;
    options.width = size.width;
    options.height = size.height;
    if (aoFull) {
        options.display.ao.fullResolutionPixels = std::numeric_limits<long long>::max();
    }
    static_cast<void>(renderer.render(scene, options));
    double solvePass = 0.0;
    for (const auto& t : renderer.lastTimings()) {
        samples[t.pass].push_back(t.cpuMilliseconds);
        if (t.pass == "vss-solve") {
            solvePass = t.cpuMilliseconds;
        }
    }
    samples["upload"].push_back(std::max(0.0, solvePass - renderer.vssStatus().solveMilliseconds));

    const vv::Image<float> depth = renderer.lastLinearDepth();
    const vv::Image<std::uint8_t> mask = vv::vss::maskFromFiniteDepth(depth.view());
    vv::vss::VssResult result;
    samples["solve"].push_back(millisecondsOf(
        [&] { result = vv::vss::solve(depth.view(), mask.view(), vv::vss::VssOptions{}); }));
    vv::Image<glm::vec4> slopes;
    samples["slopes"].push_back(
        millisecondsOf([&] { slopes = vv::vss::fittedSlopes(result.height.view(), mask.view()); }));
    const double pixelScale = 2.0 * std::tan(0.5 * 30.0 * 3.14159265358979 / 180.0) / size.height;
    samples["coherence"].push_back(millisecondsOf([&] {
        vv::vss::addNormalCoherence(slopes, result.height.view(), mask.view(),
                                    vv::vss::SlopeScale{result.dmin, result.dmax, pixelScale});
    }));
    const std::size_t i = samples["solve"].size() - 1;
    const double settle = samples["depth-readback"].back() + samples["solve"][i] +
                          samples["slopes"][i] + samples["coherence"][i];
    samples["settle"].push_back(settle);
    samples["settle+gbuffer"].push_back(settle + samples["geometry"].back());
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 2) {
        std::fprintf(stderr, "usage: settle_path MESH [--runs N] [--sizes WxH,WxH,...]\n");
        return 2;
    }
    ::setenv("VV_PASS_FINISH", "1", 1);
    int runs = 3;
    bool aoFull = false;
    std::string sizeList = "1280x720,1920x1080,3840x2160";
    for (int i = 2; i + 1 < argc; i += 2) {
        if (std::strcmp(argv[i], "--runs") == 0) {
            runs = std::max(1, std::atoi(argv[i + 1]));
        } else if (std::strcmp(argv[i], "--ao-full-resolution") == 0) {
            aoFull = std::atoi(argv[i + 1]) != 0;
        } else if (std::strcmp(argv[i], "--sizes") == 0) {
            sizeList = argv[i + 1];
        }
    }
    QGuiApplication app(argc, argv);
    try {
        const std::vector<Size> sizes = parseSizes(sizeList);
        vv::scene::Scene scene = vv::meshio::loadScene({argv[1]});
        const std::string loadBefore = loadAverage();
        std::vector<Samples> samples(sizes.size());
        for (int r = 0; r < runs; ++r) {
            for (std::size_t s = 0; s < sizes.size(); ++s) {
                runOnce(scene, sizes[s], aoFull, samples[s]);
            }
        }
        std::printf("%d runs, %d worker threads, load average %s before, %s after\n\n", runs,
                    vv::workerCount(), loadBefore.c_str(), loadAverage().c_str());
        std::printf("| stage, ms: median (min-max) |");
        for (const Size& s : sizes) {
            std::printf(" %dx%d |", s.width, s.height);
        }
        std::printf("\n|---|");
        for (std::size_t s = 0; s < sizes.size(); ++s) {
            std::printf("---:|");
        }
        std::printf("\n");
        const std::vector<std::pair<std::string, std::string>> rows = {
            {"geometry", "G-buffer (geometry pass)"},
            {"depth-readback", "read-back (depth-readback)"},
            {"solve", "solve (vss::solve)"},
            {"slopes", "slopes (vss::fittedSlopes)"},
            {"coherence", "coherence (vss::addNormalCoherence)"},
            {"settle", "**settle path**: read-back + solve + slopes + coherence"},
            {"settle+gbuffer", "settle path + G-buffer"},
            {"upload", "upload of height + slopes (vss-solve pass - solve)"},
            {"vessel-shading", "vessel-shading"},
            {"vss-shading", "showing frame: vss-shading"},
            {"composite", "composite"},
            {"ssao", "AO frame: ssao"},
            {"ao-blur", "ao-blur"},
            {"fxaa", "fxaa"},
        };
        for (const auto& [key, label] : rows) {
            std::printf("| %s |", label.c_str());
            for (Samples& sample : samples) {
                std::printf(" %s |", summary(sample[key]).c_str());
            }
            std::printf("\n");
        }
    } catch (const std::exception& e) {
        std::fprintf(stderr, "settle_path: %s\n", e.what());
        return 1;
    }
    return 0;
}
