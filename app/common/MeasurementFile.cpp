// SPDX-License-Identifier: GPL-3.0-or-later
#include "common/MeasurementFile.h"

#include <QByteArray>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QJsonParseError>
#include <array>
#include <cmath>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <utility>

#include "vv/core/Error.h"
#include "vv/core/NumberText.h"

namespace vv::app {

namespace {

constexpr std::uintmax_t kMaxBytes = 64ULL << 20U;

using planning::Blank;
using planning::LandmarkKind;

/// Reads one measurement file, naming it and where in it a problem lies.
class MeasurementReader {
  public:
    explicit MeasurementReader(std::filesystem::path file) : file_(std::move(file)) {}

    [[noreturn]] void fail(const std::string& problem) const {
        throw FormatError(file_, "not a VesselView measurement file: " + problem);
    }

    /// The file's text, at most 64 MiB. Throws IoError when it cannot be read.
    [[nodiscard]] std::string fileText() const {
        std::error_code error;
        const std::uintmax_t size = std::filesystem::file_size(file_, error);
        if (error) {
            throw IoError(file_, "cannot read the measurements: " + error.message());
        }
        if (size > kMaxBytes) {
            fail("it is larger than 64 MiB");
        }
        std::ifstream in(file_, std::ios::binary);
        std::ostringstream bytes;
        bytes << in.rdbuf();
        if (!in) {
            throw IoError(file_, "cannot read the measurements");
        }
        return bytes.str();
    }

    [[nodiscard]] QJsonObject document(const std::string& text) const {
        if (text.size() > kMaxBytes) {
            fail("it is larger than 64 MiB");
        }
        QJsonParseError parse{};
        const QJsonDocument json = QJsonDocument::fromJson(
            QByteArray(text.data(), static_cast<qsizetype>(text.size())), &parse);
        if (parse.error != QJsonParseError::NoError) {
            fail("not JSON (" + parse.errorString().toStdString() + " at byte " +
                 std::to_string(parse.offset) + ")");
        }
        if (!json.isObject() || json.object().value("format").toString() != kMeasurementFormat) {
            fail(std::string("the format \"") + kMeasurementFormat + "\" is not named");
        }
        return json.object();
    }

    [[nodiscard]] double number(const QJsonObject& o, const char* key,
                                const std::string& where) const {
        const QJsonValue v = o.value(key);
        if (!v.isDouble() || !std::isfinite(v.toDouble())) {
            fail(where + ": \"" + key + "\" is missing or not a number");
        }
        return v.toDouble();
    }

    [[nodiscard]] std::string text(const QJsonObject& o, const char* key,
                                   const std::string& where) const {
        const QJsonValue v = o.value(key);
        if (!v.isString()) {
            fail(where + ": \"" + key + "\" is missing or not a text");
        }
        return v.toString().toStdString();
    }

    [[nodiscard]] QJsonArray array(const QJsonObject& o, const char* key,
                                   const std::string& where) const {
        const QJsonValue v = o.value(key);
        if (!v.isArray()) {
            fail(where + ": \"" + key + "\" is missing or not a list");
        }
        return v.toArray();
    }

    [[nodiscard]] QJsonObject object(const QJsonValue& v, const std::string& where) const {
        if (!v.isObject()) {
            fail(where + " is not an object");
        }
        return v.toObject();
    }

    [[nodiscard]] int whole(const QJsonObject& o, const char* key, const std::string& where) const {
        const double d = number(o, key, where);
        if (d < -1.0e6 || d > 1.0e6 || d != std::floor(d)) {
            fail(where + ": \"" + key + "\" is not a whole number");
        }
        return static_cast<int>(d);
    }

    [[nodiscard]] LandmarkKind kind(const QJsonObject& o, const char* key,
                                    const std::string& where) const {
        const auto k = planning::landmarkKindOfKey(text(o, key, where));
        if (!k) {
            fail(where + ": \"" + key + "\" is not a landmark kind");
        }
        return *k;
    }

    /// A section's sizes; on `branch` when the object does not name one.
    [[nodiscard]] planning::SectionSizes sizes(const QJsonObject& o, const std::string& where,
                                               std::optional<int> branch = std::nullopt) const {
        planning::SectionSizes s;
        s.location = {branch ? *branch : whole(o, "branch", where),
                      number(o, "abscissa_mm", where)};
        s.equivalentDiameterMm = number(o, "equivalent_diameter_mm", where);
        s.minDiameterMm = number(o, "min_diameter_mm", where);
        s.maxDiameterMm = number(o, "max_diameter_mm", where);
        s.areaMm2 = number(o, "area_mm2", where);
        s.atAJunction = o.value("at_a_junction").toBool(false);
        return s;
    }

    /// [u, v] in mm (within a kilometre).
    [[nodiscard]] glm::dvec2 uv(const QJsonValue& v, const std::string& where) const {
        const QJsonArray a = v.toArray();
        if (!v.isArray() || a.size() != 2 || !a[0].isDouble() || !a[1].isDouble() ||
            std::abs(a[0].toDouble()) > 1e6 || std::abs(a[1].toDouble()) > 1e6) {
            fail(where + " is not a point [u, v]");
        }
        return {a[0].toDouble(), a[1].toDouble()};
    }

    /// [x, y, z] in mm (within a kilometre).
    [[nodiscard]] glm::dvec3 point(const QJsonValue& v, const std::string& where) const {
        const QJsonArray a = v.toArray();
        if (!v.isArray() || a.size() != 3) {
            fail(where + " is not a point [x, y, z]");
        }
        glm::dvec3 p(0.0);
        for (int i = 0; i < 3; ++i) {
            if (!a[i].isDouble() || !(std::abs(a[i].toDouble()) <= 1e6)) {
                fail(where + " is not a point [x, y, z]");
            }
            p[i] = a[i].toDouble();
        }
        return p;
    }

    /// A number or null (a blank); nullopt for null.
    [[nodiscard]] std::optional<double> maybe(const QJsonValue& v, const std::string& where) const {
        if (v.isNull()) {
            return std::nullopt;
        }
        if (!v.isDouble() || !std::isfinite(v.toDouble())) {
            fail(where + " is not a number or null");
        }
        return v.toDouble();
    }

    [[nodiscard]] Blank blank(const QJsonObject& o, const std::string& where) const {
        Blank b;
        const std::string reason = text(o, "blank_reason", where);
        const auto known = planning::blankReasonOfKey(reason);
        if (!known || *known == Blank::Reason::None) {
            fail(where + ": the blank reason \"" + reason + "\" is not known");
        }
        b.reason = *known;
        if (o.contains("blank_landmark")) {
            b.landmark = kind(o, "blank_landmark", where);
        }
        if (o.contains("blank_other")) {
            b.other = kind(o, "blank_other", where);
        }
        if (o.contains("blank_mm")) {
            b.mm = number(o, "blank_mm", where);
        }
        return b;
    }

    /// {"value": number} or {"value": null, "blank_reason": ...}.
    [[nodiscard]] planning::SizingValue<double> sizingNumber(const QJsonObject& table,
                                                             const char* key) const {
        const std::string where = std::string("aortic_sizing.") + key;
        const QJsonObject o = object(table.value(key), where);
        if (o.value("value").isNull()) {
            return {std::nullopt, blank(o, where)};
        }
        return {number(o, "value", where), {}};
    }

    [[nodiscard]] planning::SizingValue<planning::SectionSizes> sizingSizes(
        const QJsonObject& o, const char* key, const std::string& where) const {
        if (o.value(key).isNull()) {
            return {std::nullopt, blank(o, where)};
        }
        return {sizes(object(o.value(key), where), where), {}};
    }

  private:
    std::filesystem::path file_;
};

/// A landmark section's contour and calipers, where the file has them.
void readContour(const MeasurementReader& r, const QJsonObject& section, const std::string& where,
                 MeasuredLandmark& landmark) {
    if (section.contains("contour")) {
        const QJsonArray contour = r.array(section, "contour", where);
        for (qsizetype i = 0; i < contour.size(); ++i) {
            landmark.contour.push_back(
                r.uv(contour[i], where + ".contour[" + std::to_string(i) + "]"));
        }
    }
    if (section.contains("centre")) {
        MeasuredLandmark::Plane plane;
        plane.centre = r.point(section.value("centre"), where + ".centre");
        plane.u = r.point(section.value("axis_u"), where + ".axis_u");
        plane.v = r.point(section.value("axis_v"), where + ".axis_v");
        landmark.plane = plane;
    }
    if (section.contains("calipers")) {
        const QJsonObject calipers = r.object(section.value("calipers"), where + ".calipers");
        for (auto [key, target] :
             {std::pair{"min", &landmark.minCaliper}, std::pair{"max", &landmark.maxCaliper}}) {
            const std::string at = where + ".calipers." + key;
            const QJsonArray segment = r.array(calipers, key, where + ".calipers");
            if (segment.size() != 2) {
                r.fail(at + " is not two points");
            }
            *target = std::array<glm::dvec2, 2>{r.uv(segment[0], at), r.uv(segment[1], at)};
        }
    }
}

planning::AorticSizing readSizing(const MeasurementReader& r, const QJsonObject& t) {
    planning::AorticSizing s;
    const QJsonArray neck = r.array(t, "neck_diameters", "aortic_sizing");
    if (neck.size() != static_cast<qsizetype>(s.neckDiameters.size())) {
        r.fail("aortic_sizing.neck_diameters: not 4 places");
    }
    for (std::size_t i = 0; i < s.neckDiameters.size(); ++i) {
        const std::string where = "aortic_sizing.neck_diameters[" + std::to_string(i) + "]";
        s.neckDiameters[i] =
            r.sizingSizes(r.object(neck[static_cast<qsizetype>(i)], where), "sizes", where);
    }
    s.neckLengthMm = r.sizingNumber(t, "neck_length_mm");
    s.suprarenalToNeckDeg = r.sizingNumber(t, "alpha_deg");
    s.neckToAneurysmDeg = r.sizingNumber(t, "beta_deg");
    s.largestAneurysm = r.sizingSizes(r.object(t.value("largest_aneurysm"), "largest_aneurysm"),
                                      "value", "aortic_sizing.largest_aneurysm");
    s.renalToBifurcationMm = r.sizingNumber(t, "renal_to_aortic_bifurcation_mm");
    const std::array<std::string, 2> sides{"left", "right"};
    for (std::size_t side = 0; side < 2; ++side) {
        s.renalToInternalIliacMm[side] =
            r.sizingNumber(t, (sides[side] + "_renal_to_internal_iliac_mm").c_str());
        s.bifurcationToInternalIliacMm[side] =
            r.sizingNumber(t, (sides[side] + "_aortic_bifurcation_to_internal_iliac_mm").c_str());
        const std::string key = sides[side] + "_smallest_iliac";
        s.smallestIliac[side] =
            r.sizingSizes(r.object(t.value(key.c_str()), key), "value", "aortic_sizing." + key);
    }
    return s;
}

// The measurement groups ----------------------------------------------------

dicom::SrNumber diameter(double mm, std::optional<dicom::SrCode> derivation, std::string meaning) {
    return {dicom::sr::diameter(), std::move(derivation), mm, dicom::sr::millimetre(),
            std::move(meaning)};
}

dicom::SrNumber pathLength(double mm, std::string meaning) {
    return {dicom::sr::pathLength(), std::nullopt, mm, dicom::sr::millimetre(), std::move(meaning)};
}

void addSizes(std::vector<dicom::SrNumber>& numbers, const planning::SectionSizes& s,
              const std::string& where) {
    numbers.push_back(diameter(s.equivalentDiameterMm, std::nullopt,
                               "Equivalent diameter (2 sqrt(area / pi))" + where));
    numbers.push_back(diameter(s.minDiameterMm, dicom::sr::minimum(),
                               "Minimum Feret (caliper) diameter" + where));
    numbers.push_back(diameter(s.maxDiameterMm, dicom::sr::maximum(),
                               "Maximum Feret (caliper) diameter" + where));
    numbers.push_back({dicom::sr::area(), std::nullopt, s.areaMm2, dicom::sr::squareMillimetre(),
                       "Lumen area" + where});
}

/// A tracking identifier: at most 64 characters, unique in `used`.
std::string trackingId(const std::string& wanted, std::set<std::string>& used) {
    std::string id = wanted.substr(0, 64);
    for (int n = 2; !used.insert(id).second; ++n) {
        const std::string suffix = " (" + std::to_string(n) + ")";
        id = wanted.substr(0, 64 - suffix.size()) + suffix;
    }
    return id;
}

void addSizing(std::vector<dicom::SrNumber>& n, const planning::AorticSizing& s) {
    for (std::size_t i = 0; i < s.neckDiameters.size(); ++i) {
        if (const auto& cell = s.neckDiameters[i].value) {
            const double depth = planning::AorticSizing::kNeckDepthsMm[i];
            const std::string where = depth == 0.0 ? ", neck at the lowest renal artery"
                                                   : ", neck " + fixedText(depth, 0) +
                                                         " mm below the lowest renal artery";
            addSizes(n, *cell, where);
        }
    }
    if (s.neckLengthMm.value) {
        n.push_back(pathLength(*s.neckLengthMm.value,
                               "Neck length, lowest renal artery to start of the aneurysm, along "
                               "the centreline"));
    }
    const auto angle = [&n](const planning::SizingValue<double>& v, const char* meaning) {
        if (v.value) {
            n.push_back({dicom::sr::angle(), std::nullopt, *v.value, dicom::sr::degree(), meaning});
        }
    };
    angle(s.suprarenalToNeckDeg, "Neck angulation alpha, suprarenal aorta to neck axis");
    angle(s.neckToAneurysmDeg, "Neck angulation beta, neck to aneurysm axis");
    if (const auto& widest = s.largestAneurysm.value) {
        n.push_back(diameter(widest->maxDiameterMm, dicom::sr::maximum(),
                             "Largest aneurysm diameter, maximum Feret (caliper) diameter"));
        n.push_back(diameter(widest->equivalentDiameterMm, std::nullopt,
                             "Largest aneurysm diameter, equivalent diameter (2 sqrt(area / pi))"));
    }
    if (s.renalToBifurcationMm.value) {
        n.push_back(pathLength(*s.renalToBifurcationMm.value,
                               "Lowest renal artery to aortic bifurcation, along the centreline"));
    }
    const std::array<std::string, 2> sides{"left", "right"};
    for (std::size_t side = 0; side < 2; ++side) {
        if (s.renalToInternalIliacMm[side].value) {
            n.push_back(pathLength(*s.renalToInternalIliacMm[side].value,
                                   "Lowest renal artery to " + sides[side] +
                                       " internal iliac origin, along the centreline"));
        }
        if (s.bifurcationToInternalIliacMm[side].value) {
            n.push_back(pathLength(*s.bifurcationToInternalIliacMm[side].value,
                                   "Aortic bifurcation to " + sides[side] +
                                       " internal iliac origin, along the centreline"));
        }
        if (const auto& iliac = s.smallestIliac[side].value) {
            n.push_back(diameter(iliac->minDiameterMm, dicom::sr::minimum(),
                                 "Smallest " + sides[side] +
                                     " iliac access diameter, minimum Feret (caliper) diameter"));
        }
    }
}

}  // namespace

ReportMeasurements readMeasurements(const std::filesystem::path& path) {
    return readMeasurementText(MeasurementReader(path).fileText(), path);
}

ReportMeasurements readMeasurementText(const std::string& text, const std::filesystem::path& file) {
    const MeasurementReader r(file);
    const QJsonObject root = r.document(text);
    ReportMeasurements m;
    const QJsonArray branches = r.array(root, "branches", "the file");
    for (qsizetype i = 0; i < branches.size(); ++i) {
        const std::string where = "branches[" + std::to_string(i) + "]";
        const QJsonObject b = r.object(branches[i], where);
        MeasuredBranch branch;
        branch.id = r.whole(b, "id", where);
        branch.name = b.value("name").toString().toStdString();
        branch.lengthMm = r.number(b, "length_mm", where);
        for (auto [key, target] :
             {std::pair{"narrowest", &branch.narrowest}, std::pair{"widest", &branch.widest}}) {
            if (!b.value(key).isNull()) {
                *target = r.sizes(r.object(b.value(key), where + "." + key), where + "." + key,
                                  branch.id);
            }
        }
        if (!b.value("stenosis").isNull()) {
            const QJsonObject s = r.object(b.value("stenosis"), where + ".stenosis");
            branch.stenosisDiameterPercent = r.number(s, "diameter_percent", where + ".stenosis");
            branch.stenosisAreaPercent = r.number(s, "area_percent", where + ".stenosis");
            if (s.contains("path_mm")) {
                branch.stenosisPathMm = r.maybe(s.value("path_mm"), where + ".stenosis.path_mm");
            }
        }
        m.branches.push_back(std::move(branch));
    }
    if (root.contains("landmarks")) {
        const QJsonArray landmarks = r.array(root, "landmarks", "the file");
        for (qsizetype i = 0; i < landmarks.size(); ++i) {
            const std::string where = "landmarks[" + std::to_string(i) + "]";
            const QJsonObject l = r.object(landmarks[i], where);
            MeasuredLandmark landmark;
            landmark.name = r.text(l, "name", where);
            landmark.kind = r.kind(l, "kind", where);
            if (l.contains("path_mm")) {
                landmark.pathMm = r.maybe(l.value("path_mm"), where + ".path_mm");
            }
            if (!l.value("section").isNull()) {
                const QJsonObject section = r.object(l.value("section"), where + ".section");
                landmark.section = r.sizes(section, where + ".section");
                readContour(r, section, where + ".section", landmark);
            }
            m.landmarks.push_back(std::move(landmark));
        }
        const QJsonArray pairs = r.array(root, "landmark_pairs", "the file");
        for (qsizetype i = 0; i < pairs.size(); ++i) {
            const std::string where = "landmark_pairs[" + std::to_string(i) + "]";
            const QJsonObject p = r.object(pairs[i], where);
            m.lengths.push_back({r.text(p, "from", where), r.text(p, "to", where),
                                 r.number(p, "along_centreline_mm", where),
                                 r.number(p, "straight_mm", where)});
        }
    }
    if (root.contains("path")) {
        const QJsonObject path = r.object(root.value("path"), "path");
        if (path.contains("profile")) {
            MeasuredProfile profile;
            profile.fromEnd = r.whole(path, "from_end", "path");
            profile.toEnd = r.whole(path, "to_end", "path");
            profile.lengthMm = r.number(path, "length_mm", "path");
            profile.chosen = path.value("chosen").toBool(false);
            const QJsonArray points = r.array(path, "profile", "path");
            for (qsizetype i = 0; i < points.size(); ++i) {
                const std::string where = "path.profile[" + std::to_string(i) + "]";
                const QJsonArray p = points[i].toArray();
                if (!points[i].isArray() || (p.size() != 5 && p.size() != 8)) {
                    r.fail(where + " is not [path_mm, equivalent, min, max, area(, x, y, z)]");
                }
                MeasuredProfile::Point point;
                point.pathMm = r.maybe(p[0], where).value_or(0.0);
                point.equivalentMm = r.maybe(p[1], where);
                point.minMm = r.maybe(p[2], where);
                point.maxMm = r.maybe(p[3], where);
                point.areaMm2 = r.maybe(p[4], where);
                if (p.size() == 8) {
                    point.position = r.point(QJsonArray{p[5], p[6], p[7]}, where);
                }
                profile.points.push_back(point);
            }
            m.profile = std::move(profile);
        }
    }
    if (root.contains("aortic_sizing")) {
        m.sizing = readSizing(r, r.object(root.value("aortic_sizing"), "aortic_sizing"));
    }
    return m;
}

std::vector<dicom::SrGroup> measurementGroups(const ReportMeasurements& m) {
    std::vector<dicom::SrGroup> groups;
    std::set<std::string> used;
    for (const MeasuredLandmark& l : m.landmarks) {
        if (!l.section) {
            continue;
        }
        dicom::SrGroup g;
        g.trackingId = trackingId(l.name, used);
        addSizes(g.numbers, *l.section, ", at " + l.name);
        groups.push_back(std::move(g));
    }
    if (!m.lengths.empty()) {
        dicom::SrGroup g;
        g.trackingId = trackingId("Lengths between landmarks", used);
        for (const MeasuredLength& length : m.lengths) {
            g.numbers.push_back(pathLength(
                length.alongMm, length.from + " to " + length.to + ", along the centreline"));
            g.numbers.push_back({dicom::sr::distance(), std::nullopt, length.straightMm,
                                 dicom::sr::millimetre(),
                                 length.from + " to " + length.to + ", straight"});
        }
        groups.push_back(std::move(g));
    }
    if (m.sizing) {
        dicom::SrGroup g;
        g.trackingId = trackingId("Aortic sizing", used);
        addSizing(g.numbers, *m.sizing);
        if (!g.numbers.empty()) {
            groups.push_back(std::move(g));
        }
    }
    for (const MeasuredBranch& b : m.branches) {
        dicom::SrGroup g;
        g.trackingId = trackingId(b.name.empty() ? "Branch " + std::to_string(b.id) : b.name, used);
        g.numbers.push_back(pathLength(b.lengthMm, "Branch length along the centreline"));
        if (b.narrowest) {
            g.numbers.push_back(diameter(b.narrowest->equivalentDiameterMm, dicom::sr::minimum(),
                                         "Narrowest equivalent diameter of the branch"));
        }
        if (b.widest) {
            g.numbers.push_back(diameter(b.widest->equivalentDiameterMm, dicom::sr::maximum(),
                                         "Widest equivalent diameter of the branch"));
        }
        groups.push_back(std::move(g));
    }
    return groups;
}

}  // namespace vv::app
