// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QByteArray>
#include <QStringList>
#include <filesystem>
#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>
#include <optional>

#include "vv/render/FrameRenderer.h"
#include "vv/render/MeshRenderer.h"
#include "vv/segmentation/SceneSource.h"

namespace vv::gui {

class ViewerWidget;

/// A saved session (.vvs): the data files, the camera and every display
/// setting of the viewer and its panels. Stored as JSON (UTF-8):
///
///     { "format": "vesselview-session", "version": 1,
///       "files": ["/data/tree.vtp"],            // relative = to the .vvs file
///       "camera": { "target": [x, y, z], "distance": d,
///                   "rotation": [w, x, y, z], "fieldOfView": degrees },
///       "view": { "vss": { "enabled", "scale", "solver", "p", "tolerance",
///                          "step", "isoLines", "isoLineWidth",
///                          "isoLineStrength", "lighting", "opacity" },
///                 "ao": { "enabled", "radius", "strength" },
///                 "cue": { "cue", "fogStrength", "fresnelExponent" },
///                 "style": { "array", "colorMap", "bins",
///                            "range": null | [lo, hi], "vesselColor": [r, g, b],
///                            "light": [azimuth, elevation],      // optional
///                            "objects": [ { "visible", "opacity",   // optional,
///                                "color": null | [r, g, b],         // per mesh
///                                "array": null | "" | name } ] },
///                 "background": [r, g, b], "legends": true },
///       "layout": "<base64 QMainWindow::saveState>" }      // optional
///
/// "light" and "objects" came later within version 1: a session without
/// them loads with the default light and every object in the scene's style.
/// Versions: 1 is the current one. Version 0 is the layout of the first
/// prototype (no "version" key; the display settings as one flat "settings"
/// object with the keys of ViewSettings.h); migrateSession() converts it. A
/// new version adds one step to that chain, so old files keep loading.
struct Session {
    QStringList files;  ///< absolute paths once loaded
    glm::vec3 cameraTarget{0.0F};
    float cameraDistance = 4.0F;
    glm::quat cameraRotation{1.0F, 0.0F, 0.0F, 0.0F};
    float fieldOfView = 30.0F;
    render::VssSettings vss;
    render::AoSettings ao;
    render::VesselCueSettings cue;
    render::MeshStyle style;
    glm::vec3 background{0.13F, 0.14F, 0.16F};
    bool legends = true;
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

/// What `viewer` shows now, with `files` as the data.
[[nodiscard]] Session captureSession(const ViewerWidget& viewer, const QStringList& files);

/// Applies the display settings and the camera of `session` to `viewer`
/// (the files are the caller's: load them first, as setting a scene refits
/// the camera).
void applySession(ViewerWidget& viewer, const Session& session);

/// The session as JSON (the current version).
[[nodiscard]] QByteArray sessionToJson(const Session& session, const std::filesystem::path& file);

/// Parses a session of any supported version (older ones are migrated);
/// relative file names are resolved against `file`'s folder. Throws
/// FormatError naming `file` for invalid JSON (e.g. truncated), missing
/// fields, wrong types, out-of-range or non-finite numbers, unknown names,
/// and versions newer than kSessionVersion.
[[nodiscard]] Session sessionFromJson(const QByteArray& json, const std::filesystem::path& file);

/// Writes `session` to `file` atomically (the old file stays complete until
/// the new one is). Throws IoError naming `file` when it cannot be written.
void saveSession(const std::filesystem::path& file, const Session& session);

/// Reads `file`. Throws IoError when it cannot be read, FormatError as
/// sessionFromJson().
[[nodiscard]] Session loadSession(const std::filesystem::path& file);

}  // namespace vv::gui
