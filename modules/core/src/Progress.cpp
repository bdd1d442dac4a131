// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/core/Progress.h"

#include <algorithm>

#include "vv/core/Error.h"

namespace vv {

void Progress::report(double fraction, std::string_view stage) const {
    throwIfCancelled();
    if (callback_) {
        callback_(std::clamp(fraction, 0.0, 1.0), stage);
    }
}

void Progress::throwIfCancelled() const {
    if (stop_.stop_requested()) {
        throw CancelledError();
    }
}

Progress Progress::sub(double begin, double end) const {
    if (!callback_) {
        return {{}, stop_};
    }
    return {[parent = callback_, begin, end](double f, std::string_view stage) {
                parent(begin + (end - begin) * std::clamp(f, 0.0, 1.0), stage);
            },
            stop_};
}

}  // namespace vv
