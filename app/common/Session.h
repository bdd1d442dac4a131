// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QByteArray>
#include <QStringList>
#include <filesystem>
#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>
#include <optional>

#include "common/DisplaySettings.h"
#include "vv/core/Progress.h"
#include "vv/render/Camera.h"
#include "vv/scene/Mesh.h"
#include "vv/segmentation/SceneSource.h"

namespace vv::app {

/// A saved session (.vvs): the data files, the camera and every display
/// setting (DisplaySettings, described by SettingsSchema.h). Stored as JSON
/// (UTF-8):
///
///     { "format": "vesselview-session", "version": 1,
///       "files": ["/data/tree.vtp"],            // relative = to the .vvs file
///       "camera": { "target": [x, y, z], "distance": d,
///                   "rotation": [w, x, y, z], "fieldOfView": degrees },
///       "view": { "vss": { "enabled", "scale", "solver", "p", "tolerance",
///                          "step", "isoLines", "isoLineWidth",
///                          "isoLineStrength", "lighting", "opacity",
///                          "range": { "mode": "visible" }             // optional,
///                                 | { "mode": "fixed", "near", "far" } },
///                 "ao": { "enabled", "radius", "strength" },
///                 "cue": { "cue", "fogStrength", "fresnelExponent" },
///                 "style": { "array", "colorMap", "bins",
///                            "range": null | [lo, hi], "vesselColor": [r, g, b],
///                            "light": [azimuth, elevation],      // optional
///                            "noDataColor": null | [r, g, b],    // optional
///                            "legendTitle": "",                  // optional
///                            "objects": [ { "visible", "opacity",   // optional,
///                                "color": null | [r, g, b],         // per mesh
///                                "array": null | "" | name } ] },
///                 "background": [r, g, b], "legends": true },
///       "dicom": { "series", "components", "triangles", ... },   // optional
///       "layout": "<base64 QMainWindow::saveState>" }            // optional
///
/// The keys below "view" are the settings' keys (SettingsSchema.h), which
/// also give their types and ranges. The optional keys came later within
/// version 1: a session without them loads their defaults. Versions: 1 is
/// the current one. Version 0 is the layout of the first prototype (no
/// "version" key; the display settings as one flat "settings" object with
/// the settings' QSettings keys); migrateSession() converts it. A new
/// version adds one step to that chain, so old files keep loading.
struct Session : DisplaySettings {
    QStringList files;  ///< absolute paths once loaded
    glm::vec3 cameraTarget{0.0F};
    float cameraDistance = 4.0F;
    glm::quat cameraRotation{1.0F, 0.0F, 0.0F, 0.0F};
    float fieldOfView = 30.0F;
    QByteArray layout;  ///< QMainWindow::saveState(); empty = keep the current one
    /// DICOM data (files holds its folder, DICOMDIR or file): the series and
    /// how it was segmented into surfaces, so that opening the session loads
    /// the same vessels without asking. Only seriesInstanceUid, segmentation
    /// (range, keepComponents, seed, removeBone) and surface.targetTriangles
    /// are stored. Absent for meshes (and in older sessions).
    std::optional<segmentation::SceneSourceOptions> dicom;
};

/// The version saveSession() writes.
inline constexpr int kSessionVersion = 1;
/// The file name suffix (without the dot).
inline constexpr const char* kSessionSuffix = "vvs";

/// The session as JSON (the current version).
[[nodiscard]] QByteArray sessionToJson(const Session& session, const std::filesystem::path& file);

/// Parses a session of any supported version (older ones are migrated);
/// relative file names are resolved against `file`'s folder. Throws
/// FormatError naming `file` and the field ("view.vss.p") for invalid JSON
/// (e.g. truncated), missing fields, wrong types, out-of-range or
/// non-finite numbers, unknown names, and versions newer than
/// kSessionVersion.
[[nodiscard]] Session sessionFromJson(const QByteArray& json, const std::filesystem::path& file);

/// Writes `session` to `file` atomically (the old file stays complete until
/// the new one is). Throws IoError naming `file` when it cannot be written.
void saveSession(const std::filesystem::path& file, const Session& session);

/// Reads `file`. Throws IoError when it cannot be read, FormatError as
/// sessionFromJson().
[[nodiscard]] Session loadSession(const std::filesystem::path& file);

/// Loads the data of `session` (read from `file`) into one scene as the GUI
/// does when it opens the session (segmentation::loadSceneSources: its files in order, DICOM
/// sources segmented with `session.dicom`, default the only series).
/// `report` (optional) says what loading the last DICOM source did. Throws
/// FormatError naming `file` and the field ("files[1]") when a file does not
/// exist or the session names none, and as segmentation::loadSceneSources otherwise.
[[nodiscard]] scene::Scene loadSessionScene(const Session& session,
                                            const std::filesystem::path& file,
                                            const Progress& progress = {},
                                            segmentation::SceneSourceReport* report = nullptr);

/// Gives `camera` the session's field of view, target, rotation and
/// distance (in that order: the distance is clamped by the scene bounds);
/// its viewport and scene bounds stay. The GUI applies sessions with it.
void applySessionCamera(const Session& session, render::Camera& camera);

/// The session's camera for a view of width x height pixels of data within
/// `bounds` (which decide the clip planes): what the viewer shows once the
/// session is applied to it.
[[nodiscard]] render::Camera sessionCamera(const Session& session, const Aabb& bounds, int width,
                                           int height);

}  // namespace vv::app
