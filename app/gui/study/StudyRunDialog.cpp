// SPDX-License-Identifier: GPL-3.0-or-later
#include "gui/study/StudyRunDialog.h"

#include <QCheckBox>
#include <QDialogButtonBox>
#include <QFileDialog>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QScreen>
#include <QSpinBox>
#include <set>

#include "gui/PathField.h"
#include "gui/study/StudyProblem.h"
#include "gui/study/StudyRunnerWidget.h"
#include "vv/study/RunPlan.h"
#include "vv/study/StudyRun.h"

namespace vv::gui {
namespace {

std::filesystem::path pathOf(const QLineEdit* edit) {
    return {edit->text().trimmed().toStdString()};
}

}  // namespace

StudyRunDialog::StudyRunDialog(QWidget* parent)
    : QDialog(parent),
      folder_(new QLineEdit(this)),
      results_(new QLineEdit(this)),
      participant_(new QLineEdit(this)),
      studySummary_(new QLabel(this)),
      participantSummary_(new QLabel(this)),
      training_(new QCheckBox(tr("&Training images first, with feedback"), this)),
      countdown_(new QSpinBox(this)),
      breakEvery_(new QSpinBox(this)),
      buttons_(new QDialogButtonBox(QDialogButtonBox::Cancel, this)) {
    setWindowTitle(tr("Run Depth-Judgement Study"));
    auto* form = new QFormLayout(this);

    showPath(folder_);
    auto* folderRow = new QHBoxLayout;
    folderRow->addWidget(folder_, 1);
    auto* browse = new QPushButton(tr("Browse…"), this);
    folderRow->addWidget(browse);
    connect(browse, &QPushButton::clicked, this, [this] {
        const QString chosen = QFileDialog::getExistingDirectory(
            this, tr("Study folder (made by vesselview-cli study make)"), folder_->text());
        if (!chosen.isEmpty()) {
            setStudyFolder(chosen);
        }
    });
    addBuddyRow(form, tr("&Study folder:"), folder_, folderRow);
    studySummary_->setWordWrap(true);
    form->addRow(QString(), studySummary_);

    addBuddyRow(form, tr("&Results file:"), results_,
                browseRow(results_, tr("Results file"), tr("Results (*.csv)"), this));

    participant_->setPlaceholderText(tr("e.g. P07"));
    participant_->setMaxLength(64);
    form->addRow(tr("&Participant:"), participant_);
    participantSummary_->setWordWrap(true);
    form->addRow(QString(), participantSummary_);

    training_->setChecked(true);
    form->addRow(QString(), training_);
    countdown_->setRange(0, 10);
    countdown_->setValue(3);  // the paper's
    countdown_->setSuffix(tr(" s"));
    countdown_->setSpecialValueText(tr("none"));
    form->addRow(tr("&Countdown before each image:"), countdown_);
    breakEvery_->setRange(0, 1000);
    breakEvery_->setValue(50);
    breakEvery_->setSpecialValueText(tr("no breaks"));
    breakEvery_->setPrefix(tr("every "));
    breakEvery_->setSuffix(tr(" images"));
    form->addRow(tr("&Break:"), breakEvery_);

    buttons_->addButton(tr("St&art"), QDialogButtonBox::AcceptRole);
    form->addRow(buttons_);
    connect(buttons_, &QDialogButtonBox::accepted, this, [this] { static_cast<void>(start()); });
    connect(buttons_, &QDialogButtonBox::rejected, this, &QDialog::reject);
    connect(folder_, &QLineEdit::editingFinished, this, &StudyRunDialog::folderChanged);
    // Typed or browsed (every change; the default the folder sets is read
    // by folderChanged itself).
    connect(results_, &QLineEdit::textChanged, this, [this] {
        if (results_->text() != defaultResults_) {
            resultsChanged();
        }
    });
    connect(participant_, &QLineEdit::textChanged, this, &StudyRunDialog::participantChanged);
    // Wide enough for the summaries on one or two lines.
    setMinimumWidth(fontMetrics().averageCharWidth() * 90);
    folderChanged();
}

void StudyRunDialog::setStudyFolder(const QString& folder) {
    folder_->setText(folder);
    folderChanged();
}

void StudyRunDialog::setParticipant(const QString& id) {
    participant_->setText(id);
}

QString StudyRunDialog::studySummary() const {
    return studySummary_->text();
}

QString StudyRunDialog::participantSummary() const {
    return participantSummary_->text();
}

void StudyRunDialog::folderChanged() {
    manifest_.reset();
    if (folder_->text().trimmed().isEmpty()) {
        studySummary_->setText(tr("Choose the folder that vesselview-cli study make wrote."));
    } else {
        try {
            manifest_ = study::readManifest(pathOf(folder_));
            std::set<std::string> scenes;
            for (const auto& s : manifest_->stimuli) {
                scenes.insert(s.scene);
            }
            const auto count = [this](std::size_t n) {
                return locale().toString(static_cast<qulonglong>(n));
            };
            studySummary_->setText(
                tr("%1 images in %2 conditions from %3; %4 training images.")
                    .arg(count(manifest_->indicesOf(study::Block::Main).size()))
                    .arg(count(manifest_->conditions.size()))
                    .arg(tr("%n scene(s)", nullptr, static_cast<int>(scenes.size())))
                    .arg(count(manifest_->indicesOf(study::Block::Training).size())));
        } catch (const Error& e) {
            studySummary_->setText(studyProblemText(e));
        }
    }
    if (manifest_ && (results_->text().isEmpty() || results_->text() == defaultResults_)) {
        defaultResults_ = QString::fromStdString((manifest_->folder / "results.csv").string());
        results_->setText(defaultResults_);
    }
    resultsChanged();
}

void StudyRunDialog::resultsChanged() {
    answers_.clear();
    resultsReadable_ = true;
    std::error_code error;
    const auto file = pathOf(results_);
    if (!file.empty() && std::filesystem::exists(file, error)) {
        try {
            answers_ = study::readResults(file);
        } catch (const Error& e) {
            resultsReadable_ = false;
            participantSummary_->setText(studyProblemText(e));
        }
    }
    participantChanged();
}

void StudyRunDialog::participantChanged() {
    const QString id = participant_->text().trimmed();
    const bool ready = manifest_ && resultsReadable_ && !id.isEmpty() && !pathOf(results_).empty();
    bool startable = ready;
    if (!resultsReadable_) {
        startable = false;  // the summary holds the file's error
    } else if (!manifest_) {
        participantSummary_->clear();
    } else if (id.isEmpty()) {
        participantSummary_->setText(tr("Type the participant's id."));
    } else {
        const std::string name = id.toStdString();
        const std::size_t order = study::participantOrder(answers_, name);
        const std::size_t rows = study::balancedLatinSquare(manifest_->conditions.size()).size();
        std::set<std::string> answered;
        for (const auto& a : answers_) {
            if (a.participant == name && a.block == study::Block::Main) {
                answered.insert(a.stimulus);
            }
        }
        const auto total = manifest_->indicesOf(study::Block::Main).size();
        const auto count = [loc = locale()](std::size_t n) {
            return loc.toString(static_cast<qulonglong>(n));
        };
        const QString row = tr("order %1: the Latin square's row %2 of %3")
                                .arg(count(order + 1))
                                .arg(count(order % rows + 1))
                                .arg(count(rows));
        const bool known = std::any_of(answers_.begin(), answers_.end(),
                                       [&](const auto& a) { return a.participant == name; });
        if (!known) {
            participantSummary_->setText(tr("A new participant (%1).").arg(row));
            training_->setChecked(true);
        } else if (answered.size() >= total) {
            participantSummary_->setText(
                tr("%1 has answered all %2 images.").arg(id, count(total)));
            startable = false;
        } else {
            participantSummary_->setText(
                tr("%1 has answered %2 of %3 images; the run goes on from image %4 (%5).")
                    .arg(id)
                    .arg(count(answered.size()))
                    .arg(count(total))
                    .arg(count(answered.size() + 1))
                    .arg(row));
            training_->setChecked(false);
        }
    }
    for (QAbstractButton* b : buttons_->buttons()) {
        if (buttons_->buttonRole(b) == QDialogButtonBox::AcceptRole) {
            b->setEnabled(startable);
        }
    }
    fitHeight();
}

void StudyRunDialog::fitHeight() {
    // A window does not follow its wrapped labels' height for its width by
    // itself: a longer summary would be cut off at the bottom.
    layout()->activate();
    const int needed = layout()->hasHeightForWidth() ? layout()->totalHeightForWidth(width())
                                                     : layout()->totalSizeHint().height();
    if (needed > height()) {
        resize(width(), needed);
    }
}

StudyRunnerWidget* StudyRunDialog::start() {
    if (!manifest_) {
        return nullptr;
    }
    std::unique_ptr<study::StudyRun> run;
    try {
        study::RunOptions options;
        options.training = training_->isChecked();
        options.breakEvery = static_cast<std::size_t>(breakEvery_->value());
        run = std::make_unique<study::StudyRun>(
            *manifest_, participant_->text().trimmed().toStdString(), pathOf(results_), options);
    } catch (const Error& e) {
        showProblem(this, QStringLiteral("runProblem"), windowTitle(), studyProblem(e));
        return nullptr;
    }
    auto* runner = new StudyRunnerWidget(std::move(run), countdown_->value() * 1000);
    if (QScreen* here = screen()) {
        runner->setGeometry(here->geometry());
    }
    runner->showFullScreen();
    runner->activateWindow();
    runner->setFocus();
    emit runnerStarted(runner);
    accept();
    return runner;
}

}  // namespace vv::gui
