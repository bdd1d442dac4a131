// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// What the frame's passes hand each other: the names they put on the
// graph's blackboard (each the resource's name too) and the CPU values among
// those resources. Internal to vv::render.

#include <cstdint>
#include <memory>
#include <optional>
#include <string_view>
#include <utility>

#include "SolveWorker.h"
#include "vv/core/Image.h"
#include "vv/render/FrameRenderer.h"
#include "vv/render/MeshStyle.h"
#include "vv/render/RenderGraph.h"

namespace vv::render::board {

// Imported.
inline constexpr std::string_view kOutput = "output";             ///< the frame's target
inline constexpr std::string_view kSolvedImport = "vss-result";   ///< the worker's latest solve
inline constexpr std::string_view kExternalVss = "external-vss";  ///< a VSS solved outside
// "geometry": the G-buffer.
inline constexpr std::string_view kLinearDepth = "linear-depth";
inline constexpr std::string_view kNormal = "normal";
inline constexpr std::string_view kObjectId = "object-id";
inline constexpr std::string_view kParameter = "parameter";
inline constexpr std::string_view kDepth = "depth";
// "depth-readback": the linear depth on the CPU.
inline constexpr std::string_view kLinearDepthImage = "linear-depth-image";
// "vss-solve".
inline constexpr std::string_view kVssHeight = "vss-height";
inline constexpr std::string_view kVssSlope = "vss-slope";
/// The depth a VSS below the render size was solved from (VssSolveInputs::reduced).
inline constexpr std::string_view kVssDepth = "vss-depth";
inline constexpr std::string_view kShownVss = "shown-vss";
inline constexpr std::string_view kSolveInput = "solve-input";
// "depth-range".
inline constexpr std::string_view kVisibleDepthRange = "visible-depth-range";
// "vessel-shading".
inline constexpr std::string_view kVesselColor = "vessel-color";
inline constexpr std::string_view kVesselCue = "vessel-cue";
// "vss-shading", "translucent", "ssao", "ao-blur", "composite".
inline constexpr std::string_view kVssColor = "vss-color";
inline constexpr std::string_view kTranslucentColor = "translucent-color";
inline constexpr std::string_view kAoRaw = "ao-raw";
inline constexpr std::string_view kAo = "ao";
inline constexpr std::string_view kComposited = "composited";

}  // namespace vv::render::board

namespace vv::render {

/// "linear-depth-image": the G-buffer's linear depth read back (GL row
/// order, +Inf on background). Shared, never modified once made.
struct DepthImage {
    std::shared_ptr<const Image<float>> image;
};

/// "visible-depth-range": the visible vessels' linear depth range (scene
/// units); nullopt when no vessel is visible.
struct VisibleDepthRange {
    std::optional<std::pair<double, double>> range;
};

/// "shown-vss": the VSS the height texture holds after "vss-solve".
struct ShownVss {
    std::shared_ptr<const SolvedFrame> frame;  ///< null = no VSS shown
    bool slopes = false;  ///< the slope texture holds the frame's fitted slopes
    /// What the renderer reports (FrameRenderer::vssStatus()).
    VssFrameStatus status;
};

/// "solve-input": the depth the solve read for a solve it ran or submitted
/// (FrameRenderer::lastSolvedDepth, requestSolve); null when it did neither.
struct SolveInput {
    std::shared_ptr<const Image<float>> depth;
    std::uint64_t view = 0;  ///< the view (camera, size, scene) the depth shows
};

/// "vessel-cue": the cue the vessels were shaded with (the translucent
/// objects use it too) and the depth range it normalised with (none = no cue).
struct ShadedCue {
    VesselCueParameters cue;
    std::optional<std::pair<double, double>> range;
};

/// "vss-result" (imported, asynchronous mode): the worker's latest solve;
/// the import's revision tells the solve pass when a new one arrived.
struct SolvedFrameRef {
    std::shared_ptr<const SolvedFrame> frame;
};

/// "external-vss" (imported): a VSS solved outside the renderer for the
/// whole frame (FrameRenderer::setExternalVss); its revision is the
/// external version (0 = none).
struct ExternalFrame {
    std::shared_ptr<const SolvedFrame> vss;  ///< null = none: solve as usual
    std::optional<std::pair<double, double>> visibleRange;
};

}  // namespace vv::render
