// SPDX-License-Identifier: GPL-3.0-or-later
#include "gui/panels/DisplayPanel.h"

#include <QCheckBox>
#include <QColorDialog>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLocale>
#include <QSlider>
#include <QToolButton>
#include <algorithm>
#include <cmath>

#include "gui/ViewerWidget.h"
#include "gui/panels/PanelUtil.h"
#include "vv/render/FrameSettings.h"
#include "vv/render/MeshStyle.h"
#include "vv/render/ViewPresets.h"

namespace vv::gui::panels {

namespace {

/// The background choices; the first is the viewer's default.
struct BackgroundChoice {
    const char* label;  ///< translated in the panel's context
    glm::vec3 color;
};
const BackgroundChoice kBackgrounds[] = {
    {QT_TRANSLATE_NOOP("vv::gui::panels::DisplayPanel", "Dark grey"), render::kDefaultBackground},
    {QT_TRANSLATE_NOOP("vv::gui::panels::DisplayPanel", "Black"), {0.0F, 0.0F, 0.0F}},
    {QT_TRANSLATE_NOOP("vv::gui::panels::DisplayPanel", "Mid grey"), {0.5F, 0.5F, 0.5F}},
    {QT_TRANSLATE_NOOP("vv::gui::panels::DisplayPanel", "White"), {1.0F, 1.0F, 1.0F}},
};

QString capitalised(std::string_view name) {
    QString text = fromUtf8(name);
    if (!text.isEmpty()) {
        text[0] = text[0].toUpper();
    }
    return text;
}

}  // namespace

DisplayPanel::DisplayPanel(ViewerWidget* viewer, QWidget* parent)
    : QWidget(parent), viewer_(viewer) {
    setObjectName(QStringLiteral("displayPanel"));
    auto* form = new QFormLayout(this);
    addCueRows(form);
    addColourRows(form);
    addLightRow(form);
    addCameraButtons(form);
    addOverlayRows(form);

    makeNarrow(this);
    syncFromViewer();
    connectControls();
}

void DisplayPanel::addCueRows(QFormLayout* form) {
    cue_ = new QComboBox(this);
    cue_->setObjectName(QStringLiteral("vesselCueChooser"));
    cue_->setToolTip(tr("A depth cue on the vessels themselves, for comparison with the VSS"));
    for (const auto cue : render::allVesselCues()) {
        cue_->addItem(engineName(render::displayName(cue)), static_cast<int>(cue));
    }
    form->addRow(settingFormLabel("cue.cue"), cue_);
    fogStrength_ = new QSlider(Qt::Horizontal, this);
    fogStrength_->setObjectName(QStringLiteral("fogStrength"));
    setUpForSetting(fogStrength_, "cue.fogStrength");
    form->addRow(settingFormLabel("cue.fogStrength"), fogStrength_);
    fresnelExponent_ = new QDoubleSpinBox(this);
    fresnelExponent_->setObjectName(QStringLiteral("fresnelExponent"));
    setUpForSetting(fresnelExponent_, "cue.fresnelExponent");
    fresnelExponent_->setKeyboardTracking(false);
    form->addRow(settingFormLabel("cue.fresnelExponent"), fresnelExponent_);
}

void DisplayPanel::addColourRows(QFormLayout* form) {
    background_ = new QComboBox(this);
    background_->setObjectName(QStringLiteral("backgroundChooser"));
    background_->setToolTip(tr("Colour behind the vessels and the VSS"));
    for (const BackgroundChoice& choice : kBackgrounds) {
        background_->addItem(tr(choice.label), toQColor(choice.color));
    }
    background_->addItem(tr("Custom…"), QColor());
    form->addRow(settingFormLabel("background"), background_);
    vesselColor_ = new QToolButton(this);
    vesselColor_->setObjectName(QStringLiteral("vesselColor"));
    vesselColor_->setMinimumWidth(64);
    form->addRow(settingFormLabel("style.vesselColor"), vesselColor_);
    connect(vesselColor_, &QToolButton::clicked, this, &DisplayPanel::chooseVesselColor);
}

void DisplayPanel::addLightRow(QFormLayout* form) {
    // The key light: azimuth about the view's up axis, elevation above its horizon.
    auto* light = new QWidget(this);
    auto* lightRow = new QHBoxLayout(light);
    lightRow->setContentsMargins(0, 0, 0, 0);
    const auto angleBox = [&](const char* name, std::string_view key) {
        auto* box = new QDoubleSpinBox(light);
        box->setObjectName(QLatin1String(name));
        setUpForSetting(box, key);
        box->setKeyboardTracking(false);
        lightRow->addWidget(box);
        return box;
    };
    lightAzimuth_ = angleBox("lightAzimuth", "style.light[0]");
    lightAzimuth_->setWrapping(true);
    lightElevation_ = angleBox("lightElevation", "style.light[1]");
    lightReset_ = new QToolButton(light);
    lightReset_->setObjectName(QStringLiteral("lightReset"));
    lightReset_->setText(tr("Reset"));
    lightRow->addWidget(lightReset_);
    form->addRow(tr("Light:"), light);
    connect(lightReset_, &QToolButton::clicked, this, [this] {
        render::MeshStyle style = viewer_->style();
        style.light = render::LightAngles{};
        viewer_->setStyle(style);
        syncFromViewer();
        emit changed();
    });
}

void DisplayPanel::addCameraButtons(QFormLayout* form) {
    cameraButtons_ = new QWidget(this);
    auto* grid = new QGridLayout(cameraButtons_);
    grid->setContentsMargins(0, 0, 0, 0);
    int column = 0;
    for (const auto preset : render::allViewPresets()) {
        auto* button = new QToolButton(cameraButtons_);
        const QString name = capitalised(render::toString(preset));
        button->setObjectName(QStringLiteral("view") + name);
        button->setText(presetLabel(preset));
        grid->addWidget(button, 0, column++);
        connect(button, &QToolButton::clicked, this, [this, preset] {
            if (const auto& scene = viewer_->scene()) {
                viewer_->setCamera(render::presetCamera(*scene, std::max(1, viewer_->width()),
                                                        std::max(1, viewer_->height()), preset));
                emit changed();
            }
        });
    }
    int index = 0;
    for (const auto view : render::allAnatomicalViews()) {
        auto* button = new QToolButton(cameraButtons_);
        const QString name = capitalised(render::toString(view));
        button->setObjectName(QStringLiteral("view") + name);
        anatomicalButtons_.at(static_cast<std::size_t>(index)) = button;
        grid->addWidget(button, 1 + index / 3, index % 3);
        ++index;
        connect(button, &QToolButton::clicked, this, [this, view] {
            if (const auto& scene = viewer_->scene()) {
                viewer_->setCamera(render::presetCamera(
                    *scene, std::max(1, viewer_->width()), std::max(1, viewer_->height()),
                    render::ViewPreset::Far, render::anatomicalRotation(view)));
                emit changed();
            }
        });
    }
    form->addRow(tr("Camera:"), cameraButtons_);
    labelCameraButtons();
}

void DisplayPanel::addOverlayRows(QFormLayout* form) {
    legends_ = new QCheckBox(settingLabel("legends"), this);
    legends_->setObjectName(QStringLiteral("displayLegends"));
    legends_->setToolTip(tr("Depth and parameter legends over the view"));
    form->addRow(legends_);
    performance_ = new QCheckBox(tr("Performance overlay"), this);
    performance_->setObjectName(QStringLiteral("displayPerformance"));
    performance_->setToolTip(tr("The last frame's render passes and their CPU time in ms"));
    form->addRow(performance_);

    // Over the viewer's top-left corner, like the legends.
    overlay_ = new QLabel(viewer_);
    overlay_->setObjectName(QStringLiteral("performanceOverlay"));
    overlay_->setAttribute(Qt::WA_TransparentForMouseEvents);
    overlay_->setStyleSheet(
        QStringLiteral("QLabel { background: rgba(0, 0, 0, 160); color: white; padding: 4px; "
                       "font-family: monospace; }"));
    overlay_->move(8, 8);
    overlay_->hide();
}

void DisplayPanel::connectControls() {
    auto applyCueLater = [this] {
        if (!syncing_) {
            applyCue();
        }
    };
    connect(cue_, &QComboBox::currentIndexChanged, this, applyCueLater);
    connect(fogStrength_, &QSlider::valueChanged, this, applyCueLater);
    connect(fresnelExponent_, &QDoubleSpinBox::valueChanged, this, applyCueLater);
    const auto applyLightLater = [this] {
        if (!syncing_) {
            applyLight();
        }
    };
    connect(lightAzimuth_, &QDoubleSpinBox::valueChanged, this, applyLightLater);
    connect(lightElevation_, &QDoubleSpinBox::valueChanged, this, applyLightLater);
    connect(background_, &QComboBox::currentIndexChanged, this, [this] {
        if (!syncing_) {
            applyBackground();
        }
    });
    connect(legends_, &QCheckBox::toggled, this, [this](bool on) {
        if (!syncing_) {
            viewer_->setLegendsVisible(on);
            emit changed();
        }
    });
    connect(performance_, &QCheckBox::toggled, this, [this](bool on) {
        overlay_->setVisible(on);
        frameRendered();
    });
}

QString DisplayPanel::presetLabel(render::ViewPreset preset) {
    switch (preset) {
        case render::ViewPreset::Far:
            return tr("Far");
        case render::ViewPreset::Medium:
            return tr("Medium");
        case render::ViewPreset::Close:
            return tr("Close");
    }
    return {};
}

QString DisplayPanel::anatomicalLabel(render::AnatomicalView view, render::SceneFrame frame) {
    const bool patient = frame == render::SceneFrame::PatientLps;
    switch (view) {
        case render::AnatomicalView::Anterior:
            return tr("Anterior");
        case render::AnatomicalView::Posterior:
            return tr("Posterior");
        case render::AnatomicalView::Left:
            return patient ? tr("Left lateral") : tr("Left");
        case render::AnatomicalView::Right:
            return patient ? tr("Right lateral") : tr("Right");
        case render::AnatomicalView::Superior:
            return tr("Superior");
        case render::AnatomicalView::Inferior:
            return tr("Inferior");
    }
    return {};
}

QString DisplayPanel::anatomicalToolTip(render::AnatomicalView view, render::SceneFrame frame) {
    if (frame != render::SceneFrame::PatientLps) {
        // Meshes carry no anatomy: the view is along an axis, named as for LPS data.
        switch (view) {
            case render::AnatomicalView::Anterior:
                return tr("From -y, +z up (the anterior view of data in patient LPS coordinates)");
            case render::AnatomicalView::Posterior:
                return tr("From +y, +z up (the posterior view of data in patient LPS coordinates)");
            case render::AnatomicalView::Left:
                return tr(
                    "From +x, +z up (the left lateral view of data in patient LPS "
                    "coordinates)");
            case render::AnatomicalView::Right:
                return tr(
                    "From -x, +z up (the right lateral view of data in patient LPS "
                    "coordinates)");
            case render::AnatomicalView::Superior:
                return tr("From +z, -y up (the superior view of data in patient LPS coordinates)");
            case render::AnatomicalView::Inferior:
                return tr("From -z, -y up (the inferior view of data in patient LPS coordinates)");
        }
        return {};
    }
    switch (view) {
        case render::AnatomicalView::Anterior:
            return tr(
                "From the front, head up: the patient's left on the right, as on the "
                "coronal slice (the view a DICOM scene opens in)");
        case render::AnatomicalView::Posterior:
            return tr("From behind, head up: the patient's left on the left");
        case render::AnatomicalView::Left:
            return tr("From the patient's left, head up: anterior on the left");
        case render::AnatomicalView::Right:
            return tr("From the patient's right, head up: anterior on the right");
        case render::AnatomicalView::Superior:
            return tr(
                "From the head towards the feet, anterior up: the patient's left on the "
                "left");
        case render::AnatomicalView::Inferior:
            return tr(
                "From the feet towards the head, anterior up: the patient's left on the "
                "right, as on the axial slice");
    }
    return {};
}

void DisplayPanel::labelCameraButtons() {
    const render::SceneFrame frame =
        viewer_->scene() ? viewer_->scene()->frame : render::SceneFrame::Unknown;
    for (std::size_t n = 0; n < anatomicalButtons_.size(); ++n) {
        const render::AnatomicalView view = render::allAnatomicalViews()[n];
        anatomicalButtons_.at(n)->setText(anatomicalLabel(view, frame));
    }
}

void DisplayPanel::applyCue() {
    render::VesselCueSettings cue = viewer_->vesselCue();
    cue.cue = static_cast<render::VesselCue>(cue_->currentData().toInt());
    cue.fogStrength = static_cast<float>(fromControl("cue.fogStrength", fogStrength_->value()));
    cue.fresnelExponent = static_cast<float>(fresnelExponent_->value());
    viewer_->setVesselCue(cue);
    updateApplicability();
    emit changed();
}

void DisplayPanel::applyBackground() {
    QColor color = background_->currentData().value<QColor>();
    if (!color.isValid()) {  // Custom…
        color =
            QColorDialog::getColor(toQColor(viewer_->background()), this, tr("Background colour"));
        if (!color.isValid()) {
            syncFromViewer();
            return;
        }
    }
    viewer_->setBackground(toVec(color));
    syncFromViewer();
    emit changed();
}

void DisplayPanel::chooseVesselColor() {
    auto* dialog = new QColorDialog(toQColor(viewer_->style().vesselColor), this);
    dialog->setObjectName(QStringLiteral("vesselColorDialog"));
    dialog->setWindowTitle(tr("Vessel colour"));
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    connect(dialog, &QColorDialog::colorSelected, this, [this](const QColor& color) {
        render::MeshStyle style = viewer_->style();
        style.vesselColor = toVec(color);
        viewer_->setStyle(style);
        syncFromViewer();
        emit changed();
    });
    dialog->open();
}

void DisplayPanel::applyLight() {
    render::MeshStyle style = viewer_->style();
    style.light.azimuth = static_cast<float>(lightAzimuth_->value());
    style.light.elevation = static_cast<float>(lightElevation_->value());
    viewer_->setStyle(style);
    emit changed();
}

void DisplayPanel::syncFromViewer() {
    syncing_ = true;
    lightAzimuth_->setValue(static_cast<double>(viewer_->style().light.azimuth));
    lightElevation_->setValue(static_cast<double>(viewer_->style().light.elevation));
    const render::VesselCueSettings& cue = viewer_->vesselCue();
    cue_->setCurrentIndex(cue_->findData(static_cast<int>(cue.cue)));
    fogStrength_->setValue(static_cast<int>(
        std::lround(toControl("cue.fogStrength", static_cast<double>(cue.fogStrength)))));
    fresnelExponent_->setValue(static_cast<double>(cue.fresnelExponent));
    const QColor background = toQColor(viewer_->background());
    int index = background_->count() - 1;  // Custom…
    for (int i = 0; i + 1 < background_->count(); ++i) {
        if (background_->itemData(i).value<QColor>().rgb() == background.rgb()) {
            index = i;
        }
    }
    background_->setCurrentIndex(index);
    legends_->setChecked(viewer_->legendsVisible());
    labelCameraButtons();
    const QColor vessel = toQColor(viewer_->style().vesselColor);
    vesselColor_->setText(vessel.name());
    vesselColor_->setStyleSheet(QStringLiteral("QToolButton { background-color: %1; color: %2; }")
                                    .arg(vessel.name(), vessel.lightnessF() > 0.5
                                                            ? QStringLiteral("black")
                                                            : QStringLiteral("white")));
    syncing_ = false;
    updateApplicability();
}

void DisplayPanel::updateApplicability() {
    const auto cue = viewer_->vesselCue().cue;
    setApplicable(fogStrength_, cue == render::VesselCue::Fog,
                  tr("How far the farthest vessels fade into the background"),
                  tr("Only the depth fog cue uses this"));
    setApplicable(fresnelExponent_, cue == render::VesselCue::Fresnel,
                  tr("k in (1 - |n·v|)^k: higher values keep the colour nearer the silhouette"),
                  tr("Only the Fresnel edge cue uses this"));
    const bool hasScene = viewer_->scene() != nullptr;
    setApplicable(vesselColor_, viewer_->style().array.empty(),
                  tr("Material colour of the vessels when no array colours them"),
                  tr("An array colours the vessels; choose the array None to use a material "
                     "colour"));
    const QString noData = tr("No data loaded");
    setApplicable(lightAzimuth_, hasScene,
                  tr("Where the light comes from, around the view: 0° = from the eye, positive = "
                     "from the right"),
                  noData);
    setApplicable(lightElevation_, hasScene,
                  tr("Where the light comes from, above or below: positive = from above"), noData);
    setApplicable(lightReset_, hasScene,
                  tr("The default light: a little above and left of the eye"), noData);
    const render::SceneFrame frame =
        hasScene ? viewer_->scene()->frame : render::SceneFrame::Unknown;
    for (auto* button : cameraButtons_->findChildren<QToolButton*>()) {
        // An anatomical view says where it looks from and what is up.
        auto* const anatomical =
            std::find(anatomicalButtons_.begin(), anatomicalButtons_.end(), button);
        const QString what =
            anatomical == anatomicalButtons_.end()
                ? tr("Move the camera to this view of the data")
                : anatomicalToolTip(render::allAnatomicalViews()[static_cast<std::size_t>(
                                        anatomical - anatomicalButtons_.begin())],
                                    frame);
        setApplicable(button, hasScene, what, tr("No data loaded"));
    }
}

void DisplayPanel::frameRendered() {
    if (!overlay_->isVisible()) {
        return;
    }
    QStringList lines;
    double total = 0.0;
    for (const auto& pass : viewer_->lastPasses()) {
        if (pass.milliseconds) {
            lines << QStringLiteral("%1 %L2 ms")
                         .arg(QString::fromStdString(pass.name), -14)
                         .arg(*pass.milliseconds, 6, 'f', 2);
            total += *pass.milliseconds;
        } else {
            lines << QStringLiteral("%1 %2")
                         .arg(QString::fromStdString(pass.name), -14)
                         .arg(pass.state == render::PassState::Culled ? tr("culled")
                                                                      : tr("cached"));
        }
    }
    if (lines.isEmpty()) {
        lines << tr("no frame yet");
    } else {
        lines << tr("total (CPU) %1 ms").arg(QLocale().toString(total, 'f', 2), 6);
    }
    overlay_->setText(lines.join(QLatin1Char('\n')));
    overlay_->adjustSize();
    overlay_->raise();
}

}  // namespace vv::gui::panels
