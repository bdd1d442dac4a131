// SPDX-License-Identifier: GPL-3.0-or-later
// A study folder made by hand for the runner's tests: a manifest in
// makeStimuli's format and an image per stimulus (grey, with the two marker
// pixels marked), without rendering anything.
#pragma once

#include <QColor>
#include <QImage>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <filesystem>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

namespace vv::study::test {

struct StudyFolderSpec {
    std::vector<std::string> scenes{"tree", "aorta"};
    int pairs = 2;
    int trainingPairs = 1;
    std::vector<std::string> conditions{"VSS-CD", "VSS-PCD", "vessel-CD", "vessel-PCD", "baseline"};
    int width = 320;
    int height = 180;
};

inline QJsonObject studyManifestJson(const StudyFolderSpec& spec) {
    QJsonArray conditions;
    for (const auto& c : spec.conditions) {
        conditions.append(QJsonObject{{"name", QString::fromStdString(c)}});
    }
    QJsonArray stimuli;
    for (const auto& scene : spec.scenes) {
        for (int p = 1; p <= spec.pairs + spec.trainingPairs; ++p) {
            const bool training = p > spec.pairs;
            const int number = training ? p - spec.pairs : p;
            for (const auto& c : spec.conditions) {
                const std::string id = std::string(scene)
                                           .append(training ? "-t" : "-p")
                                           .append(std::to_string(number))
                                           .append("-")
                                           .append(c);
                stimuli.append(QJsonObject{
                    {"id", QString::fromStdString(id)},
                    {"image", QString::fromStdString("stimuli/" + id + ".png")},
                    {"scene", QString::fromStdString(scene)},
                    {"condition", QString::fromStdString(c)},
                    {"pair", number},
                    {"block", training ? "training" : "main"},
                    {"left", QJsonObject{{"x", spec.width / 4}, {"y", spec.height / 2}}},
                    {"right", QJsonObject{{"x", 3 * spec.width / 4}, {"y", spec.height / 2}}},
                    {"correct_answer", number % 2 == 1 ? "left" : "right"}});
            }
        }
    }
    return {{"format", "vesselview-study-1"},
            {"seed", "7"},
            {"width", spec.width},
            {"height", spec.height},
            {"conditions", conditions},
            {"stimuli", stimuli}};
}

inline void writeManifestJson(const std::filesystem::path& dir, const QJsonObject& manifest) {
    const QByteArray json = QJsonDocument(manifest).toJson();
    std::ofstream(dir / "manifest.json", std::ios::binary)
        .write(json.constData(), static_cast<std::streamsize>(json.size()));
}

/// Makes `dir` (emptied first) a study folder after `spec`.
inline void writeStudyFolder(const std::filesystem::path& dir, const StudyFolderSpec& spec = {}) {
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir / "stimuli");
    const QJsonObject manifest = studyManifestJson(spec);
    for (const auto& value : manifest["stimuli"].toArray()) {
        // Grey, the left marker's pixel and its surround red, the right's blue.
        QImage image(spec.width, spec.height, QImage::Format_RGB32);
        image.fill(QColor(90, 90, 90));
        const QJsonObject o = value.toObject();
        for (const auto& [side, colour] :
             {std::pair{"left", QColor(220, 30, 30)}, std::pair{"right", QColor(30, 30, 220)}}) {
            const QJsonObject m = o[side].toObject();
            for (int dy = -3; dy <= 3; ++dy) {
                for (int dx = -3; dx <= 3; ++dx) {
                    image.setPixelColor(m["x"].toInt() + dx, m["y"].toInt() + dy, colour);
                }
            }
        }
        image.save(QString::fromStdString(
            (dir / value.toObject()["image"].toString().toStdString()).string()));
    }
    writeManifestJson(dir, manifest);
}

}  // namespace vv::study::test
