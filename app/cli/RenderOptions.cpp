// SPDX-License-Identifier: GPL-3.0-or-later
#include "cli/RenderOptions.h"

#include <algorithm>
#include <array>
#include <tuple>
#include <utility>

#include "cli/Cli.h"
#include "common/SettingsSchema.h"
#include "common/SmoothCopy.h"
#include "vv/core/Error.h"
#include "vv/render/MeshStyle.h"
#include "vv/report/ViewExport.h"

namespace vv::cli {

namespace {

constexpr int kMaxSide = 16384;

/// `text` as a value of `setting`; UsageError "<what> <problem>" when invalid.
app::SettingValue optionValue(const app::Setting& setting, std::string_view text,
                              const std::string& what) {
    try {
        return app::parseSettingText(setting, text);
    } catch (const InvalidArgumentError& e) {
        throw UsageError(what + " " + e.problem());
    }
}

void readSetting(Arguments& a, const app::Setting& setting, app::DisplaySettings& settings) {
    const std::string option = a.name();
    setting.field.set(settings, optionValue(setting, a.value(), option));
}

/// --session: every display setting the session holds, its files, DICOM
/// options and camera. The settings sessions do not hold (FXAA) stay.
void useSession(const std::filesystem::path& file, RenderOptionValues& values) {
    app::Session session = app::loadSession(file);  // IoError, FormatError: exit code 3
    const app::DisplaySettings before = static_cast<const app::DisplaySettings&>(values);
    static_cast<app::DisplaySettings&>(values) = static_cast<const app::DisplaySettings&>(session);
    for (const app::Setting& s : app::settingsSchema()) {
        if (s.session == app::SessionForm::None && s.field.set != nullptr) {
            s.field.set(values, s.field.get(before));
        }
    }
    values.array = session.style.array;
    values.arrayFromSession = true;
    values.light = session.style.light;
    values.view.reset();
    values.viewName.clear();
    values.sessionCamera = true;
    values.source = session.dicom.value_or(segmentation::SceneSourceOptions{});
    values.sessionFile = file;
    values.session = std::move(session);
}

std::string joined(const std::vector<std::string>& names) {
    std::string text;
    for (const auto& name : names) {
        text += (text.empty() ? "" : ", ") + name;
    }
    return text.empty() ? "none" : text;
}

}  // namespace

render::LightAngles parseLightAngles(const std::string& text) {
    const auto comma = text.find(',');
    if (comma == std::string::npos) {
        throw UsageError("--light must be AZIMUTH,ELEVATION in degrees (e.g. -30,20), got '" +
                         text + "'");
    }
    app::DisplaySettings parsed;
    const std::array<std::pair<const char*, std::string>, 2> parts{
        {{"style.light[0]", text.substr(0, comma)}, {"style.light[1]", text.substr(comma + 1)}}};
    for (const auto& [key, part] : parts) {
        const app::Setting& setting = app::setting(key);
        try {
            setting.field.set(parsed, app::parseSettingText(setting, part));
        } catch (const InvalidArgumentError& e) {
            throw UsageError("--light: the " + std::string(setting.label) + " " + e.problem() +
                             " (in '" + text + "')");
        }
    }
    return parsed.style.light;
}

void parseSettingValue(Arguments& args, std::string_view key, app::DisplaySettings& settings) {
    readSetting(args, app::setting(key), settings);
}

app::SettingValue parseSettingOption(std::string_view key, std::string_view text,
                                     const std::string& what) {
    return optionValue(app::setting(key), text, what);
}

int parseTileSide(const std::string& text) {
    return parseWholeNumber(text, "--tile", report::kMinTileSide);
}

bool parseRenderOption(Arguments& a, RenderOptionValues& values) {
    const std::string& name = a.name();
    if (name == "--size") {
        std::tie(values.width, values.height) = parseSize(a.value(), "--size", 1, kMaxSide);
    } else if (name == "--array") {
        const std::string& array = a.value();
        values.array = (array == "none" || array == "None" || array.empty()) ? "" : array;
        values.arrayFromSession = false;
    } else if (name == "--light") {
        values.light = parseLightAngles(a.value());
    } else if (name == "--view") {
        const std::string& view = a.value();
        values.view = render::namedViewFromName(view);
        if (!values.view) {
            throw UsageError("unknown view '" + view + "' (known: " + render::namedViewNames() +
                             ")");
        }
        values.viewName = view;
        values.sessionCamera = false;
    } else if (name == "--session") {
        useSession(a.path(), values);
    } else if (name == "--centerlines") {
        const std::string& value = a.value();
        if (value != "on" && value != "off") {
            a.fail("--centerlines must be on or off, not '" + value + "'");
        }
        values.centerlines = value == "on";
    } else if (name == "--centerline-colour" || name == "--centerline-color") {
        const std::string& value = a.value();
        if (value == "diameter") {
            values.centerlineColouring = render::CenterlineColouring::InscribedDiameter;
        } else if (value == "branch") {
            values.centerlineColouring = render::CenterlineColouring::Branch;
        } else {
            a.fail("--centerline-colour must be diameter or branch, not '" + value + "'");
        }
    } else if (segmentation::setSceneSourceOption(name, a.peekValue(), values.source)) {
        a.takeValue();  // a DICOM option and its value
    } else if (const app::Setting* setting = app::settingForOption(name)) {
        readSetting(a, *setting, values);  // a display setting's own option ("--p 4")
    } else {
        return false;
    }
    return true;
}

bool parseRenderOption(const std::vector<std::string>& args, std::size_t& i,
                       RenderOptionValues& values, const std::string& command) {
    Arguments a(command, args, i);
    a.next();
    const bool parsed = parseRenderOption(a, values);
    if (parsed) {
        i = a.position();
    }
    return parsed;
}

render::Camera cameraFor(const RenderOptionValues& values, const scene::Scene& scene, int width,
                         int height) {
    if (values.session && values.sessionCamera) {
        return app::sessionCamera(*values.session, scene.bounds(), width, height);
    }
    render::Camera camera;
    if (values.view) {
        camera =
            render::presetCamera(scene, width, height, values.view->preset, values.view->rotation);
    } else {
        // The scene's home view: anterior for the patient frame, as the GUI opens it.
        camera.setViewport(width, height);
        camera.setHomeRotation(render::homeRotation(scene.frame));
        camera.setRotation(camera.homeRotation());
        camera.fit(scene.bounds());
    }
    return camera;
}

scene::Scene loadSessionInput(const RenderOptionValues& values,
                              segmentation::SceneSourceReport* report) {
    app::Session session = values.session.value();
    session.dicom = values.source;  // the session's, unless options after --session changed it
    return app::loadSessionScene(session, values.sessionFile, {}, report);
}

render::OffscreenOptions offscreenOptions(const RenderOptionValues& values,
                                          const scene::Scene& scene,
                                          const std::filesystem::path& input) {
    render::OffscreenOptions options;
    options.width = values.width;
    options.height = values.height;
    options.display = static_cast<const app::DisplaySettings&>(values);
    options.display.style.light = values.light;
    options.display.style.array = values.array.value_or(render::defaultArrayName(scene));
    const std::string& array = options.display.style.array;
    const auto known = render::pointArrayNames(scene);
    if (values.session && values.arrayFromSession) {
        // As the GUI: a mesh without the array shows "no data"; none having it is an error.
        if (!array.empty() && std::find(known.begin(), known.end(), array) == known.end()) {
            throw FormatError(values.sessionFile, "session field 'view.style.array' names '" +
                                                      array + "', which no mesh of its files has " +
                                                      "(they have: " + joined(known) + ")");
        }
    } else if (!array.empty() && !scene.meshes.empty() &&
               scene.meshes.front().pointArray(array) == nullptr) {
        throw UsageError("'" + input.string() + "' has no point array '" + array +
                         "' (it has: " + joined(known) + ")");
    }
    options.camera = cameraFor(values, scene, values.width, values.height);
    if (options.display.smoothCoarseMeshes) {
        // A coarse scene's smooth copy (none for a fine one): drawn where
        // its facets are large in this view.
        options.refined = app::smoothCopyOf(scene);
    }
    return options;
}

}  // namespace vv::cli
