// SPDX-License-Identifier: GPL-3.0-or-later
#include "GlTestSupport.h"

#include <gtest/gtest.h>

#include <QGuiApplication>
#include <QSurfaceFormat>

#include "vv/core/Error.h"

namespace vv::test {

void ensureGuiApplication() {
    if (QGuiApplication::instance() != nullptr) {
        return;
    }
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM") && qEnvironmentVariableIsEmpty("DISPLAY") &&
        qEnvironmentVariableIsEmpty("WAYLAND_DISPLAY")) {
        qputenv("QT_QPA_PLATFORM", "offscreen");
    }
    static int argc = 1;
    static char name[] = "vv_tests";
    static char* argv[] = {name, nullptr};
    new QGuiApplication(argc, argv);  // Qt allows one application object: kept for the process
}

std::unique_ptr<render::OffscreenRenderer> makeOffscreenRenderer() {
    try {
        return std::make_unique<render::OffscreenRenderer>();
    } catch (const vv::Error& e) {
        ADD_FAILURE() << "no offscreen renderer (run under xvfb-run -a with "
                         "QT_QPA_PLATFORM=xcb): "
                      << e.what();
        return nullptr;
    }
}

bool makeGl41Current(QOffscreenSurface& surface, QOpenGLContext& context) {
    QSurfaceFormat format;
    format.setVersion(4, 1);
    format.setProfile(QSurfaceFormat::CoreProfile);
    surface.setFormat(format);
    surface.create();
    context.setFormat(format);
    return context.create() && context.makeCurrent(&surface);
}

}  // namespace vv::test
