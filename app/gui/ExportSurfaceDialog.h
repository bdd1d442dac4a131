// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QString>
#include <QStringList>
#include <memory>

#include "common/SurfaceExport.h"
#include "gui/ExportWorker.h"
#include "vv/scene/LabelMap.h"
#include "vv/scene/Mesh.h"

class QComboBox;
class QLabel;
class QLineEdit;

namespace vv::gui {

/// What File > Export Surface… writes.
struct SurfaceExportSource {
    /// The applied segmentation's surface at full resolution (one mesh; a
    /// DICOM SEG: one mesh per segment) and the label map it came from
    /// (null for a SEG: each mesh is its segment); never a preview
    /// (DocumentController::segmentedScene()).
    std::shared_ptr<const scene::Scene> scene;
    std::shared_ptr<const scene::LabelMap> labels;
    /// The series and settings.
    app::SegmentationProvenance provenance;
};

/// File > Export Surface…: the segmented vessel surface as STL (binary,
/// 3-D printing), VTP (normals, the label array, the provenance as field
/// data) or PLY (binary), in patient LPS millimetres as the scene (a note
/// says how to get RAS), with the series and settings that made it
/// (app::writeSegmentedSurface). The format follows the file's suffix and
/// the format chooser (one sets the other). It proposes vessels.<format> in
/// the last export folder (vessels-2…, when taken; the format remembered in
/// QSettings "surface/format"). accept() checks the fields, asks before it
/// replaces a file and writes on an ExportWorker (progress and Cancel;
/// written atomically; the outcome in the status bar or a message
/// box naming the file and the problem).
class ExportSurfaceDialog : public ExportDialog {
    Q_OBJECT

  public:
    ExportSurfaceDialog(SurfaceExportSource source, QWidget* parent = nullptr);

    [[nodiscard]] QLineEdit* fileEdit() const noexcept { return file_; }
    /// Item data: the suffix (".stl", ".vtp", ".ply").
    [[nodiscard]] QComboBox* formatChooser() const noexcept { return format_; }
    /// What will be written (the applied segmentation's surface, or a SEG's segments).
    [[nodiscard]] QLabel* sourceLabel() const noexcept { return what_; }

    /// What is wrong with the fields (no file name, a folder, another
    /// suffix); empty when fine.
    [[nodiscard]] QString problem() const override;
    /// The file written: the field's path, the format's suffix added when it has none.
    [[nodiscard]] QStringList outputFiles() const override;

  protected:
    ExportWorker* startExport() override;

  private:
    [[nodiscard]] QString targetFile() const;
    void formatChosen();
    void fileEdited();

    SurfaceExportSource source_;
    QLineEdit* file_ = nullptr;
    QComboBox* format_ = nullptr;
    QLabel* what_ = nullptr;
};

}  // namespace vv::gui
