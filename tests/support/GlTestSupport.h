// SPDX-License-Identifier: GPL-3.0-or-later
// What every OpenGL test needs (render, report and GUI test folders): the
// process-wide QGuiApplication, an offscreen renderer or a failure saying why
// there is none, and a bare OpenGL 4.1 core context.
#pragma once

#include <QOffscreenSurface>
#include <QOpenGLContext>
#include <memory>

#include "vv/render/OffscreenRenderer.h"

namespace vv::test {

/// Creates the process-wide QGuiApplication once (kept until the process
/// ends). Without any display it picks Qt's offscreen platform, so that the
/// tests fail saying OpenGL is missing instead of xcb aborting the process.
void ensureGuiApplication();

/// An offscreen renderer, or null after a test failure saying that there is
/// no OpenGL 4.1 (run under xvfb-run -a with QT_QPA_PLATFORM=xcb).
[[nodiscard]] std::unique_ptr<render::OffscreenRenderer> makeOffscreenRenderer();

/// Creates `surface` and `context` for OpenGL 4.1 core and makes the context
/// current; false when the platform has none (e.g. no display).
[[nodiscard]] bool makeGl41Current(QOffscreenSurface& surface, QOpenGLContext& context);

}  // namespace vv::test
