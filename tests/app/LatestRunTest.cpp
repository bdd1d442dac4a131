// SPDX-License-Identifier: GPL-3.0-or-later
// LatestRun (app/gui/LatestRun.h), the GUI's one "newest answer wins" helper,
// under both of its policies: only the newest run's result is handed over,
// always through the event queue; destruction waits for the newest run
// (AtDestruction::Wait) or returns while it still works (Detach). Needs an
// event loop, no display.
#include <gtest/gtest.h>

#include <QCoreApplication>
#include <QEventLoop>
#include <array>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <functional>
#include <memory>
#include <mutex>
#include <stop_token>
#include <vector>

#include "WaitUntil.h"
#include "gui/LatestRun.h"

namespace vv::test {

/// The policies, named for the tests' names (outside the anonymous namespace).
struct LatestRunWaits {
    static constexpr gui::AtDestruction value = gui::AtDestruction::Wait;
};
struct LatestRunDetaches {
    static constexpr gui::AtDestruction value = gui::AtDestruction::Detach;
};

namespace {

using gui::AtDestruction;
using namespace std::chrono_literals;

/// Processes events until `done` holds or `bound` passed; returns `done()`.
bool processUntil(const std::function<bool()>& done, std::chrono::milliseconds bound = 10s) {
    return pollUntil(done, bound,
                     [] { QCoreApplication::processEvents(QEventLoop::AllEvents, 20); });
}

/// Gives a late result every chance to arrive (a dropped one must not).
void drainEvents() {
    static_cast<void>(processUntil([] { return false; }, 200ms));
}

/// Blocks a worker until released or stopped, as a silent peer or a long
/// computation does; says which ended it.
class Gate {
  public:
    /// Returns true when released, false when `stop` was requested first or
    /// a minute passed (the bound only keeps a broken program from hanging).
    bool pass(const std::stop_token& stop) {
        std::unique_lock lock(mutex_);
        entered_ = true;
        return changed_.wait_for(lock, stop, 60s, [this] { return open_; });
    }
    void open() {
        {
            const std::lock_guard lock(mutex_);
            open_ = true;
        }
        changed_.notify_all();
    }
    [[nodiscard]] bool entered() {
        const std::lock_guard lock(mutex_);
        return entered_;
    }

  private:
    std::mutex mutex_;
    std::condition_variable_any changed_;
    bool open_ = false;
    bool entered_ = false;
};

/// One QCoreApplication for the process: the results' event queue.
class EventLoopTest : public ::testing::Test {
  protected:
    static void SetUpTestSuite() {
        if (QCoreApplication::instance() == nullptr) {
            static int argc = 1;
            static std::array<char, 24> name{"vv_gui_latest_run_tests"};
            static std::array<char*, 2> argv{name.data(), nullptr};
            new QCoreApplication(argc, argv.data());  // kept for the whole process
        }
    }
};

template <typename Policy>
class LatestRunTest : public EventLoopTest {};

using Policies = ::testing::Types<LatestRunWaits, LatestRunDetaches>;
TYPED_TEST_SUITE(LatestRunTest, Policies);

TYPED_TEST(LatestRunTest, OnlyTheNewestRunsResultArrivesAndAStoppedRunsNever) {
    QObject owner;
    gui::LatestRun<int, TypeParam::value> run(&owner);
    std::vector<int> results;
    const auto keep = [&results](const int& result) { results.push_back(result); };
    // The first run works until it is stopped, as for a silent peer.
    auto first = std::make_shared<Gate>();
    std::atomic<bool> firstStopped{false};
    run.start(
        [first, &firstStopped](const std::stop_token& stop) {
            firstStopped = !first->pass(stop);
            return 1;
        },
        keep);
    EXPECT_TRUE(run.isRunning());
    // A newer one stops it; its result, not the first's, arrives.
    run.start([](const std::stop_token&) { return 2; }, keep);
    ASSERT_TRUE(processUntil([&] { return firstStopped.load() && !run.isRunning(); }));
    drainEvents();
    EXPECT_EQ(results, std::vector<int>{2});
    // A cancelled run's result never arrives, though its work ends normally.
    auto third = std::make_shared<Gate>();
    std::atomic<bool> thirdReturned{false};
    run.start(
        [third, &thirdReturned](const std::stop_token&) {
            third->pass({});
            thirdReturned = true;
            return 3;
        },
        keep);
    run.cancel();
    EXPECT_FALSE(run.isRunning());
    third->open();
    run.waitForFinished();
    EXPECT_TRUE(thirdReturned.load());
    drainEvents();
    EXPECT_EQ(results, std::vector<int>{2});
}

/// A run that has already ended by the time start() returns (a refused
/// connection ends in microseconds) still answers later, through the event
/// queue: else "Searching…", set just after starting, stayed on screen over
/// the answer (a CI failure of PacsBrowserGuiKillTest).
TYPED_TEST(LatestRunTest, AResultThatIsAlreadyThereArrivesLaterNeverInsideStart) {
    QObject owner;
    gui::LatestRun<int, TypeParam::value> run(&owner);
    std::vector<int> results;
    run.start([](const std::stop_token&) { return 9; },
              [&results](const int& result) { results.push_back(result); });
    run.waitForFinished();  // the work has returned; nothing was handed over yet
    EXPECT_TRUE(results.empty()) << "the result was handed over inside start()";
    EXPECT_TRUE(run.isRunning()) << "running until the result is handed over";
    ASSERT_TRUE(processUntil([&] { return !run.isRunning(); }));
    EXPECT_EQ(results, std::vector<int>{9});
}

/// `done` may start the next run (its watcher must survive its own signal).
TYPED_TEST(LatestRunTest, DoneMayStartTheNextRun) {
    QObject owner;
    gui::LatestRun<int, TypeParam::value> run(&owner);
    std::vector<int> results;
    std::function<void(int)> next = [&](int result) {
        results.push_back(result);
        if (result < 3) {
            run.start([result](const std::stop_token&) { return result + 1; }, next);
        }
    };
    run.start([](const std::stop_token&) { return 1; }, next);
    ASSERT_TRUE(processUntil([&] { return results.size() == 3 && !run.isRunning(); }));
    drainEvents();
    EXPECT_EQ(results, (std::vector<int>{1, 2, 3}));
}

/// A LatestRun that ends with a run under way hands nothing over.
TYPED_TEST(LatestRunTest, DestructionDropsTheResult) {
    QObject owner;
    bool called = false;
    {
        gui::LatestRun<int, TypeParam::value> run(&owner);
        run.start([](const std::stop_token&) { return 8; }, [&called](int) { called = true; });
    }
    drainEvents();
    EXPECT_FALSE(called);
}

class LatestRunPolicyTest : public EventLoopTest {};

/// Wait: the destructor returns only once the newest run's work has: that
/// work may read what its owner keeps until then.
TEST_F(LatestRunPolicyTest, WaitMakesTheDestructorWaitForTheNewestRun) {
    QObject owner;
    auto gate = std::make_shared<Gate>();
    auto returned = std::make_shared<std::atomic<bool>>(false);
    {
        gui::LatestRun<int, AtDestruction::Wait> run(&owner);
        run.start(
            [gate, returned](const std::stop_token& stop) {
                static_cast<void>(gate->pass(stop));  // until the destructor's stop
                *returned = true;
                return 1;
            },
            [](int) {});
        ASSERT_TRUE(pollUntil([&] { return gate->entered(); }, 10s));
    }
    EXPECT_TRUE(returned->load()) << "the destructor returned before the work";
}

/// Detach: the destructor returns while the newest run's work goes on (a
/// network connect a stop cannot end); its result is dropped.
TEST_F(LatestRunPolicyTest, DetachLetsTheDestructorReturnWhileTheRunWorks) {
    QObject owner;
    // The work ignores its stop token and waits for the test to let it go:
    // a destructor that waited for it would return only after the gate's
    // bound, with the work returned.
    auto gate = std::make_shared<Gate>();
    auto returned = std::make_shared<std::atomic<bool>>(false);
    bool called = false;
    {
        gui::LatestRun<int, AtDestruction::Detach> run(&owner);
        run.start(
            [gate, returned](const std::stop_token&) {
                static_cast<void>(gate->pass({}));
                *returned = true;
                return 1;
            },
            [&called](int) { called = true; });
        ASSERT_TRUE(pollUntil([&] { return gate->entered(); }, 10s));
    }
    EXPECT_FALSE(returned->load()) << "the destructor waited for the work";
    gate->open();
    ASSERT_TRUE(pollUntil([&] { return returned->load(); }, 10s));
    drainEvents();
    EXPECT_FALSE(called);
}

}  // namespace
}  // namespace vv::test
