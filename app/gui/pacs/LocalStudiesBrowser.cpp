// SPDX-License-Identifier: GPL-3.0-or-later
#include "gui/pacs/LocalStudiesBrowser.h"

#include <QDate>
#include <QDialogButtonBox>
#include <QHeaderView>
#include <QLabel>
#include <QLocale>
#include <QMessageBox>
#include <QPushButton>
#include <QStringList>
#include <QTreeWidget>
#include <QVBoxLayout>
#include <set>
#include <string>

#include "gui/pacs/ListenerService.h"
#include "gui/pacs/PacsWidgets.h"
#include "vv/core/Error.h"
#include "vv/dicom/PersonName.h"
#include "vv/pacs/LocalStore.h"

namespace vv::gui {
namespace {

enum Column { kPatient, kPatientId, kDate, kDescription, kModalities, kSeries, kColumns };
constexpr int kFolderRole = Qt::UserRole;
constexpr int kUidRole = Qt::UserRole + 1;

QString text(const std::string& s) {
    return QString::fromStdString(s);
}

/// The study row of `item` (itself, or the study of a series row).
const QTreeWidgetItem* studyOf(const QTreeWidgetItem* item) {
    return item->parent() != nullptr ? item->parent() : item;
}

/// How the confirmation and the messages name a study after "the study":
/// by its description and date ("“CTA run-off” of 3/12/24").
QString studyName(const QTreeWidgetItem* study) {
    const QString date = study->text(kDate);
    const QString description = study->text(kDescription);
    if (description.isEmpty()) {
        return date.isEmpty() ? LocalStudiesBrowser::tr("without date or description")
                              : LocalStudiesBrowser::tr("of %1").arg(date);
    }
    return date.isEmpty() ? LocalStudiesBrowser::tr("“%1”").arg(description)
                          : LocalStudiesBrowser::tr("“%1” of %2").arg(description, date);
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
    item->setText(kPatient, text(dicom::personNameText(study.patientName)));
    item->setText(kPatientId, text(study.patientId));
    item->setText(kDate, studyDateText(study.studyDate));
    item->setText(kDescription, text(study.studyDescription));
    item->setText(kModalities, modalityList.join(QStringLiteral(", ")));
    item->setText(kSeries, QLocale().toString(static_cast<qulonglong>(study.series.size())));
    item->setData(kPatient, kFolderRole, QString::fromStdString(study.folder.string()));
    item->setData(kPatient, kUidRole, text(study.studyInstanceUid));
    for (const pacs::StoredSeries& series : study.series) {
        auto* child = new QTreeWidgetItem(item);
        const QString description =
            series.seriesDescription.empty()
                ? LocalStudiesBrowser::tr("Series %1").arg(series.seriesNumber)
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
    delete_ = buttons->addButton(tr("&Delete…"), QDialogButtonBox::ActionRole);
    delete_->setObjectName(QStringLiteral("deleteLocalStudy"));
    delete_->setEnabled(false);
    message_ = new QLabel(this);
    message_->setObjectName(QStringLiteral("localStudiesMessage"));
    message_->setWordWrap(true);
    message_->hide();
    QPushButton* reload = buttons->addButton(tr("&Refresh"), QDialogButtonBox::ActionRole);
    connect(reload, &QPushButton::clicked, this, &LocalStudiesBrowser::refresh);
    connect(open_, &QPushButton::clicked, this, &LocalStudiesBrowser::openSelected);
    connect(delete_, &QPushButton::clicked, this, &LocalStudiesBrowser::askToDeleteSelected);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    connect(tree_, &QTreeWidget::itemSelectionChanged, this, &LocalStudiesBrowser::updateButtons);
    connect(tree_, &QTreeWidget::itemDoubleClicked, this, &LocalStudiesBrowser::openSelected);

    auto* layout = new QVBoxLayout(this);
    layout->addWidget(status_);
    layout->addWidget(tree_, 1);
    layout->addWidget(message_);
    layout->addWidget(buttons);
    resize(900, 480);

    connect(&listener_, &ListenerService::studiesChanged, this, &LocalStudiesBrowser::refresh);
    connect(&listener_, &ListenerService::storeChanged, this, &LocalStudiesBrowser::refresh);
    connect(&listener_, &ListenerService::stateChanged, this,
            &LocalStudiesBrowser::updateStatusLine);
    refresh();
}

void LocalStudiesBrowser::refresh() {
    reading_ = true;
    updateStatusLine();
    reader_.start(
        [folder = listener_.storeFolder()](const std::stop_token&) { return readStore(folder); },
        [this](const Listing& listing) { showListing(listing); });
}

LocalStudiesBrowser::Listing LocalStudiesBrowser::readStore(const std::filesystem::path& folder) {
    Listing listing;
    listing.folder = folder;
    try {
        if (std::filesystem::exists(folder)) {  // else nothing received yet: no store is made
            listing.studies = pacs::LocalStore(folder).studies();
        }
    } catch (const Error&) {
        listing.failed = true;
    } catch (const std::filesystem::filesystem_error&) {
        listing.failed = true;
    }
    return listing;
}

void LocalStudiesBrowser::showListing(const Listing& listing) {
    QString selected;  // as the user left it while the store was read
    if (const QList<QTreeWidgetItem*> items = tree_->selectedItems(); !items.isEmpty()) {
        selected = items.front()->data(kPatient, kUidRole).toString();
    }
    reading_ = false;
    tree_->clear();
    readProblem_ = listing.failed ? tr("The study store %1 cannot be read.")
                                        .arg(QString::fromStdString(listing.folder.string()))
                                  : QString();
    QList<QTreeWidgetItem*> rows;
    rows.reserve(static_cast<qsizetype>(listing.studies.size()));
    for (const pacs::StoredStudy& study : listing.studies) {
        rows << studyItem(study);
    }
    tree_->addTopLevelItems(rows);
    tree_->expandAll();
    for (QTreeWidgetItemIterator it(tree_); *it != nullptr; ++it) {
        if (!selected.isEmpty() && (*it)->data(kPatient, kUidRole).toString() == selected) {
            tree_->setCurrentItem(*it);
        }
    }
    updateStatusLine();
    updateButtons();
    emit refreshed();
}

void LocalStudiesBrowser::updateStatusLine() {
    const int studies = tree_->topLevelItemCount();
    const QString folder = QString::fromStdString(listener_.storeFolder().string());
    QString line;
    if (reading_) {
        line = tr("Reading the study store %1…").arg(folder);
    } else if (!readProblem_.isEmpty()) {
        line = readProblem_;
    } else {
        line =
            (studies == 1 ? tr("1 study in %1") : tr("%L1 studies in %2").arg(studies)).arg(folder);
    }
    status_->setText(line + QStringLiteral(" — ") + listener_.stateText());
}

void LocalStudiesBrowser::updateButtons() {
    const bool chosen = !tree_->selectedItems().isEmpty();
    open_->setEnabled(chosen);
    delete_->setEnabled(chosen && !remover_.isRunning());
}

void LocalStudiesBrowser::showMessage(const QString& message) {
    message_->setText(message);
    message_->setVisible(!message.isEmpty());
}

void LocalStudiesBrowser::openSelected() {
    const QList<QTreeWidgetItem*> items = tree_->selectedItems();
    if (items.isEmpty()) {
        return;
    }
    showMessage(QString());
    emit openRequested(items.front()->data(kPatient, kFolderRole).toString(),
                       studyOf(items.front())->data(kPatient, kUidRole).toString());
}

void LocalStudiesBrowser::askToDeleteSelected() {
    const QList<QTreeWidgetItem*> items = tree_->selectedItems();
    if (items.isEmpty() || remover_.isRunning()) {
        return;
    }
    const QTreeWidgetItem* study = studyOf(items.front());
    const QString uid = study->data(kPatient, kUidRole).toString();
    const QString name = studyName(study);
    auto* box =
        new QMessageBox(QMessageBox::Question, tr("Delete Study"),
                        tr("Delete the study %1 from the local study store? Its files are deleted "
                           "from this computer.")
                            .arg(name),
                        QMessageBox::Cancel, this);
    box->setObjectName(QStringLiteral("deleteStudyBox"));
    box->setAttribute(Qt::WA_DeleteOnClose);
    QPushButton* remove = box->addButton(tr("Delete"), QMessageBox::DestructiveRole);
    box->setDefaultButton(QMessageBox::Cancel);
    connect(box, &QMessageBox::buttonClicked, this,
            [this, remove, uid, name](QAbstractButton* clicked) {
                if (clicked == remove) {
                    startDelete(uid, name);
                }
            });
    box->open();
}

void LocalStudiesBrowser::startDelete(const QString& studyUid, const QString& name) {
    showMessage(QString());
    remover_.start(
        [root = listener_.storeFolder(), uid = studyUid.toStdString()](const std::stop_token&) {
            try {
                pacs::LocalStore(root).remove(uid);
                return Removal::Removed;
            } catch (const pacs::StudyOpenError&) {
                return Removal::Open;
            } catch (const InvalidArgumentError&) {
                return Removal::Gone;
            } catch (const Error&) {
                return Removal::Failed;
            }
        },
        [this, name](Removal removal) {
            refresh();
            updateButtons();
            switch (removal) {
                case Removal::Open:
                    showMessage(tr("The study %1 is open — in this window or in another program "
                                   "— and was not deleted. Close it (open other data) and try "
                                   "again.")
                                    .arg(name));
                    break;
                case Removal::Failed:
                    showMessage(tr("The study %1 could not be deleted: the study store cannot be "
                                   "written.")
                                    .arg(name));
                    break;
                case Removal::Removed:
                case Removal::Gone:
                    break;
            }
        });
    updateButtons();
}

}  // namespace vv::gui
