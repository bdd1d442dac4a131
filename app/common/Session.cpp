// SPDX-License-Identifier: GPL-3.0-or-later
#include "common/Session.h"

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

#include "common/SessionReader.h"
#include "vv/core/AtomicFile.h"
#include "vv/core/Error.h"
#include "vv/segmentation/SceneSource.h"

namespace vv::app {

namespace {

using detail::kHuge;
using detail::SessionReader;

const QString kFormat = QStringLiteral("vesselview-session");

QJsonArray array3(const glm::vec3& v) {
    return {static_cast<double>(v.x), static_cast<double>(v.y), static_cast<double>(v.z)};
}

/// A series title longer than this is not what the chooser gives: refused.
constexpr qsizetype kMaxSeriesTitle = 1024;

/// The "dicom" object: the series, its segmentation and its title (if any).
QJsonObject dicomToJson(const segmentation::SceneSourceOptions& d, const QString& title) {
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
    if (seg.correctIntensity) {
        o.insert(QStringLiteral("intensityCorrection"), *seg.correctIntensity);
    }
    if (!title.isEmpty()) {
        o.insert(QStringLiteral("title"), title);
    }
    return o;
}

/// "dicom.title" of the "dicom" object `value` (read by readDicom): empty
/// when absent (older sessions); else one non-blank line of text.
QString readSeriesTitle(const SessionReader& r, const QJsonValue& value) {
    const QJsonObject o = value.toObject();
    if (!o.contains(QLatin1String("title"))) {
        return {};
    }
    QString title = r.string(o, QStringLiteral("dicom"), "title");
    if (title.trimmed().isEmpty() || title.size() > kMaxSeriesTitle) {
        r.fail(QStringLiteral("dicom.title"),
               QStringLiteral("must be a non-blank name of at most %1 characters")
                   .arg(kMaxSeriesTitle));
    }
    if (std::any_of(title.begin(), title.end(),
                    [](QChar c) { return c.category() == QChar::Other_Control; })) {
        r.fail(QStringLiteral("dicom.title"), QStringLiteral("must be one line of text"));
    }
    return title;
}

/// Reads the "dicom" object (see dicomToJson).
segmentation::SceneSourceOptions readDicom(const SessionReader& r, const QJsonValue& value) {
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
    if (o.contains(QLatin1String("intensityCorrection"))) {
        d.segmentation.correctIntensity = r.boolean(o, w, "intensityCorrection");
    }
    return d;
}

void readCamera(const SessionReader& r, const QJsonObject& root, Session& s) {
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
}

/// Reads the "measurement" object: two finite points.
std::array<glm::vec3, 2> readMeasurement(const SessionReader& r, const QJsonValue& value) {
    const QString w = QStringLiteral("measurement");
    if (!value.isObject()) {
        r.fail(w, QStringLiteral("must be an object"));
    }
    const QJsonValue points = r.get(value.toObject(), w, "points");
    if (!points.isArray() || points.toArray().size() != 2) {
        r.fail(w + QStringLiteral(".points"), QStringLiteral("must be two points [x, y, z]"));
    }
    std::array<glm::vec3, 2> read{};
    for (qsizetype i = 0; i < 2; ++i) {
        const auto n = r.numbers(points.toArray()[i], w + QStringLiteral(".points[%1]").arg(i), 3,
                                 -kHuge, kHuge);
        read.at(static_cast<std::size_t>(i)) =
            glm::vec3(static_cast<float>(n[0]), static_cast<float>(n[1]), static_cast<float>(n[2]));
    }
    return read;
}

std::filesystem::path toPath(const QString& file) {
    return {QFile::encodeName(file).toStdString()};
}

}  // namespace

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
    QJsonObject root{
        {QStringLiteral("format"), kFormat},
        {QStringLiteral("version"), kSessionVersion},
        {QStringLiteral("files"), files},
        {QStringLiteral("camera"), camera},
        {QStringLiteral("view"), detail::viewToJson(s)},
    };
    if (!s.layout.isEmpty()) {
        root.insert(QStringLiteral("layout"), QString::fromLatin1(s.layout.toBase64()));
    }
    if (s.dicom) {
        root.insert(QStringLiteral("dicom"), dicomToJson(*s.dicom, s.seriesTitle));
    }
    if (s.slices) {
        root.insert(QStringLiteral("slices"), detail::slicesToJson(*s.slices));
    }
    if (s.measurement) {
        root.insert(
            QStringLiteral("measurement"),
            QJsonObject{{QStringLiteral("points"),
                         QJsonArray{array3(s.measurement->at(0)), array3(s.measurement->at(1))}}});
    }
    if (s.planning) {
        root.insert(QStringLiteral("planning"), detail::planningToJson(*s.planning));
    }
    return QJsonDocument(root).toJson(QJsonDocument::Indented);
}

Session sessionFromJson(const QByteArray& json, const std::filesystem::path& file) {
    const SessionReader r(file);
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
    root = detail::migrateSession(std::move(root), r);

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
    readCamera(r, root, s);
    detail::readView(r, r.object(root, QString(), "view"), s);
    if (const QJsonValue layout = root.value(QLatin1String("layout")); !layout.isUndefined()) {
        if (!layout.isString()) {
            r.fail(QStringLiteral("layout"), QStringLiteral("must be a string"));
        }
        s.layout = QByteArray::fromBase64(layout.toString().toLatin1());
    }
    if (const QJsonValue dicom = root.value(QLatin1String("dicom")); !dicom.isUndefined()) {
        s.dicom = readDicom(r, dicom);
        s.seriesTitle = readSeriesTitle(r, dicom);
    }
    if (const QJsonValue slices = root.value(QLatin1String("slices")); !slices.isUndefined()) {
        s.slices = detail::readSlices(r, slices);
    }
    if (const QJsonValue m = root.value(QLatin1String("measurement")); !m.isUndefined()) {
        s.measurement = readMeasurement(r, m);
    }
    if (const QJsonValue p = root.value(QLatin1String("planning")); !p.isUndefined()) {
        s.planning = detail::readPlanning(r, p);
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
    constexpr qint64 kMaxBytes = qint64{16} * 1024 * 1024;
    if (in.size() > kMaxBytes) {
        throw FormatError(file, "not a session: larger than 16 MiB");
    }
    return sessionFromJson(in.readAll(), file);
}

scene::Scene loadSessionScene(const Session& session, const std::filesystem::path& file,
                              const Progress& progress, segmentation::SceneSourceReport* report) {
    const SessionReader r(file);
    if (session.files.isEmpty()) {
        r.fail(QStringLiteral("files"), QStringLiteral("names no data file to show"));
    }
    std::vector<std::filesystem::path> paths;
    for (qsizetype i = 0; i < session.files.size(); ++i) {
        paths.push_back(toPath(session.files[i]));
        std::error_code ec;
        if (!std::filesystem::exists(paths.back(), ec)) {
            r.fail(QStringLiteral("files[%1]").arg(i),
                   QStringLiteral("names a file that does not exist: %1").arg(session.files[i]));
        }
    }
    return segmentation::loadSceneSources(
        paths, session.dicom.value_or(segmentation::SceneSourceOptions{}), progress, report);
}

void applySessionCamera(const Session& session, render::Camera& camera) {
    camera.setFieldOfView(session.fieldOfView);
    camera.setTarget(session.cameraTarget);
    camera.setRotation(session.cameraRotation);
    camera.setDistance(session.cameraDistance);
}

render::Camera sessionCamera(const Session& session, const Aabb& bounds, int width, int height) {
    render::Camera camera;
    camera.setViewport(width, height);
    camera.setSceneBounds(bounds);
    applySessionCamera(session, camera);
    return camera;
}

}  // namespace vv::app
