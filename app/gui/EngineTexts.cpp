// SPDX-License-Identifier: GPL-3.0-or-later
#include "gui/EngineTexts.h"

#include <QCoreApplication>
#include <QDir>
#include <QMessageBox>
#include <array>
#include <optional>
#include <string_view>
#include <utility>

#include "vv/core/Error.h"
#include "vv/segmentation/VolumeSegmentation.h"

namespace vv::gui {

namespace {

constexpr const char* kContext = "vv::gui::EngineTexts";

/// The exact stage texts of the modules (grep the modules for
/// `progress.report(` and `runAlgorithm(` when adding one).
constexpr std::array kStages = {
    // demo
    QT_TRANSLATE_NOOP("vv::gui::EngineTexts", "Generating vessel tree"),
    QT_TRANSLATE_NOOP("vv::gui::EngineTexts", "Extracting surface"),
    QT_TRANSLATE_NOOP("vv::gui::EngineTexts", "Smoothing surface"),
    QT_TRANSLATE_NOOP("vv::gui::EngineTexts", "Computing normals"),
    QT_TRANSLATE_NOOP("vv::gui::EngineTexts", "Assigning vessel data"),
    QT_TRANSLATE_NOOP("vv::gui::EngineTexts", "Voxelising the demo tree"),
    // analysis
    QT_TRANSLATE_NOOP("vv::gui::EngineTexts", "Preparing the surface"),
    QT_TRANSLATE_NOOP("vv::gui::EngineTexts", "Tetrahedralising the surface"),
    QT_TRANSLATE_NOOP("vv::gui::EngineTexts", "Joining the Voronoi diagram"),
    QT_TRANSLATE_NOOP("vv::gui::EngineTexts", "Finding the vessels' ends"),
    QT_TRANSLATE_NOOP("vv::gui::EngineTexts", "Tracing the centrelines"),
    QT_TRANSLATE_NOOP("vv::gui::EngineTexts", "Centrelines done"),
    QT_TRANSLATE_NOOP("vv::gui::EngineTexts", "Cutting the sections"),
    // dicom
    QT_TRANSLATE_NOOP("vv::gui::EngineTexts", "Listing DICOM files"),
    QT_TRANSLATE_NOOP("vv::gui::EngineTexts", "Reading DICOM headers"),
    QT_TRANSLATE_NOOP("vv::gui::EngineTexts", "Loading DICOM series"),
    QT_TRANSLATE_NOOP("vv::gui::EngineTexts", "Reading DICOM SEG"),
    QT_TRANSLATE_NOOP("vv::gui::EngineTexts", "Writing the CT series"),
    // meshio
    QT_TRANSLATE_NOOP("vv::gui::EngineTexts", "Extracting the surface"),
    QT_TRANSLATE_NOOP("vv::gui::EngineTexts", "Merging points"),
    QT_TRANSLATE_NOOP("vv::gui::EngineTexts", "simplifying"),
    // segmentation
    QT_TRANSLATE_NOOP("vv::gui::EngineTexts", "Segmenting"),
    QT_TRANSLATE_NOOP("vv::gui::EngineTexts", "Estimating the signal fall-off"),
    QT_TRANSLATE_NOOP("vv::gui::EngineTexts", "Correcting the signal fall-off"),
    QT_TRANSLATE_NOOP("vv::gui::EngineTexts", "Checking the segmentation's ends"),
    // report (exports)
    QT_TRANSLATE_NOOP("vv::gui::EngineTexts", "depth"),
    QT_TRANSLATE_NOOP("vv::gui::EngineTexts", "solving the VSS"),
    QT_TRANSLATE_NOOP("vv::gui::EngineTexts", "rendering tiles"),
    QT_TRANSLATE_NOOP("vv::gui::EngineTexts", "rendering"),
    QT_TRANSLATE_NOOP("vv::gui::EngineTexts", "Reading the patient and study"),
    QT_TRANSLATE_NOOP("vv::gui::EngineTexts", "Rendering the image"),
    QT_TRANSLATE_NOOP("vv::gui::EngineTexts", "Rendering the report's view"),
    QT_TRANSLATE_NOOP("vv::gui::EngineTexts", "Rendering the second view"),
    QT_TRANSLATE_NOOP("vv::gui::EngineTexts", "Laying out the PDF"),
    QT_TRANSLATE_NOOP("vv::gui::EngineTexts", "Writing the files"),
};

/// Stages that name a file: the module's English prefix and the translatable
/// pattern (%1 = the file name).
struct FileStage {
    const char* prefix;
    const char* pattern;
};

constexpr std::array kFileStages = {
    FileStage{"Checking ", QT_TRANSLATE_NOOP("vv::gui::EngineTexts", "Checking %1")},
    FileStage{"Reading ", QT_TRANSLATE_NOOP("vv::gui::EngineTexts", "Reading %1")},
    FileStage{"Converting ", QT_TRANSLATE_NOOP("vv::gui::EngineTexts", "Converting %1")},
    FileStage{"Loaded ", QT_TRANSLATE_NOOP("vv::gui::EngineTexts", "Loaded %1")},
};

std::optional<QString> lookUp(const QString& stage) {
    for (const char* known : kStages) {
        if (stage == QLatin1String(known)) {
            return QCoreApplication::translate(kContext, known);
        }
    }
    for (const FileStage& file : kFileStages) {
        const QLatin1String prefix(file.prefix);
        if (stage.size() > prefix.size() && stage.startsWith(prefix)) {
            return QCoreApplication::translate(kContext, file.pattern)
                .arg(stage.mid(prefix.size()));
        }
    }
    return std::nullopt;
}

}  // namespace

QString translatedStage(const QString& stage) {
    return lookUp(stage).value_or(stage);
}

bool isKnownStage(const QString& stage) {
    return lookUp(stage).has_value();
}

QString thresholdRuleText(const segmentation::ThresholdRange& range,
                          const std::function<QString(double)>& value) {
    // The rules' stable beginnings (segmentation::defaultThresholdRange()).
    const std::string_view rule = range.rule;
    const QString lower = value(static_cast<double>(range.lower));
    const QString upper = value(static_cast<double>(range.upper));
    if (rule.starts_with("CT angiography default")) {
        return QCoreApplication::translate("vv::gui::EngineTexts",
                                           "CT angiography default: %1 to %2")
            .arg(lower, upper);
    }
    if (rule.starts_with("constant volume")) {
        return QCoreApplication::translate("vv::gui::EngineTexts",
                                           "Constant volume: its only value, %1")
            .arg(lower);
    }
    if (rule.starts_with("histogram: Otsu threshold of the voxels above")) {
        return QCoreApplication::translate(
                   "vv::gui::EngineTexts",
                   "From the histogram: Otsu threshold of the voxels above the background, "
                   "%1 to %2")
            .arg(lower, upper);
    }
    if (rule.starts_with("histogram: Otsu threshold")) {
        return QCoreApplication::translate("vv::gui::EngineTexts",
                                           "From the histogram: Otsu threshold, %1 to %2")
            .arg(lower, upper);
    }
    return QString::fromStdString(range.rule);
}

bool englishUi() {
    const char* probe = QT_TRANSLATE_NOOP("vv::gui::EngineTexts", "An unexpected error occurred.");
    return QCoreApplication::translate(kContext, probe) == QLatin1String(probe);
}

QString ProblemText::line() const {
    return details.isEmpty() || !englishUi() ? summary : summary + QLatin1Char(' ') + details;
}

ProblemText describeProblem(const std::exception& error, FileAccess access) {
    const auto* known = dynamic_cast<const vv::Error*>(&error);
    const QString file =
        known != nullptr && !known->file().empty()
            ? QDir::toNativeSeparators(QString::fromStdString(known->file().string()))
            : QString();
    // Pairs: with the file's name, without one.
    std::pair<const char*, const char*> kind{
        QT_TRANSLATE_NOOP("vv::gui::EngineTexts", "An unexpected error occurred (%1)."),
        QT_TRANSLATE_NOOP("vv::gui::EngineTexts", "An unexpected error occurred.")};
    if (dynamic_cast<const IoError*>(&error) != nullptr) {
        kind =
            access == FileAccess::Reading
                ? std::pair{QT_TRANSLATE_NOOP("vv::gui::EngineTexts", "%1 could not be read."),
                            QT_TRANSLATE_NOOP("vv::gui::EngineTexts", "A file could not be read.")}
                : std::pair{
                      QT_TRANSLATE_NOOP("vv::gui::EngineTexts", "%1 could not be written."),
                      QT_TRANSLATE_NOOP("vv::gui::EngineTexts", "A file could not be written.")};
    } else if (dynamic_cast<const FormatError*>(&error) != nullptr) {
        kind = {QT_TRANSLATE_NOOP("vv::gui::EngineTexts",
                                  "%1 is damaged, empty or not of a supported type."),
                QT_TRANSLATE_NOOP("vv::gui::EngineTexts",
                                  "The data is damaged, empty or not of a supported type.")};
    } else if (dynamic_cast<const InvalidArgumentError*>(&error) != nullptr) {
        kind = {QT_TRANSLATE_NOOP("vv::gui::EngineTexts", "%1 holds a value out of its range."),
                QT_TRANSLATE_NOOP("vv::gui::EngineTexts", "A value is out of its range.")};
    } else if (dynamic_cast<const RenderError*>(&error) != nullptr) {
        kind = {QT_TRANSLATE_NOOP("vv::gui::EngineTexts", "The graphics system failed (%1)."),
                QT_TRANSLATE_NOOP("vv::gui::EngineTexts", "The graphics system failed.")};
    }
    ProblemText text;
    text.summary = file.isEmpty() ? QCoreApplication::translate(kContext, kind.second)
                                  : QCoreApplication::translate(kContext, kind.first).arg(file);
    text.details = QString::fromStdString(known != nullptr ? known->what() : error.what());
    return text;
}

void showProblem(QWidget* parent, const QString& objectName, const QString& title,
                 const ProblemText& problem) {
    auto* box =
        new QMessageBox(QMessageBox::Warning, title, problem.summary, QMessageBox::Ok, parent);
    box->setObjectName(objectName);
    box->setAttribute(Qt::WA_DeleteOnClose);
    if (!problem.details.isEmpty()) {
        if (englishUi()) {
            box->setInformativeText(problem.details);
        } else {
            box->setDetailedText(problem.details);
        }
    }
    // Window-modal but not blocking: the event loop (and tests) keep running.
    box->open();
}

}  // namespace vv::gui
