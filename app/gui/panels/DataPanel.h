// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QStringList>
#include <QWidget>
#include <cstddef>

#include "vv/render/MeshStyle.h"

class QComboBox;
class QLabel;
class QPushButton;
class QSpinBox;
class QToolButton;
class QTreeWidget;
class QTreeWidgetItem;

namespace vv::gui {

class ViewerWidget;

namespace panels {

/// The "Data" panel: the loaded file(s), and per mesh (object) a row with
/// its name and visibility check box, vertex and triangle counts, its
/// material colour (a colour dialog), its opacity (0-100 %) and the array it
/// shows ("Scene array" = the Functional panel's choice, "None" = the
/// material colour, or one of the point arrays the mesh has); below each row
/// the mesh's point arrays (name, unit, range). Every control changes the
/// view at once; a control that does not apply is disabled with a tooltip
/// saying why.
class DataPanel : public QWidget {
    Q_OBJECT

  public:
    /// Columns of meshTree().
    enum Column {
        NameColumn = 0,
        VerticesColumn,
        TrianglesColumn,
        ColorColumn,
        OpacityColumn,
        ArrayColumn,
        ColumnCount
    };

    explicit DataPanel(ViewerWidget* viewer, QWidget* parent = nullptr);

    /// Shows the viewer's scene; `title` names it (file name, "demo vessel
    /// tree", …) and `files` are the loaded paths (empty when generated).
    /// Every object starts visible, opaque, in the scene's style.
    void sceneChanged(const QString& title, const QStringList& files);

    [[nodiscard]] QTreeWidget* meshTree() const noexcept { return tree_; }
    [[nodiscard]] QLabel* fileLabel() const noexcept { return file_; }
    /// The controls of mesh `index`'s row (nullptr when there is no such mesh).
    /// The colour button opens a window-modal QColorDialog named "objectColorDialog".
    [[nodiscard]] QToolButton* colorButton(int index) const;
    [[nodiscard]] QSpinBox* opacityBox(int index) const;
    /// Item data: an ArrayChoice (Qt::UserRole) and the array's name (Qt::UserRole + 1).
    [[nodiscard]] QComboBox* arrayChooser(int index) const;

    /// What an array chooser's item stands for.
    enum ArrayChoice { SceneArray = 0, NoArray, NamedArray };

  public slots:
    /// Shows the viewer's current visibility and object styles (without
    /// writing them back), e.g. after a session was applied.
    void syncFromViewer();

    /// "DICOM Series…": browses the series of `dicomSource` (the folder, DICOMDIR
    /// or file the shown scene came from) when it is not empty, else asks for
    /// a DICOM folder. Emits browseSeries(dicomSource); the main window opens
    /// the series chooser on it.
    void setDicomSource(const QString& dicomSource);
    [[nodiscard]] QPushButton* seriesButton() const noexcept { return series_; }

  signals:
    /// The panel changed the viewer's settings (visibility, colour, opacity, array).
    void changed();
    /// The "DICOM Series…" button: browse the series at `path` (empty: choose a folder).
    void browseSeries(const QString& path);

  private:
    /// The style's hidden meshes from the check boxes.
    void applyVisibility();
    /// Sets object `index`'s style from `change` applied to its current one.
    template <typename Change>
    void changeObject(int index, Change change);
    void chooseColor(int index);
    void addObjectControls(QTreeWidgetItem* item, int index);
    void updateApplicability();
    /// The tree as wide as its shown columns need.
    void fitColumns();

    ViewerWidget* viewer_;
    QLabel* file_ = nullptr;
    QLabel* counts_ = nullptr;  ///< vertices and triangles of each mesh
    QTreeWidget* tree_ = nullptr;
    QPushButton* series_ = nullptr;
    QString dicomSource_;
    bool filling_ = false;  ///< sceneChanged() / syncFromViewer() is filling the tree
};

}  // namespace panels
}  // namespace vv::gui
