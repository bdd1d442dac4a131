// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// What the frame's passes hand each other besides textures: the CPU values
// among their resources, and the names of the resources the frame imports,
// which the blackboard keeps (RenderGraph::blackboard()). Everything a pass
// makes reaches the next pass as a handle in its inputs (FrameRenderer::
// renderGraph() wires them). Internal to vv::render.

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

// Imported by FrameRenderer, on the blackboard under these names.
inline constexpr std::string_view kOutput = "output";             ///< the frame's target
inline constexpr std::string_view kSolvedImport = "vss-result";   ///< the worker's latest solve
inline constexpr std::string_view kExternalVss = "external-vss";  ///< a VSS solved outside
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
