// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QStringList>
#include <QWidget>

class QLabel;
class QTreeWidget;

namespace vv::gui {

class ViewerWidget;

namespace panels {

/// The "Data" panel: the loaded file(s), and per mesh its name, vertex and
/// triangle counts, visibility, and its point arrays (name, unit, range).
/// The panel is read-only today; per-object visibility is shown disabled
/// (the renderer draws every mesh of a scene).
class DataPanel : public QWidget {
    Q_OBJECT

  public:
    /// Columns of meshTree().
    enum Column { NameColumn = 0, VerticesColumn, TrianglesColumn, ColumnCount };

    explicit DataPanel(ViewerWidget* viewer, QWidget* parent = nullptr);

    /// Shows the viewer's scene; `title` names it (file name, "demo vessel
    /// tree", …) and `files` are the loaded paths (empty when generated).
    void sceneChanged(const QString& title, const QStringList& files);

    [[nodiscard]] QTreeWidget* meshTree() const noexcept { return tree_; }
    [[nodiscard]] QLabel* fileLabel() const noexcept { return file_; }

  signals:
    /// The panel changed the viewer's settings (a mesh shown or hidden).
    void changed();

  private:
    /// The style's hidden meshes from the check boxes.
    void applyVisibility();

    ViewerWidget* viewer_;
    QLabel* file_ = nullptr;
    QTreeWidget* tree_ = nullptr;
    bool filling_ = false;  ///< sceneChanged() is filling the tree
};

}  // namespace panels
}  // namespace vv::gui
