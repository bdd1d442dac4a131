// SPDX-License-Identifier: GPL-3.0-or-later
// The tests' one way to wait for a state: poll it (the GUI tests' waitUntil,
// GuiFixture.h, processes events between polls; the others', PacsTestUtil.h,
// sleeps). Never a sleep standing in
// for synchronisation, never a claim about time: the bound only stops a
// broken program from hanging the suite.
#pragma once

#include <chrono>
#include <functional>
#include <thread>

namespace vv::test {

/// Polls `done` until it holds or `bound` has passed, running `between` (when
/// given) between two polls — the GUI tests process events there; without
/// it the thread sleeps a few milliseconds. Returns `done()`.
inline bool pollUntil(const std::function<bool()>& done, std::chrono::milliseconds bound,
                      const std::function<void()>& between = {}) {
    const auto end = std::chrono::steady_clock::now() + bound;
    while (!done()) {
        if (std::chrono::steady_clock::now() > end) {
            return done();
        }
        if (between) {
            between();
        } else {
            std::this_thread::sleep_for(std::chrono::milliseconds(5));
        }
    }
    return true;
}

}  // namespace vv::test
