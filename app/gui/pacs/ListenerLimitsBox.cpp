// SPDX-License-Identifier: GPL-3.0-or-later
#include "gui/pacs/ListenerLimitsBox.h"

#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLocale>
#include <QPushButton>
#include <QSpinBox>
#include <QVBoxLayout>

#include "gui/pacs/PacsWidgets.h"
#include "vv/pacs/StorageScp.h"

namespace vv::gui {

namespace {

constexpr int kSizeDecimals = 2;
constexpr double kSmallestInstanceGb = 0.01;

QSpinBox* countBox(QWidget* parent, const QString& objectName, int most) {
    auto* box = new QSpinBox(parent);
    box->setObjectName(objectName);
    box->setRange(1, most);
    return box;
}

}  // namespace

ListenerLimitsBox::ListenerLimitsBox(const pacs::ListenerLimits& limits, QWidget* parent)
    : QGroupBox(tr("Listener limits"), parent) {
    static_assert(kSmallestInstanceGb * kBytesPerGb >=
                  static_cast<double>(pacs::ListenerLimits::kMinInstanceBytes));
    associations_ =
        countBox(this, QStringLiteral("maxAssociations"), pacs::ListenerLimits::kMaxAssociations);
    associations_->setToolTip(
        tr("Associations served at once. One more is refused for now (the sender may try "
           "again later), so that many senders at once cannot overload this workstation."));
    perAddress_ = countBox(this, QStringLiteral("maxConnectionsPerAddress"),
                           pacs::ListenerLimits::kMaxConnections);
    perAddress_->setToolTip(
        tr("Open connections from the address of one configured node, at most the connections "
           "in all: one device that misbehaves cannot take every connection."));
    connections_ =
        countBox(this, QStringLiteral("maxConnections"), pacs::ListenerLimits::kMaxConnections);
    connections_->setToolTip(
        tr("Open connections in all, waiting or served, at least the simultaneous "
           "associations. A connection over a limit is closed at once."));
    requestSeconds_ =
        countBox(this, QStringLiteral("requestSeconds"), pacs::ListenerLimits::kMaxRequestSeconds);
    requestSeconds_->setSuffix(tr(" s"));
    requestSeconds_->setToolTip(
        tr("Seconds a new connection has to ask for an association before it is dropped: "
           "silent or slow connections cannot hold up the listener."));
    instance_ =
        makeGigabyteBox(this, QStringLiteral("maxInstance"), kSizeDecimals, kSmallestInstanceGb);
    instance_->setToolTip(
        tr("A larger instance is refused and not stored; the rest of the association goes "
           "on."));
    association_ =
        makeGigabyteBox(this, QStringLiteral("maxAssociation"), kSizeDecimals, kSmallestInstanceGb);
    association_->setToolTip(
        tr("All instances of one association together, at least the largest instance. The "
           "instance that crosses it and all later ones are refused, and nothing of the "
           "association is kept."));
    // The ranges follow each other: whatever is entered fits together.
    connect(associations_, &QSpinBox::valueChanged, connections_, &QSpinBox::setMinimum);
    connect(connections_, &QSpinBox::valueChanged, perAddress_, &QSpinBox::setMaximum);
    connect(instance_, &QDoubleSpinBox::valueChanged, association_, &QDoubleSpinBox::setMinimum);

    auto* form = new QFormLayout;
    form->addRow(tr("Sim&ultaneous associations:"), associations_);
    form->addRow(tr("Connections per a&ddress:"), perAddress_);
    form->addRow(tr("C&onnections in all:"), connections_);
    form->addRow(tr("Association re&quest deadline:"), requestSeconds_);
    form->addRow(tr("Lar&gest instance:"), instance_);
    form->addRow(tr("Largest association:"), association_);

    const pacs::ListenerLimits standard;
    const QLocale locale;
    const auto count = [&locale](int n) { return locale.toString(n); };
    const auto gigabytes = [](std::uint64_t bytes) {
        return quantityText(static_cast<double>(bytes) / kBytesPerGb, "GB");
    };
    defaults_ = new QLabel(
        tr("Defaults: %1 associations, %2 per address, %3 in all, %4, %5 per instance, %6 per "
           "association. Addresses that are no configured node get at most %7 connections each, "
           "%8 together.")
            .arg(count(standard.maxAssociations), count(standard.maxConnectionsPerAddress),
                 count(standard.maxConnections), quantityText(standard.requestSeconds, "s"),
                 gigabytes(standard.maxInstanceBytes), gigabytes(standard.maxAssociationBytes),
                 count(pacs::ListenerLimits::kStrangerConnectionsPerAddress),
                 count(pacs::ListenerLimits::kStrangerConnections)),
        this);
    defaults_->setObjectName(QStringLiteral("listenerLimitsDefaults"));
    defaults_->setWordWrap(true);
    restore_ = new QPushButton(tr("Restore Defaults"), this);
    restore_->setObjectName(QStringLiteral("restoreListenerLimits"));
    restore_->setToolTip(tr("Put the defaults into these fields; OK saves them"));
    connect(restore_, &QPushButton::clicked, this, [this] { setLimits(pacs::ListenerLimits{}); });
    // The button beside the defaults, not under them: the dialog fits 1280 x 720.
    auto* restoreRow = new QHBoxLayout;
    restoreRow->addWidget(defaults_, 1);
    restoreRow->addWidget(restore_, 0, Qt::AlignBottom);

    auto* layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addLayout(restoreRow);
    setLimits(limits);
}

pacs::ListenerLimits ListenerLimitsBox::limits() const {
    pacs::ListenerLimits l;
    l.maxAssociations = associations_->value();
    l.maxConnectionsPerAddress = perAddress_->value();
    l.maxConnections = connections_->value();
    l.requestSeconds = requestSeconds_->value();
    l.maxInstanceBytes = bytesOf(instance_);
    l.maxAssociationBytes = bytesOf(association_);
    return l;
}

void ListenerLimitsBox::setLimits(const pacs::ListenerLimits& limits) {
    // In the order of the ranges: each is set after the one its range follows.
    associations_->setValue(limits.maxAssociations);
    connections_->setValue(limits.maxConnections);
    perAddress_->setValue(limits.maxConnectionsPerAddress);
    requestSeconds_->setValue(limits.requestSeconds);
    setBytes(instance_, limits.maxInstanceBytes);
    setBytes(association_, limits.maxAssociationBytes);
}

}  // namespace vv::gui
