// SPDX-License-Identifier: GPL-3.0-or-later
#include "gui/pacs/LocalStudiesBrowser.h"

#include <QDate>
#include <QDialogButtonBox>
#include <QHeaderView>
#include <QLabel>
#include <QLocale>
#include <QPushButton>
#include <QStringList>
#include <QTreeWidget>
#include <QVBoxLayout>
#include <set>
#include <string>

#include "gui/pacs/ListenerService.h"
#include "vv/core/Error.h"
#include "vv/pacs/LocalStore.h"

namespace vv::gui {
namespace {

enum Column { kPatient, kPatientId, kDate, kDescription, kModalities, kSeries, kColumns };
constexpr int kFolderRole = Qt::UserRole;
constexpr int kUidRole = Qt::UserRole + 1;

QString text(const std::string& s) {
    return QString::fromStdString(s);
}

/// "Doe^Jane" as people write it: "Doe, Jane".
QString personName(const std::string& dicom) {
    QStringList parts = text(dicom).split(QLatin1Char('^'));
    while (!parts.isEmpty() && parts.back().trimmed().isEmpty()) {
        parts.removeLast();
    }
    if (parts.size() < 2) {
        return parts.value(0);
    }
    const QString family = parts.takeFirst();
    return family + QStringLiteral(", ") + parts.join(QLatin1Char(' ')).simplified();
}

/// YYYYMMDD in the UI locale's short format; other text as it is.
QString studyDate(const std::string& dicom) {
    const QDate date = QDate::fromString(text(dicom), QStringLiteral("yyyyMMdd"));
    return date.isValid() ? QLocale().toString(date, QLocale::ShortFormat) : text(dicom);
}

QTreeWidgetItem* studyItem(const pacs::StoredStudy& study) {
    auto* item = new QTreeWidgetItem;
    std::set<std::string> modalities;
    for (const pacs::StoredSeries& series : study.series) {
        if (!series.modality.empty()) {
            modalities.insert(series.modality);
        }
    }
    QStringList modalityList;
    for (const std::string& m : modalities) {
        modalityList << text(m);
    }
    item->setText(kPatient, personName(study.patientName));
    item->setText(kPatientId, text(study.patientId));
    item->setText(kDate, studyDate(study.studyDate));
    item->setText(kDescription, text(study.studyDescription));
    item->setText(kModalities, modalityList.join(QStringLiteral(", ")));
    item->setText(kSeries, QLocale().toString(static_cast<qulonglong>(study.series.size())));
    item->setData(kPatient, kFolderRole, QString::fromStdString(study.folder.string()));
    item->setData(kPatient, kUidRole, text(study.studyInstanceUid));
    for (const pacs::StoredSeries& series : study.series) {
        auto* child = new QTreeWidgetItem(item);
        const QString description =
            series.seriesDescription.empty()
                ? LocalStudiesBrowser::tr("Series %L1").arg(series.seriesNumber)
                : text(series.seriesDescription);
        child->setText(kDescription, description);
        child->setText(kModalities, text(series.modality));
        child->setText(kSeries, series.instances == 1
                                    ? LocalStudiesBrowser::tr("1 image")
                                    : LocalStudiesBrowser::tr("%L1 images").arg(series.instances));
        child->setData(kPatient, kFolderRole, QString::fromStdString(series.folder.string()));
        child->setData(kPatient, kUidRole, text(series.seriesInstanceUid));
    }
    return item;
}

}  // namespace

LocalStudiesBrowser::LocalStudiesBrowser(ListenerService& listener, QWidget* parent)
    : QDialog(parent), listener_(listener) {
    setObjectName(QStringLiteral("localStudiesBrowser"));
    setWindowTitle(tr("Local Studies"));
    status_ = new QLabel(this);
    status_->setObjectName(QStringLiteral("localStudiesStatus"));
    status_->setWordWrap(true);
    status_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    tree_ = new QTreeWidget(this);
    tree_->setObjectName(QStringLiteral("localStudiesTree"));
    tree_->setColumnCount(kColumns);
    tree_->setHeaderLabels({tr("Patient"), tr("Patient ID"), tr("Study date"), tr("Description"),
                            tr("Modalities"), tr("Series")});
    tree_->setSelectionMode(QAbstractItemView::SingleSelection);
    tree_->setAlternatingRowColors(true);
    tree_->header()->setStretchLastSection(false);
    tree_->header()->setSectionResizeMode(QHeaderView::ResizeToContents);
    tree_->header()->setSectionResizeMode(kDescription, QHeaderView::Stretch);

    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    open_ = buttons->addButton(tr("&Open"), QDialogButtonBox::ActionRole);
    open_->setObjectName(QStringLiteral("openLocalStudy"));
    open_->setEnabled(false);
    QPushButton* reload = buttons->addButton(tr("&Refresh"), QDialogButtonBox::ActionRole);
    connect(reload, &QPushButton::clicked, this, &LocalStudiesBrowser::refresh);
    connect(open_, &QPushButton::clicked, this, &LocalStudiesBrowser::openSelected);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    connect(tree_, &QTreeWidget::itemSelectionChanged, this,
            [this] { open_->setEnabled(!tree_->selectedItems().isEmpty()); });
    connect(tree_, &QTreeWidget::itemDoubleClicked, this, &LocalStudiesBrowser::openSelected);

    auto* layout = new QVBoxLayout(this);
    layout->addWidget(status_);
    layout->addWidget(tree_, 1);
    layout->addWidget(buttons);
    resize(900, 480);

    connect(&listener_, &ListenerService::studiesChanged, this, &LocalStudiesBrowser::refresh);
    connect(&listener_, &ListenerService::storeChanged, this, &LocalStudiesBrowser::refresh);
    connect(&listener_, &ListenerService::stateChanged, this,
            &LocalStudiesBrowser::updateStatusLine);
    refresh();
}

void LocalStudiesBrowser::refresh() {
    QString selected;
    if (const QList<QTreeWidgetItem*> items = tree_->selectedItems(); !items.isEmpty()) {
        selected = items.front()->data(kPatient, kUidRole).toString();
    }
    tree_->clear();
    readProblem_.clear();
    const std::filesystem::path& folder = listener_.storeFolder();
    try {
        if (!std::filesystem::exists(folder)) {
            updateStatusLine();  // nothing received yet; reading creates no store
            return;
        }
        const pacs::LocalStore store(folder);
        for (const pacs::StoredStudy& study : store.studies()) {
            tree_->addTopLevelItem(studyItem(study));
        }
    } catch (const Error&) {
        readProblem_ =
            tr("The study store %1 cannot be read.").arg(QString::fromStdString(folder.string()));
    }
    tree_->expandAll();
    for (QTreeWidgetItemIterator it(tree_); *it != nullptr; ++it) {
        if (!selected.isEmpty() && (*it)->data(kPatient, kUidRole).toString() == selected) {
            tree_->setCurrentItem(*it);
        }
    }
    updateStatusLine();
}

void LocalStudiesBrowser::updateStatusLine() {
    const int studies = tree_->topLevelItemCount();
    QString line = readProblem_.isEmpty()
                       ? (studies == 1 ? tr("1 study in %1") : tr("%L1 studies in %2").arg(studies))
                             .arg(QString::fromStdString(listener_.storeFolder().string()))
                       : readProblem_;
    status_->setText(line + QStringLiteral(" — ") + listener_.stateText());
}

void LocalStudiesBrowser::openSelected() {
    const QList<QTreeWidgetItem*> items = tree_->selectedItems();
    if (items.isEmpty()) {
        return;
    }
    emit openRequested(items.front()->data(kPatient, kFolderRole).toString());
}

}  // namespace vv::gui
