// SPDX-License-Identifier: GPL-3.0-or-later
// The "slices" object of a session: layout, window, overlay style, each
// slice view's position, zoom and pan, and the linked cursor.
#include <QJsonArray>
#include <QJsonObject>
#include <QJsonValue>
#include <QStringList>
#include <array>
#include <string>

#include "common/Session.h"
#include "common/SessionReader.h"

namespace vv::app::detail {

namespace {

/// The views' keys, in SliceSessionState::views' order.
constexpr std::array<const char*, 3> kViewKeys{"axial", "coronal", "sagittal"};
constexpr std::array<slices::WindowPreset, 5> kPresets{
    slices::WindowPreset::Cta, slices::WindowPreset::Mra, slices::WindowPreset::SoftTissue,
    slices::WindowPreset::Bone, slices::WindowPreset::FullRange};

QString presetName(slices::WindowPreset preset) {
    return text(slices::presetKey(preset));
}

/// The index of `name` in `names`; fails naming `field` when absent.
template <std::size_t N>
std::size_t indexOf(const SessionReader& r, const std::array<const char*, N>& names,
                    const QString& name, const QString& field) {
    QStringList known;
    for (std::size_t n = 0; n < N; ++n) {
        if (name == QLatin1String(names.at(n))) {
            return n;
        }
        known << QLatin1String(names.at(n));
    }
    r.fail(field, QStringLiteral("must be one of %1").arg(known.join(QStringLiteral(", "))));
}

SliceViewState readView(const SessionReader& r, const QJsonObject& slices, const char* key) {
    const QString w = SessionReader::path(QStringLiteral("slices"), key);
    const QJsonObject o = r.object(slices, QStringLiteral("slices"), key);
    SliceViewState v;
    v.position = r.number(o, w, "position", -kMaxMm, kMaxMm);
    v.zoom = r.number(o, w, "zoom", kMinSliceZoom, kMaxSliceZoom);
    const auto pan =
        r.numbers(r.get(o, w, "pan"), SessionReader::path(w, "pan"), 2, -kMaxMm, kMaxMm);
    v.pan = {pan[0], pan[1]};
    return v;
}

}  // namespace

QJsonObject slicesToJson(const SliceSessionState& state) {
    QJsonObject window{{QStringLiteral("width"), state.window.width},
                       {QStringLiteral("level"), state.window.center}};
    if (state.preset) {
        window.insert(QStringLiteral("preset"), presetName(*state.preset));
    }
    QJsonObject o{
        {QStringLiteral("layout"), QLatin1String(kSliceLayoutNames.at(state.layout))},
        {QStringLiteral("window"), window},
        {QStringLiteral("overlay"), QJsonObject{{QStringLiteral("fill"), state.fill},
                                                {QStringLiteral("outline"), state.outline}}},
    };
    for (std::size_t n = 0; n < kViewKeys.size(); ++n) {
        const SliceViewState& v = state.views.at(n);
        o.insert(QLatin1String(kViewKeys.at(n)),
                 QJsonObject{{QStringLiteral("position"), v.position},
                             {QStringLiteral("zoom"), v.zoom},
                             {QStringLiteral("pan"), QJsonArray{v.pan.x, v.pan.y}}});
    }
    if (state.cursor) {
        o.insert(QStringLiteral("cursor"),
                 QJsonArray{state.cursor->x, state.cursor->y, state.cursor->z});
    }
    return o;
}

SliceSessionState readSlices(const SessionReader& r, const QJsonValue& value) {
    const QString w = QStringLiteral("slices");
    if (!value.isObject()) {
        r.fail(w, QStringLiteral("must be an object"));
    }
    const QJsonObject o = value.toObject();
    SliceSessionState s;
    s.layout =
        indexOf(r, kSliceLayoutNames, r.string(o, w, "layout"), SessionReader::path(w, "layout"));

    const QString ww = SessionReader::path(w, "window");
    const QJsonObject window = r.object(o, w, "window");
    s.window.width = r.number(window, ww, "width", 1e-6, kHuge);
    s.window.center = r.number(window, ww, "level", -kHuge, kHuge);
    if (window.contains(QLatin1String("preset"))) {
        std::array<const char*, kPresets.size()> names{};
        std::array<std::string, kPresets.size()> keys;
        for (std::size_t n = 0; n < kPresets.size(); ++n) {
            keys.at(n) = std::string(slices::presetKey(kPresets.at(n)));
            names.at(n) = keys.at(n).c_str();
        }
        s.preset = kPresets.at(
            indexOf(r, names, r.string(window, ww, "preset"), SessionReader::path(ww, "preset")));
    }

    const QString wo = SessionReader::path(w, "overlay");
    const QJsonObject overlay = r.object(o, w, "overlay");
    s.fill = r.boolean(overlay, wo, "fill");
    s.outline = r.boolean(overlay, wo, "outline");

    for (std::size_t n = 0; n < kViewKeys.size(); ++n) {
        s.views.at(n) = readView(r, o, kViewKeys.at(n));
    }
    if (const QJsonValue cursor = o.value(QLatin1String("cursor")); !cursor.isUndefined()) {
        const auto c = r.numbers(cursor, SessionReader::path(w, "cursor"), 3, -kMaxMm, kMaxMm);
        s.cursor = glm::dvec3(c[0], c[1], c[2]);
    }
    return s;
}

}  // namespace vv::app::detail
