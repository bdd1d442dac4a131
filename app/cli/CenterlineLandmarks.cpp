// SPDX-License-Identifier: GPL-3.0-or-later
#include "cli/CenterlineLandmarks.h"

#include <array>
#include <glm/geometric.hpp>
#include <string>

#include "cli/Arguments.h"
#include "cli/Cli.h"
#include "vv/core/NumberText.h"
#include "vv/planning/AorticSizing.h"

namespace vv::cli {

namespace {

using planning::LandmarkKind;

std::string presetKeys() {
    std::string keys;
    for (const LandmarkKind kind : planning::landmarkPresets()) {
        keys += (keys.empty() ? "" : ", ") + std::string(planning::landmarkKey(kind));
    }
    return keys;
}

void writePoint(JsonWriter& json, const char* name, const glm::dvec3& p) {
    json.key(name);
    json.beginArray();
    json.number(p.x);
    json.number(p.y);
    json.number(p.z);
    json.endArray();
}

void writeSizes(JsonWriter& json, const planning::SectionSizes& s) {
    json.beginObject();
    json.member("branch", s.location.branch);
    json.member("abscissa_mm", s.location.abscissaMm);
    json.member("equivalent_diameter_mm", s.equivalentDiameterMm);
    json.member("min_diameter_mm", s.minDiameterMm);
    json.member("max_diameter_mm", s.maxDiameterMm);
    json.member("area_mm2", s.areaMm2);
    json.member("at_a_junction", s.atAJunction);
    json.endObject();
}

/// Why a value is blank: the sentence, and the reason's key with what it
/// names (for a reader that words it in its own language).
void writeBlank(JsonWriter& json, const planning::Blank& blank) {
    json.member("blank", planning::blankText(blank));
    json.member("blank_reason", std::string(planning::blankKey(blank.reason)));
    if (blank.landmark != LandmarkKind::Free) {
        json.member("blank_landmark", std::string(planning::landmarkKey(blank.landmark)));
    }
    if (blank.other != LandmarkKind::Free) {
        json.member("blank_other", std::string(planning::landmarkKey(blank.other)));
    }
    if (blank.mm != 0.0) {
        json.member("blank_mm", blank.mm);
    }
}

/// {"value": V} or {"value": null, "blank": "why", "blank_reason": key, ...}.
template <class T, class Write>
void writeValue(JsonWriter& json, const char* name, const planning::SizingValue<T>& v,
                Write write) {
    json.key(name);
    json.beginObject();
    json.key("value");
    if (v.value) {
        write(*v.value);
    } else {
        json.null();
        writeBlank(json, v.blank);
    }
    json.endObject();
}

void writeSizing(JsonWriter& json, const planning::AorticSizing& t) {
    const auto number = [&json](double v) { json.number(v); };
    const auto sizes = [&json](const planning::SectionSizes& s) { writeSizes(json, s); };
    json.key("aortic_sizing");
    json.beginObject();
    json.member("definitions",
                std::string("below: along the centreline from the source towards the aortic "
                            "bifurcation; neck diameters at the lowest renal artery and 5, 10, "
                            "15 mm below it; alpha: suprarenal aorta (15 mm above the lowest "
                            "renal) to neck axis; beta: neck to aneurysm axis (start of the "
                            "aneurysm to the aortic bifurcation); lengths along the centreline; "
                            "smallest iliac: smallest minimum Feret diameter from the aortic "
                            "bifurcation to the internal iliac origin"));
    json.key("neck_diameters");
    json.beginArray();
    for (std::size_t i = 0; i < t.neckDiameters.size(); ++i) {
        json.beginObject();
        json.member("below_renal_mm", planning::AorticSizing::kNeckDepthsMm[i]);
        json.key("sizes");
        if (t.neckDiameters[i].value) {
            writeSizes(json, *t.neckDiameters[i].value);
        } else {
            json.null();
            writeBlank(json, t.neckDiameters[i].blank);
        }
        json.endObject();
    }
    json.endArray();
    writeValue(json, "neck_length_mm", t.neckLengthMm, number);
    writeValue(json, "alpha_deg", t.suprarenalToNeckDeg, number);
    writeValue(json, "beta_deg", t.neckToAneurysmDeg, number);
    writeValue(json, "largest_aneurysm", t.largestAneurysm, sizes);
    writeValue(json, "renal_to_aortic_bifurcation_mm", t.renalToBifurcationMm, number);
    const std::array<const char*, 2> sides{"left", "right"};
    for (std::size_t side = 0; side < 2; ++side) {
        const std::string prefix = sides[side];
        writeValue(json, (prefix + "_renal_to_internal_iliac_mm").c_str(),
                   t.renalToInternalIliacMm[side], number);
        writeValue(json, (prefix + "_aortic_bifurcation_to_internal_iliac_mm").c_str(),
                   t.bifurcationToInternalIliacMm[side], number);
        writeValue(json, (prefix + "_smallest_iliac").c_str(), t.smallestIliac[side], sizes);
    }
    json.endObject();
}

}  // namespace

GivenLandmark parseLandmark(const std::string& text) {
    const auto equals = text.rfind('=');
    if (equals == std::string::npos || equals == 0) {
        throw UsageError("--landmark must be KEY=X,Y,Z, got '" + text + "'");
    }
    const std::string key = text.substr(0, equals);
    const std::vector<std::string> items = splitList(text.substr(equals + 1), "--landmark");
    if (items.size() != 3) {
        throw UsageError("--landmark must be KEY=X,Y,Z (mm), got '" + text + "'");
    }
    GivenLandmark given;
    given.point = {parseNumber(items[0], "--landmark"), parseNumber(items[1], "--landmark"),
                   parseNumber(items[2], "--landmark")};
    if (key.rfind("free:", 0) == 0) {
        given.name = key.substr(5);
        if (given.name.empty()) {
            throw UsageError("--landmark free:NAME needs a name");
        }
        return given;
    }
    const auto kind = planning::landmarkKindOfKey(key);
    if (!kind || *kind == LandmarkKind::Free) {
        throw UsageError("--landmark: unknown key '" + key + "' (one of " + presetKeys() +
                         ", or free:NAME)");
    }
    given.kind = *kind;
    given.name = std::string(planning::landmarkEnglishName(*kind));
    return given;
}

std::vector<PlacedLandmark> placeLandmarks(const analysis::CenterlineTree& tree,
                                           const std::vector<GivenLandmark>& given,
                                           std::ostream& err) {
    std::vector<PlacedLandmark> placed;
    for (const GivenLandmark& g : given) {
        const planning::NearestLocation nearest = planning::nearestLocation(tree, g.point);
        const planning::TreeLocation at = planning::placeLandmark(tree, g.kind, g.point);
        const double radius = planning::sampleAt(tree, nearest.location).radiusMm;
        if (nearest.distanceMm > radius) {
            err << "vesselview-cli: note: the landmark '" << g.name << "' ("
                << fixedText(g.point.x, 2) << ", " << fixedText(g.point.y, 2) << ", "
                << fixedText(g.point.z, 2) << ") is " << fixedText(nearest.distanceMm, 2)
                << " mm from the nearest centreline, outside its vessel (radius "
                << fixedText(radius, 2) << " mm)\n";
        }
        placed.push_back({{g.name, g.kind, at}, g.point, nearest.distanceMm});
    }
    return placed;
}

void writeLandmarksJson(JsonWriter& json, const analysis::CenterlineTree& tree,
                        const std::vector<std::vector<analysis::CrossSection>>& sections,
                        const std::vector<PlacedLandmark>& placed) {
    json.key("landmarks");
    json.beginArray();
    std::vector<planning::Landmark> landmarks;
    bool anyPreset = false;
    for (const PlacedLandmark& p : placed) {
        const planning::Landmark& l = p.landmark;
        landmarks.push_back(l);
        anyPreset = anyPreset || l.kind != LandmarkKind::Free;
        json.beginObject();
        json.member("name", l.name);
        json.member("kind", std::string(planning::landmarkKey(l.kind)));
        json.member("branch", l.location.branch);
        json.member("abscissa_mm", l.location.abscissaMm);
        writePoint(json, "position", planning::sampleAt(tree, l.location).position);
        writePoint(json, "given", p.given);
        json.member("given_distance_mm", p.distanceMm);
        json.key("section");
        if (const auto sizes = planning::sectionSizesAt(tree, sections, l.location)) {
            writeSizes(json, *sizes);
        } else {
            json.null();
        }
        json.endObject();
    }
    json.endArray();
    json.key("landmark_pairs");
    json.beginArray();
    for (std::size_t i = 0; i < landmarks.size(); ++i) {
        for (std::size_t j = i + 1; j < landmarks.size(); ++j) {
            const planning::TreeLocation& a = landmarks[i].location;
            const planning::TreeLocation& b = landmarks[j].location;
            json.beginObject();
            json.member("from", landmarks[i].name);
            json.member("to", landmarks[j].name);
            json.member("along_centreline_mm", planning::lengthAlong(tree, a, b));
            json.member("straight_mm", glm::length(planning::sampleAt(tree, b).position -
                                                   planning::sampleAt(tree, a).position));
            json.endObject();
        }
    }
    json.endArray();
    if (anyPreset) {
        writeSizing(json, planning::aorticSizing(tree, sections, landmarks));
    }
}

}  // namespace vv::cli
