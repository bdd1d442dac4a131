// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QSize>
#include <QString>
#include <QStringList>

#include "gui/ExportWorker.h"

class QCheckBox;
class QComboBox;
class QLabel;
class QLineEdit;
class QSpinBox;

namespace vv::gui {

class ViewerWidget;

/// File > Export Image…: the current view (camera and every display setting
/// of the viewer) as a PNG file at the view's size, a preset (1920 x 1080,
/// 3840 x 2160, 7680 x 4320) or a custom size up to 8K
/// (report::kMaxExportSide, report::kMaxExportPixels; larger sizes are
/// refused with a message; a preset is always exactly its size, and choosing
/// one whose shape differs from the view's turns "keep the view's aspect
/// ratio" off; a note says then how the image differs from the view),
/// optionally keeping the view's aspect ratio, with
/// or without legends, on the background or transparent. It proposes
/// vessels.png in the last export folder (vessels-2.png, … when taken).
/// accept() checks the fields (a message box says what is wrong; the dialog
/// stays open), asks before it replaces a file, remembers the folder, and renders with
/// report::renderView() on an ExportWorker (progress dialog with Cancel; written atomically; the
/// outcome in the main window's status bar or a message box naming the file and the problem).
class ExportImageDialog : public ExportDialog {
    Q_OBJECT

  public:
    ExportImageDialog(const ViewerWidget& viewer, QWidget* parent = nullptr);

    /// Size chooser items (item data = the preset's index here).
    enum SizePreset { ViewSize = 0, FullHd, Uhd4k, Uhd8k, Custom };

    [[nodiscard]] QLineEdit* fileEdit() const noexcept { return file_; }
    [[nodiscard]] QComboBox* sizeChooser() const noexcept { return sizes_; }
    [[nodiscard]] QSpinBox* widthBox() const noexcept { return width_; }
    [[nodiscard]] QSpinBox* heightBox() const noexcept { return height_; }
    [[nodiscard]] QCheckBox* keepAspectBox() const noexcept { return keepAspect_; }
    /// Says how the image differs from the view when their shapes differ
    /// (hidden when they are the same).
    [[nodiscard]] QLabel* aspectNote() const noexcept { return aspectNote_; }
    [[nodiscard]] QCheckBox* legendsBox() const noexcept { return legends_; }
    [[nodiscard]] QCheckBox* transparentBox() const noexcept { return transparent_; }

    /// The size the fields ask for.
    [[nodiscard]] QSize imageSize() const;
    /// What is wrong with the fields (no file, size beyond 8K); empty when fine.
    [[nodiscard]] QString problem() const override;
    /// The PNG file written: the field's path, ".png" added when it has no suffix.
    [[nodiscard]] QStringList outputFiles() const override;

  protected:
    ExportWorker* startExport() override;

  private:
    void presetChosen();
    void widthEdited();
    /// The height for the width in the view's shape.
    void heightFollowsWidth();
    void heightEdited();
    void updateAspectNote();
    [[nodiscard]] QSize viewSize() const;
    [[nodiscard]] double viewAspect() const;
    /// The field's path, ".png" added when it has no suffix.
    [[nodiscard]] QString targetFile() const;

    const ViewerWidget& viewer_;
    QLineEdit* file_ = nullptr;
    QComboBox* sizes_ = nullptr;
    QSpinBox* width_ = nullptr;
    QSpinBox* height_ = nullptr;
    QCheckBox* keepAspect_ = nullptr;
    QLabel* aspectNote_ = nullptr;
    QCheckBox* legends_ = nullptr;
    QCheckBox* transparent_ = nullptr;
};

/// The folder exports were last written to (QSettings "export/folder"), else
/// the user's pictures / home folder.
[[nodiscard]] QString lastExportFolder();
/// Remembers the folder of `file` for the next export dialog.
void rememberExportFolder(const QString& file);
/// The path of `name` in `folder`, or when a file of that name is there, of
/// the first free "<base>-2.<suffix>", "<base>-3.<suffix>", …: a default
/// that replaces nothing.
[[nodiscard]] QString unusedFileName(const QString& folder, const QString& name);

}  // namespace vv::gui
