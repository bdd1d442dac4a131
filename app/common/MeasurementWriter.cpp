// SPDX-License-Identifier: GPL-3.0-or-later
// The measurement file's writer (MeasurementFile.h): the one JSON form of the
// planning measurements, for `centerline --json` and the GUI alike.
#include <array>
#include <cmath>
#include <fstream>
#include <glm/geometric.hpp>
#include <optional>
#include <ostream>
#include <sstream>
#include <string>

#include "common/JsonWriter.h"
#include "common/MeasurementFile.h"
#include "vv/analysis/Bifurcations.h"
#include "vv/analysis/Stenosis.h"
#include "vv/core/AtomicFile.h"
#include "vv/core/Error.h"
#include "vv/planning/AorticSizing.h"

namespace vv::app {

namespace {

using planning::LandmarkKind;

void writePoint(JsonWriter& json, const char* name, const glm::dvec3& p) {
    json.key(name);
    json.beginArray();
    json.number(p.x);
    json.number(p.y);
    json.number(p.z);
    json.endArray();
}

void writeUv(JsonWriter& json, const glm::dvec2& p) {
    json.beginArray();
    json.number(p.x);
    json.number(p.y);
    json.endArray();
}

/// The section's plane geometry: its lumen contour and the calipers of its
/// minimum and maximum diameter, in the plane's (u, v) mm about the
/// centreline point (what the report draws at a landmark).
void writeContour(JsonWriter& json, const analysis::CrossSection& section) {
    json.key("contour");
    json.beginArray();
    for (const glm::dvec2& p : section.contour) {
        writeUv(json, p);
    }
    json.endArray();
    const analysis::FeretCalipers c = analysis::feretCalipers(section.contour);
    json.key("calipers");
    json.beginObject();
    for (const auto& [name, segment] :
         {std::pair{"min", c.minSegment}, std::pair{"max", c.maxSegment}}) {
        json.key(name);
        json.beginArray();
        writeUv(json, segment[0]);
        writeUv(json, segment[1]);
        json.endArray();
    }
    json.endObject();
}

/// The section of the centreline point nearest `at` on its branch.
const analysis::CrossSection& sectionAt(
    const analysis::CenterlineTree& tree,
    const std::vector<std::vector<analysis::CrossSection>>& sections,
    const planning::TreeLocation& at) {
    const auto& points = tree.branches[static_cast<std::size_t>(at.branch)].points;
    std::size_t nearest = 0;
    for (std::size_t i = 0; i < points.size(); ++i) {
        if (std::abs(points[i].abscissaMm - at.abscissaMm) <
            std::abs(points[nearest].abscissaMm - at.abscissaMm)) {
            nearest = i;
        }
    }
    return sections[static_cast<std::size_t>(at.branch)][nearest];
}

/// "path_mm": where `at` lies along `path`, or null off it (or without one).
void writeAlong(JsonWriter& json, const analysis::CenterlineTree& tree,
                const std::optional<planning::VesselPath>& path, const planning::TreeLocation& at) {
    json.key("path_mm");
    if (const auto along = path ? path->abscissaOf(tree, at) : std::nullopt) {
        json.number(*along);
    } else {
        json.null();
    }
}

void writeSizes(JsonWriter& json, const planning::SectionSizes& s,
                const analysis::CrossSection* geometry = nullptr) {
    json.beginObject();
    json.member("branch", s.location.branch);
    json.member("abscissa_mm", s.location.abscissaMm);
    json.member("equivalent_diameter_mm", s.equivalentDiameterMm);
    json.member("min_diameter_mm", s.minDiameterMm);
    json.member("max_diameter_mm", s.maxDiameterMm);
    json.member("area_mm2", s.areaMm2);
    json.member("at_a_junction", s.atAJunction);
    if (geometry != nullptr && geometry->status == analysis::CrossSection::Status::Ok) {
        writeContour(json, *geometry);
        // The section's plane: where a volume is resliced to show it.
        writePoint(json, "centre", geometry->centre);
        writePoint(json, "axis_u", geometry->axisU);
        writePoint(json, "axis_v", geometry->axisV);
    }
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

void writeSection(JsonWriter& json, const char* name, const analysis::CrossSection* s) {
    json.key(name);
    if (s == nullptr) {
        json.null();
        return;
    }
    json.beginObject();
    json.member("abscissa_mm", s->abscissaMm);
    json.member("equivalent_diameter_mm", s->equivalentDiameterMm);
    json.member("min_diameter_mm", s->minDiameterMm);
    json.member("max_diameter_mm", s->maxDiameterMm);
    json.member("inscribed_diameter_mm", s->inscribedDiameterMm);
    json.member("area_mm2", s->areaMm2);
    json.endObject();
}

void writeLandmarks(JsonWriter& json, const analysis::CenterlineTree& tree,
                    const std::vector<std::vector<analysis::CrossSection>>& sections,
                    const std::vector<PlacedLandmark>& placed,
                    const std::optional<planning::VesselPath>& path) {
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
        writeAlong(json, tree, path, l.location);
        if (p.given) {
            writePoint(json, "given", *p.given);
            json.member("given_distance_mm", p.distanceMm);
        }
        json.key("section");
        if (const auto sizes = planning::sectionSizesAt(tree, sections, l.location)) {
            writeSizes(json, *sizes, &sectionAt(tree, sections, sizes->location));
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

}  // namespace

BranchExtremes branchExtremes(const std::vector<analysis::CrossSection>& sections) {
    BranchExtremes e;
    for (const auto& s : sections) {
        if (!s.measuresTheVessel()) {
            continue;  // no contour, or a cap's or a junction's section
        }
        if (e.narrowest == nullptr || s.equivalentDiameterMm < e.narrowest->equivalentDiameterMm) {
            e.narrowest = &s;
        }
        if (e.widest == nullptr || s.equivalentDiameterMm > e.widest->equivalentDiameterMm) {
            e.widest = &s;
        }
    }
    return e;
}

void writeMeasurementJson(std::ostream& out, const MeasurementInput& input) {
    if (input.analysis == nullptr) {
        throw InvalidArgumentError("writeMeasurementJson: no analysis");
    }
    const analysis::CenterlineTree& tree = input.analysis->tree;
    const auto& sections = input.analysis->sections;
    // The path measured along: the one chosen, else from the source to the
    // farthest end (the main vessel).
    std::optional<MeasurementInput::Path> chosen = input.path;
    if (!chosen && planning::farthestEnd(tree) > 0) {
        chosen = MeasurementInput::Path{0, planning::farthestEnd(tree)};
    }
    std::optional<planning::VesselPath> path;
    if (chosen) {
        path = planning::VesselPath::betweenEnds(tree, chosen->fromEnd, chosen->toEnd);
    }
    JsonWriter json(out);
    json.beginObject();
    json.member("format", std::string(kMeasurementFormat));
    json.key("diameters");
    json.string(
        "equivalent: 2 sqrt(area / pi); min / max: smallest / largest Feret (caliper) "
        "width; inscribed: twice the largest sphere on the centreline inside the surface");
    json.key("branches");
    json.beginArray();
    for (const auto& branch : tree.branches) {
        json.beginObject();
        json.member("id", branch.id);
        if (const auto name = input.branchNames.find(branch.id); name != input.branchNames.end()) {
            json.member("name", name->second);
        }
        json.member("parent", branch.parent);
        json.member("length_mm", branch.lengthMm);
        json.member("tortuosity", branch.tortuosity());
        const BranchExtremes e = branchExtremes(sections[static_cast<std::size_t>(branch.id)]);
        writeSection(json, "narrowest", e.narrowest);
        writeSection(json, "widest", e.widest);
        json.key("stenosis");
        const auto given = input.stenosisReferences.find(branch.id);
        const auto stenosis = analysis::gradeStenosis(tree, sections, branch.id,
                                                      given != input.stenosisReferences.end()
                                                          ? given->second
                                                          : analysis::StenosisReference{});
        if (stenosis) {
            json.beginObject();
            json.member("abscissa_mm", stenosis->abscissaMm);
            json.member("diameter_percent", stenosis->diameterPercent);
            json.member("area_percent", stenosis->areaPercent);
            json.member("reference_diameter_mm", stenosis->referenceDiameterMm);
            json.member("reference", stenosis->method);
            writeAlong(json, tree, path, {branch.id, stenosis->abscissaMm});
            json.endObject();
        } else {
            json.null();
        }
        json.endObject();
    }
    json.endArray();
    json.key("bifurcations");
    json.beginArray();
    for (const auto& b : analysis::findBifurcations(tree)) {
        json.beginObject();
        json.member("parent", b.parent);
        json.key("children");
        json.beginArray();
        for (const int c : b.children) {
            json.integer(c);
        }
        json.endArray();
        json.member("angle_deg", b.angleDeg);
        json.endObject();
    }
    json.endArray();
    json.key("notes");
    json.beginArray();
    for (const auto& note : tree.notes) {
        json.string(note);
    }
    json.endArray();
    if (path) {
        json.key("path");
        json.beginObject();
        json.member("from_end", chosen->fromEnd);
        json.member("to_end", chosen->toEnd);
        json.member("length_mm", path->lengthMm());
        json.member("chosen", input.path.has_value());
        // The diameter profile: per centreline point along the path, its
        // distance and its section's equivalent, minimum and maximum diameter
        // and area, or nulls where no section measures the vessel, and the
        // point's position (x, y, z).
        json.key("profile");
        json.beginArray();
        for (const planning::PathPoint& p : path->points(tree)) {
            const analysis::CrossSection& c =
                sections[static_cast<std::size_t>(p.branch)][p.pointIndex];
            json.beginArray();
            json.number(p.pathMm);
            for (const double v :
                 {c.equivalentDiameterMm, c.minDiameterMm, c.maxDiameterMm, c.areaMm2}) {
                if (c.measuresTheVessel()) {
                    json.number(v);
                } else {
                    json.null();
                }
            }
            for (int axis = 0; axis < 3; ++axis) {
                json.number(c.centre[axis]);  // where it is: the reformation's path
            }
            json.endArray();
        }
        json.endArray();
        json.endObject();
    }
    if (!input.landmarks.empty()) {
        writeLandmarks(json, tree, sections, input.landmarks, path);
    }
    json.endObject();
    json.finish();
}

void writeMeasurementFile(const std::filesystem::path& path, const MeasurementInput& input) {
    std::ostringstream text;
    writeMeasurementJson(text, input);
    writeAtomically(path, [&](const std::filesystem::path& temporary) {
        std::ofstream out(temporary, std::ios::binary);
        out << text.str();
        out.flush();
        if (!out) {
            throw IoError(path, "cannot write the measurements");
        }
    });
}

ReportMeasurements measurementsOf(const MeasurementInput& input) {
    std::ostringstream text;
    writeMeasurementJson(text, input);
    return readMeasurementText(text.str(), "measurements");
}

}  // namespace vv::app
