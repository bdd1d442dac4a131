// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/render/DisplaySettings.h"

namespace vv::render {

FrameSettings frameSettings(const DisplaySettings& display) {
    // The rest (resolution scales, simplified geometry) is the still frame's default.
    return {.background = display.background,
            .vss = display.vss,
            .cue = display.cue,
            .ao = display.ao,
            .antialiasing = display.antialiasing,
            .smoothCoarseMeshes = display.smoothCoarseMeshes};
}

}  // namespace vv::render
