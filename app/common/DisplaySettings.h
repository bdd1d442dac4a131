// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "vv/render/DisplaySettings.h"

namespace vv::app {

/// Every display and VSS setting of a view (render::DisplaySettings): what
/// the GUI's panels change, a session (.vvs) stores, QSettings remembers and
/// `vesselview-cli render` / `report` take as options. SettingsSchema.h
/// describes each one (name, type, range, default, unit, label).
using DisplaySettings = render::DisplaySettings;

}  // namespace vv::app
