// SPDX-License-Identifier: GPL-3.0-or-later
// planning_profile: the time from "Find Centrelines" to the first diameter
// profile on screen (issue 35), against the analysis alone on the same
// surface: what the GUI adds on top of the analysis (handing the result
// over, the tables, the profile, the overlay, one frame). Interleaved
// rounds; a table of medians and ranges. A GoogleTest program (the GUI
// tests' fixture), run by hand like demo_rotation, not by ctest: it
// measures. docs/benchmarks/analysis.md has the command and the table:
//
//   xvfb-run -a -s "-screen 0 1920x1080x24" env QT_QPA_PLATFORM=xcb
//     [VV_BENCH_ROUNDS=5] build/release/bench/planning_profile
#include <gtest/gtest.h>

#include <QElapsedTimer>
#include <algorithm>
#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

#include "GuiFixture.h"
#include "gui/analysis/DiameterProfile.h"
#include "gui/analysis/PlanningState.h"
#include "gui/panels/AnalysisPanel.h"
#include "vv/analysis/Sections.h"
#include "vv/core/NumberText.h"
#include "vv/meshio/MeshLoader.h"

namespace {

using PlanningProfile = vv::test::GuiFixture;

struct Spread {
    double median = 0.0;
    double low = 0.0;
    double high = 0.0;
};

Spread spread(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return {v[v.size() / 2], v.front(), v.back()};
}

TEST_F(PlanningProfile, TimeToTheFirstProfileAgainstTheAnalysisAlone) {
    const char* rounds = std::getenv("VV_BENCH_ROUNDS");
    const int n = rounds != nullptr ? std::max(1, std::atoi(rounds)) : 5;
    const auto scene = std::make_shared<vv::scene::Scene>(
        vv::meshio::loadScene({std::filesystem::path(VV_DEMO_VTP)}, {}));
    ASSERT_FALSE(scene->meshes.empty());
    window_->resize(1280, 800);
    window_->setScene(scene, QStringLiteral("demo"));
    ASSERT_TRUE(waitForFrames());
    vv::gui::panels::AnalysisPanel* panel = window_->analysisPanel();
    std::vector<double> alone;
    std::vector<double> gui;
    std::vector<double> over;
    std::vector<double> worker;
    for (int round = 0; round < n; ++round) {
        QElapsedTimer timer;
        timer.start();
        const auto analysed = vv::analysis::analyseVessels(scene->meshes.front());
        alone.push_back(static_cast<double>(timer.nsecsElapsed()) * 1e-9);
        ASSERT_FALSE(analysed.tree.branches.empty());

        window_->setScene(scene, QStringLiteral("demo"));  // clears the last analysis
        ASSERT_TRUE(waitForFrames());
        // The view settled (exact VSS, then occlusion): nothing left to draw
        // but what the analysis's arrival asks for.
        ASSERT_TRUE(waitForVss());
        ASSERT_TRUE(vv::test::waitUntil([&] { return !window_->viewer()->occlusionDeferred(); }));
        const quint64 frames = window_->viewer()->framesWithScene();
        timer.restart();
        panel->findCenterlines();
        // The GUI thread stays free: frames go on while the worker runs.
        ASSERT_TRUE(vv::test::waitUntil(
            [&] {
                return window_->planning()->hasAnalysis() &&
                       !window_->planning()->profile().empty() &&
                       window_->diameterProfile()->isVisible();
            },
            600000));
        const quint64 shown = window_->viewer()->framesWithScene();
        window_->viewer()->update();
        ASSERT_TRUE(vv::test::waitUntil(
            [&] { return window_->viewer()->framesWithScene() > shown; }, 60000));
        gui.push_back(static_cast<double>(timer.nsecsElapsed()) * 1e-9);
        over.push_back(gui.back() - alone.back());
        worker.push_back(panel->lastWorkSeconds());
        std::cout << "round " << round + 1 << ": analysis alone " << vv::fixedText(alone.back(), 3)
                  << " s, in the GUI's worker " << vv::fixedText(worker.back(), 3)
                  << " s, to the first profile " << vv::fixedText(gui.back(), 3) << " s ("
                  << shown - frames << " frames meanwhile)\n";
    }
    const Spread a = spread(alone);
    const Spread g = spread(gui);
    const Spread o = spread(over);
    const auto row = [](const char* what, const Spread& s) {
        std::cout << "| " << what << " | " << vv::fixedText(s.median, 3) << " s | "
                  << vv::fixedText(s.low, 3) << "-" << vv::fixedText(s.high, 3) << " s |\n";
    };
    std::cout << "\n| demo tree (" << scene->meshes.front().triangleCount() << " triangles), " << n
              << " rounds | median | range |\n|---|---|---|\n";
    row("analysis alone (analyseVessels)", a);
    row("the same on the GUI's worker, frames drawn meanwhile", spread(worker));
    row("Find Centrelines to the profile and one frame", g);
    row("over the analysis alone", o);
    std::vector<double> after;
    for (std::size_t i = 0; i < gui.size(); ++i) {
        after.push_back(gui[i] - worker[i]);
    }
    row("after the worker: hand-over, tables, profile, one frame", spread(after));
}

}  // namespace
