// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QDialog>

#include "gui/LatestRun.h"
#include "gui/pacs/NetworkFailure.h"
#include "gui/pacs/PacsSettings.h"

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QGroupBox;
class QLabel;
class QLineEdit;
class QPushButton;
class QSpinBox;
class QTableWidget;

namespace vv::gui {

class ListenerLimitsBox;
class TlsFilesBox;

/// DICOM > Preferences…: our AE title, the listener (on/off, port, the
/// interface it binds, TLS), how long we wait for a node (connect,
/// association, each answer; 1 s to an hour), the listener's limits
/// (ListenerLimitsBox), the local study
/// store (folder, size limit in GB) and the PACS nodes (a table with Add /
/// Edit / Remove, and Test: C-ECHO on a worker, the answer or what failed
/// shown under the table). Reads and, on
/// OK, writes QSettings() through read/writePacsSettings(); invalid input
/// keeps the dialog open with a message naming the field (error()).
class NetworkPreferencesDialog : public QDialog {
    Q_OBJECT

  public:
    explicit NetworkPreferencesDialog(QWidget* parent = nullptr);
    /// Stops a Test that runs (its worker aborts the association).
    Q_DISABLE_COPY_MOVE(NetworkPreferencesDialog)

    /// The settings as entered (not yet checked).
    [[nodiscard]] PacsSettings settings() const;
    /// The message of the last refused OK ("" when none), in the UI
    /// language: the field and what is wrong with it.
    [[nodiscard]] QString error() const;
    /// The English detail of the last refused OK that writePacsSettings()
    /// refused (the message's tooltip; "" when none).
    [[nodiscard]] QString errorDetails() const;
    /// The outcome of the last Test ("" before any).
    [[nodiscard]] QString testResult() const;
    /// True while a Test runs.
    [[nodiscard]] bool testRunning() const noexcept { return testCall_.isRunning(); }

    [[nodiscard]] QLineEdit* aeTitleEdit() const noexcept { return aeTitle_; }
    [[nodiscard]] QCheckBox* listenerBox() const noexcept { return listener_; }
    [[nodiscard]] QSpinBox* listenerPortBox() const noexcept { return listenerPort_; }
    [[nodiscard]] QComboBox* bindBox() const noexcept { return bind_; }
    [[nodiscard]] TlsFilesBox* listenerTlsBox() const noexcept { return listenerTls_; }
    [[nodiscard]] ListenerLimitsBox* listenerLimitsBox() const noexcept { return limits_; }
    [[nodiscard]] QSpinBox* connectTimeoutBox() const noexcept { return connectTimeout_; }
    [[nodiscard]] QSpinBox* associateTimeoutBox() const noexcept { return associateTimeout_; }
    [[nodiscard]] QSpinBox* responseTimeoutBox() const noexcept { return responseTimeout_; }
    [[nodiscard]] QLineEdit* storeFolderEdit() const noexcept { return storeFolder_; }
    [[nodiscard]] QDoubleSpinBox* storeLimitBox() const noexcept { return storeLimit_; }
    [[nodiscard]] QTableWidget* nodeTable() const noexcept { return table_; }
    [[nodiscard]] QPushButton* addButton() const noexcept { return add_; }
    [[nodiscard]] QPushButton* editButton() const noexcept { return edit_; }
    [[nodiscard]] QPushButton* removeButton() const noexcept { return remove_; }
    [[nodiscard]] QPushButton* testButton() const noexcept { return test_; }
    /// Cancels the Test that runs: the association is aborted, Test comes
    /// back at once and the line under the table says "Test cancelled.".
    [[nodiscard]] QPushButton* cancelTestButton() const noexcept { return cancelTest_; }

    /// Adds `node` to the table (what Add does after its dialog; no check here).
    void addNode(const PacsNode& node);

    void accept() override;

  signals:
    /// Add or Edit opened the node dialog (tests fill it in).
    void nodeDialogShown(QDialog* dialog);
    /// A Test ended (or was cancelled); testResult() holds the text.
    void testFinished(bool ok);

  private:
    /// The group "Timeouts": a spin box (1 s to kMaxTimeoutSeconds) for each of `t`.
    QGroupBox* makeTimeoutsBox(const pacs::Timeouts& t);
    void fillTable();
    void editNode(int row);
    void testNode();
    void cancelTest();
    /// Shows `text` under the node table as plain information.
    void showTestResult(const QString& text);
    void updateButtons();
    void refuse(const QString& message, QWidget* field);
    /// Refuses OK for what writePacsSettings() refused: the setting named in
    /// the UI language, the English detail apart (ProblemText).
    void refuse(const PacsSettingsError& error);
    void fitHeight();

    std::vector<PacsNode> nodes_;
    QLineEdit* aeTitle_ = nullptr;
    QCheckBox* listener_ = nullptr;
    QSpinBox* listenerPort_ = nullptr;
    QComboBox* bind_ = nullptr;
    TlsFilesBox* listenerTls_ = nullptr;
    ListenerLimitsBox* limits_ = nullptr;
    QSpinBox* connectTimeout_ = nullptr;
    QSpinBox* associateTimeout_ = nullptr;
    QSpinBox* responseTimeout_ = nullptr;
    QLineEdit* storeFolder_ = nullptr;
    QDoubleSpinBox* storeLimit_ = nullptr;
    QTableWidget* table_ = nullptr;
    QPushButton* add_ = nullptr;
    QPushButton* edit_ = nullptr;
    QPushButton* remove_ = nullptr;
    QPushButton* test_ = nullptr;
    QPushButton* cancelTest_ = nullptr;
    QLabel* testResult_ = nullptr;
    QLabel* error_ = nullptr;
    LatestRun<NetworkFailure, AtDestruction::Detach> testCall_{
        this};  ///< a cancelled Test's answer is dropped
};

}  // namespace vv::gui
