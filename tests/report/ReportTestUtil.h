// SPDX-License-Identifier: GPL-3.0-or-later
// Helpers of the report tests: a QGuiApplication, a per-process folder,
// small scenes, running tools.
#pragma once

#include <QImage>
#include <filesystem>
#include <memory>
#include <string>

#include "GlTestSupport.h"
#include "vv/render/OffscreenRenderer.h"
#include "vv/scene/Mesh.h"

namespace vv::report::test {

using vv::test::ensureGuiApplication;
/// An offscreen renderer, or null after a test failure saying that there is
/// no OpenGL (run under xvfb-run -a, QT_QPA_PLATFORM=xcb).
inline std::unique_ptr<render::OffscreenRenderer> makeRenderer() {
    return vv::test::makeOffscreenRenderer();
}

/// A fresh folder for this process under VV_TEST_TMP/report/<name>.
std::filesystem::path testDir(const std::string& name);

/// An open tube of radius 1 along x (0 .. 20), axis on the x axis, with point
/// array "wss" (unit Pa) rising linearly from 0 at x = 0 to 10 at x = 20.
scene::Mesh makeTube(const std::string& name);

/// A view-like test image (gradient), width x height, RGB32.
QImage testImage(int width, int height);

/// Runs `command` through the shell; its exit status, its stdout + stderr in `output`.
int runTool(const std::string& command, std::string& output);

/// True when `tool` is on PATH.
bool haveTool(const std::string& tool);

/// Names of the files in `dir`.
std::string listing(const std::filesystem::path& dir);

}  // namespace vv::report::test
