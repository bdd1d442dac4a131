// SPDX-License-Identifier: GPL-3.0-or-later
#include "gui/Session.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QJsonParseError>
#include <QJsonValue>
#include <algorithm>
#include <cmath>
#include <string>

#include "gui/ViewerWidget.h"
#include "vv/colormaps/ColorMap.h"
#include "vv/colormaps/DepthScale.h"
#include "vv/core/AtomicFile.h"
#include "vv/core/Error.h"
#include "vv/vss/Solver.h"

namespace vv::gui {

namespace {

const QString kFormat = QStringLiteral("vesselview-session");

QString text(std::string_view s) {
    return QString::fromUtf8(s.data(), static_cast<qsizetype>(s.size()));
}

QJsonArray array3(const glm::vec3& v) {
    return {static_cast<double>(v.x), static_cast<double>(v.y), static_cast<double>(v.z)};
}

/// Reads typed, range-checked fields; every error names the file and the
/// field ("camera.distance").
class Reader {
  public:
    explicit Reader(std::filesystem::path file) : file_(std::move(file)) {}

    [[noreturn]] void fail(const QString& field, const QString& problem) const {
        throw FormatError(file_,
                          "session field '" + field.toStdString() + "' " + problem.toStdString());
    }

    [[nodiscard]] QJsonValue get(const QJsonObject& o, const QString& where,
                                 const char* key) const {
        const QJsonValue v = o.value(QLatin1String(key));
        if (v.isUndefined()) {
            fail(path(where, key), QStringLiteral("is missing"));
        }
        return v;
    }

    [[nodiscard]] QJsonObject object(const QJsonObject& o, const QString& where,
                                     const char* key) const {
        const QJsonValue v = get(o, where, key);
        if (!v.isObject()) {
            fail(path(where, key), QStringLiteral("must be an object"));
        }
        return v.toObject();
    }

    [[nodiscard]] double number(const QJsonObject& o, const QString& where, const char* key,
                                double lo, double hi) const {
        return checkNumber(get(o, where, key), path(where, key), lo, hi);
    }

    [[nodiscard]] int integer(const QJsonObject& o, const QString& where, const char* key, int lo,
                              int hi) const {
        const double v = number(o, where, key, lo, hi);
        if (v != std::floor(v)) {
            fail(path(where, key), QStringLiteral("must be a whole number"));
        }
        return static_cast<int>(v);
    }

    [[nodiscard]] float real(const QJsonObject& o, const QString& where, const char* key, double lo,
                             double hi) const {
        return static_cast<float>(number(o, where, key, lo, hi));
    }

    [[nodiscard]] bool boolean(const QJsonObject& o, const QString& where, const char* key) const {
        const QJsonValue v = get(o, where, key);
        if (!v.isBool()) {
            fail(path(where, key), QStringLiteral("must be true or false"));
        }
        return v.toBool();
    }

    [[nodiscard]] QString string(const QJsonObject& o, const QString& where,
                                 const char* key) const {
        const QJsonValue v = get(o, where, key);
        if (!v.isString()) {
            fail(path(where, key), QStringLiteral("must be a string"));
        }
        return v.toString();
    }

    /// `n` numbers in [lo, hi].
    [[nodiscard]] std::vector<double> numbers(const QJsonValue& v, const QString& field,
                                              qsizetype n, double lo, double hi) const {
        if (!v.isArray() || v.toArray().size() != n) {
            fail(field, QStringLiteral("must be an array of %1 numbers").arg(n));
        }
        std::vector<double> out;
        const QJsonArray a = v.toArray();
        for (qsizetype i = 0; i < n; ++i) {
            out.push_back(checkNumber(a[i], field + QStringLiteral("[%1]").arg(i), lo, hi));
        }
        return out;
    }

    [[nodiscard]] glm::vec3 vec3(const QJsonObject& o, const QString& where, const char* key,
                                 double lo, double hi) const {
        const auto n = numbers(get(o, where, key), path(where, key), 3, lo, hi);
        return {static_cast<float>(n[0]), static_cast<float>(n[1]), static_cast<float>(n[2])};
    }

    [[nodiscard]] const std::filesystem::path& file() const noexcept { return file_; }

    static QString path(const QString& where, const char* key) {
        return where.isEmpty() ? QLatin1String(key) : where + QLatin1Char('.') + QLatin1String(key);
    }

  private:
    [[nodiscard]] double checkNumber(const QJsonValue& v, const QString& field, double lo,
                                     double hi) const {
        if (!v.isDouble()) {
            fail(field, QStringLiteral("must be a number"));
        }
        const double d = v.toDouble();
        if (!std::isfinite(d) || d < lo || d > hi) {
            fail(field, QStringLiteral("must be a finite number in [%1, %2], not %3")
                            .arg(lo)
                            .arg(hi)
                            .arg(d));
        }
        return d;
    }

    std::filesystem::path file_;
};

constexpr double kHuge = 1e30;

// --- Version migration: one step per version, oldest first ---------------

/// Version 0 (the first prototype): no "version"; the display settings in one
/// flat "settings" object with the keys of ViewSettings.h (vss, depthScale,
/// power, solver, tolerance, step, isoLines, isoLineStrength, lighting, ao,
/// aoRadius, colorMap, bins, vesselCue as an index, background, vesselColor,
/// legends) plus "array". Missing keys took the defaults then, and do now.
QJsonObject migrate0To1(const QJsonObject& old, const Reader& reader) {
    const QJsonValue settingsValue = old.value(QLatin1String("settings"));
    if (!settingsValue.isObject()) {
        reader.fail(QStringLiteral("settings"), QStringLiteral("must be an object (version 0)"));
    }
    const QJsonObject s = settingsValue.toObject();
    const Session defaults;
    const auto take = [&s](const char* key, const QJsonValue& fallback) {
        const QJsonValue v = s.value(QLatin1String(key));
        return v.isUndefined() ? fallback : v;
    };
    QJsonObject vss{
        {QStringLiteral("enabled"), take("vss", defaults.vss.enabled)},
        {QStringLiteral("scale"), take("depthScale", text(colormaps::name(defaults.vss.scale)))},
        {QStringLiteral("solver"), take("solver", text(vss::toString(defaults.vss.solver.kind)))},
        {QStringLiteral("p"), take("power", defaults.vss.solver.p)},
        {QStringLiteral("tolerance"), take("tolerance", defaults.vss.solver.tolerance)},
        {QStringLiteral("step"), take("step", defaults.vss.solver.step)},
        {QStringLiteral("isoLines"), take("isoLines", defaults.vss.isoLines)},
        {QStringLiteral("isoLineWidth"), static_cast<double>(defaults.vss.isoLineWidth)},
        {QStringLiteral("isoLineStrength"),
         take("isoLineStrength", static_cast<double>(defaults.vss.isoLineStrength))},
        {QStringLiteral("lighting"), take("lighting", static_cast<double>(defaults.vss.lighting))},
        {QStringLiteral("opacity"), static_cast<double>(defaults.vss.opacity)},
    };
    QJsonObject ao{
        {QStringLiteral("enabled"), take("ao", defaults.ao.enabled)},
        {QStringLiteral("radius"), take("aoRadius", static_cast<double>(defaults.ao.radius))},
        {QStringLiteral("strength"), static_cast<double>(defaults.ao.strength)},
    };
    // Version 0 stored the cue as its index in allVesselCues().
    QJsonValue cueName = text(render::name(defaults.cue.cue));
    if (const QJsonValue index = s.value(QLatin1String("vesselCue")); !index.isUndefined()) {
        const auto cues = render::allVesselCues();
        const double i = index.toDouble(-1.0);
        if (!index.isDouble() || i < 0 || i != std::floor(i) ||
            i >= static_cast<double>(cues.size())) {
            reader.fail(QStringLiteral("settings.vesselCue"),
                        QStringLiteral("must be a cue index 0..%1").arg(cues.size() - 1));
        }
        cueName = text(render::name(cues[static_cast<std::size_t>(i)]));
    }
    QJsonObject cue{
        {QStringLiteral("cue"), cueName},
        {QStringLiteral("fogStrength"), static_cast<double>(defaults.cue.fogStrength)},
        {QStringLiteral("fresnelExponent"), static_cast<double>(defaults.cue.fresnelExponent)},
    };
    QJsonObject style{
        {QStringLiteral("array"), take("array", QString())},
        {QStringLiteral("colorMap"),
         take("colorMap", text(colormaps::name(defaults.style.colorMap)))},
        {QStringLiteral("bins"), take("bins", defaults.style.bins)},
        {QStringLiteral("range"), QJsonValue::Null},
        {QStringLiteral("vesselColor"), take("vesselColor", array3(defaults.style.vesselColor))},
    };
    QJsonObject view{
        {QStringLiteral("vss"), vss},
        {QStringLiteral("ao"), ao},
        {QStringLiteral("cue"), cue},
        {QStringLiteral("style"), style},
        {QStringLiteral("background"), take("background", array3(defaults.background))},
        {QStringLiteral("legends"), take("legends", defaults.legends)},
    };
    QJsonObject next;
    next.insert(QStringLiteral("format"), kFormat);
    next.insert(QStringLiteral("version"), 1);
    next.insert(QStringLiteral("files"), old.value(QLatin1String("files")));
    next.insert(QStringLiteral("camera"), old.value(QLatin1String("camera")));
    next.insert(QStringLiteral("view"), view);
    return next;
}

/// Brings `root` to kSessionVersion, one step at a time.
QJsonObject migrate(QJsonObject root, const Reader& reader) {
    int version = 0;
    const QJsonValue v = root.value(QLatin1String("version"));
    if (v.isUndefined()) {
        if (!root.contains(QLatin1String("settings"))) {
            reader.fail(QStringLiteral("version"), QStringLiteral("is missing"));
        }
        version = 0;  // the prototype's files had no version
    } else {
        version = reader.integer(root, QString(), "version", 0, 1 << 20);
    }
    if (version > kSessionVersion) {
        throw FormatError(reader.file(), "session version " + std::to_string(version) +
                                             " is newer than this VesselView supports (" +
                                             std::to_string(kSessionVersion) +
                                             "); update VesselView");
    }
    if (version == 0) {
        root = migrate0To1(root, reader);
        version = 1;
    }
    // Future: if (version == 1) { root = migrate1To2(root, reader); version = 2; }
    return root;
}

/// Per object: "visible", "opacity", "color" (null = the vessel colour) and
/// "array" (null = the scene's array, "" = none), in mesh order.
QJsonArray objectsToJson(const render::MeshStyle& style) {
    QJsonArray objects;
    std::size_t count = style.objects.size();
    for (const std::size_t hidden : style.hidden) {
        count = std::max(count, hidden + 1);
    }
    for (std::size_t i = 0; i < count; ++i) {
        const render::ObjectStyle& o = style.object(i);
        const bool hidden =
            std::find(style.hidden.begin(), style.hidden.end(), i) != style.hidden.end();
        objects.append(QJsonObject{
            {QStringLiteral("visible"), !hidden},
            {QStringLiteral("opacity"), static_cast<double>(o.opacity)},
            {QStringLiteral("color"), o.color ? QJsonValue(array3(*o.color)) : QJsonValue()},
            {QStringLiteral("array"),
             o.array ? QJsonValue(QString::fromStdString(*o.array)) : QJsonValue()},
        });
    }
    return objects;
}

/// The objects objectsToJson() wrote, into `style` (objects and hidden).
void readObjects(const Reader& r, const QJsonValue& value, const QString& where,
                 render::MeshStyle& style) {
    if (!value.isArray()) {
        r.fail(where, QStringLiteral("must be an array"));
    }
    style.objects.clear();
    style.hidden.clear();
    const QJsonArray objects = value.toArray();
    for (qsizetype i = 0; i < objects.size(); ++i) {
        const QString w = where + QStringLiteral("[%1]").arg(i);
        if (!objects[i].isObject()) {
            r.fail(w, QStringLiteral("must be an object"));
        }
        const QJsonObject o = objects[i].toObject();
        render::ObjectStyle object;
        object.opacity = r.real(o, w, "opacity", 0.0, 1.0);
        if (const QJsonValue color = r.get(o, w, "color"); !color.isNull()) {
            object.color = r.vec3(o, w, "color", 0.0, 1.0);
        }
        if (const QJsonValue array = r.get(o, w, "array"); !array.isNull()) {
            object.array = r.string(o, w, "array").toStdString();
        }
        if (!r.boolean(o, w, "visible")) {
            style.hidden.push_back(static_cast<std::size_t>(i));
        }
        style.objects.push_back(std::move(object));
    }
}

}  // namespace

Session captureSession(const ViewerWidget& viewer, const QStringList& files) {
    Session s;
    for (const QString& f : files) {
        s.files << QFileInfo(f).absoluteFilePath();
    }
    const render::Camera& camera = viewer.camera();
    s.cameraTarget = camera.target();
    s.cameraDistance = camera.distance();
    s.cameraRotation = camera.rotation();
    s.fieldOfView = camera.fieldOfView();
    s.vss = viewer.vssSettings();
    s.vss.preview = false;
    s.ao = viewer.aoSettings();
    s.cue = viewer.vesselCue();
    s.style = viewer.style();
    s.background = viewer.background();
    s.legends = viewer.legendsVisible();
    return s;
}

void applySession(ViewerWidget& viewer, const Session& session) {
    viewer.setVssSettings(session.vss);
    viewer.setAoSettings(session.ao);
    viewer.setVesselCue(session.cue);
    render::MeshStyle style = session.style;
    style.lighting = viewer.style().lighting;
    viewer.setStyle(style);
    viewer.setBackground(session.background);
    viewer.setLegendsVisible(session.legends);
    render::Camera camera = viewer.camera();  // keeps viewport and scene bounds
    camera.setFieldOfView(session.fieldOfView);
    camera.setTarget(session.cameraTarget);
    camera.setRotation(session.cameraRotation);
    camera.setDistance(session.cameraDistance);
    viewer.setCamera(camera);
}

/// The "dicom" object: the series and its segmentation.
QJsonObject dicomToJson(const segmentation::SceneSourceOptions& d) {
    const segmentation::SegmentationOptions& seg = d.segmentation;
    QJsonObject o{
        {QStringLiteral("series"), QString::fromStdString(d.seriesInstanceUid)},
        {QStringLiteral("components"), seg.keepComponents},
        {QStringLiteral("triangles"), static_cast<double>(d.surface.targetTriangles)},
    };
    if (seg.range) {
        o.insert(QStringLiteral("threshold"), QJsonArray{static_cast<double>(seg.range->lower),
                                                         static_cast<double>(seg.range->upper)});
    }
    if (seg.seed) {
        o.insert(QStringLiteral("seed"), QJsonArray{seg.seed->x, seg.seed->y, seg.seed->z});
    }
    if (seg.removeBone) {
        o.insert(QStringLiteral("boneRemoval"), *seg.removeBone);
    }
    return o;
}

/// Reads the "dicom" object (see dicomToJson).
segmentation::SceneSourceOptions readDicom(const Reader& r, const QJsonValue& value) {
    const QString w = QStringLiteral("dicom");
    if (!value.isObject()) {
        r.fail(w, QStringLiteral("must be an object"));
    }
    const QJsonObject o = value.toObject();
    segmentation::SceneSourceOptions d;
    d.seriesInstanceUid = r.string(o, w, "series").toStdString();
    d.segmentation.keepComponents = r.integer(o, w, "components", 1, 255);
    d.surface.targetTriangles = static_cast<std::size_t>(r.number(o, w, "triangles", 0.0, 1e9));
    if (const QJsonValue t = o.value(QLatin1String("threshold")); !t.isUndefined()) {
        const auto n = r.numbers(t, w + QStringLiteral(".threshold"), 2, -kHuge, kHuge);
        if (!(n[0] <= n[1])) {
            r.fail(w + QStringLiteral(".threshold"), QStringLiteral("must have lower <= upper"));
        }
        segmentation::ThresholdRange range;
        range.lower = static_cast<float>(n[0]);
        range.upper = static_cast<float>(n[1]);
        range.rule = "saved in the session";
        d.segmentation.range = range;
    }
    if (const QJsonValue seed = o.value(QLatin1String("seed")); !seed.isUndefined()) {
        const auto n = r.numbers(seed, w + QStringLiteral(".seed"), 3, 0.0, 1e6);
        for (const double c : n) {
            if (c != std::floor(c)) {
                r.fail(w + QStringLiteral(".seed"), QStringLiteral("must be voxel indices"));
            }
        }
        d.segmentation.seed =
            glm::ivec3(static_cast<int>(n[0]), static_cast<int>(n[1]), static_cast<int>(n[2]));
    }
    if (o.contains(QLatin1String("boneRemoval"))) {
        d.segmentation.removeBone = r.boolean(o, w, "boneRemoval");
    }
    return d;
}

QByteArray sessionToJson(const Session& s, const std::filesystem::path& file) {
    static_cast<void>(file);
    QJsonArray files;
    for (const QString& f : s.files) {
        files.append(f);
    }
    const QJsonObject camera{
        {QStringLiteral("target"), array3(s.cameraTarget)},
        {QStringLiteral("distance"), static_cast<double>(s.cameraDistance)},
        {QStringLiteral("rotation"), QJsonArray{static_cast<double>(s.cameraRotation.w),
                                                static_cast<double>(s.cameraRotation.x),
                                                static_cast<double>(s.cameraRotation.y),
                                                static_cast<double>(s.cameraRotation.z)}},
        {QStringLiteral("fieldOfView"), static_cast<double>(s.fieldOfView)},
    };
    const QJsonObject vss{
        {QStringLiteral("enabled"), s.vss.enabled},
        {QStringLiteral("scale"), text(colormaps::name(s.vss.scale))},
        {QStringLiteral("solver"), text(vss::toString(s.vss.solver.kind))},
        {QStringLiteral("p"), s.vss.solver.p},
        {QStringLiteral("tolerance"), s.vss.solver.tolerance},
        {QStringLiteral("step"), s.vss.solver.step},
        {QStringLiteral("isoLines"), s.vss.isoLines},
        {QStringLiteral("isoLineWidth"), static_cast<double>(s.vss.isoLineWidth)},
        {QStringLiteral("isoLineStrength"), static_cast<double>(s.vss.isoLineStrength)},
        {QStringLiteral("lighting"), static_cast<double>(s.vss.lighting)},
        {QStringLiteral("opacity"), static_cast<double>(s.vss.opacity)},
        {QStringLiteral("range"),
         s.vss.range.mode == vss::RangeMode::Fixed
             ? QJsonObject{{QStringLiteral("mode"), QStringLiteral("fixed")},
                           {QStringLiteral("near"), s.vss.range.dmin},
                           {QStringLiteral("far"), s.vss.range.dmax}}
             : QJsonObject{{QStringLiteral("mode"), QStringLiteral("visible")}}},
    };
    const QJsonObject ao{
        {QStringLiteral("enabled"), s.ao.enabled},
        {QStringLiteral("radius"), static_cast<double>(s.ao.radius)},
        {QStringLiteral("strength"), static_cast<double>(s.ao.strength)},
    };
    const QJsonObject cue{
        {QStringLiteral("cue"), text(render::name(s.cue.cue))},
        {QStringLiteral("fogStrength"), static_cast<double>(s.cue.fogStrength)},
        {QStringLiteral("fresnelExponent"), static_cast<double>(s.cue.fresnelExponent)},
    };
    const QJsonValue range =
        s.style.range ? QJsonValue(QJsonArray{static_cast<double>(s.style.range->first),
                                              static_cast<double>(s.style.range->second)})
                      : QJsonValue(QJsonValue::Null);
    const QJsonObject style{
        {QStringLiteral("array"), QString::fromStdString(s.style.array)},
        {QStringLiteral("colorMap"), text(colormaps::name(s.style.colorMap))},
        {QStringLiteral("bins"), s.style.bins},
        {QStringLiteral("range"), range},
        {QStringLiteral("vesselColor"), array3(s.style.vesselColor)},
        {QStringLiteral("light"), QJsonArray{static_cast<double>(s.style.light.azimuth),
                                             static_cast<double>(s.style.light.elevation)}},
        {QStringLiteral("objects"), objectsToJson(s.style)},
    };
    const QJsonObject view{
        {QStringLiteral("vss"), vss},
        {QStringLiteral("ao"), ao},
        {QStringLiteral("cue"), cue},
        {QStringLiteral("style"), style},
        {QStringLiteral("background"), array3(s.background)},
        {QStringLiteral("legends"), s.legends},
    };
    QJsonObject root{
        {QStringLiteral("format"), kFormat}, {QStringLiteral("version"), kSessionVersion},
        {QStringLiteral("files"), files},    {QStringLiteral("camera"), camera},
        {QStringLiteral("view"), view},
    };
    if (!s.layout.isEmpty()) {
        root.insert(QStringLiteral("layout"), QString::fromLatin1(s.layout.toBase64()));
    }
    if (s.dicom) {
        root.insert(QStringLiteral("dicom"), dicomToJson(*s.dicom));
    }
    return QJsonDocument(root).toJson(QJsonDocument::Indented);
}

Session sessionFromJson(const QByteArray& json, const std::filesystem::path& file) {
    const Reader r(file);
    QJsonParseError error{};
    const QJsonDocument document = QJsonDocument::fromJson(json, &error);
    if (error.error != QJsonParseError::NoError) {
        throw FormatError(file, "not a valid session (JSON error at byte " +
                                    std::to_string(error.offset) + ": " +
                                    error.errorString().toStdString() + ")");
    }
    if (!document.isObject()) {
        throw FormatError(file, "not a valid session (the JSON is not an object)");
    }
    QJsonObject root = document.object();
    if (const QJsonValue format = root.value(QLatin1String("format"));
        !format.isUndefined() && format.toString() != kFormat) {
        r.fail(QStringLiteral("format"), QStringLiteral("must be \"%1\"").arg(kFormat));
    }
    root = migrate(std::move(root), r);

    Session s;
    const QJsonValue files = r.get(root, QString(), "files");
    if (!files.isArray()) {
        r.fail(QStringLiteral("files"), QStringLiteral("must be an array of file names"));
    }
    const QDir base(QFileInfo(QString::fromStdString(file.string())).absolutePath());
    for (qsizetype i = 0; i < files.toArray().size(); ++i) {
        const QJsonValue f = files.toArray()[i];
        if (!f.isString() || f.toString().isEmpty()) {
            r.fail(QStringLiteral("files[%1]").arg(i), QStringLiteral("must be a file name"));
        }
        s.files << QDir::cleanPath(base.absoluteFilePath(f.toString()));
    }

    const QString cam = QStringLiteral("camera");
    const QJsonObject camera = r.object(root, QString(), "camera");
    s.cameraTarget = r.vec3(camera, cam, "target", -kHuge, kHuge);
    s.cameraDistance = r.real(camera, cam, "distance", 1e-9, kHuge);
    const auto q = r.numbers(r.get(camera, cam, "rotation"), cam + QStringLiteral(".rotation"), 4,
                             -1.0001, 1.0001);
    s.cameraRotation = glm::quat(static_cast<float>(q[0]), static_cast<float>(q[1]),
                                 static_cast<float>(q[2]), static_cast<float>(q[3]));
    if (glm::length(s.cameraRotation) < 1e-3F) {
        r.fail(cam + QStringLiteral(".rotation"), QStringLiteral("must be a unit quaternion"));
    }
    s.fieldOfView = r.real(camera, cam, "fieldOfView", 1.001, 169.999);

    const QJsonObject view = r.object(root, QString(), "view");
    const QString v = QStringLiteral("view");
    {
        const QString w = v + QStringLiteral(".vss");
        const QJsonObject o = r.object(view, v, "vss");
        s.vss.enabled = r.boolean(o, w, "enabled");
        const QString scale = r.string(o, w, "scale");
        const auto parsedScale = colormaps::depthScaleFromName(scale.toStdString());
        if (!parsedScale) {
            r.fail(w + QStringLiteral(".scale"),
                   QStringLiteral("names no depth scale: \"%1\"").arg(scale));
        }
        s.vss.scale = *parsedScale;
        try {
            s.vss.solver.kind = vss::parseSolverKind(r.string(o, w, "solver").toStdString());
        } catch (const vv::InvalidArgumentError& e) {
            r.fail(w + QStringLiteral(".solver"), QString::fromStdString(e.problem()));
        }
        s.vss.solver.p = r.number(o, w, "p", 0.25, 64.0);
        s.vss.solver.tolerance = r.number(o, w, "tolerance", 1e-6, 1.0);
        s.vss.solver.step = r.integer(o, w, "step", 1, 64);
        s.vss.isoLines = r.integer(o, w, "isoLines", 0, 64);
        s.vss.isoLineWidth = r.real(o, w, "isoLineWidth", 0.0, 64.0);
        s.vss.isoLineStrength = r.real(o, w, "isoLineStrength", 0.0, 1.0);
        s.vss.lighting = r.real(o, w, "lighting", 0.0, 1.0);
        s.vss.opacity = r.real(o, w, "opacity", 0.0, 1.0);
        // Optional in version 1 (files written before it: the visible range).
        if (o.contains(QStringLiteral("range"))) {
            const QString rw = w + QStringLiteral(".range");
            const QJsonObject range = r.object(o, w, "range");
            const QString mode = r.string(range, rw, "mode");
            if (mode == QStringLiteral("fixed")) {
                s.vss.range.mode = vss::RangeMode::Fixed;
                s.vss.range.dmin = r.number(range, rw, "near", -1.0e9, 1.0e9);
                s.vss.range.dmax = r.number(range, rw, "far", s.vss.range.dmin, 1.0e9);
            } else if (mode != QStringLiteral("visible")) {
                r.fail(rw + QStringLiteral(".mode"),
                       QStringLiteral("must be \"visible\" or \"fixed\", not \"%1\"").arg(mode));
            }
        }
    }
    {
        const QString w = v + QStringLiteral(".ao");
        const QJsonObject o = r.object(view, v, "ao");
        s.ao.enabled = r.boolean(o, w, "enabled");
        s.ao.radius = r.real(o, w, "radius", 0.01, 1000.0);
        s.ao.strength = r.real(o, w, "strength", 0.0, 1.0);
    }
    {
        const QString w = v + QStringLiteral(".cue");
        const QJsonObject o = r.object(view, v, "cue");
        const QString name = r.string(o, w, "cue");
        const auto cue = render::vesselCueFromName(name.toStdString());
        if (!cue) {
            r.fail(w + QStringLiteral(".cue"),
                   QStringLiteral("names no vessel cue: \"%1\"").arg(name));
        }
        s.cue.cue = *cue;
        s.cue.fogStrength = r.real(o, w, "fogStrength", 0.0, 1.0);
        s.cue.fresnelExponent = r.real(o, w, "fresnelExponent", 0.01, 64.0);
    }
    {
        const QString w = v + QStringLiteral(".style");
        const QJsonObject o = r.object(view, v, "style");
        s.style.array = r.string(o, w, "array").toStdString();
        const QString map = r.string(o, w, "colorMap");
        const auto parsedMap = colormaps::colorMapFromName(map.toStdString());
        if (!parsedMap) {
            r.fail(w + QStringLiteral(".colorMap"),
                   QStringLiteral("names no colour map: \"%1\"").arg(map));
        }
        s.style.colorMap = *parsedMap;
        s.style.bins = r.integer(o, w, "bins", 0, colormaps::kMaxBins);
        if (s.style.bins == 1) {
            r.fail(w + QStringLiteral(".bins"),
                   QStringLiteral("must be 0 (continuous) or 2..%1").arg(colormaps::kMaxBins));
        }
        const QJsonValue range = r.get(o, w, "range");
        if (!range.isNull()) {
            const auto n = r.numbers(range, w + QStringLiteral(".range"), 2, -kHuge, kHuge);
            if (!(n[0] < n[1])) {
                r.fail(w + QStringLiteral(".range"), QStringLiteral("must have min < max"));
            }
            s.style.range = std::make_pair(static_cast<float>(n[0]), static_cast<float>(n[1]));
        }
        s.style.vesselColor = r.vec3(o, w, "vesselColor", 0.0, 1.0);
        // Optional (older sessions have neither): the light and the objects' styles.
        if (const QJsonValue light = o.value(QLatin1String("light")); !light.isUndefined()) {
            const QString field = w + QStringLiteral(".light");
            const auto n = r.numbers(light, field, 2, -180.0, 180.0);
            if (std::abs(n[1]) > 90.0) {
                r.fail(field + QStringLiteral("[1]"),
                       QStringLiteral("(elevation) must be within [-90, 90]"));
            }
            s.style.light.azimuth = static_cast<float>(n[0]);
            s.style.light.elevation = static_cast<float>(n[1]);
        }
        if (const QJsonValue objects = o.value(QLatin1String("objects")); !objects.isUndefined()) {
            readObjects(r, objects, w + QStringLiteral(".objects"), s.style);
        }
    }
    s.background = r.vec3(view, v, "background", 0.0, 1.0);
    s.legends = r.boolean(view, v, "legends");
    if (const QJsonValue layout = root.value(QLatin1String("layout")); !layout.isUndefined()) {
        if (!layout.isString()) {
            r.fail(QStringLiteral("layout"), QStringLiteral("must be a string"));
        }
        s.layout = QByteArray::fromBase64(layout.toString().toLatin1());
    }
    if (const QJsonValue dicom = root.value(QLatin1String("dicom")); !dicom.isUndefined()) {
        s.dicom = readDicom(r, dicom);
    }
    return s;
}

void saveSession(const std::filesystem::path& file, const Session& session) {
    const QByteArray json = sessionToJson(session, file);
    writeAtomically(file, [&](const std::filesystem::path& temporary) {
        QFile out(QString::fromStdString(temporary.string()));
        if (!out.open(QIODevice::WriteOnly | QIODevice::Truncate) ||
            out.write(json) != json.size() || !out.flush()) {
            throw IoError(file, "cannot write the session: " + out.errorString().toStdString());
        }
    });
}

Session loadSession(const std::filesystem::path& file) {
    QFile in(QString::fromStdString(file.string()));
    if (!in.open(QIODevice::ReadOnly)) {
        throw IoError(file, "cannot read the session: " + in.errorString().toStdString());
    }
    constexpr qint64 kMaxBytes = 16 * 1024 * 1024;
    if (in.size() > kMaxBytes) {
        throw FormatError(file, "not a session: larger than 16 MiB");
    }
    return sessionFromJson(in.readAll(), file);
}

}  // namespace vv::gui
