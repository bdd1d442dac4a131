// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QStringList>

#include "common/Session.h"

namespace vv::gui {

class ViewerWidget;

// The session format lives in app/common (common/Session.h) so that the
// command line renders sessions too; the GUI adds taking them from and
// giving them to the viewer.
using app::kSessionSuffix;
using app::kSessionVersion;
using app::loadSession;
using app::saveSession;
using app::Session;
using app::sessionFromJson;
using app::sessionToJson;

/// What `viewer` shows now, with `files` as the data.
[[nodiscard]] Session captureSession(const ViewerWidget& viewer, const QStringList& files);

/// Applies the display settings and the camera of `session` to `viewer`
/// (the files are the caller's: load them first, as setting a scene refits
/// the camera).
void applySession(ViewerWidget& viewer, const Session& session);

}  // namespace vv::gui
