// SPDX-License-Identifier: GPL-3.0-or-later
// Micro-benchmark of the fast VSS solver (issue 3), self-contained: synthetic
// 1280x720 vessel-tree masks in three framings like the paper's views (Far:
// inside the image; Medium: touching the border; Close: crossing it often),
// its own labelling / contours, timings of the fast solver (median of runs)
// against a simple float brute force, and the max error against an exact
// double-precision reference on a pixel sample.
//
//   vss_fast_micro [--runs N] [--p 2,4,8,64] [--tol T] [--views far,medium,close]
//                  [--brute] [--sample K] [--budget-scale F] [--size WxH] [--no-coarse]
//                  [--no-near-boxes] [--near-split]
// --size scales the views with the width (default 1280x720).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <limits>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "FastKernel.h"
#include "FastSolver.h"
#include "FastStats.h"
#include "MicroArgs.h"
#include "vv/core/Image.h"
#include "vv/core/Parallel.h"
#include "vv/vss/Solver.h"
#include "vv/vss/VoidRegions.h"

namespace {

using namespace vv;
using namespace vv::vss;

struct Rng {
    std::uint64_t s;
    std::uint64_t next() {
        std::uint64_t z = (s += 0x9e3779b97f4a7c15ULL);
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
        return z ^ (z >> 31);
    }
    double uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }
};

struct Frame {
    Image<std::int32_t> labels;
    std::vector<VoidRegion> regions;
    long voidPixels = 0;
};

// A branching tree in a unit square, drawn with a view transform (scale, offset).
Frame makeFrame(int w, int h, double scale, double ox, double oy, std::uint64_t seed) {
    Image<std::uint8_t> mask(w, h, 0);
    Image<float> depth(w, h, 0.0F);
    Rng rng{seed};
    struct Br {
        double x, y, a, r, z;
        int d;
    };
    std::vector<Br> todo{{0.5, 1.0, -1.5707963, 0.016, 0.5, 0}};
    while (!todo.empty()) {
        const Br b = todo.back();
        todo.pop_back();
        const double len = 0.1 + 0.14 * rng.uniform() * std::pow(0.85, b.d);
        const double x1 = b.x + len * std::cos(b.a);
        const double y1 = b.y + len * std::sin(b.a);
        const double z1 = std::clamp(b.z + (rng.uniform() - 0.5) * 0.3, 0.0, 1.0);
        // paint the segment in pixels
        const double px0 = ox + b.x * scale, py0 = oy + b.y * scale;
        const double px1 = ox + x1 * scale, py1 = oy + y1 * scale;
        const double rad = std::max(0.7, b.r * scale);
        const int bx0 = std::max(0, static_cast<int>(std::min(px0, px1) - rad - 1));
        const int bx1 = std::min(w - 1, static_cast<int>(std::max(px0, px1) + rad + 1));
        const int by0 = std::max(0, static_cast<int>(std::min(py0, py1) - rad - 1));
        const int by1 = std::min(h - 1, static_cast<int>(std::max(py0, py1) + rad + 1));
        const double vx = px1 - px0, vy = py1 - py0, l2 = vx * vx + vy * vy;
        for (int y = by0; y <= by1; ++y) {
            for (int x = bx0; x <= bx1; ++x) {
                double t = l2 > 0 ? ((x - px0) * vx + (y - py0) * vy) / l2 : 0.0;
                t = std::clamp(t, 0.0, 1.0);
                const double dx = x - (px0 + t * vx), dy = y - (py0 + t * vy);
                if (dx * dx + dy * dy <= rad * rad) {
                    mask(x, y) = 1;
                    depth(x, y) = static_cast<float>(b.z + t * (z1 - b.z));
                }
            }
        }
        if (b.d < 6) {
            const double spread = 0.35 + 0.35 * rng.uniform();
            todo.push_back({x1, y1, b.a - spread, b.r * 0.78, z1, b.d + 1});
            todo.push_back(
                {x1, y1, b.a + spread * (0.6 + 0.8 * rng.uniform()), b.r * 0.72, z1, b.d + 1});
        }
    }
    // The library's labelling and contours (tested in VoidRegionsTest).
    VoidRegionSet set = findVoidRegions(mask.view(), depth.view());
    Frame f;
    f.labels = std::move(set.labels);
    f.regions = std::move(set.regions);
    for (const VoidRegion& r : f.regions) {
        f.voidPixels += r.pixelCount;
    }
    return f;
}

double exactPixel(const VoidRegion& r, int x, int y, double p) {
    double dmin2 = std::numeric_limits<double>::infinity();
    for (const ContourPoint& c : r.contour) {
        const double dx = x - c.x, dy = y - c.y;
        dmin2 = std::min(dmin2, dx * dx + dy * dy);
    }
    double D = 0.0, N = 0.0;
    for (const ContourPoint& c : r.contour) {
        const double dx = x - c.x, dy = y - c.y;
        const double w = std::pow(dmin2 / (dx * dx + dy * dy), p / 2.0);
        D += w;
        N += w * c.z;
    }
    return N / D;
}

// The library's float brute force (every contour pixel, vectorised, threaded).
void bruteFrame(const Frame& f, double p, Image<float>& out) {
    SolverOptions o;
    o.kind = SolverKind::Brute;
    o.p = p;
    const auto solver = makeSolver(o);
    for (const VoidRegion& r : f.regions) {
        solver->solveRegion(f.labels.view(), r, out.view(), {});
    }
}

using vv::bench::median;
using vv::bench::parseList;

}  // namespace

int main(int argc, char** argv) {
    int runs = 5;
    std::vector<double> powers = {2.0, 4.0, 8.0, 64.0};
    double tol = 0.5 / 255.0;
    std::string views = "far,medium,close";
    bool brute = false;
    int sample = 4000;
    int w = 1280;
    int h = 720;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        const bool more = i + 1 < argc;
        if (a == "--runs" && more) {
            runs = std::atoi(argv[++i]);
        } else if (a == "--p" && more) {
            powers = parseList(argv[++i]);
        } else if (a == "--tol" && more) {
            tol = std::atof(argv[++i]);
        } else if (a == "--views" && more) {
            views = argv[++i];
        } else if (a == "--brute") {
            brute = true;
        } else if (a == "--sample" && more) {
            sample = std::atoi(argv[++i]);
        } else if (a == "--size" && more) {
            if (std::sscanf(argv[++i], "%dx%d", &w, &h) != 2 || w < 16 || h < 16) {
                std::fprintf(stderr, "vss_fast_micro: bad --size\n");
                return 2;
            }
        } else if (a == "--no-coarse") {
            detail::setFastSolverCoarseBoxesForTesting(false);
        } else if (a == "--no-near-boxes") {
            detail::setFastSolverNearBoxesForTesting(false);
        } else if (a == "--near-split") {
            detail::setFastSolverNearSplitForTesting(true);
        } else if (a == "--budget-scale" && more) {
            // test hook: a looser a-priori budget, to see how much slack the check has
            detail::setFastSolverBudgetScaleForTesting(std::atof(argv[++i]));
        } else {
            std::fprintf(stderr,
                         "usage: vss_fast_micro [--runs N] [--p 2,4,8] [--tol T] "
                         "[--views far,medium,close] [--brute] [--sample K] "
                         "[--budget-scale F] [--size WxH] [--no-coarse] [--no-near-boxes] "
                         "[--near-split]\n");
            return 2;
        }
    }
    const double zoom = w / 1280.0;
    struct View {
        const char* name;
        double scale, ox, oy;
    };
    const View all[] = {{"far", 560.0, 360.0, 100.0},
                        {"medium", 900.0, 190.0, -80.0},
                        {"close", 1700.0, -200.0, -700.0}};
    std::printf("kernel ISA: %s, threads: %d, tolerance %.3g\n", vv::vss::detail::leafKernelIsa(),
                vv::workerCount(), tol);
    std::printf(
        "| view | regions | max contour | void px | p | fast ms (median) | fast ms (min) | cpu ms "
        "(min) | max err (sample) | "
        "fallback px | M2L | near pairs/px | coarse px | near-tile px | near-box px | leaves |%s\n",
        brute ? " brute ms |" : "");
    std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|%s\n",
                brute ? "---|" : "");
    for (const View& v : all) {
        if (views.find(v.name) == std::string::npos) {
            continue;
        }
        const Frame f = makeFrame(w, h, v.scale * zoom, v.ox * zoom, v.oy * zoom, 12345);
        std::size_t maxContour = 0;
        for (const VoidRegion& r : f.regions) {
            maxContour = std::max(maxContour, r.contour.size());
        }
        std::vector<std::size_t> order(f.regions.size());
        for (std::size_t i = 0; i < order.size(); ++i) {
            order[i] = i;
        }
        std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
            return f.regions[a].pixelCount > f.regions[b].pixelCount;
        });
        const auto work = [&](std::size_t i) {
            return static_cast<double>(f.regions[i].pixelCount) *
                   static_cast<double>(std::max<std::size_t>(1, f.regions[i].contour.size()));
        };
        constexpr double kSmallPairs = 4.0e6;
        for (const double p : powers) {
            SolverOptions o;
            o.p = p;
            o.tolerance = tol;
            const auto solver = vv::vss::detail::makeFastSolver(o);
            Image<float> out(w, h, 0.0F);
            std::vector<double> times;
            std::vector<double> cpu;
            vv::vss::detail::FastSolverStats st{};
            for (int k = 0; k < runs; ++k) {
                vv::vss::detail::resetFastSolverStats();
                const auto t0 = std::chrono::steady_clock::now();
                const std::clock_t c0 = std::clock();
                // as the library's pipeline does: large regions one after the
                // other (parallel inside), small ones in parallel with each other
                std::size_t next = 0;
                for (; next < order.size() && work(order[next]) >= kSmallPairs; ++next) {
                    solver->solveRegion(f.labels.view(), f.regions[order[next]], out.view(), {});
                }
                vv::parallelFor(static_cast<long>(next), static_cast<long>(order.size()), 16,
                                [&](long b, long e) {
                                    for (long i = b; i < e; ++i) {
                                        solver->solveRegion(
                                            f.labels.view(),
                                            f.regions[order[static_cast<std::size_t>(i)]],
                                            out.view(), {});
                                    }
                                });
                cpu.push_back(1000.0 * static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC);
                times.push_back(
                    std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0)
                        .count());
                st = vv::vss::detail::fastSolverStats();
            }
            // error on a deterministic pixel sample
            Rng rng{99};
            double maxErr = 0.0;
            for (int k = 0; k < sample; ++k) {
                const int x = static_cast<int>(rng.next() % w);
                const int y = static_cast<int>(rng.next() % h);
                const std::int32_t id = f.labels(x, y);
                if (id < 0) {
                    continue;
                }
                const VoidRegion& r = f.regions[static_cast<std::size_t>(id)];
                maxErr = std::max(maxErr, std::abs(out(x, y) - exactPixel(r, x, y, p)));
            }
            std::string bruteCol;
            if (brute) {
                Image<float> bo(w, h, 0.0F);
                const auto t0 = std::chrono::steady_clock::now();
                bruteFrame(f, p, bo);
                char buf[64];
                std::snprintf(
                    buf, sizeof buf, " %.0f |",
                    std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0)
                        .count());
                bruteCol = buf;
            }
            std::printf(
                "| %s | %zu | %zu | %ld | %g | %.1f | %.1f | %.1f | %.2e | %lld | %lld | %.1f "
                "| %.1f %% | %.1f %% | %.1f %% | %lld |%s\n",
                v.name, f.regions.size(), maxContour, f.voidPixels, p, median(times),
                *std::min_element(times.begin(), times.end()),
                *std::min_element(cpu.begin(), cpu.end()), maxErr,
                static_cast<long long>(st.fallbackPixels), static_cast<long long>(st.m2l),
                16.0 * static_cast<double>(st.nearPairs) /
                    static_cast<double>(std::max<std::int64_t>(1, st.pixels)),
                100.0 * static_cast<double>(st.coarsePixels) /
                    static_cast<double>(std::max<std::int64_t>(1, st.pixels)),
                100.0 * static_cast<double>(st.nearLeafPixels) /
                    static_cast<double>(std::max<std::int64_t>(1, st.pixels)),
                100.0 * static_cast<double>(st.nearBoxPixels) /
                    static_cast<double>(std::max<std::int64_t>(1, st.pixels)),
                static_cast<long long>(st.leaves), bruteCol.c_str());
            std::fflush(stdout);
        }
    }
    return 0;
}
