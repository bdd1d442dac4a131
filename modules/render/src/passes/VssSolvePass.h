// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <cstdint>
#include <glm/glm.hpp>

#include "SolveWorker.h"
#include "passes/FrameResources.h"
#include "passes/PassContext.h"
#include "vv/render/RenderGraph.h"
#include "vv/vss/DepthNormalization.h"
#include "vv/vss/Solver.h"

namespace vv::render {

/// The solver options as plain bytes for dependsOn and request keys (no
/// padding surprises).
struct SolverKey {
    double p = 0.0;
    double tolerance = 0.0;
    double rangeMin = 0.0;  ///< fixed depth range; 0, 0 when visible
    double rangeMax = 0.0;
    std::int32_t kind = 0;
    std::int32_t step = 0;
    std::int32_t rangeMode = 0;
    std::int32_t padding = 0;
};

[[nodiscard]] SolverKey solverKey(const vss::SolverOptions& options,
                                  const vss::DepthRange& range) noexcept;

struct VssSolveInputs {
    PassContext context;
    /// The depth to solve (DepthReadbackOutputs::image); not read when
    /// `external`.
    Handle<CpuValue<DepthImage>> depth;
    /// The asynchronous solver; null = solve inside the frame. With it, the
    /// graph must have imported board::kSolvedImport (its latest solve).
    SolveWorker* worker = nullptr;
    /// Show the imported board::kExternalVss's VSS instead of solving
    /// (tiled rendering).
    bool external = false;
    vss::SolverOptions options;  ///< effectiveSolverOptions()
    vss::DepthRange range;
    bool preview = false;
    std::uint64_t depthView = 0;  ///< the view the depth shows (camera, size, scene)
    std::uint64_t request = 0;    ///< the solve's key: depthView, solver, preview
    float pixelScale = 0.0F;      ///< scene units per pixel per unit of depth
    float reduction = 1.0F;       ///< window pixels per render pixel (solveFrame())
    glm::ivec2 size{1, 1};        ///< the VSS's size: the render size, or below it (`reduced`)
    /// The VSS is solved below the render size (from the depth reduced to
    /// `size`, solveFrame()): the depth it was solved from goes into
    /// VssSolveOutputs::depth (R32F, +Inf off the vessels), for the passes
    /// that tell its vessel pixels from its void ones at its size.
    bool reduced = false;
    /// Give the slope texture the render size (the solver's thread fits the
    /// slopes); else a stand-in texel and the shader fits them.
    bool cpuSlopes = true;
};

struct VssSolveOutputs {
    Handle<Texture> height;  ///< R32F z' (void) / z (vessels) / -1 (no VSS)
    Handle<Texture> slope;   ///< RGBA32F fitted slopes when ShownVss::slopes
    Handle<Texture> depth;   ///< "vss-depth" when `reduced`, else invalid
    Handle<CpuValue<ShownVss>> shown;
    Handle<CpuValue<SolveInput>> input;
};

/// "vss-solve": solves the VSS of the depth read back (inline, or
/// submitted to the worker, showing its latest solve meanwhile), or takes
/// board::kExternalVss's, and uploads height and slopes (and, reduced, the
/// depth it was solved from). Every output is persistent: cached while
/// depth, solver, preview and the external VSS stay, so colour scale and
/// iso-line changes never re-solve.
VssSolveOutputs addVssSolvePass(RenderGraph& graph, const VssSolveInputs& inputs);

}  // namespace vv::render
