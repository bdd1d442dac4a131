// SPDX-License-Identifier: GPL-3.0-or-later
// The whole vss::solve (normalisation, labelling and contours, the solver) on
// depth PFMs as `vesselview-cli render --depth-out` writes them, repeated in
// one process (issue 19: cost against image size on a loaded machine, where
// process CPU time is steadier than wall time). Prints one Markdown row per
// file and p: wall and CPU ms of the solve (median and min over the runs; the
// first run apart, it pays the first touches of a fresh process), the stage
// medians (wall), and the counters of the fast solver.
//
// With --previous A.pfm, each solve of FILE is given the solve of A (same
// solver) as its previous one (vss::solve's `previous`: the regions that did
// not change are taken from it); the column "taken from previous" says how
// many pixels were. With --max-error, the last column is the largest
// |z' - z'_brute| over every void pixel of the last run, against one solve by
// the brute solver (slow: minutes at 3840x2160); else "-".
//
//   vss_solve_pfm [--runs N] [--p 2,4,8] [--tol T] [--solver fast|brute] [--near-split]
//                 [--no-band-boxes] [--no-distance-table] [--max-error] [--previous A.pfm]
//                 FILE.pfm...
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "FastStats.h"
#include "MicroArgs.h"
#include "vv/core/Image.h"
#include "vv/vss/DepthNormalization.h"
#include "vv/vss/Pfm.h"
#include "vv/vss/Solver.h"
#include "vv/vss/Vss.h"

// printf: a benchmark's table for machines and people alike, in the C locale
// NOLINTBEGIN(cppcoreguidelines-pro-type-vararg)

namespace {

using namespace vv;

using vv::bench::median;
using vv::bench::parseList;

double minOf(const std::vector<double>& v) {
    return *std::min_element(v.begin(), v.end());
}

// The largest |a - b| over the void pixels (label >= 0) of a solve.
double maxVoidDifference(const vss::VssResult& a, const vss::VssResult& b) {
    double worst = 0.0;
    for (int y = 0; y < a.height.height(); ++y) {
        for (int x = 0; x < a.height.width(); ++x) {
            if (a.labels(x, y) >= 0) {
                worst = std::max(worst, std::abs(static_cast<double>(a.height(x, y)) -
                                                 static_cast<double>(b.height(x, y))));
            }
        }
    }
    return worst;
}

}  // namespace

int main(int argc, char** argv) {
    int runs = 5;
    std::vector<double> powers = {2.0, 4.0, 8.0};
    vss::SolverOptions options;
    std::vector<std::string> files;
    std::string previousFile;
    bool maxError = false;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        const bool more = i + 1 < argc;
        if (a == "--runs" && more) {
            runs = std::max(2, std::atoi(argv[++i]));
        } else if (a == "--p" && more) {
            powers = parseList(argv[++i]);
        } else if (a == "--tol" && more) {
            options.tolerance = std::atof(argv[++i]);
        } else if (a == "--solver" && more) {
            options.kind =
                std::string(argv[++i]) == "brute" ? vss::SolverKind::Brute : vss::SolverKind::Fast;
        } else if (a == "--near-split") {
            vv::vss::detail::setFastSolverNearSplitForTesting(true);
        } else if (a == "--no-band-boxes") {
            vv::vss::detail::setFastSolverBandBoxesForTesting(false);
        } else if (a == "--max-error") {
            maxError = true;
        } else if (a == "--no-distance-table") {
            vv::vss::detail::setFastSolverDistanceTableForTesting(false);
        } else if (a == "--previous" && more) {
            previousFile = argv[++i];
        } else if (!a.empty() && a[0] != '-') {
            files.push_back(a);
        } else {
            std::fprintf(
                stderr,
                "usage: vss_solve_pfm [--runs N] [--p 2,4,8] [--tol T] "
                "[--solver fast|brute] [--near-split] [--no-band-boxes] [--no-distance-table] "
                "[--max-error] "
                "[--previous A.pfm] FILE.pfm...\n");
            return 2;
        }
    }
    std::printf(
        "| file | size | p | first wall ms | wall ms (median) | wall ms (min) | cpu ms "
        "(median) | cpu ms (min) | normalize | regions | interpolate | M2L | near "
        "pairs/px | near-tile px | coarse px | near-box px | near-box points | band-box px | "
        "band exact px | band samples | table pairs | taken from previous | fall-back px | "
        "max error |\n");
    std::printf(
        "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|-"
        "--:|"
        "---:|---:|---:|---:|---:|\n");
    const Image<float> previousDepth =
        previousFile.empty() ? Image<float>() : vss::readPfm(previousFile);
    const Image<std::uint8_t> previousMask = vss::maskFromFiniteDepth(previousDepth.view());
    for (const std::string& file : files) {
        const Image<float> depth = vss::readPfm(file);
        const Image<std::uint8_t> mask = vss::maskFromFiniteDepth(depth.view());
        for (const double p : powers) {
            options.p = p;
            const auto solver = vss::makeSolver(options);
            std::optional<vss::VssResult> before;
            if (!previousFile.empty()) {
                before = vss::solve(previousDepth.view(), previousMask.view(), *solver, {});
            }
            const vss::PreviousSolve previous =
                before ? vss::PreviousSolve{before->height.view(), before->labels.view(),
                                            &before->regions}
                       : vss::PreviousSolve{};
            double takenShare = 0.0;
            std::vector<double> wall;
            std::vector<double> cpu;
            std::vector<double> norm;
            std::vector<double> regions;
            std::vector<double> interp;
            double first = 0.0;
            vv::vss::detail::FastSolverStats st{};
            std::optional<vss::VssResult> last;
            for (int k = 0; k < runs; ++k) {
                vv::vss::detail::resetFastSolverStats();
                const auto t0 = std::chrono::steady_clock::now();
                const std::clock_t c0 = std::clock();
                const vss::VssResult r = vss::solve(depth.view(), mask.view(), *solver, {}, {},
                                                    before ? &previous : nullptr);
                takenShare = 100.0 * static_cast<double>(r.stats.reusedPixels) /
                             static_cast<double>(std::max<std::int64_t>(1, r.stats.voidPixels));
                const double c = 1000.0 * static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC;
                const double t =
                    std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0)
                        .count();
                st = vv::vss::detail::fastSolverStats();
                if (k == runs - 1 && maxError) {
                    last = r;
                }
                if (k == 0) {
                    first = t;  // a fresh process: first touches of every buffer
                    continue;
                }
                wall.push_back(t);
                cpu.push_back(c);
                norm.push_back(r.stats.normalizeMs);
                regions.push_back(r.stats.regionsMs);
                interp.push_back(r.stats.interpolateMs);
            }
            std::string errText = "-";
            if (last) {
                vss::SolverOptions bo = options;
                bo.kind = vss::SolverKind::Brute;
                const vss::VssResult ref =
                    vss::solve(depth.view(), mask.view(), *vss::makeSolver(bo), {});
                std::array<char, 32> buf{};
                std::snprintf(buf.data(), buf.size(), "%.2e", maxVoidDifference(*last, ref));
                errText = buf.data();
            }
            const auto px = static_cast<double>(std::max<std::int64_t>(1, st.pixels));
            std::printf(
                "| %s | %dx%d | %g | %.1f | %.1f | %.1f | %.1f | %.1f | %.1f | %.1f | "
                "%.1f | %lld | %.1f | %.1f %% | %.1f %% | %.1f %% | %lld | %.1f %% | %.1f %% | "
                "%lld | %.1f %% | %.1f %% | %lld | %s |\n",
                file.c_str(), depth.width(), depth.height(), p, first, median(wall), minOf(wall),
                median(cpu), minOf(cpu), median(norm), median(regions), median(interp),
                static_cast<long long>(st.m2l), 16.0 * static_cast<double>(st.nearPairs) / px,
                100.0 * static_cast<double>(st.nearLeafPixels) / px,
                100.0 * static_cast<double>(st.coarsePixels) / px,
                100.0 * static_cast<double>(st.nearBoxPixels) / px,
                static_cast<long long>(st.nearBoxPoints),
                100.0 * static_cast<double>(st.bandBoxPixels) / px,
                100.0 * static_cast<double>(st.bandExactPixels) / px,
                static_cast<long long>(st.bandSamples),
                100.0 * static_cast<double>(st.tablePairs) /
                    static_cast<double>(std::max<std::int64_t>(1, st.nearPairs)),
                takenShare, static_cast<long long>(st.fallbackPixels), errText.c_str());
            std::fflush(stdout);
        }
    }
    return 0;
}

// NOLINTEND(cppcoreguidelines-pro-type-vararg)
