// SPDX-License-Identifier: GPL-3.0-or-later
#include "gui/panels/SidePanel.h"

#include <QAbstractSlider>
#include <QAbstractSpinBox>
#include <QComboBox>
#include <QCoreApplication>
#include <QEvent>
#include <QScrollBar>
#include <QStyle>
#include <QToolButton>
#include <QVBoxLayout>
#include <algorithm>

#include "gui/panels/CollapsibleSection.h"

namespace vv::gui::panels {

namespace {

/// A control that a mouse wheel would change: a combo box, spin box or
/// slider (not the panel's own scroll bars).
bool turnsWithTheWheel(const QObject* object) {
    return (qobject_cast<const QComboBox*>(object) != nullptr ||
            qobject_cast<const QAbstractSpinBox*>(object) != nullptr ||
            qobject_cast<const QAbstractSlider*>(object) != nullptr) &&
           qobject_cast<const QScrollBar*>(object) == nullptr;
}

}  // namespace

SidePanel::SidePanel(QWidget* parent) : QScrollArea(parent), content_(new QWidget) {
    setObjectName(QStringLiteral("sidePanel"));
    content_->setObjectName(QStringLiteral("sidePanelContent"));
    auto* layout = new QVBoxLayout(content_);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(2);
    layout->addStretch(1);
    setWidget(content_);
    setWidgetResizable(true);
    setFrameShape(QFrame::NoFrame);
    setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    setVerticalScrollBarPolicy(Qt::ScrollBarAsNeeded);
    content_->installEventFilter(this);
}

CollapsibleSection* SidePanel::addSection(const QString& title, QWidget* panel,
                                          bool expandedByDefault) {
    auto* section =
        new CollapsibleSection(title, panel, panel->objectName(), expandedByDefault, content_);
    auto* layout = qobject_cast<QVBoxLayout*>(content_->layout());
    layout->insertWidget(layout->count() - 1, section);  // above the stretch
    sections_ << section;
    // Scrolling the panel must not change a value the cursor passes over:
    // controls take the wheel only once clicked or tabbed into.
    for (QWidget* child : panel->findChildren<QWidget*>()) {
        if (turnsWithTheWheel(child)) {
            child->setFocusPolicy(Qt::StrongFocus);
            child->installEventFilter(this);
        }
    }
    updateGeometry();
    return section;
}

CollapsibleSection* SidePanel::sectionOf(const QWidget* panel) const {
    for (CollapsibleSection* section : sections_) {
        if (section->content() == panel) {
            return section;
        }
    }
    return nullptr;
}

void SidePanel::reveal(const QWidget* panel) {
    if (CollapsibleSection* section = sectionOf(panel)) {
        section->setExpanded(true);
        content_->layout()->activate();
        ensureWidgetVisible(section->header(), 0, 0);
    }
}

void SidePanel::moveSection(CollapsibleSection* section, int index) {
    const qsizetype from = sections_.indexOf(section);
    if (from < 0) {
        return;
    }
    const qsizetype to = std::clamp<qsizetype>(index, 0, sections_.size() - 1);
    sections_.move(from, to);
    auto* layout = qobject_cast<QVBoxLayout*>(content_->layout());
    layout->removeWidget(section);
    layout->insertWidget(static_cast<int>(to), section);  // the stretch stays last
}

QSize SidePanel::minimumSizeHint() const {
    // Room for the widest part and the vertical scroll bar beside it.
    const int scrollBar = style()->pixelMetric(QStyle::PM_ScrollBarExtent, nullptr, this);
    const QSize content = content_->minimumSizeHint();
    return {content.width() + scrollBar + 2 * frameWidth(),
            QScrollArea::minimumSizeHint().height()};
}

QSize SidePanel::sizeHint() const {
    return {minimumSizeHint().width(), QScrollArea::sizeHint().height()};
}

bool SidePanel::eventFilter(QObject* watched, QEvent* event) {
    if (watched == content_ && event->type() == QEvent::LayoutRequest) {
        updateGeometry();  // a part grew: the dock follows
    }
    const auto* control = qobject_cast<const QWidget*>(watched);
    if (event->type() == QEvent::Wheel && turnsWithTheWheel(watched) && control != nullptr &&
        !control->hasFocus()) {
        QCoreApplication::sendEvent(verticalScrollBar(), event);  // the panel scrolls
        return true;
    }
    return QScrollArea::eventFilter(watched, event);
}

}  // namespace vv::gui::panels
