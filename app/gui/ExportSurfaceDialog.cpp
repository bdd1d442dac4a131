// SPDX-License-Identifier: GPL-3.0-or-later
#include "gui/ExportSurfaceDialog.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>
#include <QLocale>
#include <QPushButton>
#include <QSettings>
#include <QSignalBlocker>
#include <filesystem>
#include <utility>

#include "gui/ExportImageDialog.h"
#include "gui/PathField.h"

namespace vv::gui {

namespace {

const char* const kFormatKey = "surface/format";

}  // namespace

ExportSurfaceDialog::ExportSurfaceDialog(SurfaceExportSource source, QWidget* parent)
    : ExportDialog(parent),
      source_(std::move(source)),
      format_(new QComboBox(this)),
      what_(new QLabel(this)) {
    setObjectName(QStringLiteral("exportSurfaceDialog"));
    setWindowTitle(tr("Export Surface"));
    auto* form = new QFormLayout(this);

    format_->addItem(tr("STL, binary (3-D printing)"), QStringLiteral(".stl"));
    format_->addItem(tr("VTK polydata (labels and provenance)"), QStringLiteral(".vtp"));
    format_->addItem(tr("PLY, binary"), QStringLiteral(".ply"));
    const int remembered =
        format_->findData(QSettings().value(QLatin1String(kFormatKey)).toString());
    format_->setCurrentIndex(remembered >= 0 ? remembered : 0);

    const QString suffix = format_->currentData().toString();
    file_ =
        new QLineEdit(unusedFileName(lastExportFolder(), QStringLiteral("vessels") + suffix), this);
    addBuddyRow(form, tr("&File:"), file_,
                browseRow(file_, tr("Export surface"), tr("Surfaces (*.stl *.vtp *.ply)"), this));
    form->addRow(tr("F&ormat:"), format_);

    what_->setObjectName(QStringLiteral("surfaceSource"));
    what_->setWordWrap(true);
    const QString triangles = QLocale().toString(
        static_cast<qulonglong>(source_.scene ? source_.scene->triangleCount() : 0));
    what_->setText(source_.labels
                       ? tr("The applied segmentation's surface: %1 triangles.").arg(triangles)
                       : tr("The surface on screen: %1 triangles.").arg(triangles));
    form->addRow(what_);
    auto* frame = new QLabel(
        tr("Coordinates: DICOM patient LPS, millimetres, as the scene (x to the patient's left, "
           "y posterior, z to the head). Tools that expect RAS: negate x and y. The file names "
           "the series and the settings that made it."),
        this);
    frame->setObjectName(QStringLiteral("surfaceFrame"));
    frame->setWordWrap(true);
    form->addRow(frame);

    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    buttons->button(QDialogButtonBox::Ok)->setText(tr("&Export"));
    connect(buttons, &QDialogButtonBox::accepted, this, &ExportSurfaceDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    form->addRow(buttons);

    connect(format_, &QComboBox::currentIndexChanged, this, &ExportSurfaceDialog::formatChosen);
    connect(file_, &QLineEdit::textEdited, this, &ExportSurfaceDialog::fileEdited);
}

void ExportSurfaceDialog::formatChosen() {
    // The file takes the chosen format's suffix.
    const QString suffix = format_->currentData().toString();
    const QFileInfo info(file_->text().trimmed());
    if (!file_->text().trimmed().isEmpty()) {
        file_->setText(info.dir().filePath(info.completeBaseName() + suffix));
    }
}

void ExportSurfaceDialog::fileEdited() {
    // A typed suffix chooses the format.
    const int index = format_->findData(QStringLiteral(".") +
                                        QFileInfo(file_->text().trimmed()).suffix().toLower());
    if (index >= 0) {
        const QSignalBlocker block(format_);
        format_->setCurrentIndex(index);
    }
}

QString ExportSurfaceDialog::targetFile() const {
    QString file = file_->text().trimmed();
    if (QFileInfo(file).suffix().isEmpty()) {
        file += format_->currentData().toString();
    }
    return file;
}

QString ExportSurfaceDialog::problem() const {
    const QString file = file_->text().trimmed();
    if (file.isEmpty()) {
        return tr("Choose a file name for the surface.");
    }
    if (QFileInfo(file).isDir()) {
        return tr("%1 is a folder; choose a file name for the surface.").arg(file);
    }
    if (format_->findData(QStringLiteral(".") + QFileInfo(targetFile()).suffix().toLower()) < 0) {
        return tr("%1: surfaces are written as .stl, .vtp or .ply files.")
            .arg(QFileInfo(file).fileName());
    }
    if (!source_.scene || source_.scene->meshes.empty()) {
        return tr("There is no segmented surface to export.");
    }
    return {};
}

QStringList ExportSurfaceDialog::outputFiles() const {
    return {QFileInfo(targetFile()).absoluteFilePath()};
}

ExportWorker* ExportSurfaceDialog::startExport() {
    const QString file = targetFile();
    rememberExportFolder(file);
    QSettings().setValue(QLatin1String(kFormatKey), format_->currentData().toString());
    const std::filesystem::path target(QFile::encodeName(file).toStdString());
    return ExportWorker::launch(
        tr("Exporting %1").arg(QFileInfo(file).fileName()),
        [source = source_, target, file](const Progress& progress) {
            SurfaceExportSource s = source;
            progress.report(0.0, tr("Writing the surface").toStdString());
            const std::size_t triangles = s.scene->triangleCount();
            if (s.labels) {
                app::writeSegmentedSurface(s.scene->meshes.front(), s.labels.get(), target,
                                           s.provenance);
            } else {
                for (const scene::Mesh& mesh : s.scene->meshes) {
                    s.provenance.segmentNames.push_back(mesh.name);
                }
                app::writeSegmentedSurface(app::meshWithLabels(*s.scene), nullptr, target,
                                           s.provenance);
            }
            return tr("Exported %1 (%2 triangles, patient LPS mm)")
                .arg(QFileInfo(file).fileName(),
                     QLocale().toString(static_cast<qulonglong>(triangles)));
        },
        this);
}

}  // namespace vv::gui
