// SPDX-License-Identifier: GPL-3.0-or-later
#include "gui/HelpTexts.h"

#include <QAction>
#include <QMenu>
#include <QMenuBar>
#include <QStringList>
#include <functional>

#include "vv/dicom/Versions.h"
#include "vv/meshio/Versions.h"

namespace vv::gui {

QString HelpTexts::about(const QString& glDescription) {
    const QString gl = glDescription.isEmpty() ? tr("not initialised") : glDescription;
    QStringList libraries;
    libraries << QStringLiteral("Qt %1 (%2)")
                     .arg(QString::fromLatin1(qVersion()),
                          tr("built with %1").arg(QStringLiteral(QT_VERSION_STR)));
    libraries << QStringLiteral("VTK ") + QString::fromStdString(meshio::vtkVersion());
    libraries << QStringLiteral("DCMTK ") + QString::fromStdString(dicom::dcmtkVersion());
    for (QString& library : libraries) {
        library = library.toHtmlEscaped();
    }
    return tr("<h3>VesselView %1</h3>"
              "<p>A workstation for vessel trees: meshes with wall shear stress, pressure and "
              "other parameters on the vessel wall, and Void Space Surfaces.</p>"
              "<p>OpenGL: %2</p><p>Libraries: %3</p>"
              "<p>Licensed under the GNU General Public License, version 3 or later.</p>")
        .arg(QStringLiteral(VV_VERSION), gl.toHtmlEscaped(),
             libraries.join(QStringLiteral("<br>")));
}

QString HelpTexts::shortcuts(const QMenuBar& menus) {
    QStringList rows;
    const auto row = [&rows](const QString& what, const QString& keys) {
        rows << QStringLiteral("<tr><td>%1</td><td><b>%2</b></td></tr>")
                    .arg(what.toHtmlEscaped(), keys.toHtmlEscaped());
    };
    const std::function<void(const QMenu*)> collect = [&](const QMenu* menu) {
        for (const QAction* action : menu->actions()) {
            if (action->menu() != nullptr) {
                collect(action->menu());
            } else if (!action->shortcut().isEmpty()) {
                row(action->text().remove(QLatin1Char('&')),
                    action->shortcut().toString(QKeySequence::NativeText));
            }
        }
    };
    for (const QAction* action : menus.actions()) {
        if (action->menu() != nullptr) {
            collect(action->menu());
        }
    }
    row(tr("Rotate"), tr("left drag"));
    row(tr("Pan"), tr("right or middle drag, Shift + left drag"));
    row(tr("Zoom"), tr("mouse wheel"));
    row(tr("Pick a point to measure"), tr("Ctrl + click (any click in Measure mode)"));
    return QStringLiteral("<table cellspacing=\"6\">") + rows.join(QString()) +
           QStringLiteral("</table>");
}

}  // namespace vv::gui
