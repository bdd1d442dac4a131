// SPDX-License-Identifier: GPL-3.0-or-later
#include "gui/Session.h"

#include <QFileInfo>

#include "gui/ViewSettings.h"
#include "gui/ViewerWidget.h"

namespace vv::gui {

Session captureSession(const ViewerWidget& viewer, const QStringList& files) {
    Session s;
    static_cast<app::DisplaySettings&>(s) = displaySettings(viewer);
    for (const QString& f : files) {
        s.files << QFileInfo(f).absoluteFilePath();
    }
    const render::Camera& camera = viewer.camera();
    s.cameraTarget = camera.target();
    s.cameraDistance = camera.distance();
    s.cameraRotation = camera.rotation();
    s.fieldOfView = camera.fieldOfView();
    return s;
}

void applySession(ViewerWidget& viewer, const Session& session) {
    applyDisplaySettings(viewer, session);
    render::Camera camera = viewer.camera();  // keeps viewport and scene bounds
    app::applySessionCamera(session, camera);
    viewer.setCamera(camera);
}

}  // namespace vv::gui
