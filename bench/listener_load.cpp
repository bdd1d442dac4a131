// SPDX-License-Identifier: GPL-3.0-or-later
// listener_load: the DICOM listener (storage SCP) under load (issue 31).
// Prints a Markdown table (docs/benchmarks/listener.md) of:
//  (a) a configured node's 34-instance store on an idle listener,
//  (b) the same with 200 idle connections held open from 127.0.0.2 (an
//      address that is no configured node), and the ratio (b)/(a),
//  (c) ten configured nodes storing 34 instances each at once,
//  (d) one huge instance (--big-gb, default 2 GB) sent to
//      `vesselview-cli pacs listen` in a child process: the time, the
//      listener's answer, the child's peak memory growth (VmHWM, reset
//      through /proc/<pid>/clear_refs, minus VmRSS before) and whether it
//      serves the next association.
// (a) to (c) run the listener (vv::pacs::StorageScp) in this process; every
// wait is bounded (a listener that serves one association at a time makes
// (b) time out, it does not hang).
//
//   listener_load [--quick] [--big-gb N] [--dir DIR] [--cli PATH]
//
// --quick: 128 x 128 slices and a 0.2 GB instance (default 512 x 512, 2 GB).
// DIR (default a folder in the temporary directory) holds the series, the
// stores and the huge file; it is removed at the end.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "ListenerPeers.h"
#include "WaitUntil.h"
#include "vv/core/ProcessMemory.h"
#include "vv/demo/DemoCtSeries.h"
#include "vv/dicom/SeriesWriter.h"
#include "vv/pacs/Echo.h"
#include "vv/pacs/LocalStore.h"
#include "vv/pacs/Send.h"
#include "vv/pacs/StorageScp.h"

namespace {

namespace fs = std::filesystem;
using namespace vv::pacs;
using Clock = std::chrono::steady_clock;
using vv::bench::storedInstances;

constexpr const char* kListenerAe = "VVBENCH";
constexpr int kSlices = 34;
constexpr int kIdle = 200;
constexpr int kNodes = 10;

struct Options {
    bool quick = false;
    double bigGb = 2.0;
    fs::path dir;
    fs::path cli = VV_CLI_EXE;
};

/// What one association came to.
struct Transfer {
    double seconds = 0.0;
    std::size_t accepted = 0;
    std::size_t sent = 0;
    std::uint16_t lastStatus = 0;
    std::string problem;  ///< the exception's message when it failed
};

Transfer timedSend(const LocalAe& me, const Node& node, const std::vector<fs::path>& files) {
    Transfer t;
    const auto start = Clock::now();
    try {
        for (const SendStatus& s : sendFiles(me, node, files)) {
            t.accepted += s.accepted ? 1 : 0;
            t.lastStatus = s.status;
            ++t.sent;
        }
    } catch (const std::exception& e) {
        t.problem = e.what();
    }
    t.seconds = std::chrono::duration<double>(Clock::now() - start).count();
    return t;
}

/// A sender with bounded, generous waits.
LocalAe sender(const std::string& aeTitle) {
    return LocalAe{aeTitle, Timeouts{10, 30, 60}};
}

ListenerConfig listenerConfig(const std::vector<std::string>& senders) {
    ListenerConfig config;
    config.aeTitle = kListenerAe;
    config.port = vv::bench::RawServer().port();
    for (const std::string& ae : senders) {
        config.allowedPeers.push_back(Node{ae, "127.0.0.1", 104, {}});
    }
    config.limits.requestSeconds = 2;
    config.limits.maxConnectionsPerAddress = 2 * kNodes;
    return config;
}

Node nodeOf(const ListenerConfig& config) {
    return Node{kListenerAe, "127.0.0.1", config.port, {}};
}

std::string format(const char* pattern, double value) {
    char text[64];
    std::snprintf(text, sizeof text, pattern, value);
    return text;
}

std::string hex(std::uint16_t status) {
    char text[16];
    std::snprintf(text, sizeof text, "0x%04X", status);
    return text;
}

std::string outcome(const Transfer& t) {
    if (!t.problem.empty()) {
        return "failed after " + format("%.1f s", t.seconds) + ": " + t.problem;
    }
    return std::to_string(t.accepted) + " of " + std::to_string(t.sent) + " accepted";
}

struct Row {
    std::string what;
    std::string figure;
    std::string note;
};

/// The median of `runs` stores of `files` by NODE0, each to a new listener
/// and store; `withIdle`: while 200 idle connections from 127.0.0.2 are held
/// open (`note` then says what the listener made of them).
Transfer medianStore(const Options& o, const std::vector<fs::path>& files, int runs, bool withIdle,
                     std::string& note) {
    std::vector<Transfer> all;
    for (int run = 0; run < runs; ++run) {
        const fs::path root = o.dir / ("store-" + std::to_string(run));
        fs::remove_all(root);
        LocalStore store(root);
        const ListenerConfig config = listenerConfig({"NODE0"});
        StorageScp listener(store, config);
        std::vector<vv::bench::Connection> idle;
        if (withIdle) {
            idle = vv::bench::idleConnections("127.0.0.2", config.port, kIdle);
            // Until the listener has closed all it does not keep (a stranger
            // keeps 2); bounded, as a listener that counts nothing never gets there.
            (void)vv::test::pollUntil(
                [&] {
                    const ListenerStats s = listener.stats();
                    return s.refusedConnections + s.droppedConnections >= kIdle - 2;
                },
                std::chrono::seconds(10));
        }
        all.push_back(timedSend(sender("NODE0"), nodeOf(config), files));
        const ListenerStats s = listener.stats();
        note = std::to_string(s.refusedConnections) + " refused, " +
               std::to_string(s.droppedConnections) + " dropped, " +
               std::to_string(s.openConnections) + " open after the store";
        idle.clear();
        if (!all.back().problem.empty()) {
            break;  // one failure (a timeout) is enough
        }
    }
    std::sort(all.begin(), all.end(),
              [](const Transfer& a, const Transfer& b) { return a.seconds < b.seconds; });
    return all[all.size() / 2];
}

/// The same synthetic CTA (the voxelised demo tree, `side` x `side` x 34)
/// written as ten series, one per node (patients VV-BENCH-0..9).
std::vector<std::vector<fs::path>> writeSeries(const fs::path& dir, int side) {
    vv::demo::DemoCtOptions ctOptions;
    ctOptions.dims = {side, side, kSlices};
    const vv::demo::DemoCt ct = vv::demo::generateDemoCt(ctOptions);
    std::vector<std::vector<fs::path>> series;
    series.reserve(kNodes);
    for (int i = 0; i < kNodes; ++i) {
        vv::dicom::CtSeriesWriteOptions w;
        w.patientId = "VV-BENCH-" + std::to_string(i);
        const fs::path folder = dir / ("series-" + std::to_string(i));
        (void)vv::dicom::writeCtSeries(folder, ct.volume, w);
        std::vector<fs::path> files;
        for (const auto& e : fs::directory_iterator(folder)) {
            files.push_back(e.path());
        }
        std::sort(files.begin(), files.end());
        series.push_back(files);
    }
    return series;
}

/// (a), (b) and their ratio.
void idleAndBusy(const Options& o, const std::vector<fs::path>& files, std::vector<Row>& rows) {
    std::string note;
    const Transfer idle = medianStore(o, files, 3, false, note);
    rows.push_back({"(a) 34-instance store, idle listener (median of 3)",
                    idle.problem.empty() ? format("%.2f s", idle.seconds) : "—", outcome(idle)});
    std::fprintf(stderr, "(a) %.2f s\n", idle.seconds);
    const Transfer busy = medianStore(o, files, 3, true, note);
    rows.push_back({"(b) the same, 200 idle connections from 127.0.0.2 held open (median of 3)",
                    busy.problem.empty() ? format("%.2f s", busy.seconds) : "—",
                    outcome(busy) + "; " + note});
    std::fprintf(stderr, "(b) %.2f s %s\n", busy.seconds, busy.problem.c_str());
    rows.push_back({"ratio (b) / (a) (goal: at most 2)",
                    busy.problem.empty() ? format("%.2f", busy.seconds / idle.seconds) : "—",
                    busy.problem.empty() ? "" : "(b) did not complete"});
}

/// (c): NODE0..9 each send their series at once.
void tenNodes(const Options& o, const std::vector<std::vector<fs::path>>& series,
              std::vector<Row>& rows) {
    LocalStore store(o.dir / "store-ten");
    std::vector<std::string> nodes;
    nodes.reserve(kNodes);
    for (int i = 0; i < kNodes; ++i) {
        nodes.push_back("NODE" + std::to_string(i));
    }
    const ListenerConfig config = listenerConfig(nodes);
    StorageScp listener(store, config);
    std::vector<Transfer> transfers(kNodes);
    const auto start = Clock::now();
    std::vector<std::thread> threads;
    threads.reserve(kNodes);
    for (std::size_t k = 0; k < kNodes; ++k) {
        threads.emplace_back(
            [&, k] { transfers[k] = timedSend(sender(nodes[k]), nodeOf(config), series[k]); });
    }
    for (std::thread& t : threads) {
        t.join();
    }
    const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
    const std::size_t expected = std::size_t{kNodes} * kSlices;
    const bool arrived = vv::test::pollUntil([&] { return storedInstances(store) == expected; },
                                             std::chrono::seconds(30));
    std::size_t accepted = 0;
    std::string problems;
    for (const Transfer& t : transfers) {
        accepted += t.accepted;
        if (!t.problem.empty()) {
            problems += "; " + t.problem;
        }
    }
    rows.push_back({"(c) ten nodes storing 34 instances each at once",
                    format("%.2f s", seconds) + ", " +
                        format("%.0f instances/s", static_cast<double>(accepted) / seconds),
                    std::string("all arrived: ") + (arrived ? "yes" : "no") + " (" +
                        std::to_string(storedInstances(store)) + " of " + std::to_string(expected) +
                        " stored)" + problems});
    std::fprintf(stderr, "(c) %.2f s\n", seconds);
}

/// (d): one huge instance (made from `model`) to `vesselview-cli pacs listen`
/// in a child process, whose memory we read.
void hugeInstance(const Options& o, const fs::path& model, std::vector<Row>& rows) {
    const auto side =
        static_cast<int>(std::lround(std::sqrt(o.bigGb * 1e9 / 2.0) / 2.0)) * 2;  // even
    const fs::path big = o.dir / "big.dcm";
    vv::bench::writeLargeImage(model, big, side);
    const double gb = static_cast<double>(fs::file_size(big)) / 1e9;
    std::fprintf(stderr, "(d) wrote %.2f GB (%d x %d)\n", gb, side, side);
    const std::uint16_t port = vv::bench::RawServer().port();
    vv::bench::ChildProcess child(
        o.cli.string(), {"pacs", "listen", "--store", (o.dir / "store-big").string(), "--port",
                         std::to_string(port), "--aet", kListenerAe, "--allow", "BENCH@127.0.0.1",
                         "--for", "1800", "--timeout", "120"});
    const auto started = child.readLine(60);
    if (!started || started->rfind("listening", 0) != 0) {
        throw std::runtime_error("the listener process did not start: " + started.value_or(""));
    }
    const auto before = vv::residentKiB(child.pid());
    const bool reset = vv::resetPeakResident(child.pid());
    const Node listener{kListenerAe, "127.0.0.1", port, {}};
    const Transfer huge = timedSend(LocalAe{"BENCH", Timeouts{10, 60, 300}}, listener, {big});
    const auto peak = vv::peakResidentKiB(child.pid());
    std::string next = "yes";
    try {
        echo(LocalAe{"BENCH", Timeouts{10, 30, 30}}, listener);
    } catch (const std::exception& e) {
        next = std::string("no: ") + e.what();
    }
    const double growthMb =
        before && peak ? (static_cast<double>(*peak) - static_cast<double>(*before)) / 1024.0
                       : std::nan("");
    std::string answer = outcome(huge);
    if (huge.problem.empty()) {
        answer += " (status " + hex(huge.lastStatus) + ")";
    }
    rows.push_back({format("(d) one %.2f GB instance to `pacs listen` (child process)", gb),
                    format("%.1f s", huge.seconds), answer});
    rows.push_back(
        {"(d) the listener process's peak memory growth (goal: under 100 MB)",
         format("%.0f MB", growthMb),
         std::string(reset ? "VmHWM reset before" : "VmHWM (not reset)") + " minus VmRSS before"});
    rows.push_back({"(d) it serves the next association (C-ECHO)", next, ""});
    if (!child.end(SIGTERM, 60)) {
        std::fprintf(stderr, "the listener process did not end on SIGTERM; killed\n");
    }
}

int run(const Options& o) {
    const int side = o.quick ? 128 : 512;
    fs::remove_all(o.dir);
    const auto series = writeSeries(o.dir, side);
    std::vector<Row> rows;
    idleAndBusy(o, series[0], rows);
    tenNodes(o, series, rows);
    hugeInstance(o, series[0][0], rows);

    std::printf("Slices %d x %d, 16 bit\n\n", side, side);
    std::printf("| Measurement | Figure | Note |\n|---|---|---|\n");
    for (const Row& r : rows) {
        std::printf("| %s | %s | %s |\n", r.what.c_str(), r.figure.c_str(), r.note.c_str());
    }
    fs::remove_all(o.dir);
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    try {
        Options o;
        for (int i = 1; i < argc; ++i) {
            const std::string a = argv[i];
            const bool hasValue = i + 1 < argc;
            if (a == "--quick") {
                o.quick = true;
                o.bigGb = 0.2;
            } else if (a == "--big-gb" && hasValue) {
                o.bigGb = std::stod(argv[++i]);
            } else if (a == "--dir" && hasValue) {
                o.dir = argv[++i];
            } else if (a == "--cli" && hasValue) {
                o.cli = argv[++i];
            } else {
                throw std::invalid_argument("unknown option or missing value: " + a);
            }
        }
        if (o.bigGb <= 0.0 || o.bigGb > 4.2) {
            throw std::invalid_argument("--big-gb must be above 0 and at most 4.2");
        }
        if (o.dir.empty()) {
            o.dir = fs::temp_directory_path() / "vv-listener-load";
        }
        return run(o);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "listener_load: %s\n", e.what());
        return 1;
    }
}
