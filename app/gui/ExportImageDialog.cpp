// SPDX-License-Identifier: GPL-3.0-or-later
#include "gui/ExportImageDialog.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QLocale>
#include <QPushButton>
#include <QSettings>
#include <QSignalBlocker>
#include <QSpinBox>
#include <QStandardPaths>
#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <memory>

#include "gui/ExportWorker.h"
#include "gui/PathField.h"
#include "gui/ViewerWidget.h"
#include "vv/report/ViewExport.h"

namespace vv::gui {

namespace {

const char* const kFolderKey = "export/folder";
/// The spin boxes accept more than 8K so that a larger size gets a message.
constexpr int kMaxSpin = 16384;
constexpr std::array<QSize, 3> kPresets{QSize(1920, 1080), QSize(3840, 2160), QSize(7680, 4320)};

}  // namespace

QString lastExportFolder() {
    QString folder = QSettings().value(QLatin1String(kFolderKey)).toString();
    if (!folder.isEmpty() && QFileInfo(folder).isDir()) {
        return folder;
    }
    const QString pictures = QStandardPaths::writableLocation(QStandardPaths::PicturesLocation);
    return QFileInfo(pictures).isDir() ? pictures : QDir::homePath();
}

void rememberExportFolder(const QString& file) {
    QSettings().setValue(QLatin1String(kFolderKey), QFileInfo(file).absolutePath());
}

QString unusedFileName(const QString& folder, const QString& name) {
    const QDir dir(folder);
    const QFileInfo info(name);
    QString path = dir.filePath(name);
    for (int n = 2; QFileInfo::exists(path); ++n) {
        path = dir.filePath(
            QStringLiteral("%1-%2.%3").arg(info.completeBaseName()).arg(n).arg(info.suffix()));
    }
    return path;
}

ExportImageDialog::ExportImageDialog(const ViewerWidget& viewer, QWidget* parent)
    : ExportDialog(parent), viewer_(viewer) {
    setObjectName(QStringLiteral("exportImageDialog"));
    setWindowTitle(tr("Export Image"));
    auto* form = new QFormLayout(this);

    file_ = new QLineEdit(unusedFileName(lastExportFolder(), QStringLiteral("vessels.png")), this);
    addBuddyRow(form, tr("&File:"), file_,
                browseRow(file_, tr("Export image"), tr("PNG images (*.png)"), this));

    const QSize view = viewSize();
    sizes_ = new QComboBox(this);
    sizes_->addItem(tr("View size (%1 × %2)").arg(view.width()).arg(view.height()), ViewSize);
    sizes_->addItem(tr("Full HD (1920 × 1080)"), FullHd);
    sizes_->addItem(tr("4K UHD (3840 × 2160)"), Uhd4k);
    sizes_->addItem(tr("8K UHD (7680 × 4320)"), Uhd8k);
    sizes_->addItem(tr("Custom"), Custom);
    form->addRow(tr("&Size:"), sizes_);

    width_ = new QSpinBox(this);
    height_ = new QSpinBox(this);
    for (QSpinBox* box : {width_, height_}) {
        box->setRange(1, kMaxSpin);
        box->setSuffix(tr(" px"));
    }
    width_->setValue(view.width());
    height_->setValue(view.height());
    auto* sizeRow = new QHBoxLayout;
    sizeRow->addWidget(width_);
    sizeRow->addWidget(new QLabel(QStringLiteral("×"), this));
    sizeRow->addWidget(height_);
    sizeRow->addStretch(1);
    form->addRow(tr("Width × height:"), sizeRow);

    keepAspect_ = new QCheckBox(tr("&Keep the view's aspect ratio"), this);
    keepAspect_->setChecked(true);
    keepAspect_->setToolTip(
        tr("The image shows exactly what the view shows. A preset sets its exact size and "
           "turns this off when its shape differs from the view's."));
    form->addRow(QString(), keepAspect_);
    aspectNote_ = new QLabel(this);
    aspectNote_->setObjectName(QStringLiteral("aspectNote"));
    aspectNote_->setWordWrap(true);
    form->addRow(QString(), aspectNote_);
    legends_ = new QCheckBox(tr("&Legends"), this);
    legends_->setChecked(viewer.legendsVisible());
    form->addRow(QString(), legends_);
    transparent_ = new QCheckBox(tr("&Transparent background"), this);
    transparent_->setToolTip(tr("Pixels without vessels or VSS get alpha 0"));
    form->addRow(QString(), transparent_);

    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    buttons->button(QDialogButtonBox::Ok)->setText(tr("&Export"));
    connect(buttons, &QDialogButtonBox::accepted, this, &ExportImageDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    form->addRow(buttons);

    connect(sizes_, &QComboBox::currentIndexChanged, this, &ExportImageDialog::presetChosen);
    connect(width_, &QSpinBox::valueChanged, this, &ExportImageDialog::widthEdited);
    connect(height_, &QSpinBox::valueChanged, this, &ExportImageDialog::heightEdited);
    connect(keepAspect_, &QCheckBox::toggled, this, [this](bool on) {
        const QSize before = imageSize();
        if (on) {
            heightFollowsWidth();  // back to the view's shape
        }
        if (imageSize() != before) {
            const QSignalBlocker block(sizes_);
            sizes_->setCurrentIndex(sizes_->findData(Custom));
        }
        updateAspectNote();
    });
    updateAspectNote();
}

void ExportImageDialog::updateAspectNote() {
    const QSize size = imageSize();
    // The same shape up to the rounding of one side to whole pixels.
    const bool same =
        std::abs(std::lround(size.width() / viewAspect()) - static_cast<long>(size.height())) <= 1;
    aspectNote_->setVisible(!same);
    if (same) {
        aspectNote_->clear();
        return;
    }
    const double aspect = static_cast<double>(size.width()) / size.height();
    const auto ratio = [](double a) {
        return QLocale().toString(a, 'f', 2) + QStringLiteral(":1");
    };
    // The height of the view is kept (the camera's vertical field of view).
    aspectNote_->setText(
        aspect > viewAspect()
            ? tr("The image (%1) is wider than the view (%2): it shows more at the left and "
                 "right than the view does.")
                  .arg(ratio(aspect), ratio(viewAspect()))
            : tr("The image (%1) is narrower than the view (%2): it leaves out part of the "
                 "view at the left and right.")
                  .arg(ratio(aspect), ratio(viewAspect())));
}

QSize ExportImageDialog::viewSize() const {
    return viewPixelSize(viewer_);
}

double ExportImageDialog::viewAspect() const {
    const QSize view = viewSize();
    return static_cast<double>(view.width()) / view.height();
}

QSize ExportImageDialog::imageSize() const {
    return {width_->value(), height_->value()};
}

void ExportImageDialog::presetChosen() {
    const int preset = sizes_->currentData().toInt();
    if (preset == Custom) {
        return;
    }
    // A preset is exactly its size; a lock to the view's shape that would
    // change it comes off.
    const QSize size =
        preset == ViewSize ? viewSize() : kPresets.at(static_cast<std::size_t>(preset - 1));
    const QSignalBlocker blockWidth(width_);
    const QSignalBlocker blockHeight(height_);
    const QSignalBlocker blockAspect(keepAspect_);
    if (keepAspect_->isChecked() &&
        std::lround(size.width() / viewAspect()) != static_cast<long>(size.height())) {
        keepAspect_->setChecked(false);
    }
    width_->setValue(size.width());
    height_->setValue(size.height());
    updateAspectNote();
}

void ExportImageDialog::heightFollowsWidth() {
    const QSignalBlocker block(height_);
    height_->setValue(std::max(1, static_cast<int>(std::lround(width_->value() / viewAspect()))));
}

void ExportImageDialog::widthEdited() {
    if (keepAspect_->isChecked()) {
        heightFollowsWidth();
    }
    const QSignalBlocker block(sizes_);
    sizes_->setCurrentIndex(sizes_->findData(Custom));
    updateAspectNote();
}

void ExportImageDialog::heightEdited() {
    if (keepAspect_->isChecked()) {
        const QSignalBlocker block(width_);
        width_->setValue(
            std::max(1, static_cast<int>(std::lround(height_->value() * viewAspect()))));
    }
    const QSignalBlocker block(sizes_);
    sizes_->setCurrentIndex(sizes_->findData(Custom));
    updateAspectNote();
}

QString ExportImageDialog::problem() const {
    if (file_->text().trimmed().isEmpty()) {
        return tr("Choose a file name for the image.");
    }
    if (QFileInfo(file_->text()).isDir()) {
        return tr("%1 is a folder; choose a file name for the image.").arg(file_->text());
    }
    const QSize size = imageSize();
    if (size.width() > report::kMaxExportSide || size.height() > report::kMaxExportSide ||
        static_cast<long long>(size.width()) * size.height() > report::kMaxExportPixels) {
        return tr("%1 × %2 pixels is larger than 8K: images are at most 7680 × 4320 pixels "
                  "(either way round).")
            .arg(size.width())
            .arg(size.height());
    }
    if (!viewer_.scene()) {
        return tr("There is no data on screen to export.");
    }
    return {};
}

QString ExportImageDialog::targetFile() const {
    QString file = file_->text().trimmed();
    if (QFileInfo(file).suffix().isEmpty()) {
        file += QStringLiteral(".png");
    }
    return file;
}

QStringList ExportImageDialog::outputFiles() const {
    return {QFileInfo(targetFile()).absoluteFilePath()};
}

ExportWorker* ExportImageDialog::startExport() {
    const QString file = targetFile();
    rememberExportFolder(file);
    const QSize size = imageSize();
    report::ViewExportOptions options;
    options.render = currentViewOptions(viewer_, size.width(), size.height());
    options.legends = legends_->isChecked();
    options.transparentBackground = transparent_->isChecked();
    const std::shared_ptr<const scene::Scene> scene = viewer_.scene();
    const std::filesystem::path target(QFile::encodeName(file).toStdString());
    const bool transparent = options.transparentBackground;
    return ExportWorker::launch(
        tr("Exporting %1").arg(QFileInfo(file).fileName()),
        [scene, options, target, file, transparent](render::OffscreenRenderer& renderer,
                                                    const Progress& progress) {
            progress.report(0.0, tr("Rendering %1 × %2")
                                     .arg(options.render.width)
                                     .arg(options.render.height)
                                     .toStdString());
            // Tiles report their progress; Cancel is seen between tiles.
            const report::RenderedView view =
                report::renderView(renderer, *scene, options, progress.sub(0.0, 0.9));
            progress.report(0.9, tr("Writing the PNG file").toStdString());
            report::writePng(target, view.image);
            return tr("Exported %1 (%2 × %3%4)")
                .arg(file)
                .arg(view.image.width())
                .arg(view.image.height())
                .arg(transparent ? tr(", transparent background") : QString());
        },
        this);
}

}  // namespace vv::gui
