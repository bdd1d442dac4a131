// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QCoreApplication>
#include <QString>

class QMenuBar;

namespace vv::gui {

/// The Help menu's texts (HTML).
class HelpTexts {
    Q_DECLARE_TR_FUNCTIONS(vv::gui::HelpTexts)

  public:
    /// Help > About: the versions of VesselView, OpenGL (`glDescription`;
    /// empty: not initialised), Qt, VTK and DCMTK, and the licence.
    [[nodiscard]] static QString about(const QString& glDescription);
    /// Help > Keyboard Shortcuts: every action of `menus` with a shortcut
    /// (submenus too), then the mouse, as a table.
    [[nodiscard]] static QString shortcuts(const QMenuBar& menus);
};

}  // namespace vv::gui
