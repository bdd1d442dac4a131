// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <string>

namespace vv::scene {

/// How every text a person reads names a quantity with its unit: "wss (Pa)",
/// "Depth behind the frontmost vessel (mm)"; the name alone when the unit is
/// empty. Files keep their own convention, "wss [Pa]" (meshio). Legends, the
/// side panel, the status bar, probe tooltips and reports all use this one.
[[nodiscard]] std::string quantityTitle(const std::string& name, const std::string& unit);

}  // namespace vv::scene
