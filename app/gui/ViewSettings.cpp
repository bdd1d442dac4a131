// SPDX-License-Identifier: GPL-3.0-or-later
#include "gui/ViewSettings.h"

#include <QSettings>

#include "common/SettingsSchema.h"
#include "common/StoredSettings.h"
#include "gui/ViewerWidget.h"

namespace vv::gui {

app::DisplaySettings displaySettings(const ViewerWidget& viewer) {
    app::DisplaySettings s;
    s.vss = viewer.vssSettings();
    s.vss.preview = false;
    s.ao = viewer.aoSettings();
    s.cue = viewer.vesselCue();
    s.style = viewer.style();
    s.background = viewer.background();
    s.legends = viewer.legendsVisible();
    s.orientationMarker = viewer.viewAnnotations().orientationMarker;
    s.scaleBar = viewer.viewAnnotations().scaleBar;
    s.antialiasing = true;
    s.smoothCoarseMeshes = viewer.smoothCoarseMeshes();
    return s;
}

void applyDisplaySettings(ViewerWidget& viewer, const app::DisplaySettings& settings) {
    viewer.setVssSettings(settings.vss);
    viewer.setAoSettings(settings.ao);
    viewer.setVesselCue(settings.cue);
    render::MeshStyle style = settings.style;
    style.lighting = viewer.style().lighting;
    viewer.setStyle(style);
    viewer.setBackground(settings.background);
    viewer.setLegendsVisible(settings.legends);
    render::ViewAnnotations annotations = viewer.viewAnnotations();  // the frame stays
    annotations.orientationMarker = settings.orientationMarker;
    annotations.scaleBar = settings.scaleBar;
    viewer.setViewAnnotations(annotations);
    viewer.setSmoothCoarseMeshes(settings.smoothCoarseMeshes);
}

void saveViewSettings(const ViewerWidget& viewer, QSettings& settings) {
    app::writeStoredSettings(displaySettings(viewer), settings);
}

void restoreViewSettings(ViewerWidget& viewer, const QSettings& settings) {
    app::DisplaySettings display = displaySettings(viewer);
    app::readStoredSettings(settings, display);
    applyDisplaySettings(viewer, display);
}

void resetViewSettings(ViewerWidget& viewer) {
    app::DisplaySettings display = displaySettings(viewer);
    app::resetToDefaults(display);
    applyDisplaySettings(viewer, display);
}

}  // namespace vv::gui
