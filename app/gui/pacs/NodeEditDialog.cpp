// SPDX-License-Identifier: GPL-3.0-or-later
#include "gui/pacs/NodeEditDialog.h"

#include <QCheckBox>
#include <QCoreApplication>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSpinBox>
#include <QVBoxLayout>

#include "gui/pacs/PacsWidgets.h"
#include "gui/pacs/TlsFilesBox.h"
#include "vv/core/Error.h"

namespace vv::gui {

QString aeTitleProblem(const QString& aeTitle, const QString& field) {
    try {
        pacs::validateAeTitle(aeTitle.toStdString());
        return {};
    } catch (const InvalidArgumentError&) {
        return QCoreApplication::translate(
                   "vv::gui::NodeEditDialog",
                   "%1: 1 to 16 characters (letters, digits, spaces, no backslash) are needed.")
            .arg(field);
    }
}

NodeEditDialog::NodeEditDialog(const PacsNode& node, QStringList takenNames, QWidget* parent)
    : QDialog(parent), takenNames_(std::move(takenNames)) {
    setObjectName(QStringLiteral("nodeEditDialog"));
    setWindowTitle(tr("PACS Node"));
    auto* form = new QFormLayout;
    name_ = new QLineEdit(QString::fromStdString(node.name), this);
    name_->setObjectName(QStringLiteral("nodeName"));
    name_->setPlaceholderText(tr("e.g. Radiology PACS"));
    aeTitle_ = new QLineEdit(QString::fromStdString(node.node.aeTitle), this);
    aeTitle_->setObjectName(QStringLiteral("nodeAeTitle"));
    aeTitle_->setMaxLength(16);
    host_ = new QLineEdit(QString::fromStdString(node.node.host), this);
    host_->setObjectName(QStringLiteral("nodeHost"));
    port_ = new QSpinBox(this);
    port_->setObjectName(QStringLiteral("nodePort"));
    port_->setRange(1, kMaxPort);
    port_->setGroupSeparatorShown(false);
    port_->setValue(node.node.port == 0 ? 104 : node.node.port);
    allowPush_ = new QCheckBox(tr("May send studies to our listener"), this);
    allowPush_->setObjectName(QStringLiteral("nodeAllowPush"));
    allowPush_->setChecked(node.allowPush);
    form->addRow(tr("&Name:"), name_);
    form->addRow(tr("&AE title:"), aeTitle_);
    form->addRow(tr("&Host:"), host_);
    form->addRow(tr("&Port:"), port_);
    form->addRow(QString(), allowPush_);

    tls_ = new TlsFilesBox(tr("Use &TLS (encrypted DICOM)"), node.node.tls,
                           TlsFilesBox::OurCertificate::Optional, QStringLiteral("node"), this);
    tls_->setObjectName(QStringLiteral("nodeTls"));

    error_ = makeErrorLabel(this, QStringLiteral("nodeError"));
    QDialogButtonBox* buttons = makeOkCancel(this);

    auto* layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addWidget(tls_);
    layout->addWidget(error_);
    layout->addWidget(buttons);
}

PacsNode NodeEditDialog::node() const {
    PacsNode n;
    n.name = name_->text().trimmed().toStdString();
    n.node.aeTitle = aeTitle_->text().trimmed().toStdString();
    n.node.host = host_->text().trimmed().toStdString();
    n.node.port = static_cast<std::uint16_t>(port_->value());
    n.allowPush = allowPush_->isChecked();
    n.node.tls = tls_->settings();
    return n;
}

QString NodeEditDialog::error() const {
    return error_->text();
}

QString NodeEditDialog::check(QWidget** field) const {
    const QString name = name_->text().trimmed();
    if (name.isEmpty()) {
        *field = name_;
        return tr("Name: give the node a name.");
    }
    if (takenNames_.contains(name)) {
        *field = name_;
        return tr("Name: another node is already called \"%1\".").arg(name);
    }
    if (QString problem = aeTitleProblem(aeTitle_->text().trimmed(), tr("AE title"));
        !problem.isEmpty()) {
        *field = aeTitle_;
        return problem;
    }
    if (host_->text().trimmed().isEmpty()) {
        *field = host_;
        return tr("Host: enter the PACS's host name or IP address.");
    }
    if (QString problem = tls_->problem(field); !problem.isEmpty()) {
        return problem;
    }
    return {};
}

void NodeEditDialog::accept() {
    QWidget* field = nullptr;
    const QString problem = check(&field);
    if (!problem.isEmpty()) {
        error_->setText(problem);
        error_->show();
        if (field != nullptr) {
            field->setFocus();
        }
        return;
    }
    error_->clear();
    error_->hide();
    QDialog::accept();
}

}  // namespace vv::gui
