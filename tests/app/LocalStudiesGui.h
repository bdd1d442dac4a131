// SPDX-License-Identifier: GPL-3.0-or-later
// Opening DICOM > Local Studies… in the GUI tests, as a user does.
#pragma once

#include <gtest/gtest.h>

#include <QAction>

#include "GuiFixture.h"
#include "gui/MainWindow.h"
#include "gui/pacs/LocalStudiesBrowser.h"

namespace vv::test {

/// Triggers DICOM > Local Studies… of `window` and waits (bounded) until the
/// browser is shown with its read of the store on screen; nullptr (and a
/// test failure) when no browser came.
inline gui::LocalStudiesBrowser* openLocalStudies(gui::MainWindow& window) {
    window.findChild<QAction*>(QStringLiteral("localStudies"))->trigger();
    auto* browser = window.findChild<gui::LocalStudiesBrowser*>();
    EXPECT_NE(browser, nullptr);
    if (browser != nullptr) {
        EXPECT_TRUE(waitUntil([&] { return browser->isVisible(); }, 5000));
        EXPECT_TRUE(waitUntil([&] { return !browser->isReading(); }, 15000));
    }
    return browser;
}

}  // namespace vv::test
