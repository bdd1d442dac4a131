// SPDX-License-Identifier: GPL-3.0-or-later
#include "gui/panels/VssPanel.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLocale>
#include <QSignalBlocker>
#include <QSlider>
#include <QSpinBox>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>

#include "common/SettingsSchema.h"
#include "gui/EngineTexts.h"
#include "gui/ViewerWidget.h"
#include "gui/panels/CollapsibleSection.h"
#include "gui/panels/PanelUtil.h"
#include "vv/colormaps/DepthScale.h"
#include "vv/core/Error.h"
#include "vv/vss/DepthNormalization.h"
#include "vv/vss/Solver.h"

namespace vv::gui::panels {

namespace {

/// A slider's position for the setting `key` (a fraction shown in percent).
int sliderPosition(std::string_view key, float value) {
    return static_cast<int>(std::lround(toControl(key, static_cast<double>(value))));
}

/// The setting `key`'s value at a slider's position.
float sliderValue(std::string_view key, const QSlider* slider) {
    return static_cast<float>(fromControl(key, slider->value()));
}

}  // namespace

double VssPanel::powerFromSlider(int position) noexcept {
    const app::Setting& p = app::setting("vss.p");
    const double t = std::clamp(position, 0, kSliderSteps) / static_cast<double>(kSliderSteps);
    return p.min * std::pow(p.max / p.min, t);
}

int VssPanel::sliderFromPower(double power) noexcept {
    const app::Setting& p = app::setting("vss.p");
    if (!(power > p.min)) {
        return 0;
    }
    const double t = std::log(power / p.min) / std::log(p.max / p.min);
    return std::clamp(static_cast<int>(std::lround(t * kSliderSteps)), 0, kSliderSteps);
}

VssPanel::VssPanel(ViewerWidget* viewer, QWidget* parent) : QWidget(parent), viewer_(viewer) {
    setObjectName(QStringLiteral("vssPanel"));
    // What a newcomer needs first: on/off, colour scale, p; then how the
    // surface looks; the solver's internals in "Advanced", folded.
    auto* outer = new QVBoxLayout(this);
    auto* form = new QFormLayout;
    outer->addLayout(form);
    addFirstRows(form);
    addLookRows(form);
    addRangeRows(form);
    outer->addWidget(buildAdvancedSection());

    makeNarrow(this);
    powerBox_->setSizePolicy(QSizePolicy::Fixed, QSizePolicy::Fixed);
    powerBox_->setFixedWidth(powerBox_->sizeHint().width());
    syncFromViewer();
    connectControls();
}

void VssPanel::addFirstRows(QFormLayout* form) {
    enabled_ = new QCheckBox(settingLabel("vss.enabled"), this);
    enabled_->setObjectName(QStringLiteral("vssEnabled"));
    enabled_->setToolTip(tr("A depth-coded surface in the space between the vessels"));
    form->addRow(enabled_);

    scale_ = new QComboBox(this);
    scale_->setObjectName(QStringLiteral("depthScaleChooser"));
    for (const auto scale : colormaps::allDepthScales()) {
        scale_->addItem(engineName(colormaps::displayName(scale)), static_cast<int>(scale));
    }
    form->addRow(settingFormLabel("vss.scale"), scale_);

    powerSlider_ = new QSlider(Qt::Horizontal, this);
    powerSlider_->setObjectName(QStringLiteral("vssPowerSlider"));
    powerSlider_->setRange(0, kSliderSteps);
    powerBox_ = new QDoubleSpinBox(this);
    powerBox_->setObjectName(QStringLiteral("vssPower"));
    setUpForSetting(powerBox_, "vss.p");
    powerBox_->setKeyboardTracking(false);  // one solve per entered value, not per digit
    auto* powerRow = new QHBoxLayout;
    powerRow->addWidget(powerSlider_, 1);
    powerRow->addWidget(powerBox_);
    form->addRow(settingFormLabel("vss.p"), powerRow);
}

void VssPanel::addLookRows(QFormLayout* form) {
    isoLines_ = new QSpinBox(this);
    isoLines_->setObjectName(QStringLiteral("vssIsoLines"));
    setUpForSetting(isoLines_, "vss.isoLines");
    isoLines_->setSpecialValueText(tr("None"));
    form->addRow(settingFormLabel("vss.isoLines"), isoLines_);
    isoStrength_ = new QSlider(Qt::Horizontal, this);
    isoStrength_->setObjectName(QStringLiteral("vssIsoStrength"));
    setUpForSetting(isoStrength_, "vss.isoLineStrength");
    form->addRow(settingFormLabel("vss.isoLineStrength"), isoStrength_);
    lighting_ = new QSlider(Qt::Horizontal, this);
    lighting_->setObjectName(QStringLiteral("vssLighting"));
    setUpForSetting(lighting_, "vss.lighting");
    form->addRow(settingFormLabel("vss.lighting"), lighting_);

    ao_ = new QCheckBox(settingLabel("ao.enabled"), this);
    ao_->setObjectName(QStringLiteral("aoEnabled"));
    form->addRow(ao_);
    aoRadius_ = new QDoubleSpinBox(this);
    aoRadius_->setObjectName(QStringLiteral("aoRadius"));
    setUpForSetting(aoRadius_, "ao.radius");
    aoRadius_->setKeyboardTracking(false);
    form->addRow(settingFormLabel("ao.radius"), aoRadius_);
}

void VssPanel::addRangeRows(QFormLayout* form) {
    rangeMode_ = new QComboBox(this);
    rangeMode_->setObjectName(QStringLiteral("vssRangeMode"));
    rangeMode_->addItem(tr("Visible vessels"), static_cast<int>(vss::RangeMode::Visible));
    rangeMode_->addItem(tr("Fixed"), static_cast<int>(vss::RangeMode::Fixed));
    form->addRow(settingFormLabel("vss.range.mode"), rangeMode_);
    rangeMin_ = new QDoubleSpinBox(this);
    rangeMin_->setObjectName(QStringLiteral("vssRangeMin"));
    rangeMax_ = new QDoubleSpinBox(this);
    rangeMax_->setObjectName(QStringLiteral("vssRangeMax"));
    setUpForSetting(rangeMin_, "vss.range.near");
    setUpForSetting(rangeMax_, "vss.range.far");
    for (QDoubleSpinBox* box : {rangeMin_, rangeMax_}) {
        box->setKeyboardTracking(false);
    }
    auto* rangeRow = new QHBoxLayout;
    rangeRow->addWidget(rangeMin_);
    rangeRow->addWidget(rangeMax_);
    form->addRow(tr("Near / far:"), rangeRow);
}

CollapsibleSection* VssPanel::buildAdvancedSection() {
    auto* advanced = new QWidget(this);
    auto* advancedForm = new QFormLayout(advanced);
    solver_ = new QComboBox(this);
    solver_->setObjectName(QStringLiteral("vssSolver"));
    solver_->addItem(tr("Fast (with tolerance)"), static_cast<int>(vss::SolverKind::Fast));
    solver_->addItem(tr("Exact"), static_cast<int>(vss::SolverKind::Brute));
    solver_->addItem(tr("Paper's step"), static_cast<int>(vss::SolverKind::Step));
    advancedForm->addRow(settingFormLabel("vss.solver"), solver_);
    tolerance_ = new QDoubleSpinBox(this);
    tolerance_->setObjectName(QStringLiteral("vssTolerance"));
    setUpForSetting(tolerance_, "vss.tolerance");
    tolerance_->setKeyboardTracking(false);
    advancedForm->addRow(settingFormLabel("vss.tolerance"), tolerance_);
    step_ = new QSpinBox(this);
    step_->setObjectName(QStringLiteral("vssStep"));
    setUpForSetting(step_, "vss.step");
    step_->setKeyboardTracking(false);
    advancedForm->addRow(settingFormLabel("vss.step"), step_);

    status_ = new QLabel(this);
    status_->setObjectName(QStringLiteral("vssStatus"));
    status_->setWordWrap(true);
    advancedForm->addRow(status_);

    advanced_ = new CollapsibleSection(tr("Advanced"), advanced, QStringLiteral("vssAdvanced"),
                                       false, this);
    advanced_->setToolTip(tr("How the surface is computed: solver, tolerance, solve time"));
    return advanced_;
}

void VssPanel::connectControls() {
    connect(powerSlider_, &QSlider::valueChanged, this, [this](int position) {
        if (!syncing_) {
            powerBox_->setValue(powerFromSlider(position));  // applies through the spin box
        }
    });
    connect(powerBox_, &QDoubleSpinBox::valueChanged, this, [this](double p) {
        if (!syncing_) {
            const QSignalBlocker blocker(powerSlider_);
            powerSlider_->setValue(sliderFromPower(p));
            apply();
        }
    });
    auto applyLater = [this] {
        if (!syncing_) {
            apply();
        }
    };
    connect(enabled_, &QCheckBox::toggled, this, applyLater);
    connect(solver_, &QComboBox::currentIndexChanged, this, applyLater);
    connect(tolerance_, &QDoubleSpinBox::valueChanged, this, applyLater);
    connect(step_, &QSpinBox::valueChanged, this, applyLater);
    connect(scale_, &QComboBox::currentIndexChanged, this, applyLater);
    connect(isoLines_, &QSpinBox::valueChanged, this, applyLater);
    connect(isoStrength_, &QSlider::valueChanged, this, applyLater);
    connect(lighting_, &QSlider::valueChanged, this, applyLater);
    connect(ao_, &QCheckBox::toggled, this, applyLater);
    connect(aoRadius_, &QDoubleSpinBox::valueChanged, this, applyLater);
    connect(rangeMode_, &QComboBox::currentIndexChanged, this, &VssPanel::rangeModeChosen);
    connect(rangeMin_, &QDoubleSpinBox::valueChanged, this, applyLater);
    connect(rangeMax_, &QDoubleSpinBox::valueChanged, this, applyLater);
}

void VssPanel::rangeModeChosen() {
    if (syncing_) {
        return;
    }
    // Fixing starts from the range on screen, so nothing jumps.
    const render::VssFrameStatus& status = viewer_->vssStatus();
    if (rangeMode_->currentData().toInt() == static_cast<int>(vss::RangeMode::Fixed) &&
        status.shown && std::isfinite(status.dmin) && std::isfinite(status.dmax)) {
        const QSignalBlocker blockMin(rangeMin_);
        const QSignalBlocker blockMax(rangeMax_);
        rangeMin_->setValue(status.dmin);
        rangeMax_->setValue(status.dmax);
    }
    apply();
}

void VssPanel::syncFromViewer() {
    syncing_ = true;
    const render::VssSettings& vss = viewer_->vssSettings();
    const render::AoSettings& ao = viewer_->aoSettings();
    enabled_->setChecked(vss.enabled);
    powerBox_->setValue(vss.solver.p);
    powerSlider_->setValue(sliderFromPower(vss.solver.p));
    int solverIndex = solver_->findData(static_cast<int>(vss.solver.kind));
    if (solverIndex < 0) {  // the reference solver is exact too
        solverIndex = solver_->findData(static_cast<int>(vss::SolverKind::Brute));
    }
    solver_->setCurrentIndex(solverIndex);
    tolerance_->setValue(toControl("vss.tolerance", vss.solver.tolerance));
    step_->setValue(vss.solver.step);
    scale_->setCurrentIndex(scale_->findData(static_cast<int>(vss.scale)));
    isoLines_->setValue(vss.isoLines);
    isoStrength_->setValue(sliderPosition("vss.isoLineStrength", vss.isoLineStrength));
    lighting_->setValue(sliderPosition("vss.lighting", vss.lighting));
    ao_->setChecked(ao.enabled);
    aoRadius_->setValue(static_cast<double>(ao.radius));
    rangeMode_->setCurrentIndex(rangeMode_->findData(static_cast<int>(vss.range.mode)));
    if (vss.range.mode == vss::RangeMode::Fixed) {
        rangeMin_->setValue(vss.range.dmin);
        rangeMax_->setValue(vss.range.dmax);
    }
    syncing_ = false;
    updateApplicability();
    updateBound();
    updateStatus();
}

void VssPanel::apply() {
    render::VssSettings vss = viewer_->vssSettings();
    vss.enabled = enabled_->isChecked();
    vss.solver.p = powerBox_->value();
    const auto kind = static_cast<vss::SolverKind>(solver_->currentData().toInt());
    // Keep the reference solver while "Exact" stays selected.
    if (!(kind == vss::SolverKind::Brute && vss.solver.kind == vss::SolverKind::Reference)) {
        vss.solver.kind = kind;
    }
    vss.solver.tolerance = fromControl("vss.tolerance", tolerance_->value());
    vss.solver.step = step_->value();
    vss.scale = static_cast<colormaps::DepthScale>(scale_->currentData().toInt());
    vss.isoLines = isoLines_->value();
    vss.isoLineStrength = sliderValue("vss.isoLineStrength", isoStrength_);
    vss.lighting = sliderValue("vss.lighting", lighting_);
    vss.range.mode = static_cast<vss::RangeMode>(rangeMode_->currentData().toInt());
    if (vss.range.mode == vss::RangeMode::Fixed) {
        // Near never beyond far: the far box follows.
        if (rangeMax_->value() < rangeMin_->value()) {
            const QSignalBlocker blocker(rangeMax_);
            rangeMax_->setValue(rangeMin_->value());
        }
        vss.range.dmin = rangeMin_->value();
        vss.range.dmax = rangeMax_->value();
    }
    viewer_->setVssSettings(vss);
    render::AoSettings ao = viewer_->aoSettings();
    ao.enabled = ao_->isChecked();
    ao.radius = static_cast<float>(aoRadius_->value());
    viewer_->setAoSettings(ao);
    updateApplicability();
    updateBound();
    updateStatus();
    emit changed();
}

void VssPanel::updateApplicability() {
    const bool on = enabled_->isChecked();
    const QString off = tr("Turn the Void Space Surface on to change this");
    const auto kind = static_cast<vss::SolverKind>(solver_->currentData().toInt());
    const app::Setting& p = app::setting("vss.p");
    setApplicable(powerSlider_, on,
                  tr("Interpolation power p (logarithmic, %L1 to %L2)").arg(p.min).arg(p.max), off);
    setApplicable(powerBox_, on,
                  tr("Interpolation power p: higher values follow the nearest vessel more "
                     "closely"),
                  off);
    setApplicable(solver_, on, tr("How the surface is interpolated: speed against accuracy"), off);
    setApplicable(tolerance_, on && kind == vss::SolverKind::Fast,
                  tr("Largest error of the fast solver, in 1/255 of the depth range"),
                  on ? tr("Only the fast solver has a tolerance") : off);
    setApplicable(step_, on && kind == vss::SolverKind::Step,
                  tr("The paper's approximation: every k-th contour pixel"),
                  on ? tr("Only the paper's step solver uses k") : off);
    setApplicable(scale_, on, tr("Colours of depth on the surface"), off);
    setApplicable(isoLines_, on, tr("Lines of equal depth on the surface"), off);
    setApplicable(isoStrength_, on && isoLines_->value() > 0, tr("How dark the iso-lines are"),
                  on ? tr("No iso-lines are drawn (set a count first)") : off);
    setApplicable(lighting_, on, tr("0: flat colours, 100: fully lit surface"), off);
    ao_->setToolTip(tr("Shade the surface next to the vessels, so they look anchored on it"));
    setApplicable(aoRadius_, ao_->isChecked(), tr("Reach of the ambient occlusion, scene units"),
                  tr("Ambient occlusion is off"));
    setApplicable(rangeMode_, on,
                  tr("Visible: the scale spans the vessels in view; fixed: colours keep their "
                     "depth when the view changes"),
                  off);
    const bool fixed = rangeMode_->currentData().toInt() == static_cast<int>(vss::RangeMode::Fixed);
    for (QDoubleSpinBox* box : {rangeMin_, rangeMax_}) {
        setApplicable(box, on && fixed,
                      tr("Depths mapped to the near and far end of the scale (viewing distance)"),
                      on ? tr("Choose a fixed depth range first") : off);
    }
}

void VssPanel::updateBound() {
    const render::VssSettings& vss = viewer_->vssSettings();
    try {
        // errorBound() is the solver's own promise (0 exact, NaN none).
        const double error = vss::makeSolver(render::effectiveSolverOptions(vss))->errorBound();
        if (std::isnan(error)) {
            bound_ = tr("no error bound (step solver)");
        } else if (error == 0.0) {
            bound_ = tr("exact");
        } else {
            bound_ = tr("error ≤ %1 / 255").arg(QLocale().toString(error * 255.0, 'g', 3));
        }
    } catch (const vv::Error& e) {
        bound_ = describeProblem(e, FileAccess::Reading).line();  // the detail in English only
    }
}

void VssPanel::updateStatus() {
    const render::VssSettings& vss = viewer_->vssSettings();
    if (!vss.enabled) {
        status_->setText(tr("Void Space Surface off"));
        return;
    }
    const render::VssFrameStatus& status = viewer_->vssStatus();
    // Visible: the (disabled) near / far boxes show the range on screen,
    // never numbers left from earlier.
    if (vss.range.mode == vss::RangeMode::Visible && status.shown && std::isfinite(status.dmin) &&
        std::isfinite(status.dmax)) {
        const QSignalBlocker blockMin(rangeMin_);
        const QSignalBlocker blockMax(rangeMax_);
        rangeMin_->setValue(status.dmin);
        rangeMax_->setValue(status.dmax);
    }
    QString solve;
    if (status.pending) {
        solve = tr("solving…");
    } else if (status.shown) {
        solve = status.preview ? tr("preview, %1 ms").arg(std::lround(status.solveMilliseconds))
                               : tr("solved in %1 ms").arg(std::lround(status.solveMilliseconds));
    } else {
        solve = tr("not solved yet");
    }
    status_->setText(tr("Solve: %1; %2").arg(solve, bound_));
}

}  // namespace vv::gui::panels
