// SPDX-License-Identifier: GPL-3.0-or-later
#include "gui/pacs/TlsFilesBox.h"

#include <QFileDialog>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLineEdit>
#include <QPushButton>
#include <array>
#include <utility>

#include "gui/PathField.h"

namespace vv::gui {

namespace {

QLineEdit* pathEdit(const std::filesystem::path& path, const QString& name, QWidget* parent) {
    auto* edit = new QLineEdit(QString::fromStdString(path.string()), parent);
    edit->setObjectName(name);
    showPath(edit);
    return edit;
}

}  // namespace

TlsFilesBox::TlsFilesBox(const QString& title, const pacs::TlsSettings& tls, OurCertificate ours,
                         const QString& objectPrefix, QWidget* parent)
    : QGroupBox(title, parent), ours_(ours) {
    setCheckable(true);
    setChecked(tls.enabled);
    auto* form = new QFormLayout(this);
    trusted_ = pathEdit(tls.trustedCertificates, objectPrefix + QStringLiteral("Trusted"), this);
    certificate_ = pathEdit(tls.certificate, objectPrefix + QStringLiteral("Certificate"), this);
    key_ = pathEdit(tls.privateKey, objectPrefix + QStringLiteral("Key"), this);
    const bool optional = ours == OurCertificate::Optional;
    const std::array<std::pair<QLineEdit*, QString>, 3> files{{
        {trusted_, tr("Trusted &CA certificate:")},
        {certificate_, optional ? tr("Our c&ertificate (optional):") : tr("Our c&ertificate:")},
        {key_, optional ? tr("Our &key (with the certificate):") : tr("Our &key:")},
    }};
    for (const auto& [edit, label] : files) {
        auto* row = new QHBoxLayout;
        row->addWidget(edit);
        auto* browse = new QPushButton(tr("Browse…"), this);
        QLineEdit* target = edit;
        connect(browse, &QPushButton::clicked, this, [this, target] {
            const QString chosen =
                QFileDialog::getOpenFileName(this, tr("Choose a PEM file"), target->text(),
                                             tr("PEM files (*.pem *.crt *.key);;All files (*)"));
            if (!chosen.isEmpty()) {
                target->setText(chosen);
            }
        });
        row->addWidget(browse);
        addBuddyRow(form, label, edit, row);
    }
}

pacs::TlsSettings TlsFilesBox::settings() const {
    pacs::TlsSettings tls;
    tls.enabled = isChecked();
    tls.trustedCertificates = trusted_->text().trimmed().toStdString();
    tls.certificate = certificate_->text().trimmed().toStdString();
    tls.privateKey = key_->text().trimmed().toStdString();
    return tls;
}

QString TlsFilesBox::problem(QWidget** field) const {
    if (!isChecked()) {
        return {};
    }
    if (trusted_->text().trimmed().isEmpty()) {
        *field = trusted_;
        return ours_ == OurCertificate::Optional
                   ? tr("Trusted CA certificate: TLS needs the certificate of the CA that "
                        "signed the PACS's certificate.")
                   : tr("Trusted CA certificate: the listener needs the certificate of the CA "
                        "that signed the certificates of the nodes sending to us.");
    }
    const bool noCertificate = certificate_->text().trimmed().isEmpty();
    const bool noKey = key_->text().trimmed().isEmpty();
    if (ours_ == OurCertificate::Required && (noCertificate || noKey)) {
        *field = noCertificate ? certificate_ : key_;
        return tr("Our certificate and key: the listener needs both to speak TLS.");
    }
    if (noCertificate != noKey) {
        *field = noCertificate ? certificate_ : key_;
        return tr("Our certificate and key: give both or neither.");
    }
    return {};
}

}  // namespace vv::gui
