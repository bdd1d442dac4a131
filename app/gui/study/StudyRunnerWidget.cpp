// SPDX-License-Identifier: GPL-3.0-or-later
#include "gui/study/StudyRunnerWidget.h"

#include <QKeyEvent>
#include <QMessageBox>
#include <QPainter>
#include <chrono>
#include <cmath>

#include "gui/EngineTexts.h"
#include "vv/core/Error.h"

namespace vv::gui {
namespace {

const QColor kNeutral(96, 96, 96);  // the neutral screen: mid grey, no afterimage
const QColor kText(235, 235, 235);

}  // namespace

StudyRunnerWidget::StudyRunnerWidget(std::unique_ptr<study::StudyRun> run, int countdownMs,
                                     QWidget* parent)
    : QOpenGLWidget(parent), run_(std::move(run)), countdownMs_(std::max(0, countdownMs)) {
    setAttribute(Qt::WA_DeleteOnClose);
    setFocusPolicy(Qt::StrongFocus);
    setCursor(Qt::BlankCursor);
    setWindowTitle(tr("Depth-judgement study"));
    countdown_.setSingleShot(true);
    connect(&countdown_, &QTimer::timeout, this, &StudyRunnerWidget::countdownTick);
    connect(this, &QOpenGLWidget::frameSwapped, this, &StudyRunnerWidget::afterSwap);
}

double StudyRunnerWidget::nowMs() {
    return std::chrono::duration<double, std::milli>(
               std::chrono::steady_clock::now().time_since_epoch())
        .count();
}

void StudyRunnerWidget::afterSwap() {
    if (stimulusPainted_ && !onsetSent_ && run_->screen() == study::RunScreen::Stimulus) {
        const double t = nowMs();
        onsetSent_ = true;
        run_->stimulusShown(t);
        emit stimulusOnset(t);
    }
}

void StudyRunnerWidget::enterScreen() {
    stimulusPainted_ = false;
    onsetSent_ = false;
    if (run_->screen() == study::RunScreen::Countdown) {
        const study::ManifestStimulus* s = run_->stimulus();
        image_ = QImage(QString::fromStdString(s->image.string()));
        if (image_.isNull()) {
            QMessageBox::critical(
                this, tr("Depth-judgement study"),
                tr("The image %1 cannot be read. The run stops; the answers given so far are "
                   "saved.")
                    .arg(QString::fromStdString(s->image.string())));
            close();
            return;
        }
        if (countdownMs_ == 0) {
            run_->countdownFinished();
        } else {
            countdownLeft_ = (countdownMs_ + 999) / 1000;
            countdown_.start(countdownMs_ - (countdownLeft_ - 1) * 1000);
        }
    }
    emit screenChanged(run_->screen());
    update();
}

void StudyRunnerWidget::countdownTick() {
    if (--countdownLeft_ > 0) {
        countdown_.start(1000);
    } else {
        run_->countdownFinished();
        emit screenChanged(run_->screen());
    }
    update();
}

void StudyRunnerWidget::answer(study::Side side, double ms) {
    std::optional<study::Answer> given;
    try {
        given = run_->answer(side, ms);
    } catch (const Error& e) {
        // The runner is full screen: the message on it, then the run closes.
        QMessageBox::critical(this, tr("Depth-judgement study"),
                              tr("The answer cannot be saved; the run stops, and the answers "
                                 "saved before stay in the file.") +
                                  QStringLiteral("\n\n") +
                                  describeProblem(e, FileAccess::Writing).line());
        close();
        return;
    }
    if (given) {
        emit answered(*given);
        enterScreen();
    }
}

void StudyRunnerWidget::stop() {
    if (run_->screen() == study::RunScreen::Finished) {
        close();
        return;
    }
    // A pause on an image: the image comes again from its countdown, so the
    // pause never counts in its response time.
    const bool onImage = run_->screen() == study::RunScreen::Countdown ||
                         run_->screen() == study::RunScreen::Stimulus;
    countdown_.stop();
    setCursor(Qt::ArrowCursor);
    const auto choice = QMessageBox::question(
        this, tr("Depth-judgement study"),
        tr("Stop the run? The answers given so far are saved; the same participant id goes on "
           "from here."));
    setCursor(Qt::BlankCursor);
    if (choice == QMessageBox::Yes) {
        close();
    } else if (onImage) {
        run_->restartTrial();
        enterScreen();
    }
}

void StudyRunnerWidget::keyPressEvent(QKeyEvent* event) {
    const double t = nowMs();  // first: the press's time, before anything else runs
    if (event->isAutoRepeat()) {
        return;
    }
    switch (event->key()) {
        case Qt::Key_F:
        case Qt::Key_Left:
            answer(study::Side::Left, t);
            break;
        case Qt::Key_J:
        case Qt::Key_Right:
            answer(study::Side::Right, t);
            break;
        case Qt::Key_Space:
            run_->space();
            enterScreen();
            break;
        case Qt::Key_Return:
        case Qt::Key_Enter:
            run_->enter();
            enterScreen();
            break;
        case Qt::Key_Escape:
            stop();
            break;
        default:
            QOpenGLWidget::keyPressEvent(event);
    }
}

QString StudyRunnerWidget::screenText(QString* title) const {
    const study::RunProgress& p = run_->progress();
    switch (run_->screen()) {
        case study::RunScreen::Instructions: {
            *title = tr("Which marker is closer to you?");
            QString body =
                tr("Each image shows vessels with two markers. Press F (or the left arrow) when "
                   "the left marker is closer to you, J (or the right arrow) when the right "
                   "one is. Answer as quickly as you can while being sure.\n\nA countdown comes "
                   "before each image; between images this grey screen waits for the space "
                   "bar.");
            if (run_->block() == study::Block::Training) {
                body += "\n\n" + tr("You begin with training images and are told after each "
                                    "whether your answer was right. Go on with them until you "
                                    "feel familiar with the task, then press Enter.");
            }
            if (run_->resumed() && p.mainAnswered > 0) {
                body += "\n\n" + tr("Welcome back: %1 of %2 images are answered; the study "
                                    "goes on from there.")
                                     .arg(p.mainAnswered)
                                     .arg(p.mainTotal);
            }
            return body + "\n\n" + tr("Press the space bar to begin.");
        }
        case study::RunScreen::Ready:
            *title = tr("Image %1 of %2").arg(p.mainAnswered + 1).arg(p.mainTotal);
            return tr("Press the space bar to go on.");
        case study::RunScreen::Feedback: {
            const auto& last = run_->lastAnswer();
            const bool right = last && last->correct();
            *title = right ? tr("Correct") : tr("Not correct");
            const QString closer = last && last->correctAnswer == study::Side::Left
                                       ? tr("The left marker was closer.")
                                       : tr("The right marker was closer.");
            return closer + "\n\n" +
                   tr("Space bar: another training image. Enter: begin the study.");
        }
        case study::RunScreen::MainReady:
            *title = tr("The study begins");
            return tr("From now on you are not told whether an answer was right. %1 images.")
                       .arg(p.mainTotal - p.mainAnswered) +
                   "\n\n" + tr("Press the space bar to begin.");
        case study::RunScreen::Break:
            *title = tr("Break");
            return tr("Take a rest: %1 of %2 images are done.")
                       .arg(p.mainAnswered)
                       .arg(p.mainTotal) +
                   "\n\n" + tr("Press the space bar when you are ready.");
        case study::RunScreen::Finished:
            *title = tr("Thank you");
            return tr(
                "The study is complete and your answers are saved. The person running "
                "the study closes this screen with Escape.");
        default:
            return {};
    }
}

void StudyRunnerWidget::paintText(QPainter& painter, const QString& title, const QString& body,
                                  bool centred) const {
    const int w = width();
    const int h = height();
    const int column = std::min(w * 5 / 6, std::max(400, h));
    QFont font = painter.font();
    font.setPixelSize(std::max(14, h / 40));
    QFont heading = font;
    heading.setPixelSize(font.pixelSize() * 3 / 2);
    heading.setBold(true);
    const QRect area((w - column) / 2, h / 5, column, h * 3 / 5);
    painter.setPen(kText);
    painter.setFont(heading);
    const QRect headingRect =
        painter.boundingRect(area, Qt::AlignHCenter | Qt::TextWordWrap, title);
    painter.drawText(area, Qt::AlignHCenter | Qt::TextWordWrap, title);
    painter.setFont(font);
    painter.drawText(area.adjusted(0, headingRect.height() + font.pixelSize(), 0, 0),
                     (centred ? Qt::AlignHCenter : Qt::AlignLeft) | Qt::TextWordWrap, body);
}

void StudyRunnerWidget::paintGL() {
    QPainter painter(this);
    painter.setRenderHint(QPainter::SmoothPixmapTransform);
    const study::RunScreen screen = run_->screen();
    if (screen == study::RunScreen::Stimulus && !image_.isNull()) {
        // The render's own background around the image; one image pixel on
        // one screen pixel (on a high-DPI screen too), made smaller (keeping
        // its shape) only when the screen is smaller.
        painter.fillRect(rect(), image_.pixelColor(0, 0));
        const double ratio = devicePixelRatioF();
        const double scale = std::min({1.0 / ratio, static_cast<double>(width()) / image_.width(),
                                       static_cast<double>(height()) / image_.height()});
        const QSizeF size(image_.width() * scale, image_.height() * scale);
        const QRectF target(QPointF((width() - size.width()) / 2, (height() - size.height()) / 2),
                            size);
        painter.drawImage(target, image_);
        stimulusPainted_ = true;
        return;
    }
    painter.fillRect(rect(), kNeutral);
    if (screen == study::RunScreen::Countdown) {
        QFont font = painter.font();
        font.setPixelSize(std::max(24, height() / 6));
        painter.setFont(font);
        painter.setPen(kText);
        painter.drawText(rect(), Qt::AlignCenter, QString::number(countdownLeft_));
        return;
    }
    QString title;
    const QString body = screenText(&title);
    // The instructions read as a text; the short screens centred under their title.
    paintText(painter, title, body, screen != study::RunScreen::Instructions);
}

}  // namespace vv::gui
