// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QDialog>
#include <QStringList>

#include "gui/pacs/PacsSettings.h"
#include "gui/pacs/TlsFilesBox.h"

class QCheckBox;
class QLabel;
class QLineEdit;
class QSpinBox;

namespace vv::gui {

/// Add / Edit of one PACS node (Preferences > DICOM network): its name, AE
/// title, host, port, whether it may push studies to our listener, and TLS
/// (trusted CA certificate, our certificate and key). OK checks the input and,
/// when something is wrong, keeps the dialog open with a message naming the
/// field (error()) and focuses that field.
class NodeEditDialog : public QDialog {
    Q_OBJECT

  public:
    /// Edits `node`; `takenNames` are the other nodes' names (a name must be unique).
    NodeEditDialog(const PacsNode& node, QStringList takenNames, QWidget* parent = nullptr);

    /// The node as entered (valid once the dialog was accepted).
    [[nodiscard]] PacsNode node() const;
    /// The message shown for invalid input ("" when none).
    [[nodiscard]] QString error() const;

    [[nodiscard]] QLineEdit* nameEdit() const noexcept { return name_; }
    [[nodiscard]] QLineEdit* aeTitleEdit() const noexcept { return aeTitle_; }
    [[nodiscard]] QLineEdit* hostEdit() const noexcept { return host_; }
    [[nodiscard]] QSpinBox* portBox() const noexcept { return port_; }
    [[nodiscard]] QCheckBox* allowPushBox() const noexcept { return allowPush_; }
    [[nodiscard]] TlsFilesBox* tlsBox() const noexcept { return tls_; }
    [[nodiscard]] QLineEdit* trustedEdit() const noexcept { return tls_->trustedEdit(); }
    [[nodiscard]] QLineEdit* certificateEdit() const noexcept { return tls_->certificateEdit(); }
    [[nodiscard]] QLineEdit* keyEdit() const noexcept { return tls_->keyEdit(); }

    void accept() override;

  private:
    /// The first problem of the input and the field it concerns; "" when none.
    [[nodiscard]] QString check(QWidget** field) const;

    QStringList takenNames_;
    QLineEdit* name_ = nullptr;
    QLineEdit* aeTitle_ = nullptr;
    QLineEdit* host_ = nullptr;
    QSpinBox* port_ = nullptr;
    QCheckBox* allowPush_ = nullptr;
    TlsFilesBox* tls_ = nullptr;
    QLabel* error_ = nullptr;
};

/// A translated sentence why `aeTitle` is not a valid AE title, naming
/// `field` ("AE title"); "" when it is valid.
[[nodiscard]] QString aeTitleProblem(const QString& aeTitle, const QString& field);

}  // namespace vv::gui
