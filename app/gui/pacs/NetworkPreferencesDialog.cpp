// SPDX-License-Identifier: GPL-3.0-or-later
#include "gui/pacs/NetworkPreferencesDialog.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFormLayout>
#include <QGridLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLayout>
#include <QLineEdit>
#include <QPushButton>
#include <QSettings>
#include <QSpinBox>
#include <QTableWidget>
#include <QVBoxLayout>
#include <algorithm>
#include <array>

#include "gui/EngineTexts.h"
#include "gui/PathField.h"
#include "gui/pacs/ListenerLimitsBox.h"
#include "gui/pacs/NetworkFailure.h"
#include "gui/pacs/NodeEditDialog.h"
#include "gui/pacs/PacsWidgets.h"
#include "gui/pacs/TlsFilesBox.h"
#include "vv/core/Error.h"
#include "vv/pacs/Echo.h"

namespace vv::gui {

namespace {

enum Column { NameColumn, AeColumn, HostColumn, PortColumn, TlsColumn, PushColumn, ColumnCount };

/// True for a dotted IPv4 address ("127.0.0.1", "0.0.0.0").
bool isIpv4(const QString& text) {
    const QStringList parts = text.split(QLatin1Char('.'));
    if (parts.size() != 4) {
        return false;
    }
    for (const QString& part : parts) {
        bool ok = false;
        const int value = part.toInt(&ok);
        if (!ok || part.isEmpty() || part.size() > 3 || value < 0 || value > 255) {
            return false;
        }
    }
    return true;
}

}  // namespace

NetworkPreferencesDialog::NetworkPreferencesDialog(QWidget* parent) : QDialog(parent) {
    setObjectName(QStringLiteral("networkPreferences"));
    setWindowTitle(tr("DICOM Network Preferences"));
    const PacsSettings s = readPacsSettings(QSettings());
    nodes_ = s.nodes;

    auto* ours = new QGroupBox(tr("This workstation"), this);
    auto* oursForm = new QFormLayout(ours);
    aeTitle_ = new QLineEdit(QString::fromStdString(s.me.aeTitle), ours);
    aeTitle_->setObjectName(QStringLiteral("ourAeTitle"));
    aeTitle_->setMaxLength(16);
    aeTitle_->setToolTip(tr("The AE title the PACS knows this workstation by"));
    oursForm->addRow(tr("Our &AE title:"), aeTitle_);
    listener_ = new QCheckBox(tr("&Receive studies (listener on)"), ours);
    listener_->setObjectName(QStringLiteral("listenerEnabled"));
    listener_->setChecked(s.listenerEnabled);
    listener_->setToolTip(
        tr("Run the DICOM listener while VesselView runs: nodes allowed to send can push "
           "studies, and C-MOVE retrieves arrive here"));
    oursForm->addRow(QString(), listener_);
    listenerPort_ = new QSpinBox(ours);
    listenerPort_->setObjectName(QStringLiteral("listenerPort"));
    listenerPort_->setRange(1, kMaxPort);
    listenerPort_->setGroupSeparatorShown(false);
    listenerPort_->setValue(s.listenerPort);
    oursForm->addRow(tr("Listener &port:"), listenerPort_);
    bind_ = new QComboBox(ours);
    bind_->setObjectName(QStringLiteral("listenerBind"));
    bind_->setEditable(true);
    bind_->addItem(QStringLiteral("127.0.0.1"));
    bind_->addItem(QStringLiteral("0.0.0.0"));
    bind_->setItemData(0, tr("This computer only"), Qt::ToolTipRole);
    bind_->setItemData(1, tr("All network interfaces"), Qt::ToolTipRole);
    bind_->setCurrentText(QString::fromStdString(s.listenerBindAddress));
    bind_->setToolTip(
        tr("The IPv4 address of the interface to listen on: 127.0.0.1 for this "
           "computer only, 0.0.0.0 for all interfaces"));
    oursForm->addRow(tr("Listen on &interface:"), bind_);
    listenerTls_ =
        new TlsFilesBox(tr("Listener uses TL&S (encrypted DICOM)"), s.listenerTls,
                        TlsFilesBox::OurCertificate::Required, QStringLiteral("listener"), ours);
    listenerTls_->setObjectName(QStringLiteral("listenerTls"));
    listenerTls_->setToolTip(
        tr("Nodes sending to us must then use TLS with a certificate signed by the trusted CA"));
    oursForm->addRow(listenerTls_);

    QGroupBox* waits = makeTimeoutsBox(s.me.timeouts);

    auto* store = new QGroupBox(tr("Local study store"), this);
    auto* storeForm = new QFormLayout(store);
    storeFolder_ = new QLineEdit(QString::fromStdString(s.storeFolder.string()), store);
    storeFolder_->setObjectName(QStringLiteral("storeFolder"));
    showPath(storeFolder_);
    auto* folderRow = new QHBoxLayout;
    folderRow->addWidget(storeFolder_);
    auto* browse = new QPushButton(tr("Browse…"), store);
    connect(browse, &QPushButton::clicked, this, [this] {
        const QString folder = QFileDialog::getExistingDirectory(
            this, tr("Folder of the local study store"), storeFolder_->text());
        if (!folder.isEmpty()) {
            storeFolder_->setText(folder);
        }
    });
    folderRow->addWidget(browse);
    addBuddyRow(storeForm, tr("&Folder:"), storeFolder_, folderRow);
    storeLimit_ = makeGigabyteBox(store, QStringLiteral("storeLimit"), 1, 0.0);
    storeLimit_->setSpecialValueText(tr("No limit"));
    setBytes(storeLimit_, s.storeLimitBytes);
    storeLimit_->setToolTip(
        tr("Above this size the oldest studies are removed first; open "
           "studies are never removed"));
    storeForm->addRow(tr("Size &limit:"), storeLimit_);
    limits_ = new ListenerLimitsBox(s.listenerLimits, this);
    limits_->setObjectName(QStringLiteral("listenerLimits"));

    auto* nodes = new QGroupBox(tr("PACS nodes"), this);
    auto* nodesLayout = new QVBoxLayout(nodes);
    table_ = makeResultTable(
        nodes, QStringLiteral("pacsNodes"),
        {tr("Name"), tr("AE title"), tr("Host"), tr("Port"), tr("TLS"), tr("May send to us")});
    table_->setMinimumHeight(110);  // a header and three nodes
    nodesLayout->addWidget(table_);
    auto* buttonRow = new QHBoxLayout;
    add_ = new QPushButton(tr("&Add…"), nodes);
    edit_ = new QPushButton(tr("&Edit…"), nodes);
    remove_ = new QPushButton(tr("Re&move"), nodes);
    test_ = new QPushButton(tr("&Test"), nodes);
    add_->setObjectName(QStringLiteral("addNode"));
    edit_->setObjectName(QStringLiteral("editNode"));
    remove_->setObjectName(QStringLiteral("removeNode"));
    test_->setObjectName(QStringLiteral("testNode"));
    test_->setToolTip(tr("C-ECHO: does the node answer and accept our AE title?"));
    cancelTest_ = new QPushButton(tr("Ca&ncel Test"), nodes);
    cancelTest_->setObjectName(QStringLiteral("cancelTest"));
    cancelTest_->setToolTip(tr("Stop waiting for the node's answer"));
    for (QPushButton* button : {add_, edit_, remove_, test_, cancelTest_}) {
        buttonRow->addWidget(button);
    }
    buttonRow->addStretch();
    nodesLayout->addLayout(buttonRow);
    testResult_ = new QLabel(nodes);
    testResult_->setObjectName(QStringLiteral("testResult"));
    testResult_->setWordWrap(true);
    testResult_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    nodesLayout->addWidget(testResult_);
    connect(add_, &QPushButton::clicked, this, [this] { editNode(-1); });
    connect(edit_, &QPushButton::clicked, this, [this] { editNode(table_->currentRow()); });
    connect(table_, &QTableWidget::cellDoubleClicked, this, [this](int row) { editNode(row); });
    connect(remove_, &QPushButton::clicked, this, [this] {
        const int row = table_->currentRow();
        if (row >= 0 && row < static_cast<int>(nodes_.size())) {
            nodes_.erase(nodes_.begin() + row);
            fillTable();
        }
    });
    connect(test_, &QPushButton::clicked, this, &NetworkPreferencesDialog::testNode);
    connect(cancelTest_, &QPushButton::clicked, this, &NetworkPreferencesDialog::cancelTest);
    connect(table_, &QTableWidget::itemSelectionChanged, this,
            &NetworkPreferencesDialog::updateButtons);

    error_ = makeErrorLabel(this, QStringLiteral("preferencesError"));
    QDialogButtonBox* buttons = makeOkCancel(this);

    auto* layout = new QVBoxLayout(this);
    auto* top = new QHBoxLayout;
    auto* left = new QVBoxLayout;
    left->addWidget(ours);
    left->addWidget(waits);
    left->addStretch();
    top->addLayout(left);
    auto* right = new QVBoxLayout;
    right->addWidget(store);
    right->addWidget(limits_);
    right->addStretch();
    top->addLayout(right, 1);
    layout->addLayout(top);
    layout->addWidget(nodes, 1);
    layout->addWidget(error_);
    layout->addWidget(buttons);
    fillTable();
}

QGroupBox* NetworkPreferencesDialog::makeTimeoutsBox(const pacs::Timeouts& t) {
    // Two rows (names over boxes), so that the dialog fits a 1280 x 720 screen.
    auto* waits = new QGroupBox(tr("Timeouts"), this);
    waits->setObjectName(QStringLiteral("timeouts"));
    waits->setToolTip(tr("How long VesselView waits for a PACS node before it gives up"));
    auto* grid = new QGridLayout(waits);
    int column = 0;
    const auto secondsBox = [waits, grid, &column](const QString& name, const QString& label,
                                                   int seconds, const QString& tip) {
        auto* box = new QSpinBox(waits);
        box->setObjectName(name);
        box->setRange(1, kMaxTimeoutSeconds);
        box->setSuffix(tr(" s"));
        box->setValue(seconds);
        box->setToolTip(tip);
        auto* title = new QLabel(label, waits);
        title->setBuddy(box);
        grid->addWidget(title, 0, column);
        grid->addWidget(box, 1, column);
        ++column;
        return box;
    };
    connectTimeout_ =
        secondsBox(QStringLiteral("connectTimeout"), tr("Connect:"), t.connectSeconds,
                   tr("How long the node's computer may take to accept the connection"));
    associateTimeout_ = secondsBox(
        QStringLiteral("associateTimeout"), tr("Association:"), t.associateSeconds,
        tr("How long the node may take to accept or reject the association, and to release it"));
    responseTimeout_ = secondsBox(
        QStringLiteral("responseTimeout"), tr("Each answer:"), t.responseSeconds,
        tr("How long the node may take for each answer (a search result, a status, an image); "
           "raise it for a slow PACS"));
    const pacs::Timeouts standard;
    const auto seconds = [](int n) { return quantityText(n, "s"); };
    auto* defaults =
        new QLabel(tr("Defaults: %1, %2, %3")
                       .arg(seconds(standard.connectSeconds), seconds(standard.associateSeconds),
                            seconds(standard.responseSeconds)),
                   waits);
    defaults->setObjectName(QStringLiteral("timeoutsDefaults"));
    auto* restore = new QPushButton(tr("Restore Defaults"), waits);
    restore->setObjectName(QStringLiteral("restoreTimeouts"));
    restore->setToolTip(tr("Put the default timeouts into these fields; OK saves them"));
    connect(restore, &QPushButton::clicked, this, [this, standard] {
        connectTimeout_->setValue(standard.connectSeconds);
        associateTimeout_->setValue(standard.associateSeconds);
        responseTimeout_->setValue(standard.responseSeconds);
    });
    grid->addWidget(defaults, 0, column);
    grid->addWidget(restore, 1, column);
    return waits;
}

PacsSettings NetworkPreferencesDialog::settings() const {
    PacsSettings s = readPacsSettings(QSettings());
    s.me.aeTitle = aeTitle_->text().trimmed().toStdString();
    s.me.timeouts = {connectTimeout_->value(), associateTimeout_->value(),
                     responseTimeout_->value()};
    s.listenerEnabled = listener_->isChecked();
    s.listenerPort = static_cast<std::uint16_t>(listenerPort_->value());
    s.listenerBindAddress = bind_->currentText().trimmed().toStdString();
    s.listenerTls = listenerTls_->settings();
    s.storeFolder = storeFolder_->text().trimmed().toStdString();
    s.storeLimitBytes = bytesOf(storeLimit_);
    s.listenerLimits = limits_->limits();
    s.nodes = nodes_;
    return s;
}

QString NetworkPreferencesDialog::error() const {
    return error_->text();
}

QString NetworkPreferencesDialog::errorDetails() const {
    return error_->toolTip();
}

QString NetworkPreferencesDialog::testResult() const {
    return testResult_->text();
}

void NetworkPreferencesDialog::addNode(const PacsNode& node) {
    nodes_.push_back(node);
    fillTable();
    table_->selectRow(static_cast<int>(nodes_.size()) - 1);
}

void NetworkPreferencesDialog::fillTable() {
    const int current = table_->currentRow();
    table_->setRowCount(static_cast<int>(nodes_.size()));
    for (int row = 0; row < static_cast<int>(nodes_.size()); ++row) {
        const PacsNode& n = nodes_[static_cast<std::size_t>(row)];
        const std::array<QString, ColumnCount> texts = {
            QString::fromStdString(n.name),
            QString::fromStdString(n.node.aeTitle),
            QString::fromStdString(n.node.host),
            portText(n.node.port),
            n.node.tls.enabled ? tr("on") : tr("off"),
            n.allowPush ? tr("yes") : tr("no"),
        };
        for (int column = 0; column < ColumnCount; ++column) {
            table_->setItem(row, column,
                            new QTableWidgetItem(texts[static_cast<std::size_t>(column)]));
        }
    }
    if (!nodes_.empty()) {
        table_->selectRow(std::clamp(current, 0, static_cast<int>(nodes_.size()) - 1));
    }
    updateButtons();
}

void NetworkPreferencesDialog::updateButtons() {
    const bool selected = table_->currentRow() >= 0 && !nodes_.empty();
    edit_->setEnabled(selected);
    remove_->setEnabled(selected);
    test_->setEnabled(selected && !testCall_.isRunning());
    cancelTest_->setEnabled(testCall_.isRunning());
}

void NetworkPreferencesDialog::editNode(int row) {
    const bool adding = row < 0 || row >= static_cast<int>(nodes_.size());
    PacsNode start;
    QStringList taken;
    for (int i = 0; i < static_cast<int>(nodes_.size()); ++i) {
        if (adding || i != row) {
            taken << QString::fromStdString(nodes_[static_cast<std::size_t>(i)].name);
        }
    }
    if (!adding) {
        start = nodes_[static_cast<std::size_t>(row)];
    }
    auto* dialog = new NodeEditDialog(start, taken, this);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    connect(dialog, &QDialog::accepted, this, [this, dialog, adding, row] {
        if (adding) {
            addNode(dialog->node());
        } else if (row < static_cast<int>(nodes_.size())) {
            nodes_[static_cast<std::size_t>(row)] = dialog->node();
            fillTable();
        }
    });
    dialog->open();
    emit nodeDialogShown(dialog);
}

void NetworkPreferencesDialog::testNode() {
    const int row = table_->currentRow();
    if (testCall_.isRunning() || row < 0 || row >= static_cast<int>(nodes_.size())) {
        return;
    }
    const QString ourProblem = aeTitleProblem(aeTitle_->text().trimmed(), tr("Our AE title"));
    if (!ourProblem.isEmpty()) {
        showTestResult(ourProblem);
        fitHeight();
        emit testFinished(false);
        return;
    }
    pacs::LocalAe me = settings().me;
    const pacs::Node node = nodes_[static_cast<std::size_t>(row)].node;
    const QString name = QString::fromStdString(nodes_[static_cast<std::size_t>(row)].name);
    testCall_.start(
        [me, node](const std::stop_token& stop) {
            return tryNetwork([&] { pacs::echo(me, node, stop); });
        },
        [this, node, name](const NetworkFailure& failure) {
            test_->setText(tr("&Test"));
            updateButtons();
            const bool ok = failure.kind == NetworkFailure::Kind::None;
            if (ok) {
                showTestResult(tr("Success: %1 answered C-ECHO.")
                                   .arg(QString::fromStdString(pacs::describe(node))));
            } else {
                showProblemText(testResult_, failureText(failure, name, node));
            }
            fitHeight();
            emit testFinished(ok);
        });
    test_->setText(tr("Testing…"));
    updateButtons();
    showTestResult(tr("Testing %1…").arg(QString::fromStdString(pacs::describe(node))));
    fitHeight();
}

void NetworkPreferencesDialog::cancelTest() {
    if (!testCall_.isRunning()) {
        return;
    }
    testCall_.cancel();  // the worker aborts its association at once
    test_->setText(tr("&Test"));
    updateButtons();
    showTestResult(tr("Test cancelled."));
    fitHeight();
    emit testFinished(false);
}

void NetworkPreferencesDialog::showTestResult(const QString& text) {
    testResult_->setText(text);
    testResult_->setToolTip(QString());
    showAsProblem(testResult_, false);
}

void NetworkPreferencesDialog::fitHeight() {
    // A word-wrapped line that appears does not raise the window's minimum
    // height by itself: without this the fields above it are squeezed. The
    // group boxes that hold it learn of its new size hint first (else the
    // window's layout still counts the hint it had before).
    for (QWidget* w = testResult_->parentWidget(); w != nullptr && w != this;
         w = w->parentWidget()) {
        w->updateGeometry();
    }
    const int width = this->width();
    const int needed =
        std::max(layout()->totalMinimumSize().height(), layout()->totalHeightForWidth(width));
    if (needed > height()) {
        resize(width, needed);
    }
}

void NetworkPreferencesDialog::refuse(const QString& message, QWidget* field) {
    error_->setText(message);
    error_->setToolTip(QString());
    error_->show();
    fitHeight();
    if (field != nullptr) {
        field->setFocus();
    }
}

void NetworkPreferencesDialog::refuse(const PacsSettingsError& error) {
    using Setting = PacsSettingsError::Setting;
    const QString node = QString::fromStdString(error.node());
    ProblemText problem;
    problem.details = QString::fromStdString(error.what());
    QWidget* field = table_;
    switch (error.setting()) {
        case Setting::OurAeTitle:
            problem.summary = tr("Not saved: our AE title is not valid.");
            field = aeTitle_;
            break;
        case Setting::ListenerPort:
            problem.summary = tr("Not saved: the listener port must be 1 to 65535.");
            field = listenerPort_;
            break;
        case Setting::ListenerTls:
            problem.summary =
                tr("Not saved: the listener's TLS needs our certificate, its private key and "
                   "the trusted CA certificate.");
            field = listenerTls_;
            break;
        case Setting::ListenerLimits:
            problem.summary = tr("Not saved: the listener limits do not fit together.");
            field = limits_;
            break;
        case Setting::Timeouts:
            problem.summary =
                tr("Not saved: each timeout must be 1 to %L1 s.").arg(kMaxTimeoutSeconds);
            field = connectTimeout_;
            break;
        case Setting::NodeName:
            problem.summary = node.isEmpty()
                                  ? tr("Not saved: a node has no name.")
                                  : tr("Not saved: two nodes are called \"%1\".").arg(node);
            break;
        case Setting::Node:
            problem.summary =
                tr("Not saved: the AE title, host or port of the node \"%1\" is not valid.")
                    .arg(node);
            break;
    }
    // The node's (last) row, so that Edit opens it.
    for (int row = static_cast<int>(nodes_.size()) - 1; row >= 0 && !node.isEmpty(); --row) {
        if (nodes_[static_cast<std::size_t>(row)].name == error.node()) {
            table_->selectRow(row);
            break;
        }
    }
    refuse(problem.line(), field);
    error_->setToolTip(problem.details);  // the module's own words, on demand
}

void NetworkPreferencesDialog::accept() {
    if (const QString problem = aeTitleProblem(aeTitle_->text().trimmed(), tr("Our AE title"));
        !problem.isEmpty()) {
        refuse(problem, aeTitle_);
        return;
    }
    if (!isIpv4(bind_->currentText().trimmed())) {
        refuse(tr("Listen on interface: enter an IPv4 address such as 127.0.0.1 (this computer "
                  "only) or 0.0.0.0 (all interfaces)."),
               bind_);
        return;
    }
    QWidget* tlsField = nullptr;
    if (const QString problem = listenerTls_->problem(&tlsField); !problem.isEmpty()) {
        refuse(problem, tlsField);
        return;
    }
    if (storeFolder_->text().trimmed().isEmpty()) {
        refuse(tr("Folder: choose a folder for the local study store."), storeFolder_);
        return;
    }
    QSettings store;
    try {
        writePacsSettings(settings(), store);
    } catch (const PacsSettingsError& e) {
        refuse(e);
        return;
    }
    store.sync();
    error_->clear();
    error_->hide();
    QDialog::accept();
}

}  // namespace vv::gui
