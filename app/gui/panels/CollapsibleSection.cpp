// SPDX-License-Identifier: GPL-3.0-or-later
#include "gui/panels/CollapsibleSection.h"

#include <QSettings>
#include <QToolButton>
#include <QVBoxLayout>
#include <algorithm>

namespace vv::gui::panels {

namespace {

QString settingsKey(const QString& key) {
    return QStringLiteral("sections/") + key;
}

}  // namespace

CollapsibleSection::CollapsibleSection(const QString& title, QWidget* content, const QString& key,
                                       bool expandedByDefault, QWidget* parent)
    : QWidget(parent),
      header_(new QToolButton(this)),
      content_(content),
      key_(key),
      expandedByDefault_(expandedByDefault) {
    setObjectName(key + QStringLiteral("Section"));
    header_->setObjectName(key + QStringLiteral("SectionHeader"));
    header_->setText(title);
    header_->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
    header_->setAutoRaise(true);
    header_->setCheckable(true);
    header_->setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);
    QFont bold = header_->font();
    bold.setBold(true);
    header_->setFont(bold);

    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(0);
    layout->addWidget(header_);
    content_->setParent(this);
    layout->addWidget(content_);

    applyExpanded(QSettings().value(settingsKey(key_), expandedByDefault_).toBool());
    connect(header_, &QToolButton::toggled, this, &CollapsibleSection::setExpanded);
}

void CollapsibleSection::setExpanded(bool expanded) {
    QSettings().setValue(settingsKey(key_), expanded);
    if (expanded != expanded_) {
        applyExpanded(expanded);
        emit expandedChanged(expanded);
    }
}

void CollapsibleSection::resetToDefault() {
    QSettings().remove(settingsKey(key_));
    if (expandedByDefault_ != expanded_) {
        applyExpanded(expandedByDefault_);
        emit expandedChanged(expanded_);
    }
}

void CollapsibleSection::applyExpanded(bool expanded) {
    expanded_ = expanded;
    const QSignalBlocker blocker(header_);
    header_->setChecked(expanded);
    header_->setArrowType(expanded ? Qt::DownArrow : Qt::RightArrow);
    content_->setVisible(expanded);
    updateGeometry();
}

QSize CollapsibleSection::minimumSizeHint() const {
    QSize size = QWidget::minimumSizeHint();
    size.setWidth(std::max(size.width(), content_->minimumSizeHint().width()));
    return size;
}

}  // namespace vv::gui::panels
