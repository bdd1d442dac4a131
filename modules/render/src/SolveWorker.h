// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// The VSS solve of a frame's depth, inline or on a worker thread.
// Internal to vv::render (FrameRenderer and its "vss-solve" pass).

#include <condition_variable>
#include <cstdint>
#include <functional>
#include <glm/glm.hpp>
#include <memory>
#include <mutex>
#include <optional>
#include <stop_token>
#include <thread>
#include <utility>
#include <vector>

#include "vv/core/Image.h"
#include "vv/render/FrameRenderer.h"
#include "vv/vss/DepthNormalization.h"
#include "vv/vss/Solver.h"

namespace vv::render {

/// Frames up to this many pixels (4K UHD) get their VSS slopes from the
/// solver's thread (16 bytes a pixel, CPU and texture); larger ones (big
/// exports) let the shader fit them, slower but without the memory.
constexpr long long kMaxCpuSlopePixels = 3840LL * 2160LL;

/// The void regions of an exact solve, kept with its frame so that the next
/// exact solve of the same size and solver options takes the regions that
/// did not change (vss::PreviousSolve): 4 bytes a pixel and the contours.
struct SolvedRegions {
    Image<std::int32_t> labels;
    std::vector<vss::VoidRegion> regions;
    vss::SolverOptions options;
};

/// A solved VSS for one view.
struct SolvedFrame {
    std::uint64_t key = 0;  ///< view, viewport, scene and solver it belongs to
    Image<float> height;    ///< GL row order (bottom row first); NaN = no VSS
    double dmin = 0.0;
    double dmax = 0.0;
    double milliseconds = 0.0;
    bool preview = false;     ///< a preview-quality solve
    double errorBound = 0.0;  ///< the solver's bound on |z' error|; NaN = none
    /// The depth the VSS was solved from when that was reduced from the
    /// frame's (solveFrame()'s `solveSize`), same size as `height`: its
    /// finite pixels are the VSS's vessel pixels there (the shading tells
    /// vessel from void by it); null when the VSS was solved at the frame's
    /// own size (the G-buffer tells them).
    std::shared_ptr<const Image<float>> solvedDepth;
    /// The lighting's plane-fit slopes (vss::fittedSlopes), same order and
    /// size as `height`; empty for previews (quick normals) and above
    /// kMaxCpuSlopePixels (the shader fits them itself there).
    Image<glm::vec4> slopes;
    /// Exact solves kept for the next one (solveFrame's `keepRegions`):
    /// their regions, for its `previous`; null otherwise.
    std::shared_ptr<const SolvedRegions> regions;
    std::size_t reusedRegions = 0;  ///< regions taken from `previous` (vss::VssStatistics)
    std::int64_t reusedPixels = 0;  ///< their void pixels
};

/// Solves the VSS of `depth` (mask = finite depth); exact solves also get
/// their lighting slopes (`pixelScale`: scene units per pixel per unit of
/// depth of the view, for the normals' coherence). A frame drawn at a
/// reduced size (`reduction` window pixels per render pixel, > 1) is solved
/// from silhouetteDepth() (ReducedContourDepth.h), normalised over the depth
/// as read in the visible range mode, so that its iso-lines lie where the
/// window-size solve puts them; 1 solves `depth` as it is.
///
/// A `solveSize` below `depth`'s size (a VSS solved below the render size;
/// {0, 0} = `depth`'s size) solves reduceDepth(depth, solveSize) instead,
/// `pixelScale` and `reduction` being those of `depth`, and the frame keeps
/// that depth (SolvedFrame::solvedDepth).
///
/// An exact solve given the `previous` exact frame (any view; solved with
/// the same `options` and at the same size, else it is ignored) takes from it
/// the void regions whose pixels and contour did not change (vss::solve's
/// `previous`): a view whose depth changed in one place (an object hidden,
/// shown or made translucent) re-solves only the regions next to it. With
/// `keepRegions`, an exact frame keeps its labels and regions
/// (SolvedFrame::regions, 4 bytes a pixel) to serve as the next one's
/// `previous` (the solve worker's frames); an inline solve (exports, the
/// command line) has no next solve to serve and keeps none. Throws what
/// vss::solve throws (CancelledError when `stop` is requested) and
/// InvalidArgumentError for a `solveSize` larger than `depth`.
[[nodiscard]] SolvedFrame solveFrame(
    std::uint64_t key, const Image<float>& depth, const vss::SolverOptions& options, bool preview,
    const vss::DepthRange& range, float pixelScale, float reduction, glm::ivec2 solveSize,
    const std::stop_token& stop, const SolvedFrame* previous = nullptr, bool keepRegions = false);

/// One worker thread solving the latest requested view; a newer request
/// cancels a running stale one (vss::solve's stop token). An exact solve
/// takes the unchanged regions of the latest exact one (solveFrame's
/// `previous`).
class SolveWorker {
  public:
    struct Job {
        std::uint64_t key = 0;
        std::shared_ptr<const Image<float>> depth;
        vss::SolverOptions options;
        bool preview = false;
        vss::DepthRange range;
        float pixelScale = 0.0F;     ///< of the view (slopes' normals), see solveFrame()
        float reduction = 1.0F;      ///< window pixels per render pixel, see solveFrame()
        glm::ivec2 solveSize{0, 0};  ///< the VSS's size, see solveFrame(); 0 = the depth's
    };

    /// `onSolved` is called on the worker thread after a solve that no
    /// queued request supersedes.
    explicit SolveWorker(std::function<void()> onSolved);
    /// Cancels what runs, drops what is queued and joins the thread.
    ~SolveWorker();
    SolveWorker(const SolveWorker&) = delete;
    SolveWorker& operator=(const SolveWorker&) = delete;
    SolveWorker(SolveWorker&&) = delete;
    SolveWorker& operator=(SolveWorker&&) = delete;

    /// Queues `job` (replacing a queued one) and stops a running solve of another key.
    void submit(Job job);
    /// True when `key` is queued or being solved.
    [[nodiscard]] bool requested(std::uint64_t key) const;
    /// True when a solve is queued or running (and not being stopped).
    [[nodiscard]] bool busy() const;
    /// The latest finished solve (null before the first) and a revision
    /// that grows with every finished solve.
    [[nodiscard]] std::pair<std::shared_ptr<const SolvedFrame>, std::uint64_t> latest() const;
    [[nodiscard]] SolveCounters counters() const;
    /// Blocks until nothing is queued or running.
    void waitIdle();

  private:
    void run(const std::stop_token& stop);

    std::function<void()> onSolved_;
    mutable std::mutex mutex_;
    std::condition_variable wake_;
    std::condition_variable idle_;
    std::optional<Job> pending_;
    bool running_ = false;
    std::uint64_t runningKey_ = 0;
    std::stop_source runningStop_;
    std::shared_ptr<const SolvedFrame> latest_;
    std::uint64_t revision_ = 0;
    SolveCounters counters_;
    std::jthread thread_;  // last: starts after, and joins before, the members above go
};

}  // namespace vv::render
