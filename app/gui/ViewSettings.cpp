// SPDX-License-Identifier: GPL-3.0-or-later
#include "gui/ViewSettings.h"

#include <QSettings>
#include <QVariantList>
#include <cmath>
#include <optional>

#include "gui/ViewerWidget.h"
#include "vv/colormaps/ColorMap.h"
#include "vv/colormaps/DepthScale.h"
#include "vv/core/Error.h"

namespace vv::gui {

namespace {

QString key(const char* name) {
    return QStringLiteral("view/") + QLatin1String(name);
}

QString text(std::string_view s) {
    return QString::fromUtf8(s.data(), static_cast<qsizetype>(s.size()));
}

/// The value of `name` when present and convertible, else `fallback`.
template <typename T>
T value(const QSettings& settings, const char* name, T fallback) {
    const QVariant v = settings.value(key(name));
    if (!v.isValid() || !v.canConvert<T>()) {
        return fallback;
    }
    return v.value<T>();
}

QVariantList toList(const glm::vec3& c) {
    return {static_cast<double>(c.r), static_cast<double>(c.g), static_cast<double>(c.b)};
}

/// Three sRGB components in [0, 1] stored under `name`, or nullopt.
std::optional<glm::vec3> colorValue(const QSettings& settings, const char* name) {
    const QVariantList list = value(settings, name, QVariantList());
    if (list.size() != 3) {
        return std::nullopt;
    }
    glm::vec3 color{0.0F};
    for (int i = 0; i < 3; ++i) {
        bool ok = false;
        const double c = list[i].toDouble(&ok);
        if (!ok || !(c >= 0.0 && c <= 1.0)) {
            return std::nullopt;
        }
        color[i] = static_cast<float>(c);
    }
    return color;
}

double finiteOr(double v, double fallback, double lo, double hi) {
    return std::isfinite(v) && v >= lo && v <= hi ? v : fallback;
}

}  // namespace

void saveViewSettings(const ViewerWidget& viewer, QSettings& settings) {
    const render::VssSettings& vss = viewer.vssSettings();
    settings.setValue(key("vss"), vss.enabled);
    settings.setValue(key("depthScale"), text(colormaps::name(vss.scale)));
    settings.setValue(key("power"), vss.solver.p);
    settings.setValue(key("solver"), text(vss::toString(vss.solver.kind)));
    settings.setValue(key("tolerance"), vss.solver.tolerance);
    settings.setValue(key("step"), vss.solver.step);
    settings.setValue(key("isoLines"), vss.isoLines);
    settings.setValue(key("isoLineStrength"), static_cast<double>(vss.isoLineStrength));
    settings.setValue(key("lighting"), static_cast<double>(vss.lighting));
    settings.setValue(key("ao"), viewer.aoSettings().enabled);
    settings.setValue(key("aoRadius"), static_cast<double>(viewer.aoSettings().radius));
    settings.setValue(key("colorMap"), text(colormaps::name(viewer.style().colorMap)));
    settings.setValue(key("bins"), viewer.style().bins);
    settings.setValue(key("vesselCue"), static_cast<int>(viewer.vesselCue().cue));
    settings.setValue(key("background"), toList(viewer.background()));
    settings.setValue(key("vesselColor"), toList(viewer.style().vesselColor));
    settings.setValue(key("legends"), viewer.legendsVisible());
    settings.setValue(key("lightAzimuth"), static_cast<double>(viewer.style().light.azimuth));
    settings.setValue(key("lightElevation"), static_cast<double>(viewer.style().light.elevation));
}

void restoreViewSettings(ViewerWidget& viewer, const QSettings& settings) {
    render::VssSettings vss = viewer.vssSettings();
    vss.enabled = value(settings, "vss", vss.enabled);
    if (const auto scale =
            colormaps::depthScaleFromName(value(settings, "depthScale", QString()).toStdString())) {
        vss.scale = *scale;
    }
    vss.solver.p = finiteOr(value(settings, "power", vss.solver.p), vss.solver.p, 0.25, 64.0);
    try {
        vss.solver.kind = vss::parseSolverKind(value(settings, "solver", QString()).toStdString());
    } catch (const vv::Error&) {
        // keep the current solver
    }
    vss.solver.tolerance = finiteOr(value(settings, "tolerance", vss.solver.tolerance),
                                    vss.solver.tolerance, 1e-6, 1.0);
    vss.solver.step = std::clamp(value(settings, "step", vss.solver.step), 1, 64);
    vss.isoLines = std::clamp(value(settings, "isoLines", vss.isoLines), 0, 64);
    vss.isoLineStrength = static_cast<float>(
        finiteOr(value(settings, "isoLineStrength", static_cast<double>(vss.isoLineStrength)),
                 static_cast<double>(vss.isoLineStrength), 0.0, 1.0));
    vss.lighting =
        static_cast<float>(finiteOr(value(settings, "lighting", static_cast<double>(vss.lighting)),
                                    static_cast<double>(vss.lighting), 0.0, 1.0));
    viewer.setVssSettings(vss);

    render::AoSettings ao = viewer.aoSettings();
    ao.enabled = value(settings, "ao", ao.enabled);
    ao.radius =
        static_cast<float>(finiteOr(value(settings, "aoRadius", static_cast<double>(ao.radius)),
                                    static_cast<double>(ao.radius), 0.01, 1000.0));
    viewer.setAoSettings(ao);

    render::MeshStyle style = viewer.style();
    if (const auto map =
            colormaps::colorMapFromName(value(settings, "colorMap", QString()).toStdString())) {
        style.colorMap = *map;
    }
    const int bins = value(settings, "bins", style.bins);
    if (bins == 0 || (bins >= 2 && bins <= colormaps::kMaxBins)) {
        style.bins = bins;
    }
    style.vesselColor = colorValue(settings, "vesselColor").value_or(style.vesselColor);
    style.light.azimuth = static_cast<float>(
        finiteOr(value(settings, "lightAzimuth", static_cast<double>(style.light.azimuth)),
                 static_cast<double>(style.light.azimuth), -180.0, 180.0));
    style.light.elevation = static_cast<float>(
        finiteOr(value(settings, "lightElevation", static_cast<double>(style.light.elevation)),
                 static_cast<double>(style.light.elevation), -90.0, 90.0));
    viewer.setStyle(style);

    render::VesselCueSettings cue = viewer.vesselCue();
    const int cueIndex = value(settings, "vesselCue", static_cast<int>(cue.cue));
    for (const auto known : render::allVesselCues()) {
        if (static_cast<int>(known) == cueIndex) {
            cue.cue = known;
        }
    }
    viewer.setVesselCue(cue);

    if (const auto background = colorValue(settings, "background")) {
        viewer.setBackground(*background);
    }
    viewer.setLegendsVisible(value(settings, "legends", viewer.legendsVisible()));
}

void resetViewSettings(ViewerWidget& viewer) {
    viewer.setVssSettings(render::VssSettings{});
    viewer.setAoSettings(render::AoSettings{});
    render::MeshStyle style = viewer.style();
    const render::MeshStyle defaults;
    style.colorMap = defaults.colorMap;
    style.bins = defaults.bins;
    style.vesselColor = defaults.vesselColor;
    style.light = defaults.light;
    viewer.setStyle(style);
    viewer.setVesselCue(render::VesselCueSettings{});
    viewer.setBackground(render::FrameSettings{}.background);
    viewer.setLegendsVisible(true);
}

}  // namespace vv::gui
