// SPDX-License-Identifier: GPL-3.0-or-later
#include "gui/panels/SegmentationPanel.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QEvent>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLocale>
#include <QMouseEvent>
#include <QProgressBar>
#include <QPushButton>
#include <QSignalBlocker>
#include <QSpinBox>
#include <QStyle>
#include <QTimer>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>
#include <limits>

#include "common/SegmentationText.h"
#include "gui/EngineTexts.h"
#include "gui/SegmentationTask.h"
#include "gui/ViewerWidget.h"
#include "gui/panels/PanelUtil.h"
#include "vv/core/Error.h"

namespace vv::gui::panels {

namespace {

/// Delay between the last change of a control and its preview.
constexpr int kDebounceMs = 300;
/// The preview's surface is decimated to at most this many triangles.
constexpr int kPreviewTriangles = 40000;
/// A seed taken from a surface point may lie this many voxels from it.
constexpr int kSeedRadius = 2;
constexpr int kMaxTriangles = 10000000;
constexpr int kTriangleStep = 10000;

}  // namespace

SegmentationPanel::SegmentationPanel(ViewerWidget* viewer, QWidget* parent)
    : QWidget(parent), viewer_(viewer), debounce_(new QTimer(this)) {
    setObjectName(QStringLiteral("segmentationPanel"));
    debounce_->setSingleShot(true);
    debounce_->setInterval(kDebounceMs);
    connect(debounce_, &QTimer::timeout, this, &SegmentationPanel::startPreview);
    buildControls();
    makeNarrow(this);
    viewer_->installEventFilter(this);
    connect(viewer_, &ViewerWidget::volumeFailed, this, [this](const QString& why) {
        if (display_ == Display::RaycastIsoSurface) {
            setDisplay(Display::SurfaceMesh);
            showMessage(tr("The volume cannot be ray cast here: %1").arg(why));
        }
    });
    setVolume(nullptr);
}

void SegmentationPanel::buildControls() {
    auto* outer = new QVBoxLayout(this);
    auto* top = new QFormLayout;
    outer->addLayout(top);
    addVolumeRows(top);

    segmentation_ = new QWidget(this);
    auto* form = new QFormLayout(segmentation_);
    form->setContentsMargins(0, 0, 0, 0);
    outer->addWidget(segmentation_);
    addThresholdRows(form);
    addComponentRows(form);
    addSurfaceRows(form);

    addSeedAndPreviewRow(outer);
    addApplyRows(outer);
    outer->addStretch(1);
}

void SegmentationPanel::addVolumeRows(QFormLayout* top) {
    volumeLabel_ = new QLabel(this);
    volumeLabel_->setObjectName(QStringLiteral("segmentationVolume"));
    volumeLabel_->setWordWrap(true);
    top->addRow(volumeLabel_);

    displayBox_ = new QComboBox(this);
    displayBox_->setObjectName(QStringLiteral("volumeDisplay"));
    displayBox_->addItem(tr("Surface mesh"), static_cast<int>(Display::SurfaceMesh));
    displayBox_->addItem(tr("Ray-cast iso-surface"), static_cast<int>(Display::RaycastIsoSurface));
    displayBox_->setToolTip(
        tr("Surface mesh: the segmented vessels. Ray-cast iso-surface: the volume itself, "
           "without segmentation, cut at the iso value"));
    top->addRow(tr("Show volume as:"), displayBox_);
    connect(displayBox_, &QComboBox::currentIndexChanged, this,
            [this] { setDisplay(static_cast<Display>(displayBox_->currentData().toInt())); });
    iso_ = new QDoubleSpinBox(this);
    iso_->setObjectName(QStringLiteral("isoValue"));
    iso_->setDecimals(0);
    iso_->setKeyboardTracking(false);
    top->addRow(tr("Iso value:"), iso_);
    connect(iso_, &QDoubleSpinBox::valueChanged, this, [this](double value) {
        if (filling_) {
            return;
        }
        isoFollowsLower_ = false;
        if (display_ == Display::RaycastIsoSurface && volume_) {
            viewer_->setVolume(volume_, static_cast<float>(value));
        }
    });
}

void SegmentationPanel::addThresholdRows(QFormLayout* form) {
    lower_ = new QDoubleSpinBox(segmentation_);
    lower_->setObjectName(QStringLiteral("thresholdLower"));
    upper_ = new QDoubleSpinBox(segmentation_);
    upper_->setObjectName(QStringLiteral("thresholdUpper"));
    for (QDoubleSpinBox* box : {lower_, upper_}) {
        box->setDecimals(0);
        box->setKeyboardTracking(false);  // one preview per entered value
    }
    lower_->setToolTip(tr("Voxels at or above this value may be vessels"));
    upper_->setToolTip(tr("Voxels at or below this value may be vessels"));
    auto* range = new QHBoxLayout;
    range->addWidget(lower_, 1);
    range->addWidget(new QLabel(tr("to"), segmentation_));
    range->addWidget(upper_, 1);
    form->addRow(tr("Threshold:"), range);
    default_ = new QPushButton(tr("Default"), segmentation_);
    default_->setObjectName(QStringLiteral("thresholdDefault"));
    defaultLabel_ = new QLabel(segmentation_);
    defaultLabel_->setObjectName(QStringLiteral("thresholdDefaultLabel"));
    defaultLabel_->setWordWrap(true);
    auto* defaults = new QHBoxLayout;
    defaults->addWidget(defaultLabel_, 1);
    defaults->addWidget(default_);
    form->addRow(defaults);
    connect(default_, &QPushButton::clicked, this, [this] {
        if (defaultRange_) {
            setRange(*defaultRange_, true);
        }
    });
    connect(lower_, &QDoubleSpinBox::valueChanged, this, [this](double value) {
        if (isoFollowsLower_ && !filling_) {
            const QSignalBlocker block(iso_);
            iso_->setValue(value);
        }
        rangeIsDefault_ = rangeIsDefault_ && settingRange_;
        optionsChanged();
    });
    connect(upper_, &QDoubleSpinBox::valueChanged, this, [this] {
        rangeIsDefault_ = rangeIsDefault_ && settingRange_;
        optionsChanged();
    });
}

void SegmentationPanel::addComponentRows(QFormLayout* form) {
    mode_ = new QComboBox(segmentation_);
    mode_->setObjectName(QStringLiteral("componentMode"));
    mode_->addItem(tr("Largest components"), static_cast<int>(Mode::Largest));
    mode_->addItem(tr("Component under seed"), static_cast<int>(Mode::Seed));
    form->addRow(tr("Keep:"), mode_);
    connect(mode_, &QComboBox::currentIndexChanged, this, [this] {
        updateApplicability();
        optionsChanged();
    });
    components_ = new QSpinBox(segmentation_);
    components_->setObjectName(QStringLiteral("componentCount"));
    components_->setRange(1, 255);
    components_->setKeyboardTracking(false);
    form->addRow(tr("Components:"), components_);
    connect(components_, &QSpinBox::valueChanged, this, &SegmentationPanel::optionsChanged);
    seedLabel_ = new QLabel(segmentation_);
    seedLabel_->setObjectName(QStringLiteral("seedLabel"));
    seedLabel_->setWordWrap(true);
    seedLabel_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    form->addRow(tr("Seed:"), seedLabel_);
    bone_ = new QCheckBox(tr("Remove bone-like components"), segmentation_);
    bone_->setObjectName(QStringLiteral("boneRemoval"));
    bone_->setToolTip(
        tr("Drop bright components mostly made of voxels of 1000 HU or more (CT); a vessel "
           "touching bone is dropped with it"));
    form->addRow(bone_);
    connect(bone_, &QCheckBox::toggled, this, &SegmentationPanel::optionsChanged);
}

void SegmentationPanel::addSurfaceRows(QFormLayout* form) {
    correction_ = new QCheckBox(tr("Correct the signal fall-off (MR)"), segmentation_);
    correction_->setObjectName(QStringLiteral("intensityCorrection"));
    form->addRow(correction_);
    connect(correction_, &QCheckBox::toggled, this, [this] {
        if (filling_ || !volume_) {
            return;
        }
        // The default range (and the gain field) belong to the corrected or
        // the plain values: computed again; a range at the default follows it.
        gain_.reset();
        startDefaultRange();
        optionsChanged();
    });
    triangles_ = new QSpinBox(segmentation_);
    triangles_->setObjectName(QStringLiteral("surfaceTriangles"));
    triangles_->setRange(0, kMaxTriangles);
    triangles_->setSingleStep(kTriangleStep);
    triangles_->setSpecialValueText(tr("All"));
    triangles_->setKeyboardTracking(false);
    triangles_->setToolTip(tr("Decimate the surface to about this many triangles (All: none)"));
    form->addRow(tr("Surface triangles:"), triangles_);
    connect(triangles_, &QSpinBox::valueChanged, this, &SegmentationPanel::optionsChanged);
}

void SegmentationPanel::addSeedAndPreviewRow(QVBoxLayout* outer) {
    // Pick seed and preview stay usable in the ray-cast display.
    pickSeed_ = new QPushButton(tr("Pick Seed"), this);
    pickSeed_->setObjectName(QStringLiteral("pickSeed"));
    pickSeed_->setCheckable(true);
    pickSeed_->setToolTip(
        tr("Click a vessel in the 3-D view: keep only the component under that point"));
    preview_ = new QCheckBox(tr("Live preview"), this);
    preview_->setObjectName(QStringLiteral("segmentationPreview"));
    preview_->setChecked(true);
    preview_->setToolTip(
        tr("Show a quick segmentation of a downsampled copy whenever a control changes"));
    connect(preview_, &QCheckBox::toggled, this, [this](bool on) {
        if (on && dirty_) {
            debounce_->start();
        } else if (!on) {
            stopPreview();
        }
    });
    auto* seedRow = new QHBoxLayout;
    seedRow->addWidget(pickSeed_);
    seedRow->addWidget(preview_, 1);
    outer->addLayout(seedRow);
}

void SegmentationPanel::addApplyRows(QVBoxLayout* outer) {
    apply_ = new QPushButton(tr("Apply"), this);
    apply_->setObjectName(QStringLiteral("segmentationApply"));
    apply_->setToolTip(tr("Segment the whole volume at full resolution"));
    connect(apply_, &QPushButton::clicked, this, &SegmentationPanel::apply);
    cancel_ = new QPushButton(tr("Cancel"), this);
    cancel_->setObjectName(QStringLiteral("segmentationCancel"));
    connect(cancel_, &QPushButton::clicked, this, &SegmentationPanel::cancelApply);
    progress_ = new QProgressBar(this);
    progress_->setRange(0, 1000);
    progress_->setTextVisible(false);
    auto* applyRow = new QHBoxLayout;
    applyRow->addWidget(apply_);
    applyRow->addWidget(progress_, 1);
    applyRow->addWidget(cancel_);
    outer->addLayout(applyRow);
    message_ = new QLabel(this);
    message_->setObjectName(QStringLiteral("segmentationMessage"));
    message_->setWordWrap(true);
    message_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    outer->addWidget(message_);
    cutOffBox_ = new QWidget(this);
    auto* cutOffRow = new QHBoxLayout(cutOffBox_);
    cutOffRow->setContentsMargins(0, 0, 0, 0);
    auto* icon = new QLabel(cutOffBox_);
    const int side = style()->pixelMetric(QStyle::PM_SmallIconSize);
    icon->setPixmap(style()->standardIcon(QStyle::SP_MessageBoxWarning).pixmap(side, side));
    icon->setAlignment(Qt::AlignTop);
    cutOffRow->addWidget(icon, 0, Qt::AlignTop);
    cutOff_ = new QLabel(cutOffBox_);
    cutOff_->setObjectName(QStringLiteral("cutOffWarning"));
    cutOff_->setWordWrap(true);
    cutOff_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    cutOffRow->addWidget(cutOff_, 1);
    cutOffBox_->hide();
    outer->addWidget(cutOffBox_);
}

void SegmentationPanel::setVolume(std::shared_ptr<const scene::Volume> volume,
                                  const segmentation::SegmentationOptions& options,
                                  const segmentation::ThresholdRange& range,
                                  const segmentation::SurfaceOptions& surface) {
    stopPreview();
    abandon(applyTask_);
    if (display_ == Display::RaycastIsoSurface) {
        viewer_->setVolume(nullptr, 0.0F);
    }
    display_ = Display::SurfaceMesh;
    meshScene_.reset();
    volume_ = std::move(volume);
    defaultRange_.reset();
    gain_.reset();
    rangeIsDefault_ = volume_ != nullptr && !options.range;
    cutOffBox_->hide();
    seed_ = options.seed;
    dirty_ = false;
    isoFollowsLower_ = true;
    lastOutcome_.reset();
    previewShown_ = false;
    applyRequest_.reset();
    pickSeed_->setChecked(false);
    progress_->setValue(0);
    message_->clear();

    filling_ = true;
    {
        const QSignalBlocker blockDisplay(displayBox_);
        const QSignalBlocker blockLower(lower_);
        const QSignalBlocker blockUpper(upper_);
        const QSignalBlocker blockMode(mode_);
        const QSignalBlocker blockComponents(components_);
        const QSignalBlocker blockBone(bone_);
        const QSignalBlocker blockCorrection(correction_);
        const QSignalBlocker blockTriangles(triangles_);
        displayBox_->setCurrentIndex(0);
        if (volume_) {
            // Room beyond the values in the volume, so any range can be typed.
            const auto [lo, hi] = volume_->valueRange();
            const double span = std::max(1.0, static_cast<double>(hi) - static_cast<double>(lo));
            const QString suffix = volume_->unit().empty()
                                       ? QString()
                                       : QStringLiteral(" ") + fromUtf8(volume_->unit());
            for (QDoubleSpinBox* box : {lower_, upper_, iso_}) {
                box->setSpecialValueText(QString());
                box->setRange(static_cast<double>(lo) - span, static_cast<double>(hi) + span);
                box->setSuffix(suffix);
            }
            const segmentation::ThresholdRange used = options.range.value_or(range);
            lower_->setValue(static_cast<double>(used.lower));
            upper_->setValue(static_cast<double>(used.upper));
            iso_->setValue(static_cast<double>(used.lower));
            components_->setValue(std::clamp(options.keepComponents, 1, 255));
            mode_->setCurrentIndex(options.seed ? 1 : 0);
            const bool ct = volume_->modality() == "CT" || volume_->unit() == "HU";
            bone_->setChecked(options.removeBone.value_or(ct));
            correction_->setChecked(!ct && options.correctIntensity.value_or(
                                               segmentation::intensityCorrectionDefault(*volume_)));
            triangles_->setValue(
                static_cast<int>(std::min<std::size_t>(surface.targetTriangles, kMaxTriangles)));
            const glm::ivec3 d = volume_->dims();
            volumeLabel_->setText(
                tr("Volume: %1 × %2 × %3 voxels%4")
                    .arg(d.x)
                    .arg(d.y)
                    .arg(d.z)
                    .arg(volume_->modality().empty()
                             ? QString()
                             : QStringLiteral(", ") + fromUtf8(volume_->modality())));
            startDefaultRange();
        } else {
            // Nothing of the last volume stays (its thresholds, modality, seed):
            // the disabled controls show no values.
            for (QDoubleSpinBox* box : {lower_, upper_, iso_}) {
                box->setRange(0.0, 0.0);
                box->setSuffix(QString());
                box->setSpecialValueText(QStringLiteral("\u2014"));
                box->setValue(0.0);
            }
            components_->setValue(1);
            mode_->setCurrentIndex(0);
            bone_->setChecked(false);
            triangles_->setValue(0);
            volumeLabel_->setText(tr("No volume"));
            defaultLabel_->clear();
            defaultLabel_->setToolTip(QString());
        }
    }
    filling_ = false;
    seedLabel_->setText(
        seed_ && volume_
            ? tr("(%1, %2, %3): %4")
                  .arg(seed_->x)
                  .arg(seed_->y)
                  .arg(seed_->z)
                  .arg(valueText(static_cast<double>(volume_->value(seed_->x, seed_->y, seed_->z))))
            : tr("none"));
    setApplicable(this, volume_ != nullptr, QString(),
                  tr("Only for scenes segmented from a CT or MR series: open one with "
                     "File > Open Folder…"));
    updateApplicability();
}

void SegmentationPanel::startDefaultRange() {
    // The modality default: a histogram pass for MR (after the intensity
    // correction, whose gain field is estimated here once), so not on the GUI thread.
    const std::shared_ptr<const scene::Volume> volume = volume_;
    const bool correct = correcting();
    defaultLabel_->setText(tr("Default: computing…"));
    defaultRange_.reset();
    updateApplicability();
    defaultRangeRun_.start(
        [volume, correct](const std::stop_token& stop) -> Defaults {
            Defaults defaults;
            try {
                if (!correct) {
                    defaults.range = segmentation::defaultThresholdRange(*volume);
                    return defaults;
                }
                const Progress progress({}, stop);
                defaults.gain = std::make_shared<const segmentation::GainField>(
                    segmentation::estimateGainField(*volume, {}, progress));
                defaults.range = segmentation::defaultThresholdRange(
                    segmentation::correctedVolume(*volume, *defaults.gain, progress));
            } catch (const vv::Error&) {
                defaults.range.reset();  // cancelled, or a single value: no default
            }
            return defaults;
        },
        [this, volume, correct](Defaults defaults) {
            if (volume != volume_ || correct != correcting()) {
                return;  // computed for an older volume or setting
            }
            defaultRange_ = std::move(defaults.range);
            gain_ = std::move(defaults.gain);
            defaultLabel_->setText(
                defaultRange_ ? tr("Default: %1 to %2")
                                    .arg(valueText(static_cast<double>(defaultRange_->lower)),
                                         valueText(static_cast<double>(defaultRange_->upper)))
                              : tr("Default: none (the volume holds a single value)"));
            // The rule behind it, in the UI language ("CT angiography default: …").
            defaultLabel_->setToolTip(
                defaultRange_
                    ? thresholdRuleText(*defaultRange_, [this](double v) { return valueText(v); })
                    : QString());
            if (defaultRange_ && rangeIsDefault_) {
                setRange(*defaultRange_, true);  // the default of the values now thresholded
            }
            updateApplicability();
        });
}

void SegmentationPanel::setRange(const segmentation::ThresholdRange& range, bool isDefault) {
    const auto lower = static_cast<double>(range.lower);
    const auto upper = static_cast<double>(range.upper);
    rangeIsDefault_ = isDefault;
    // The boxes round to their decimals: a range they already show is no change.
    const auto shows = [](const QDoubleSpinBox* box, double value) {
        return box->textFromValue(value) == box->textFromValue(box->value());
    };
    if (shows(lower_, lower) && shows(upper_, upper)) {
        return;
    }
    settingRange_ = true;
    {
        const QSignalBlocker block(upper_);
        upper_->setValue(upper);
    }
    lower_->setValue(lower);  // previews once
    settingRange_ = false;
    optionsChanged();
}

bool SegmentationPanel::correcting() const {
    return volume_ && correction_->isChecked();  // never ticked for CT (setVolume)
}

double SegmentationPanel::thresholdedValue(const glm::ivec3& voxel) const {
    const auto value = static_cast<double>(volume_->value(voxel.x, voxel.y, voxel.z));
    return correcting() && gain_ ? value / gain_->at(volume_->worldPosition(glm::dvec3(voxel)))
                                 : value;
}

QString SegmentationPanel::valueText(double value) const {
    const QString number = QLocale().toString(value, 'f', 0);
    return volume_ && !volume_->unit().empty()
               ? number + QStringLiteral(" ") + fromUtf8(volume_->unit())
               : number;
}

segmentation::SegmentationOptions SegmentationPanel::segmentationOptions() const {
    segmentation::SegmentationOptions options;
    segmentation::ThresholdRange range;
    range.lower = static_cast<float>(std::min(lower_->value(), upper_->value()));
    range.upper = static_cast<float>(std::max(lower_->value(), upper_->value()));
    range.rule = "chosen in the Segmentation panel";
    options.range = range;
    options.keepComponents = components_->value();
    if (static_cast<Mode>(mode_->currentData().toInt()) == Mode::Seed) {
        options.seed = seed_;
    }
    options.removeBone = bone_->isChecked();
    options.correctIntensity = correcting();
    if (options.correctIntensity.value_or(false)) {
        options.gainField = gain_;
    }
    return options;
}

segmentation::SurfaceOptions SegmentationPanel::surfaceOptions() const {
    segmentation::SurfaceOptions surface;
    surface.targetTriangles = static_cast<std::size_t>(triangles_->value());
    return surface;
}

void SegmentationPanel::updateApplicability() {
    const bool applying = isApplying();
    const bool raycast = display_ == Display::RaycastIsoSurface;
    const bool seedMode = static_cast<Mode>(mode_->currentData().toInt()) == Mode::Seed;
    setApplicable(segmentation_, !applying && !raycast, QString(),
                  applying ? tr("Wait for Apply to finish, or cancel it")
                           : tr("The segmentation shapes the surface mesh: show the volume "
                                "as a surface mesh to change it"));
    setApplicable(displayBox_, !applying, displayBox_->toolTip(),
                  tr("Wait for Apply to finish, or cancel it"));
    setApplicable(iso_, raycast,
                  tr("The iso-surface that rays stop at; follows the lower threshold until "
                     "edited"),
                  tr("Only for the ray-cast iso-surface display"));
    setApplicable(components_, !seedMode, tr("Keep this many of the largest components"),
                  tr("The seed mode keeps the one component under the seed"));
    const bool ct = volume_ && (volume_->modality() == "CT" || volume_->unit() == "HU");
    setApplicable(correction_, !ct,
                  tr("Divide out the slow fall-off of the MR signal away from the receive coils "
                     "before thresholding, so that a vessel is not cut off where the signal "
                     "fades. The thresholds then apply to the corrected values."),
                  tr("CT values (HU) have no receive-coil fall-off to correct"));
    setApplicable(default_, defaultRange_.has_value(),
                  tr("Use the default range of the volume's modality"),
                  tr("The default range is not known yet"));
    setApplicable(pickSeed_, !applying, pickSeed_->toolTip(),
                  tr("Wait for Apply to finish, or cancel it"));
    const bool seedMissing = seedMode && !seed_;
    setApplicable(apply_, !applying && !raycast && !seedMissing,
                  tr("Segment the whole volume at full resolution"),
                  raycast       ? tr("Show the volume as a surface mesh to apply a segmentation")
                  : seedMissing ? tr("Pick a seed first")
                                : tr("Apply is running"));
    cancel_->setEnabled(applying);
    cancel_->setToolTip(applying ? tr("Stop Apply; the scene stays as it is")
                                 : tr("Nothing to cancel"));
    progress_->setVisible(applying);
}

void SegmentationPanel::showMessage(const QString& text) {
    message_->setText(text);
    message_->setToolTip(QString());
    emit statusMessage(text);
}

void SegmentationPanel::showProblemMessage(const QString& text, const ProblemText& problem) {
    showMessage(text);
    message_->setToolTip(problem.details);  // the module's own words, on demand
}

void SegmentationPanel::optionsChanged() {
    if (filling_ || !volume_) {
        return;
    }
    dirty_ = true;
    if (preview_->isChecked()) {
        debounce_->start();  // restarts: one preview 300 ms after the last change
    }
}

segmentation::SegmentationRequest SegmentationPanel::segmentationRequest(int step,
                                                                         int maxTriangles) const {
    segmentation::SegmentationRequest request;
    request.volume = volume_;
    request.segmentation = segmentationOptions();
    request.surface = surfaceOptions();
    if (maxTriangles > 0 &&
        (request.surface.targetTriangles == 0 ||
         request.surface.targetTriangles > static_cast<std::size_t>(maxTriangles))) {
        request.surface.targetTriangles = static_cast<std::size_t>(maxTriangles);
    }
    request.step = step;
    return request;
}

SegmentationTask* SegmentationPanel::makeTask(int step, int maxTriangles) {
    return new SegmentationTask(segmentationRequest(step, maxTriangles), this);
}

bool SegmentationPanel::showsFullResolution() const {
    return volume_ && display_ == Display::SurfaceMesh && !dirty_ && !isPreviewing() &&
           (!lastOutcome_ || lastOutcome_->step == 1);
}

void SegmentationPanel::abandon(QPointer<SegmentationTask>& task) {
    if (!task.isNull()) {
        // Its result is no longer wanted; it deletes itself once the worker stops.
        disconnect(task, nullptr, this, nullptr);
        connect(task, &SegmentationTask::finished, task, &QObject::deleteLater);
        task->cancel();
        task = nullptr;
    }
}

void SegmentationPanel::stopPreview() {
    debounce_->stop();
    abandon(previewTask_);
}

bool SegmentationPanel::isPreviewing() const {
    return debounce_->isActive() || !previewTask_.isNull();
}

void SegmentationPanel::startPreview() {
    debounce_->stop();
    if (!volume_ || isApplying() || display_ == Display::RaycastIsoSurface) {
        return;
    }
    const segmentation::SegmentationOptions options = segmentationOptions();
    if (static_cast<Mode>(mode_->currentData().toInt()) == Mode::Seed && !options.seed) {
        showMessage(tr("Pick a seed: turn on Pick Seed and click a vessel"));
        return;
    }
    stopPreview();  // a newer change wins
    const int step = segmentation::previewStep(volume_->dims());
    SegmentationTask* task = makeTask(step, kPreviewTriangles);
    previewTask_ = task;
    connect(task, &SegmentationTask::succeeded, this, &SegmentationPanel::previewDone);
    connect(task, &SegmentationTask::failed, this, [this](const ProblemText& problem) {
        showProblemMessage(tr("No preview: %1").arg(problem.summary), problem);
    });
    connect(task, &SegmentationTask::finished, this, [this, task] {
        if (previewTask_ == task) {
            previewTask_ = nullptr;
        }
        task->deleteLater();
    });
    task->start();
}

void SegmentationPanel::previewDone(
    const std::shared_ptr<const segmentation::SegmentationOutcome>& outcome) {
    lastOutcome_ = outcome;
    previewShown_ = true;
    ++previewsShown_;
    const QString sampling = outcome->step == 1 ? tr("full resolution")
                                                : tr("one voxel in %1 per axis").arg(outcome->step);
    const QString what = tr("Preview (%1): %2 triangles; components kept: %3")
                             .arg(sampling)
                             .arg(QLocale().toString(static_cast<qulonglong>(outcome->triangles)))
                             .arg(outcome->componentsKept);
    // A preview is never exported or sent (DocumentController::showsPreview()).
    message_->setText(what + QStringLiteral("; ") +
                      tr("Apply it to export, report or send it at full resolution"));
    showCutOff(outcome->cutOff, outcome->intensityCorrected);
    emit labelMapReady(outcome->labelMap);
    emit sceneReady(outcome->scene,
                    what + QStringLiteral(" — ") +
                        tr("Apply it to export, report or send it at full resolution"));
}

void SegmentationPanel::apply() {
    if (!volume_ || isApplying() || display_ == Display::RaycastIsoSurface) {
        return;
    }
    stopPreview();
    applyRequest_ = segmentationRequest(1, 0);
    auto* task = new SegmentationTask(*applyRequest_, this);
    applyTask_ = task;
    connect(task, &SegmentationTask::progressChanged, this, [this](double fraction) {
        progress_->setValue(static_cast<int>(std::lround(fraction * 1000.0)));
    });
    connect(task, &SegmentationTask::succeeded, this, &SegmentationPanel::applyDone);
    connect(task, &SegmentationTask::failed, this, [this](const ProblemText& problem) {
        showProblemMessage(tr("Apply failed: %1").arg(problem.summary), problem);
        emit applyFinished(false);
    });
    connect(task, &SegmentationTask::cancelled, this, [this] {
        showMessage(tr("Apply cancelled; the scene is unchanged"));
        emit applyFinished(false);
    });
    connect(task, &SegmentationTask::finished, this, [this, task] {
        if (applyTask_ == task) {
            applyTask_ = nullptr;
        }
        task->deleteLater();
        updateApplicability();
    });
    progress_->setValue(0);
    message_->setText(tr("Segmenting at full resolution…"));
    task->start();
    updateApplicability();
}

void SegmentationPanel::applyDone(
    const std::shared_ptr<const segmentation::SegmentationOutcome>& outcome) {
    lastOutcome_ = outcome;
    dirty_ = false;
    const QString what = tr("Segmented: %1 triangles; components kept: %2 of %3")
                             .arg(QLocale().toString(static_cast<qulonglong>(outcome->triangles)))
                             .arg(outcome->componentsKept)
                             .arg(outcome->componentsFound);
    message_->setText(what);
    showCutOff(outcome->cutOff, outcome->intensityCorrected);
    previewShown_ = false;
    emit applied(outcome, *applyRequest_);
    emit labelMapReady(outcome->labelMap);
    emit sceneReady(outcome->scene, what);
    emit applyFinished(true);
}

void SegmentationPanel::cancelApply() {
    if (!applyTask_.isNull()) {
        applyTask_->cancel();
        message_->setText(tr("Cancelling…"));
    }
}

bool SegmentationPanel::isApplying() const {
    return !applyTask_.isNull();
}

void SegmentationPanel::setDisplay(Display display) {
    if (!volume_ || display == display_ || isApplying()) {
        const QSignalBlocker block(displayBox_);
        displayBox_->setCurrentIndex(static_cast<int>(display_));
        return;
    }
    display_ = display;
    {
        const QSignalBlocker block(displayBox_);
        displayBox_->setCurrentIndex(static_cast<int>(display_));
    }
    if (display_ == Display::RaycastIsoSurface) {
        stopPreview();
        meshScene_ = viewer_->scene();
        const auto iso = static_cast<float>(iso_->value());
        viewer_->setVolume(volume_, iso);
        auto volumeOnly = std::make_shared<scene::Scene>();  // no meshes, the volume's frame
        volumeOnly->frame = scene::SceneFrame::PatientLps;
        emit sceneReady(std::move(volumeOnly),
                        tr("Ray-cast iso-surface at %1").arg(valueText(static_cast<double>(iso))));
    } else {
        viewer_->setVolume(nullptr, 0.0F);
        std::shared_ptr<const scene::Scene> scene = std::move(meshScene_);
        meshScene_.reset();
        emit sceneReady(scene, tr("Surface mesh"));
        if (dirty_ && preview_->isChecked()) {
            debounce_->start();
        }
    }
    updateApplicability();
}

bool SegmentationPanel::pickSeed(const glm::vec3& world) {
    if (!volume_) {
        return false;
    }
    const glm::dvec3 ijk(volume_->worldToIndex() * glm::dvec4(glm::dvec3(world), 1.0));
    const glm::ivec3 dims = volume_->dims();
    const glm::ivec3 nearest(static_cast<int>(std::lround(ijk.x)),
                             static_cast<int>(std::lround(ijk.y)),
                             static_cast<int>(std::lround(ijk.z)));
    if (!std::isfinite(ijk.x) || !std::isfinite(ijk.y) || !std::isfinite(ijk.z) ||
        glm::any(glm::lessThan(nearest, glm::ivec3(0))) ||
        glm::any(glm::greaterThanEqual(nearest, dims))) {
        showMessage(tr("The point lies outside the volume: no seed there"));
        return false;
    }
    const segmentation::SegmentationOptions options = segmentationOptions();
    const float lower = options.range->lower;
    const float upper = options.range->upper;
    const std::optional<glm::ivec3> voxel = segmentation::nearestVoxelInRange(
        *volume_, ijk, lower, upper, kSeedRadius, correcting() ? gain_.get() : nullptr);
    if (!voxel) {
        showMessage(
            tr("Voxel (%1, %2, %3) holds %4, outside the threshold range %5 to %6: no component "
               "there. Click on a vessel, or widen the range.")
                .arg(nearest.x)
                .arg(nearest.y)
                .arg(nearest.z)
                .arg(valueText(thresholdedValue(nearest)), valueText(static_cast<double>(lower)),
                     valueText(static_cast<double>(upper))));
        return false;
    }
    seed_ = voxel;
    const QString where = tr("(%1, %2, %3): %4")
                              .arg(voxel->x)
                              .arg(voxel->y)
                              .arg(voxel->z)
                              .arg(valueText(thresholdedValue(*voxel)));
    seedLabel_->setText(where);
    pickSeed_->setChecked(false);
    showMessage(tr("Seed at voxel %1").arg(where));
    if (mode_->currentIndex() != static_cast<int>(Mode::Seed)) {
        mode_->setCurrentIndex(static_cast<int>(Mode::Seed));  // previews via optionsChanged
    } else {
        optionsChanged();
    }
    updateApplicability();
    return true;
}

void SegmentationPanel::showCutOff(const std::vector<segmentation::CutOffVessel>& vessels,
                                   bool corrected) {
    if (vessels.empty()) {
        cutOffBox_->hide();
        cutOff_->clear();
        return;
    }
    QString text = app::cutOffText(vessels);
    text += QStringLiteral(" ") +
            // (Not correction_->isEnabled(): the controls are off while Apply runs.)
            (!corrected && volume_ && volume_->modality() != "CT" && volume_->unit() != "HU"
                 ? tr("Turn on “Correct the signal fall-off (MR)” or lower the threshold.")
                 : tr("Lower the threshold, or pick a seed in the missing part."));
    cutOff_->setText(text);
    cutOffBox_->show();
}

void SegmentationPanel::pickAt(const QPointF& position) {
    if (const auto result = viewer_->probeAt(position)) {
        pickSeed(result->worldPosition);
    } else {
        showMessage(tr("No surface under the mouse: click on a vessel"));
    }
}

bool SegmentationPanel::eventFilter(QObject* watched, QEvent* event) {
    if (watched == viewer_ && pickSeed_->isChecked() && volume_) {
        if (const auto at = click_.clicked(event)) {
            pickAt(*at);
        }
    }
    return QWidget::eventFilter(watched, event);
}

}  // namespace vv::gui::panels
