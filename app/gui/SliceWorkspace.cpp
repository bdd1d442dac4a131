// SPDX-License-Identifier: GPL-3.0-or-later
#include "gui/SliceWorkspace.h"

#include <QAction>
#include <QActionGroup>
#include <QGridLayout>
#include <QMenu>
#include <QSettings>
#include <algorithm>
#include <utility>

#include "common/SliceReport.h"
#include "common/SliceTexts.h"
#include "gui/SliceCursor.h"
#include "gui/SliceView.h"
#include "gui/ViewerWidget.h"
#include "vv/slices/VoxelProbe.h"

namespace vv::gui {

namespace {

using app::kSliceLayoutNames;

SliceLayout storedLayout() {
    const QString name = QSettings().value(QLatin1String(SliceWorkspace::kLayoutKey)).toString();
    for (std::size_t n = 0; n < kSliceLayoutNames.size(); ++n) {
        if (name == QLatin1String(kSliceLayoutNames.at(n))) {
            return static_cast<SliceLayout>(n);
        }
    }
    return SliceLayout::ThreeDAndSlices;
}

constexpr std::array<slices::SliceOrientation, 3> kOrientations{slices::SliceOrientation::Axial,
                                                                slices::SliceOrientation::Coronal,
                                                                slices::SliceOrientation::Sagittal};

}  // namespace

SliceWorkspace::SliceWorkspace(ViewerWidget* viewer, QWidget* parent)
    : QWidget(parent),
      viewer_(viewer),
      cursor_(new SliceCursor(viewer, this)),
      grid_(new QGridLayout(this)) {
    setObjectName(QStringLiteral("sliceWorkspace"));
    layout_ = storedLayout();
    grid_->setContentsMargins(0, 0, 0, 0);
    grid_->setSpacing(2);
    if (viewer_ != nullptr) {
        grid_->addWidget(viewer_, 0, 0);
    }
    // 3-D top left, axial top right, coronal bottom left, sagittal bottom right.
    const std::array<QPoint, 3> cells{QPoint(1, 0), QPoint(0, 1), QPoint(1, 1)};
    for (std::size_t n = 0; n < views_.size(); ++n) {
        auto* view = new SliceView(kOrientations[n], this);
        views_[n] = view;
        grid_->addWidget(view, cells[n].y(), cells[n].x());
        connect(view, &SliceView::windowDragged, this, &SliceWorkspace::setWindow);
        connect(view, &SliceView::clickedAt, cursor_, [this](const glm::dvec3& world) {
            cursor_->setPoint(world);
            emit sliceClicked(world);
        });
        // The cursor follows the planes: a view scrolled to another slice
        // moves it to that slice, so that the other views' crosshairs show
        // the level it shows now (not where the last click was).
        connect(view, &SliceView::sliceChanged, this, [this, view] {
            const std::optional<glm::dvec3>& point = cursor_->point();
            if (followingCursor_ || !point || !view->stack()) {
                return;
            }
            glm::dvec3 moved = *point;
            moved[view->stack()->axis] = view->slicePosition();
            cursor_->setPoint(moved);
        });
    }
    connect(cursor_, &SliceCursor::pointChanged, this,
            [this](const std::optional<glm::dvec3>& world) {
                // The views go to the slices through the cursor; those
                // changes follow the cursor and do not move it.
                followingCursor_ = true;
                for (SliceView* view : views_) {
                    if (world) {
                        view->showSliceThrough(*world);
                    }
                    view->setCrosshair(world);
                }
                followingCursor_ = false;
            });
    buildMenu();
    applyLayout();
}

SliceView* SliceWorkspace::sliceView(slices::SliceOrientation orientation) const {
    return views_[static_cast<std::size_t>(orientation)];
}

void SliceWorkspace::buildMenu() {
    menu_ = new QMenu(tr("S&lices"), this);
    menu_->setObjectName(QStringLiteral("slicesMenu"));
    layoutGroup_ = new QActionGroup(this);
    const std::array<std::pair<SliceLayout, QString>, 5> layouts{{
        {SliceLayout::ThreeDOnly, tr("&3-D Only")},
        {SliceLayout::ThreeDAndSlices, tr("3-D and &Three Slices")},
        {SliceLayout::AxialLarge, tr("Large &Axial Slice")},
        {SliceLayout::CoronalLarge, tr("Large &Coronal Slice")},
        {SliceLayout::SagittalLarge, tr("Large &Sagittal Slice")},
    }};
    for (const auto& [layout, text] : layouts) {
        QAction* action = menu_->addAction(text);
        action->setCheckable(true);
        action->setData(static_cast<int>(layout));
        action->setChecked(layout == layout_);
        layoutGroup_->addAction(action);
        connect(action, &QAction::triggered, this,
                [this, layout = layout] { setSliceLayout(layout); });
    }
    menu_->addSeparator();
    presetMenu_ = menu_->addMenu(tr("&Window"));
    presetMenu_->setObjectName(QStringLiteral("windowPresetMenu"));
    presetGroup_ = new QActionGroup(this);
    menu_->addSeparator();
    fillAction_ = menu_->addAction(tr("Segmentation &Fill"));
    outlineAction_ = menu_->addAction(tr("Segmentation &Outline"));
    for (QAction* action : {fillAction_, outlineAction_}) {
        action->setCheckable(true);
        action->setChecked(true);
        connect(action, &QAction::toggled, this, &SliceWorkspace::applyOverlayStyle);
    }
    fillAction_->setToolTip(tr("The segmented voxels tinted in their label colour"));
    outlineAction_->setToolTip(tr("The edge of the segmentation drawn in its label colour"));
    menu_->menuAction()->setVisible(false);
}

void SliceWorkspace::rebuildPresetMenu() {
    for (QAction* action : presetGroup_->actions()) {
        presetGroup_->removeAction(action);
        delete action;
    }
    for (std::size_t n = 0; n < presets_.size(); ++n) {
        QAction* action = presetMenu_->addAction(app::presetName(presets_[n].preset));
        action->setCheckable(true);
        action->setChecked(n == 0);
        presetGroup_->addAction(action);
        connect(action, &QAction::triggered, this, [this, n] { applyPreset(n); });
    }
}

void SliceWorkspace::setVolume(std::shared_ptr<const scene::Volume> volume,
                               const std::shared_ptr<const scene::LabelMap>& labelMap) {
    volume_ = std::move(volume);
    presetRun_.cancel();
    presetsPending_ = false;
    pendingWindow_.reset();
    presets_.clear();
    rebuildPresetMenu();
    for (SliceView* view : views_) {
        view->setLabelMap(labelMap);
        view->setVolume(volume_);
    }
    if (volume_ && !volume_->empty()) {
        if (volume_->voxelCount() <= SliceView::kSynchronousVoxels) {
            presetsReady(slices::windowPresets(*volume_));
        } else {
            if (slices::valueUnit(*volume_) == "HU") {
                setWindow({300.0, 600.0});  // CTA until the presets are there
            }
            presetsPending_ = true;
            presetRun_.start(
                [volume = volume_](const std::stop_token& /*stop*/) {
                    return slices::windowPresets(*volume);
                },
                [this](const std::vector<slices::PresetWindow>& presets) {
                    presetsReady(presets);
                });
        }
    }
    menu_->menuAction()->setVisible(volume_ != nullptr);
    cursor_->setActive(volume_ != nullptr);
    cursor_->setPoint(std::nullopt);
    applyLayout();
}

void SliceWorkspace::presetsReady(const std::vector<slices::PresetWindow>& presets) {
    presetsPending_ = false;
    presets_ = presets;
    rebuildPresetMenu();
    if (presets_.empty()) {
        return;
    }
    // The full range preset's width is the span of the values.
    const auto full = std::find_if(presets_.begin(), presets_.end(), [](const auto& p) {
        return p.preset == slices::WindowPreset::FullRange;
    });
    for (SliceView* view : views_) {
        view->setValueSpan(full != presets_.end() ? full->window.width : 1.0);
    }
    if (const auto pending = std::exchange(pendingWindow_, std::nullopt)) {
        showWindow(pending->first, pending->second);
        return;
    }
    setWindow(presets_.front().window);
}

void SliceWorkspace::showWindow(const slices::Window& window,
                                const std::optional<slices::WindowPreset>& preset) {
    if (presetsPending_) {
        pendingWindow_ = {window, preset};  // presetsReady() would replace it
    }
    setWindow(window);
    const auto actions = presetGroup_->actions();
    for (std::size_t n = 0; n < presets_.size() && n < static_cast<std::size_t>(actions.size());
         ++n) {
        actions.at(static_cast<qsizetype>(n))->setChecked(preset == presets_[n].preset);
    }
}

std::optional<slices::WindowPreset> SliceWorkspace::chosenPreset() const {
    const auto actions = presetGroup_->actions();
    for (std::size_t n = 0; n < presets_.size() && n < static_cast<std::size_t>(actions.size());
         ++n) {
        const slices::Window& w = presets_[n].window;
        if (actions.at(static_cast<qsizetype>(n))->isChecked() && w.center == window_.center &&
            w.width == window_.width) {
            return presets_[n].preset;
        }
    }
    return std::nullopt;
}

std::optional<app::SliceSessionState> SliceWorkspace::sessionState() const {
    if (!volume_) {
        return std::nullopt;
    }
    app::SliceSessionState state;
    state.layout = static_cast<std::size_t>(layout_);
    state.window = window_;
    state.preset = pendingWindow_ ? pendingWindow_->second : chosenPreset();
    state.fill = fillAction_->isChecked();
    state.outline = outlineAction_->isChecked();
    for (std::size_t n = 0; n < views_.size(); ++n) {
        state.views.at(n) = {views_[n]->slicePosition(), views_[n]->zoom(), views_[n]->pan()};
    }
    state.cursor = cursor_->point();
    return state;
}

void SliceWorkspace::applySessionState(const app::SliceSessionState& state) {
    setSliceLayout(static_cast<SliceLayout>(std::min<std::size_t>(state.layout, 4)));
    if (!volume_) {
        return;
    }
    showWindow(state.window, state.preset);
    fillAction_->setChecked(state.fill);
    outlineAction_->setChecked(state.outline);
    cursor_->setPoint(state.cursor);  // moves the slices through it
    for (std::size_t n = 0; n < views_.size(); ++n) {
        const app::SliceViewState& v = state.views.at(n);
        views_[n]->setSlicePosition(v.position);
        views_[n]->setZoom(v.zoom);
        views_[n]->setPan(v.pan);
    }
}

void SliceWorkspace::setLabelMap(const std::shared_ptr<const scene::LabelMap>& labelMap) {
    for (SliceView* view : views_) {
        view->setLabelMap(labelMap);
    }
}

void SliceWorkspace::setSliceLayout(SliceLayout layout) {
    layout_ = layout;
    QSettings().setValue(QLatin1String(kLayoutKey),
                         QLatin1String(kSliceLayoutNames.at(static_cast<std::size_t>(layout))));
    for (QAction* action : layoutGroup_->actions()) {
        action->setChecked(action->data().toInt() == static_cast<int>(layout));
    }
    applyLayout();
}

bool SliceWorkspace::showsSlices() const {
    return std::any_of(views_.begin(), views_.end(),
                       [](const SliceView* v) { return !v->isHidden(); });
}

void SliceWorkspace::applyLayout() {
    const SliceLayout shown = volume_ ? layout_ : SliceLayout::ThreeDOnly;
    const bool threeD = shown == SliceLayout::ThreeDOnly || shown == SliceLayout::ThreeDAndSlices;
    if (viewer_ != nullptr) {
        viewer_->setVisible(threeD);
    }
    for (std::size_t n = 0; n < views_.size(); ++n) {
        const bool large = static_cast<int>(shown) ==
                           static_cast<int>(SliceLayout::AxialLarge) + static_cast<int>(n);
        views_[n]->setVisible(shown == SliceLayout::ThreeDAndSlices || large);
    }
    emit layoutChanged();
}

std::optional<std::pair<QImage, QString>> SliceWorkspace::reportSlice() const {
    if (!volume_) {
        return std::nullopt;
    }
    const int large = static_cast<int>(layout_) - static_cast<int>(SliceLayout::AxialLarge);
    const SliceView* view = views_[large >= 0 && large < 3 ? static_cast<std::size_t>(large) : 0];
    const QImage image = view->printImage(app::kPrintedSliceWidth);
    if (image.isNull()) {
        return std::nullopt;
    }
    app::SliceFacts facts;
    facts.orientation = view->orientation();
    facts.axis = view->stack()->axis;
    facts.position = view->slicePosition();
    facts.window = window_;
    facts.preset = chosenPreset();
    facts.unit = slices::valueUnit(*volume_);
    if (view->labelMap() && (fillAction_->isChecked() || outlineAction_->isChecked())) {
        slices::OverlayStyle overlay;
        overlay.fill = fillAction_->isChecked();
        overlay.outline = outlineAction_->isChecked();
        facts.overlay = overlay;
    }
    return std::pair{image, app::sliceCaption(facts)};
}

void SliceWorkspace::applyPreset(std::size_t index) {
    if (index >= presets_.size()) {
        return;
    }
    presetGroup_->actions().at(static_cast<qsizetype>(index))->setChecked(true);
    setWindow(presets_[index].window);
}

void SliceWorkspace::setWindow(const slices::Window& window) {
    window_ = window;
    emit windowChanged(window_);
    for (SliceView* view : views_) {
        if (view->window().center != window.center || view->window().width != window.width) {
            view->setWindow(window);
        }
    }
}

void SliceWorkspace::applyOverlayStyle() {
    slices::OverlayStyle style;
    style.fill = fillAction_->isChecked();
    style.outline = outlineAction_->isChecked();
    for (SliceView* view : views_) {
        view->setOverlayStyle(style);
    }
}

}  // namespace vv::gui
