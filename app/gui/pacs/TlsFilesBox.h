// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QGroupBox>

#include "vv/pacs/Node.h"

class QLineEdit;

namespace vv::gui {

/// A checkable group "use TLS" with the three PEM files of DICOM over TLS:
/// the trusted CA certificate, our certificate and our key, each with a
/// Browse… button. A PACS node's TLS (our certificate optional) and the
/// listener's (all three required) are edited with it.
class TlsFilesBox : public QGroupBox {
    Q_OBJECT

  public:
    enum class OurCertificate { Optional, Required };

    /// `objectPrefix` names the children ("<prefix>Trusted", "<prefix>Certificate",
    /// "<prefix>Key") for tests and the clipping checks.
    TlsFilesBox(const QString& title, const pacs::TlsSettings& tls, OurCertificate ours,
                const QString& objectPrefix, QWidget* parent);

    /// The TLS settings as entered (paths trimmed, not checked).
    [[nodiscard]] pacs::TlsSettings settings() const;

    /// What is missing when TLS is on ("" when nothing): the message names
    /// the field, and `*field` is set to its edit.
    [[nodiscard]] QString problem(QWidget** field) const;

    [[nodiscard]] QLineEdit* trustedEdit() const noexcept { return trusted_; }
    [[nodiscard]] QLineEdit* certificateEdit() const noexcept { return certificate_; }
    [[nodiscard]] QLineEdit* keyEdit() const noexcept { return key_; }

  private:
    OurCertificate ours_;
    QLineEdit* trusted_ = nullptr;
    QLineEdit* certificate_ = nullptr;
    QLineEdit* key_ = nullptr;
};

}  // namespace vv::gui
