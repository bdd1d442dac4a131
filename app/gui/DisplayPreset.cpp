// SPDX-License-Identifier: GPL-3.0-or-later
#include "gui/DisplayPreset.h"

#include "gui/ViewerWidget.h"

namespace vv::gui {

namespace {

bool safeMap(colormaps::ColorMap map) noexcept {
    return map == colormaps::ColorMap::Cividis || map == colormaps::ColorMap::Viridis;
}

bool safeCue(render::VesselCue cue) noexcept {
    return cue == render::VesselCue::None || cue == render::VesselCue::Fog;
}

}  // namespace

DisplayState displayState(const ViewerWidget& viewer) {
    return {viewer.vssSettings(), viewer.style(), viewer.vesselCue()};
}

void applyDisplayState(ViewerWidget& viewer, const DisplayState& state) {
    viewer.setVssSettings(state.vss);
    viewer.setStyle(state.style);
    viewer.setVesselCue(state.cue);
}

bool isColorBlindSafe(const DisplayState& state) noexcept {
    // The scale is checked even with the VSS off, so that turning it on keeps the view safe.
    return state.vss.scale == colormaps::DepthScale::DarkMeansDeep &&
           safeMap(state.style.colorMap) && safeCue(state.cue.cue);
}

DisplayState colorBlindSafe(DisplayState state) noexcept {
    state.vss.scale = colormaps::DepthScale::DarkMeansDeep;
    state.style.colorMap = colormaps::ColorMap::Cividis;
    if (!safeCue(state.cue.cue)) {
        state.cue.cue = render::VesselCue::None;
    }
    return state;
}

}  // namespace vv::gui
