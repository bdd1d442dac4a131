// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/study/Stimuli.h"

#include <QBuffer>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QPainter>
#include <QPainterPath>
#include <set>

#include "vv/core/AtomicFile.h"
#include "vv/core/Error.h"
#include "vv/study/Results.h"

namespace vv::study {
namespace {

QString qs(const std::string& text) {
    return QString::fromStdString(text);
}

void checkInputs(const std::vector<StimulusScene>& scenes,
                 const std::vector<StimulusCondition>& conditions, const StimulusOptions& o) {
    if (scenes.empty() || conditions.empty()) {
        throw InvalidArgumentError("stimuli need at least one scene and one condition");
    }
    if (o.width < 64 || o.height < 64 || o.width > 8192 || o.height > 8192) {
        throw InvalidArgumentError("a stimulus must be 64 to 8192 pixels wide and high");
    }
    if (o.pairsPerScene < 1 || o.pairsPerScene > 1000 || o.trainingPairsPerScene > 1000) {
        throw InvalidArgumentError(
            "1 to 1000 marker pairs per scene, 0 to 1000 training pairs per scene");
    }
    const auto unique = [](const auto& items, const char* what) {
        std::set<std::string> names;
        for (const auto& item : items) {
            const bool safe = !item.name.empty() &&
                              item.name.find_first_of("/\\\0:*?\"<>|", 0, 10) == std::string::npos;
            if (!safe || !names.insert(item.name).second) {
                throw InvalidArgumentError(std::string(what) + " name '" + item.name +
                                           "' is empty, repeated or not fit for a file name");
            }
        }
    };
    unique(scenes, "a scene");
    unique(conditions, "a condition");
}

QJsonObject markerJson(const MarkerSite& s) {
    return {{"x", s.x}, {"y", s.y}, {"depth", s.depth}};
}

QJsonObject displayJson(const render::DisplaySettings& d) {
    const auto scaleName = [](colormaps::DepthScale s) {
        return s == colormaps::DepthScale::Chromadepth         ? "chromadepth"
               : s == colormaps::DepthScale::PseudoChromadepth ? "pseudo-chromadepth"
                                                               : "other";
    };
    return {
        {"vss", d.vss.enabled},
        {"vss_scale", scaleName(d.vss.scale)},
        {"iso_lines", d.vss.isoLines},
        {"vessel_cue", QString::fromUtf8(render::name(d.cue.cue).data(),
                                         static_cast<qsizetype>(render::name(d.cue.cue).size()))},
        {"fog_strength", d.cue.fogStrength},
        {"fresnel_exponent", d.cue.fresnelExponent},
        {"ambient_occlusion", d.ao.enabled},
        {"light_azimuth_deg", d.style.light.azimuth},
        {"light_elevation_deg", d.style.light.elevation}};
}

QJsonObject cameraJson(const render::Camera& c) {
    const glm::vec3 eye = c.eye();
    const glm::vec3 target = c.target();
    const glm::vec3 up = c.up();
    return {{"eye", QJsonArray{eye.x, eye.y, eye.z}},
            {"target", QJsonArray{target.x, target.y, target.z}},
            {"up", QJsonArray{up.x, up.y, up.z}},
            {"field_of_view_deg", c.fieldOfView()}};
}

}  // namespace

std::vector<StimulusCondition> paperConditions() {
    render::DisplaySettings plain;
    plain.ao.enabled = false;
    plain.vss.isoLines = 0;
    plain.legends = false;
    plain.orientationMarker = false;
    plain.scaleBar = false;
    plain.vss.enabled = false;
    plain.cue.cue = render::VesselCue::None;
    const auto with = [&](bool vss, colormaps::DepthScale scale, render::VesselCue cue) {
        render::DisplaySettings d = plain;
        d.vss.enabled = vss;
        d.vss.scale = scale;
        d.cue.cue = cue;
        return d;
    };
    using colormaps::DepthScale;
    using render::VesselCue;
    return {{"VSS-CD", with(true, DepthScale::Chromadepth, VesselCue::None), {}},
            {"VSS-PCD", with(true, DepthScale::PseudoChromadepth, VesselCue::None), {}},
            {"vessel-CD", with(false, DepthScale::Chromadepth, VesselCue::Chromadepth), {}},
            {"vessel-PCD", with(false, DepthScale::Chromadepth, VesselCue::PseudoChromadepth), {}},
            {"baseline", plain, {}}};
}

void drawMarker(QImage& image, QPoint centre, int radius) {
    QPainter painter(&image);
    painter.setRenderHint(QPainter::Antialiasing);
    const double r = radius;
    const double gap = 0.35 * r;                 // the marked point stays visible
    const double half = std::max(2.5, 0.2 * r);  // half the arm's width
    QPainterPath arms;
    arms.addRect(QRectF(centre.x() + gap, centre.y() - half, r - gap, 2 * half));
    arms.addRect(QRectF(centre.x() - r, centre.y() - half, r - gap, 2 * half));
    arms.addRect(QRectF(centre.x() - half, centre.y() + gap, 2 * half, r - gap));
    arms.addRect(QRectF(centre.x() - half, centre.y() - r, 2 * half, r - gap));
    painter.setPen(QPen(Qt::black, std::max(1.2, 0.08 * r)));
    painter.setBrush(Qt::white);
    painter.drawPath(arms);
}

StudyStimuli makeStimuli(render::OffscreenRenderer& renderer,
                         const std::vector<StimulusScene>& scenes,
                         const std::vector<StimulusCondition>& conditions,
                         const StimulusOptions& options, const std::filesystem::path& folder,
                         const Progress& progress) {
    checkInputs(scenes, conditions, options);
    std::error_code error;
    std::filesystem::create_directories(folder / "stimuli", error);
    if (error) {
        throw IoError(folder, "cannot create the study folder: " + error.message());
    }
    StudyStimuli out;
    QJsonArray sceneArray;
    QJsonArray stimulusArray;
    const auto images = static_cast<double>(scenes.size() * conditions.size());
    std::size_t done = 0;
    for (std::size_t s = 0; s < scenes.size(); ++s) {
        const StimulusScene& scene = scenes[s];
        render::OffscreenOptions view;
        view.width = options.width;
        view.height = options.height;
        view.display = conditions.front().display;
        view.camera = render::OffscreenRenderer::cameraFor(scene.scene, view);
        const Image<float> depth = renderer.renderDepth(scene.scene, view);
        // Each scene its own stream of pairs (the seed plus its index): its
        // pairs do not depend on what the other scenes show.
        const PairSet pairs =
            pickMarkerPairs(depth.view(), options.pairsPerScene + options.trainingPairsPerScene,
                            options.seed + 7919 * s, options.criteria);
        for (const std::string& note : pairs.notes) {
            out.notes.push_back(scene.name + ": " + note);
        }
        if (pairs.pairs.empty()) {
            throw StudyError(
                "scene '" + scene.name + "' gives no marker pair (" +
                (pairs.notes.empty() ? std::string("no vessel in view") : pairs.notes.back()) +
                ")");
        }
        sceneArray.append(QJsonObject{{"name", qs(scene.name)},
                                      {"source", qs(scene.source)},
                                      {"camera", cameraJson(*view.camera)},
                                      {"depth_min", pairs.depthMin},
                                      {"depth_max", pairs.depthMax}});
        for (const StimulusCondition& condition : conditions) {
            progress.throwIfCancelled();
            progress.report(static_cast<double>(done) / images,
                            "Rendering " + scene.name + ", " + condition.name);
            view.display = condition.display;
            const QImage plain = renderer.render(scene.scene, view);
            for (std::size_t p = 0; p < pairs.pairs.size(); ++p) {
                const MarkerPair& pair = pairs.pairs[p];
                const bool training = p >= options.pairsPerScene;
                const std::size_t number = training ? p - options.pairsPerScene + 1 : p + 1;
                Stimulus stimulus{scene.name + (training ? "-t" : "-p") + std::to_string(number) +
                                      "-" + condition.name,
                                  {},
                                  scene.name,
                                  condition.name,
                                  number - 1,
                                  pair,
                                  training ? Block::Training : Block::Main};
                stimulus.image = "stimuli/" + stimulus.id + ".png";
                QImage image = plain.convertToFormat(QImage::Format_RGB32);
                drawMarker(image, {pair.left.x, pair.left.y}, options.criteria.markerRadius);
                drawMarker(image, {pair.right.x, pair.right.y}, options.criteria.markerRadius);
                QByteArray png;
                QBuffer buffer(&png);
                buffer.open(QIODevice::WriteOnly);
                if (!image.save(&buffer, "PNG")) {
                    throw IoError(folder / stimulus.image, "cannot encode the image");
                }
                writeFileAtomically(
                    folder / stimulus.image,
                    std::string_view(png.constData(), static_cast<std::size_t>(png.size())));
                stimulusArray.append(
                    QJsonObject{{"id", qs(stimulus.id)},
                                {"image", qs(stimulus.image)},
                                {"scene", qs(scene.name)},
                                {"condition", qs(condition.name)},
                                {"pair", static_cast<int>(number)},
                                {"block", training ? "training" : "main"},
                                {"left", markerJson(pair.left)},
                                {"right", markerJson(pair.right)},
                                {"correct_answer", pair.leftIsCloser ? "left" : "right"},
                                {"depth_difference", pair.depthDifference},
                                {"screen_distance", pair.screenDistance},
                                {"same_void_region", pair.sameRegion},
                                {"stratum", pair.stratum}});
                out.stimuli.push_back(std::move(stimulus));
            }
            ++done;
        }
    }
    QJsonArray conditionArray;
    for (const StimulusCondition& c : conditions) {
        QJsonObject condition{{"name", qs(c.name)}, {"display", displayJson(c.display)}};
        if (!c.settings.empty()) {
            condition["settings"] = qs(c.settings);
        }
        conditionArray.append(condition);
    }
    const QJsonObject manifest{
        {"format", "vesselview-study-1"},
        {"seed", QString::number(options.seed)},
        {"width", options.width},
        {"height", options.height},
        {"pairs_per_scene", static_cast<int>(options.pairsPerScene)},
        {"training_pairs_per_scene", static_cast<int>(options.trainingPairsPerScene)},
        {"criteria",
         QJsonObject{{"min_depth_difference", options.criteria.minDepthDifference},
                     {"min_horizontal_separation", options.criteria.minHorizontalSeparation},
                     {"marker_radius_px", options.criteria.markerRadius}}},
        {"conditions", conditionArray},
        {"scenes", sceneArray},
        {"stimuli", stimulusArray},
        {"notes", QJsonArray::fromStringList([&] {
             QStringList notes;
             for (const auto& n : out.notes) {
                 notes << qs(n);
             }
             return notes;
         }())}};
    const QByteArray json = QJsonDocument(manifest).toJson();
    writeFileAtomically(folder / "manifest.json",
                        std::string_view(json.constData(), static_cast<std::size_t>(json.size())));
    progress.report(1.0, "Stimuli written");
    return out;
}

}  // namespace vv::study
