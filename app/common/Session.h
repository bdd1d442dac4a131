// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QByteArray>
#include <QStringList>
#include <array>
#include <filesystem>
#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "common/DisplaySettings.h"
#include "vv/analysis/Stenosis.h"
#include "vv/core/Progress.h"
#include "vv/planning/Landmarks.h"
#include "vv/render/Camera.h"
#include "vv/scene/Mesh.h"
#include "vv/segmentation/SceneSource.h"
#include "vv/slices/WindowLevel.h"

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
///       "dicom": { "series", "components", "triangles", ...,     // optional
///                  "title": "Run-off CTA" },                     // optional
///       "slices": { "layout": "3d+slices",                       // optional
///                   "window": { "width", "level", "preset": "cta" },
///                   "overlay": { "fill": true, "outline": true },
///                   "axial": { "position": mm, "zoom", "pan": [right, down] },
///                   "coronal": { ... }, "sagittal": { ... },
///                   "cursor": [x, y, z] },                      // optional
///       "measurement": { "points": [[x, y, z], [x, y, z]] },     // optional
///       "planning": { "path": { "from": end, "to": end },        // optional
///                     "cursor_mm": mm, "source": [x, y, z],     // source, targets
///                     "targets": [[x, y, z], ...],              //   optional
///                     "branch_names": [ { "branch", "name" } ],
///                     "landmarks": [ { "name", "kind", "branch", "abscissa_mm" } ],
///                     "stenosis_references": [ { "branch", "kind": "given",
///                                                "proximal_mm", "distal_mm" } ] },
///       "layout": "<base64 QMainWindow::saveState>" }            // optional
///
/// The keys below "view" are the settings' keys (SettingsSchema.h), which
/// also give their types and ranges. The optional keys came later within
/// version 1: a session without them loads their defaults. Versions: 1 is
/// the current one. Version 0 is the layout of the first prototype (no
/// "version" key; the display settings as one flat "settings" object with
/// the settings' QSettings keys); migrateSession() converts it. A new
/// version adds one step to that chain, so old files keep loading.
/// The layouts of the slice views by their names in sessions and QSettings,
/// in the order of gui::SliceLayout: the 3-D view alone, 3-D and three
/// slices, one large axial, coronal or sagittal slice.
inline constexpr std::array<const char*, 5> kSliceLayoutNames{"3d", "3d+slices", "axial", "coronal",
                                                              "sagittal"};
/// The zoom range of a slice view (1 = the slice fits the view).
inline constexpr double kMinSliceZoom = 0.25;
inline constexpr double kMaxSliceZoom = 32.0;

/// One slice view in a session. Positions are in mm, not slice numbers, so
/// that they survive a different grid (the nearest slice is shown).
struct SliceViewState {
    double position = 0.0;  ///< slice position, mm along the view's world axis
    double zoom = 1.0;      ///< [kMinSliceZoom, kMaxSliceZoom]
    /// Where the slice's centre lies from the view's centre, mm along the
    /// view's right and down (0, 0: centred).
    glm::dvec2 pan{0.0};
};

/// The slice views of a scene from a volume (the "slices" object): what the
/// radiologist saw, so that reopening the session shows the same picture.
struct SliceSessionState {
    std::size_t layout = 1;  ///< index into kSliceLayoutNames
    slices::Window window;   ///< shared by the three views
    /// The window preset chosen in View > Slices > Window (nullopt: none, e.g.
    /// after a drag); stored by presetKey().
    std::optional<slices::WindowPreset> preset;
    bool fill = true;                     ///< the segmentation as a translucent fill
    bool outline = true;                  ///< and / or its outline
    std::array<SliceViewState, 3> views;  ///< axial, coronal, sagittal
    std::optional<glm::dvec3> cursor;     ///< the linked cursor, LPS mm
};

/// The planning work of a session (the "planning" object, issue 35): the
/// centrelines were found (with the given end points, if any), and on them
/// the chosen path, the cursor, branch names, landmarks and stenosis
/// references. The analysis is found again when the session opens (the same
/// surface and end points give the same tree).
struct PlanningSessionState {
    std::optional<glm::dvec3> source;  ///< a given source point; nullopt: automatic ends
    std::vector<glm::dvec3> targets;   ///< given target points
    int pathFrom = 0;                  ///< CenterlineTree::ends indices
    int pathTo = 0;
    double cursorMm = 0.0;  ///< along the path
    std::map<int, std::string> branchNames;
    std::vector<planning::Landmark> landmarks;
    std::map<int, analysis::StenosisReference> stenosisReferences;
};

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
    /// (range, keepComponents, seed, removeBone, correctIntensity) and
    /// surface.targetTriangles are stored. Absent for meshes (and in older sessions).
    std::optional<segmentation::SceneSourceOptions> dicom;
    /// How the window named the series ("dicom.title": its description, or
    /// "CT series 1"; gui::seriesName()), so that a reopened session names
    /// the series so while it loads rather than by its folder (a study
    /// store's folders are UIDs); once loaded, the GUI names it by what the
    /// series says of itself, in the UI language. Empty: named after its
    /// folder while loading (meshes, older sessions). Stored only with `dicom`.
    QString seriesTitle;
    /// The slice views (scenes from a volume); absent for meshes and in
    /// older sessions, which open with the slice views' defaults. The
    /// command line renders the 3-D view; `report --session --slice PLANE`
    /// prints that plane's slice with its position, the window and the overlay.
    std::optional<SliceSessionState> slices;
    /// The distance measurement (View > Measure Distance): its points 1 and
    /// 2 in scene coordinates (mm), so that the reopened session shows the
    /// same measurement. Absent when none was shown (and in older sessions).
    /// The command line ignores it (it is still checked).
    std::optional<std::array<glm::vec3, 2>> measurement;
    /// The planning work (centrelines found); absent when none was done (and
    /// in older sessions). The command line ignores it (it is still checked).
    std::optional<PlanningSessionState> planning;
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
