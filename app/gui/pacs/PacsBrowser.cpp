// SPDX-License-Identifier: GPL-3.0-or-later
#include "gui/pacs/PacsBrowser.h"

#include <QButtonGroup>
#include <QComboBox>
#include <QDateEdit>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QGridLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QProgressBar>
#include <QPushButton>
#include <QRadioButton>
#include <QSettings>
#include <QShowEvent>
#include <QSplitter>
#include <QTableWidget>
#include <QTimer>
#include <QVBoxLayout>
#include <array>
#include <cmath>

#include "gui/DateText.h"
#include "gui/pacs/BackgroundCall.h"
#include "gui/pacs/NetworkFailure.h"
#include "gui/pacs/PacsWidgets.h"
#include "gui/pacs/RetrieveJob.h"
#include "vv/core/Log.h"
#include "vv/dicom/PersonName.h"

namespace vv::gui {

namespace {

constexpr log::Category kLog("vv.gui");

/// The "any" date of the date fields (their minimum).
const QDate kAnyDate(1900, 1, 1);
constexpr int kProgressSteps = 1000;
constexpr int kProgressPollMs = 50;

enum StudyColumn {
    PatientColumn,
    PatientIdColumn,
    DateColumn,
    DescriptionColumn,
    ModalitiesColumn,
    AccessionColumn,
    SeriesCountColumn,
    StudyColumnCount
};
enum SeriesColumn {
    NumberColumn,
    ModalityColumn,
    SeriesDescriptionColumn,
    InstancesColumn,
    SeriesColumnCount
};

QString text(const std::string& value) {
    return QString::fromStdString(value);
}

/// A count as a person reads it; "" when the PACS did not say (-1).
QString countText(int count) {
    return count < 0 ? QString() : QLocale().toString(count);
}

QDateEdit* dateField(QWidget* parent, const QString& name) {
    auto* edit = new QDateEdit(parent);
    edit->setObjectName(name);
    edit->setCalendarPopup(true);
    // Typed and shown as every date in the UI (07.03.2025 in German): the
    // locale's short format has a two-digit year.
    edit->setDisplayFormat(uiDateFormat());
    edit->setMinimumDate(kAnyDate);
    edit->setSpecialValueText(PacsBrowser::tr("any"));
    edit->setDate(kAnyDate);
    return edit;
}

QString noNodeText() {
    return PacsBrowser::tr("No PACS node is set up yet: add one in DICOM > Preferences.");
}

QString studiesFoundText(int count) {
    return PacsBrowser::tr("Studies found: %1.").arg(QLocale().toString(count));
}

std::string dicomDate(const QDateEdit* edit) {
    return edit->date() == kAnyDate
               ? std::string()
               : edit->date().toString(QStringLiteral("yyyyMMdd")).toStdString();
}

}  // namespace

PacsBrowser::PacsBrowser(QWidget* parent) : QDialog(parent) {
    setObjectName(QStringLiteral("pacsBrowser"));
    setWindowTitle(tr("Query PACS"));

    // Built in the order the widgets are created, which is their tab order.
    QGroupBox* queryBox = buildSearchBox();
    QSplitter* split = buildResultTables();
    QGroupBox* retrieveBox = buildRetrieveBox();

    status_ = new QLabel(this);
    status_->setObjectName(QStringLiteral("pacsStatus"));
    status_->setWordWrap(true);
    status_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    auto* close = new QDialogButtonBox(QDialogButtonBox::Close, this);
    connect(close, &QDialogButtonBox::rejected, this, &QDialog::reject);

    auto* layout = new QVBoxLayout(this);
    layout->addWidget(queryBox);
    layout->addWidget(split, 1);
    layout->addWidget(retrieveBox);
    layout->addWidget(status_);
    layout->addWidget(close);

    progressTimer_ = new QTimer(this);
    progressTimer_->setInterval(kProgressPollMs);
    connect(progressTimer_, &QTimer::timeout, this, &PacsBrowser::pollRetrieveProgress);
    connectSearch();
    connectRetrieve();
    reloadSettings();
}

QGroupBox* PacsBrowser::buildSearchBox() {
    auto* queryBox = new QGroupBox(tr("Search"), this);
    auto* grid = new QGridLayout(queryBox);
    node_ = new QComboBox(queryBox);
    node_->setObjectName(QStringLiteral("pacsNode"));
    patientName_ = new QLineEdit(queryBox);
    patientName_->setObjectName(QStringLiteral("queryPatientName"));
    patientName_->setPlaceholderText(tr("e.g. Doe*"));
    patientName_->setToolTip(
        tr("The patient's name to search for, e.g. Doe*: * matches any text, ? any one character"));
    patientId_ = new QLineEdit(queryBox);
    patientId_->setObjectName(QStringLiteral("queryPatientId"));
    dateFrom_ = dateField(queryBox, QStringLiteral("queryDateFrom"));
    dateTo_ = dateField(queryBox, QStringLiteral("queryDateTo"));
    modality_ = new QComboBox(queryBox);
    modality_->setObjectName(QStringLiteral("queryModality"));
    modality_->setEditable(true);
    modality_->addItems({QString(), QStringLiteral("CT"), QStringLiteral("MR"),
                         QStringLiteral("XA"), QStringLiteral("US"), QStringLiteral("PT")});
    description_ = new QLineEdit(queryBox);
    description_->setObjectName(QStringLiteral("queryDescription"));
    accession_ = new QLineEdit(queryBox);
    accession_->setObjectName(QStringLiteral("queryAccession"));
    search_ = new QPushButton(tr("&Search"), queryBox);
    search_->setObjectName(QStringLiteral("search"));
    search_->setDefault(true);
    cancelSearch_ = new QPushButton(tr("Cancel Searc&h"), queryBox);
    cancelSearch_->setObjectName(QStringLiteral("cancelSearch"));
    cancelSearch_->setToolTip(tr("Stop waiting for the PACS's answer"));
    layOutSearchBox(queryBox, grid);
    return queryBox;
}

void PacsBrowser::layOutSearchBox(QGroupBox* queryBox, QGridLayout* grid) {
    const auto addField = [grid, queryBox](int row, int column, const QString& label,
                                           QWidget* field) {
        auto* l = new QLabel(label, queryBox);
        l->setBuddy(field);
        grid->addWidget(l, row, column * 2);
        grid->addWidget(field, row, column * 2 + 1);
    };
    addField(0, 0, tr("&Node:"), node_);
    addField(1, 0, tr("Patient &name:"), patientName_);
    addField(2, 0, tr("Patient &ID:"), patientId_);
    addField(0, 1, tr("Study date &from:"), dateFrom_);
    addField(1, 1, tr("&to:"), dateTo_);
    addField(2, 1, tr("&Modality:"), modality_);
    addField(0, 2, tr("&Description:"), description_);
    addField(1, 2, tr("&Accession:"), accession_);
    auto* searchButtons = new QHBoxLayout;
    searchButtons->addStretch();
    searchButtons->addWidget(cancelSearch_);
    searchButtons->addWidget(search_);
    grid->addLayout(searchButtons, 2, 5);
    grid->setColumnStretch(1, 2);
    grid->setColumnStretch(3, 1);
    grid->setColumnStretch(5, 2);
}

QSplitter* PacsBrowser::buildResultTables() {
    studies_ = makeResultTable(this, QStringLiteral("pacsStudies"),
                               {tr("Patient"), tr("Patient ID"), tr("Date"), tr("Description"),
                                tr("Modalities"), tr("Accession"), tr("Series")});
    series_ =
        makeResultTable(this, QStringLiteral("pacsSeries"),
                        {tr("Number"), tr("Modality"), tr("Series description"), tr("Images")});
    auto* split = new QSplitter(Qt::Vertical, this);
    split->addWidget(studies_);
    split->addWidget(series_);
    split->setStretchFactor(0, 3);
    split->setStretchFactor(1, 2);
    return split;
}

QGroupBox* PacsBrowser::buildRetrieveBox() {
    auto* retrieveBox = new QGroupBox(tr("Retrieve into the local study store"), this);
    auto* retrieveLayout = new QVBoxLayout(retrieveBox);
    retrieveLayout->addLayout(buildRetrieveMethodRow(retrieveBox));
    retrieveLayout->addLayout(buildRetrieveRunRow(retrieveBox));
    return retrieveBox;
}

QHBoxLayout* PacsBrowser::buildRetrieveMethodRow(QGroupBox* retrieveBox) {
    auto* how = new QHBoxLayout;
    useGet_ = new QRadioButton(tr("C-&GET (direct)"), retrieveBox);
    useGet_->setObjectName(QStringLiteral("useGet"));
    useGet_->setChecked(true);
    useMove_ = new QRadioButton(tr("C-M&OVE to our listener"), retrieveBox);
    useMove_->setObjectName(QStringLiteral("useMove"));
    auto* group = new QButtonGroup(retrieveBox);
    group->addButton(useGet_);
    group->addButton(useMove_);
    moveNote_ = new QLabel(retrieveBox);
    moveNote_->setObjectName(QStringLiteral("moveNote"));
    moveNote_->setWordWrap(true);
    how->addWidget(useGet_);
    how->addWidget(useMove_);
    how->addWidget(moveNote_, 1);
    return how;
}

QHBoxLayout* PacsBrowser::buildRetrieveRunRow(QGroupBox* retrieveBox) {
    auto* run = new QHBoxLayout;
    retrieveStudy_ = new QPushButton(tr("Retrieve S&tudy"), retrieveBox);
    retrieveStudy_->setObjectName(QStringLiteral("retrieveStudy"));
    retrieveSeries_ = new QPushButton(tr("Retrieve S&eries"), retrieveBox);
    retrieveSeries_->setObjectName(QStringLiteral("retrieveSeries"));
    progress_ = new QProgressBar(retrieveBox);
    progress_->setObjectName(QStringLiteral("retrieveProgress"));
    progress_->setRange(0, kProgressSteps);
    progress_->setValue(0);
    cancel_ = new QPushButton(tr("&Cancel"), retrieveBox);
    cancel_->setObjectName(QStringLiteral("cancelRetrieve"));
    open_ = new QPushButton(tr("O&pen"), retrieveBox);
    open_->setObjectName(QStringLiteral("openRetrieved"));
    open_->setToolTip(tr("Open the retrieved series in VesselView"));
    for (QWidget* w : std::initializer_list<QWidget*>{retrieveStudy_, retrieveSeries_}) {
        run->addWidget(w);
    }
    run->addWidget(progress_, 1);
    run->addWidget(cancel_);
    run->addWidget(open_);
    return run;
}

void PacsBrowser::pollRetrieveProgress() {
    if (retrieve_ == nullptr) {
        return;
    }
    const double fraction = retrieve_->fraction;
    const int value = static_cast<int>(std::lround(fraction * kProgressSteps));
    if (value != progress_->value()) {
        progress_->setValue(value);
        if (retrieveTotal_ > 0) {
            const int received = static_cast<int>(std::lround(fraction * retrieveTotal_));
            progress_->setFormat(
                tr("%1 of %2 images")
                    .arg(QLocale().toString(received), QLocale().toString(retrieveTotal_)));
        }
        emit retrieveProgress(fraction);
    }
}

void PacsBrowser::connectSearch() {
    connect(search_, &QPushButton::clicked, this, &PacsBrowser::startSearch);
    connect(cancelSearch_, &QPushButton::clicked, this, &PacsBrowser::cancelSearch);
    for (QLineEdit* edit : {patientName_, patientId_, description_, accession_}) {
        connect(edit, &QLineEdit::returnPressed, this, &PacsBrowser::startSearch);
    }
    connect(studies_, &QTableWidget::itemSelectionChanged, this, &PacsBrowser::studySelected);
    connect(series_, &QTableWidget::itemSelectionChanged, this, &PacsBrowser::updateButtons);
}

void PacsBrowser::connectRetrieve() {
    connect(retrieveStudy_, &QPushButton::clicked, this, [this] { startRetrieve(true); });
    connect(retrieveSeries_, &QPushButton::clicked, this, [this] { startRetrieve(false); });
    connect(cancel_, &QPushButton::clicked, this, [this] {
        if (retrieve_ != nullptr) {
            retrieve_->stop.request_stop();
            cancel_->setEnabled(false);
            setStatus(tr("Cancelling…"));
        }
    });
    connect(open_, &QPushButton::clicked, this, [this] {
        if (!retrievedFolder_.isEmpty()) {
            emit openFolder(retrievedFolder_, retrievedStore_, retrievedStudy_);
        }
    });
    connect(useMove_, &QRadioButton::toggled, this, &PacsBrowser::updateMoveNote);
    connect(node_, &QComboBox::currentIndexChanged, this, &PacsBrowser::updateButtons);
}

PacsBrowser::~PacsBrowser() {
    if (retrieve_ != nullptr) {
        retrieve_->stop.request_stop();  // the worker ends on its own; nothing waits for it
    }
}

void PacsBrowser::setListenerRunning(ListenerRunning running) {
    listenerRunning_ = std::move(running);
    updateMoveNote();
}

void PacsBrowser::reloadSettings() {
    settings_ = readPacsSettings(QSettings());
    const QString current = node_->currentText();
    node_->clear();
    for (const PacsNode& n : settings_.nodes) {
        node_->addItem(text(n.name));
        node_->setItemData(node_->count() - 1, text(pacs::describe(n.node)), Qt::ToolTipRole);
    }
    if (const int index = node_->findText(current); index >= 0) {
        node_->setCurrentIndex(index);
    }
    if (settings_.nodes.empty()) {
        setStatus(noNodeText(), true);
    }
    updateMoveNote();
    updateButtons();
}

QString PacsBrowser::status() const {
    return status_->text();
}

void PacsBrowser::setStatus(const QString& message, bool problem) {
    status_->setText(message);
    status_->setToolTip(QString());
    showAsProblem(status_, problem);
}

const PacsNode* PacsBrowser::currentNode() const {
    return findNode(settings_, node_->currentText().toStdString());
}

const PacsNode* PacsBrowser::resultsNode() const {
    return findNode(settings_, resultsNode_);
}

pacs::StudyQuery PacsBrowser::query() const {
    pacs::StudyQuery q;
    q.patientName = patientName_->text().trimmed().toStdString();
    q.patientId = patientId_->text().trimmed().toStdString();
    q.studyDateFrom = dicomDate(dateFrom_);
    q.studyDateTo = dicomDate(dateTo_);
    q.modality = modality_->currentText().trimmed().toUpper().toStdString();
    q.studyDescription = description_->text().trimmed().toStdString();
    q.accessionNumber = accession_->text().trimmed().toStdString();
    return q;
}

void PacsBrowser::startSearch() {
    const PacsNode* node = currentNode();
    if (searchCall_.isRunning() || node == nullptr) {
        return;
    }
    if (dateFrom_->date() != kAnyDate && dateTo_->date() != kAnyDate &&
        dateFrom_->date() > dateTo_->date()) {
        setStatus(tr("Study date: \"from\" is after \"to\"."), true);
        emit searchFinished(false);
        return;
    }
    searchCall_.start(
        [me = settings_.me, peer = node->node, q = query()](const std::stop_token& stop) {
            return tryNetwork([&] { return pacs::findStudies(me, peer, q, {}, stop); });
        },
        [this, peer = node->node, name = node->name](
            const std::pair<std::vector<pacs::StudyResult>, NetworkFailure>& answer) {
            const bool ok = answer.second.kind == NetworkFailure::Kind::None;
            // The tables show the last search's answer, and its node serves them.
            resultsNode_ = ok ? name : std::string();
            showStudies(answer.first);
            if (ok) {
                setStatus(studiesFoundText(static_cast<int>(answer.first.size())));
            } else {
                showProblemText(status_, failureText(answer.second, text(name), peer));
            }
            updateButtons();
            emit searchFinished(ok);
        });
    updateButtons();
    setStatus(tr("Searching %1…").arg(text(pacs::describe(node->node))));
}

void PacsBrowser::cancelSearch() {
    if (!searchCall_.isRunning() && !seriesCall_.isRunning()) {
        return;
    }
    const bool studies = searchCall_.isRunning();
    // The workers abort their associations at once; their answers are dropped.
    searchCall_.cancel();
    seriesCall_.cancel();
    if (studies) {
        resultsNode_.clear();  // the rows shown are not this search's answer
        showStudies({});
    }
    setStatus(tr("Search cancelled."));
    updateButtons();
    if (studies) {
        emit searchFinished(false);
    } else {
        emit seriesFinished(false);
    }
}

void PacsBrowser::showStudies(const std::vector<pacs::StudyResult>& studies) {
    studyResults_ = studies;
    seriesResults_.clear();
    series_->setRowCount(0);
    studies_->setRowCount(0);
    studies_->setRowCount(static_cast<int>(studies.size()));
    for (int row = 0; row < static_cast<int>(studies.size()); ++row) {
        const pacs::StudyResult& s = studies[static_cast<std::size_t>(row)];
        QString modalities = text(s.modalitiesInStudy);
        modalities.replace(QLatin1Char('\\'), QStringLiteral(", "));
        const std::array<QString, StudyColumnCount> cells = {
            text(dicom::personNameText(s.patientName)),
            text(s.patientId),
            studyDateText(s.studyDate),
            text(s.studyDescription),
            modalities,
            text(s.accessionNumber),
            countText(s.numberOfSeries),
        };
        for (int column = 0; column < StudyColumnCount; ++column) {
            studies_->setItem(row, column,
                              new QTableWidgetItem(cells[static_cast<std::size_t>(column)]));
        }
    }
}

void PacsBrowser::studySelected() {
    seriesResults_.clear();
    series_->setRowCount(0);
    // The series of the study selected before: not wanted any more.
    seriesCall_.cancel();
    updateButtons();
    const int row = studies_->currentRow();
    const PacsNode* node = resultsNode();
    if (row < 0 || row >= static_cast<int>(studyResults_.size()) || node == nullptr) {
        return;
    }
    pacs::SeriesQuery q;
    q.studyInstanceUid = studyResults_[static_cast<std::size_t>(row)].studyInstanceUid;
    seriesCall_.start(
        [me = settings_.me, peer = node->node, q](const std::stop_token& stop) {
            return tryNetwork([&] { return pacs::findSeries(me, peer, q, {}, stop); });
        },
        [this, peer = node->node, name = text(node->name)](
            const std::pair<std::vector<pacs::SeriesResult>, NetworkFailure>& answer) {
            const bool ok = answer.second.kind == NetworkFailure::Kind::None;
            if (ok) {
                showSeries(answer.first);
            } else {
                showProblemText(status_, failureText(answer.second, name, peer));
            }
            updateButtons();
            emit seriesFinished(ok);
        });
    updateButtons();
}

void PacsBrowser::showSeries(const std::vector<pacs::SeriesResult>& series) {
    seriesResults_ = series;
    series_->setRowCount(static_cast<int>(series.size()));
    for (int row = 0; row < static_cast<int>(series.size()); ++row) {
        const pacs::SeriesResult& s = series[static_cast<std::size_t>(row)];
        const std::array<QString, SeriesColumnCount> cells = {
            countText(s.seriesNumber), text(s.modality), text(s.seriesDescription),
            countText(s.numberOfInstances)};
        for (int column = 0; column < SeriesColumnCount; ++column) {
            series_->setItem(row, column,
                             new QTableWidgetItem(cells[static_cast<std::size_t>(column)]));
        }
    }
    if (series.size() == 1) {
        series_->selectRow(0);
    }
    updateButtons();
}

void PacsBrowser::updateMoveNote() {
    const bool running = listenerRunning_ && listenerRunning_();
    useMove_->setText(tr("C-M&OVE to our listener (%1, port %2)")
                          .arg(text(settings_.me.aeTitle))
                          .arg(portText(settings_.listenerPort)));
    moveNote_->setText(useMove_->isChecked() && !running
                           ? tr("Our listener is not running: turn it on in DICOM > Preferences, "
                                "or use C-GET.")
                           : QString());
    showAsProblem(moveNote_, true);
    updateButtons();
}

void PacsBrowser::updateButtons() {
    const bool busy = searchCall_.isRunning() || retrieve_ != nullptr;
    const bool hasStudy = studies_->currentRow() >= 0 &&
                          studies_->currentRow() < static_cast<int>(studyResults_.size());
    const bool hasSeries = series_->currentRow() >= 0 &&
                           series_->currentRow() < static_cast<int>(seriesResults_.size());
    search_->setEnabled(!searchCall_.isRunning() && currentNode() != nullptr);
    cancelSearch_->setEnabled(searchCall_.isRunning() || seriesCall_.isRunning());
    retrieveStudy_->setEnabled(!busy && hasStudy);
    retrieveSeries_->setEnabled(!busy && hasSeries);
    cancel_->setEnabled(retrieve_ != nullptr && !retrieve_->stop.stop_requested());
    // Open opens what was retrieved: only while that is what is selected.
    const auto [study, series] = selectedUids();
    open_->setEnabled(retrieve_ == nullptr && !retrievedFolder_.isEmpty() &&
                      study == retrievedStudy_.toStdString() &&
                      (retrievedSeries_.empty() || series == retrievedSeries_));
    useGet_->setEnabled(retrieve_ == nullptr);
    useMove_->setEnabled(retrieve_ == nullptr);
}

std::pair<std::string, std::string> PacsBrowser::selectedUids() const {
    std::pair<std::string, std::string> uids;
    const int studyRow = studies_->selectionModel()->hasSelection() ? studies_->currentRow() : -1;
    if (studyRow < 0 || studyRow >= static_cast<int>(studyResults_.size())) {
        return uids;
    }
    uids.first = studyResults_[static_cast<std::size_t>(studyRow)].studyInstanceUid;
    const int seriesRow = series_->selectionModel()->hasSelection() ? series_->currentRow() : -1;
    if (seriesRow >= 0 && seriesRow < static_cast<int>(seriesResults_.size())) {
        uids.second = seriesResults_[static_cast<std::size_t>(seriesRow)].seriesInstanceUid;
    }
    return uids;
}

void PacsBrowser::forgetRetrieve() {
    retrievedFolder_.clear();
    retrievedStudy_.clear();
    retrievedSeries_.clear();
    progress_->setValue(0);
    progress_->resetFormat();
    // What the tables show still holds; anything said of a retrieve does not.
    if (settings_.nodes.empty()) {
        setStatus(noNodeText(), true);
    } else if (resultsNode() != nullptr) {
        setStatus(studiesFoundText(studies_->rowCount()));
    } else {
        setStatus(QString());
    }
    updateButtons();
}

void PacsBrowser::showEvent(QShowEvent* event) {
    QDialog::showEvent(event);
    if (!event->spontaneous() && retrieve_ == nullptr) {
        forgetRetrieve();
    }
}

void PacsBrowser::startRetrieve(bool wholeStudy) {
    const PacsNode* node = resultsNode();
    const int studyRow = studies_->currentRow();
    if (retrieve_ != nullptr || node == nullptr || studyRow < 0 ||
        studyRow >= static_cast<int>(studyResults_.size())) {
        return;
    }
    RetrieveJob job;
    job.settings = settings_;
    job.node = node->node;
    job.move = useMove_->isChecked();
    job.request.studyInstanceUid =
        studyResults_[static_cast<std::size_t>(studyRow)].studyInstanceUid;
    retrieveTotal_ = -1;
    if (wholeStudy) {
        int total = 0;
        for (const pacs::SeriesResult& s : seriesResults_) {
            total = s.numberOfInstances < 0 || total < 0 ? -1 : total + s.numberOfInstances;
        }
        retrieveTotal_ = seriesResults_.empty() ? -1 : total;
    } else {
        const int seriesRow = series_->currentRow();
        if (seriesRow < 0 || seriesRow >= static_cast<int>(seriesResults_.size())) {
            return;
        }
        const pacs::SeriesResult& s = seriesResults_[static_cast<std::size_t>(seriesRow)];
        job.request.seriesInstanceUid = s.seriesInstanceUid;
        retrieveTotal_ = s.numberOfInstances;
    }
    if (job.move && !(listenerRunning_ && listenerRunning_())) {
        setStatus(tr("C-MOVE needs our listener, and it is not running: turn it on in DICOM > "
                     "Preferences (nodes must be allowed to send to us), or use C-GET."),
                  true);
        emit retrieveFinished(false);
        return;
    }
    retrievedFolder_.clear();
    retrievedStore_ = QString::fromStdString(job.settings.storeFolder.string());
    retrievedStudy_ = QString::fromStdString(job.request.studyInstanceUid);
    retrievedSeries_ = job.request.seriesInstanceUid;
    retrieve_ = std::make_shared<RetrieveControl>();
    progress_->setValue(0);
    progress_->resetFormat();
    setStatus(tr("Retrieving from %1…").arg(text(pacs::describe(job.node))));
    progressTimer_->start();
    updateButtons();
    runInBackground(
        this, [job, control = retrieve_] { return runRetrieve(job, *control); },
        [this, peer = job.node, name = text(node->name)](const RetrieveOutcome& outcome) {
            progressTimer_->stop();
            retrieve_.reset();
            retrieveEnded(outcome);
            if (outcome.failure.kind == NetworkFailure::Kind::Cancelled) {
                setStatus(tr("Retrieve cancelled: nothing of it was kept."));
            } else if (outcome.failure.kind != NetworkFailure::Kind::None) {
                // One plain sentence; the technical detail in the tooltip and the log.
                showProblemText(status_,
                                retrieveFailureText(outcome.failure, name, peer, outcome.kept));
                log::warning(kLog, "retrieve failed: " + outcome.failure.detail);
            }
            updateButtons();
            emit retrieveFinished(outcome.failure.kind == NetworkFailure::Kind::None &&
                                  !outcome.notStoredByListener);
        });
}

void PacsBrowser::retrieveEnded(const RetrieveOutcome& outcome) {
    if (outcome.failure.kind != NetworkFailure::Kind::None) {
        progress_->setValue(0);
        progress_->resetFormat();  // no "64 of 400 images": none of them is kept
        return;
    }
    if (outcome.notStoredByListener) {
        setStatus(tr("The PACS reports the move done, but our listener did not store the "
                     "images. Check that the PACS knows our AE title, host and listener port."),
                  true);
        return;
    }
    progress_->setValue(kProgressSteps);
    const QString count = QLocale().toString(static_cast<qulonglong>(outcome.instances));
    progress_->setFormat(tr("%1 of %2 images").arg(count, count));
    retrievedFolder_ = QString::fromStdString(outcome.folder.string());
    setStatus(tr("Done: images retrieved into the local study store: %1.")
                  .arg(QLocale().toString(static_cast<qulonglong>(outcome.instances))));
}

}  // namespace vv::gui
