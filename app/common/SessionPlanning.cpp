// SPDX-License-Identifier: GPL-3.0-or-later
// The "planning" object of a session (issue 35): that the centrelines were
// found, the chosen path and cursor, branch names, landmarks and stenosis
// references. The analysis itself is not stored: it is found again from the
// same surface with the same options, which gives the same tree.
#include <QJsonArray>
#include <QJsonObject>
#include <QJsonValue>
#include <string>

#include "common/Session.h"
#include "common/SessionReader.h"

namespace vv::app::detail {

namespace {

/// Branch ids and ends stay below this bound (abscissae within kMaxMm).
constexpr int kMaxIndex = 1'000'000;

QJsonArray array3(const glm::dvec3& p) {
    return QJsonArray{p.x, p.y, p.z};
}

QJsonArray arrayOf(const QJsonObject& o, const SessionReader& r, const QString& where,
                   const char* key) {
    const QJsonValue v = r.get(o, where, key);
    if (!v.isArray()) {
        r.fail(SessionReader::path(where, key), QStringLiteral("must be an array"));
    }
    return v.toArray();
}

QJsonObject item(const SessionReader& r, const QJsonValue& v, const QString& field) {
    if (!v.isObject()) {
        r.fail(field, QStringLiteral("must be an object"));
    }
    return v.toObject();
}

}  // namespace

QJsonObject planningToJson(const PlanningSessionState& p) {
    QJsonArray names;
    for (const auto& [id, name] : p.branchNames) {
        names.append(QJsonObject{{QStringLiteral("branch"), id},
                                 {QStringLiteral("name"), QString::fromStdString(name)}});
    }
    QJsonArray landmarks;
    for (const planning::Landmark& l : p.landmarks) {
        landmarks.append(QJsonObject{
            {QStringLiteral("name"), QString::fromStdString(l.name)},
            {QStringLiteral("kind"),
             QString::fromUtf8(planning::landmarkKey(l.kind).data(),
                               static_cast<qsizetype>(planning::landmarkKey(l.kind).size()))},
            {QStringLiteral("branch"), l.location.branch},
            {QStringLiteral("abscissa_mm"), l.location.abscissaMm}});
    }
    QJsonArray references;
    for (const auto& [id, reference] : p.stenosisReferences) {
        references.append(QJsonObject{
            {QStringLiteral("branch"), id},
            {QStringLiteral("kind"), reference.kind == analysis::StenosisReference::Kind::Nascet
                                         ? QStringLiteral("nascet")
                                         : QStringLiteral("given")},
            {QStringLiteral("proximal_mm"), reference.proximalMm},
            {QStringLiteral("distal_mm"), reference.distalMm}});
    }
    QJsonObject o{{QStringLiteral("path"), QJsonObject{{QStringLiteral("from"), p.pathFrom},
                                                       {QStringLiteral("to"), p.pathTo}}},
                  {QStringLiteral("cursor_mm"), p.cursorMm},
                  {QStringLiteral("branch_names"), names},
                  {QStringLiteral("landmarks"), landmarks},
                  {QStringLiteral("stenosis_references"), references}};
    if (p.source) {
        o.insert(QStringLiteral("source"), array3(*p.source));
    }
    if (!p.targets.empty()) {
        QJsonArray targets;
        for (const glm::dvec3& t : p.targets) {
            targets.append(array3(t));
        }
        o.insert(QStringLiteral("targets"), targets);
    }
    return o;
}

PlanningSessionState readPlanning(const SessionReader& r, const QJsonValue& value) {
    const QString w = QStringLiteral("planning");
    const QJsonObject o = item(r, value, w);
    PlanningSessionState p;
    const QString wp = SessionReader::path(w, "path");
    const QJsonObject path = r.object(o, w, "path");
    p.pathFrom = r.integer(path, wp, "from", 0, kMaxIndex);
    p.pathTo = r.integer(path, wp, "to", 0, kMaxIndex);
    p.cursorMm = r.number(o, w, "cursor_mm", 0.0, kMaxMm);
    const QJsonArray names = arrayOf(o, r, w, "branch_names");
    for (qsizetype i = 0; i < names.size(); ++i) {
        const QString f = SessionReader::path(w, "branch_names") + QStringLiteral("[%1]").arg(i);
        const QJsonObject n = item(r, names[i], f);
        p.branchNames[r.integer(n, f, "branch", 0, kMaxIndex)] =
            r.string(n, f, "name").toStdString();
    }
    const QJsonArray landmarks = arrayOf(o, r, w, "landmarks");
    for (qsizetype i = 0; i < landmarks.size(); ++i) {
        const QString f = SessionReader::path(w, "landmarks") + QStringLiteral("[%1]").arg(i);
        const QJsonObject l = item(r, landmarks[i], f);
        planning::Landmark landmark;
        landmark.name = r.string(l, f, "name").toStdString();
        const auto kind = planning::landmarkKindOfKey(r.string(l, f, "kind").toStdString());
        if (!kind) {
            r.fail(SessionReader::path(f, "kind"), QStringLiteral("is not a landmark kind"));
        }
        landmark.kind = *kind;
        landmark.location = {r.integer(l, f, "branch", 0, kMaxIndex),
                             r.number(l, f, "abscissa_mm", -kMaxMm, kMaxMm)};
        p.landmarks.push_back(std::move(landmark));
    }
    const QJsonArray references = arrayOf(o, r, w, "stenosis_references");
    for (qsizetype i = 0; i < references.size(); ++i) {
        const QString f =
            SessionReader::path(w, "stenosis_references") + QStringLiteral("[%1]").arg(i);
        const QJsonObject s = item(r, references[i], f);
        analysis::StenosisReference reference;
        const QString kind = r.string(s, f, "kind");
        if (kind == QStringLiteral("given")) {
            reference.kind = analysis::StenosisReference::Kind::Given;
        } else if (kind == QStringLiteral("nascet")) {
            reference.kind = analysis::StenosisReference::Kind::Nascet;
        } else {
            r.fail(SessionReader::path(f, "kind"), QStringLiteral("must be given or nascet"));
        }
        reference.proximalMm = r.number(s, f, "proximal_mm", -kMaxMm, kMaxMm);
        reference.distalMm = r.number(s, f, "distal_mm", -kMaxMm, kMaxMm);
        p.stenosisReferences[r.integer(s, f, "branch", 0, kMaxIndex)] = reference;
    }
    if (const QJsonValue source = o.value(QLatin1String("source")); !source.isUndefined()) {
        const auto c = r.numbers(source, SessionReader::path(w, "source"), 3, -kMaxMm, kMaxMm);
        p.source = glm::dvec3(c[0], c[1], c[2]);
    }
    if (const QJsonValue targets = o.value(QLatin1String("targets")); !targets.isUndefined()) {
        if (!targets.isArray()) {
            r.fail(SessionReader::path(w, "targets"), QStringLiteral("must be an array"));
        }
        for (qsizetype i = 0; i < targets.toArray().size(); ++i) {
            const auto c =
                r.numbers(targets.toArray()[i],
                          SessionReader::path(w, "targets") + QStringLiteral("[%1]").arg(i), 3,
                          -kMaxMm, kMaxMm);
            p.targets.emplace_back(c[0], c[1], c[2]);
        }
    }
    return p;
}

}  // namespace vv::app::detail
