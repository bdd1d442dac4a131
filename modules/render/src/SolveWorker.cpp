// SPDX-License-Identifier: GPL-3.0-or-later
#include "SolveWorker.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>
#include <memory>

#include "ReducedContourDepth.h"
#include "vv/core/Error.h"
#include "vv/core/ImageRange.h"
#include "vv/vss/Shading.h"
#include "vv/vss/Vss.h"

namespace vv::render {

SolvedFrame solveFrame(std::uint64_t key, const Image<float>& depth,
                       const vss::SolverOptions& options, bool preview,
                       const vss::DepthRange& range, float pixelScale, float reduction,
                       glm::ivec2 solveSize, const std::stop_token& stop,
                       const SolvedFrame* previous, bool keepRegions) {
    const auto start = std::chrono::steady_clock::now();
    // A VSS below the render size: solved from the depth reduced to its
    // size, each reduced pixel's depth from the render size's silhouette.
    const bool belowRenderSize = solveSize.x > 0 && solveSize.y > 0 &&
                                 (solveSize.x != depth.width() || solveSize.y != depth.height());
    Image<float> reducedDepth =
        belowRenderSize ? reduceDepth(depth, solveSize.x, solveSize.y) : Image<float>{};
    const Image<float>& input = belowRenderSize ? reducedDepth : depth;
    const float inputPixelScale = belowRenderSize
                                      ? pixelScale * static_cast<float>(depth.height()) /
                                            static_cast<float>(std::max(solveSize.y, 1))
                                      : pixelScale;
    vss::DepthRange solveRange = range;
    // A reduced frame solves from contour depths moved to the silhouette
    // (thin vessels widened by a pixel, so the mask follows that depth),
    // normalised over the depth as read: the moved contours must not widen it.
    const bool reduced = silhouetteReach(reduction) > 0.0F;
    if (reduced && range.mode == vss::RangeMode::Visible) {
        if (const auto visible = finiteRange(input.view())) {
            solveRange = {vss::RangeMode::Fixed, visible->first, visible->second};
        }
    }
    auto solved = std::make_shared<Image<float>>(
        reduced ? silhouetteDepth(input, reduction, inputPixelScale) : Image<float>{});
    const ImageView<const float> solvedView = reduced ? solved->view() : input.view();
    const Image<std::uint8_t> mask = vss::maskFromFiniteDepth(solvedView);
    const SolvedRegions* before = previous != nullptr && !preview && previous->regions != nullptr &&
                                          previous->regions->options == options
                                      ? previous->regions.get()
                                      : nullptr;
    const vss::PreviousSolve previousSolve =
        before != nullptr
            ? vss::PreviousSolve{previous->height.view(), before->labels.view(), &before->regions}
            : vss::PreviousSolve{};
    const std::unique_ptr<vss::Solver> solver = vss::makeSolver(options);
    vss::VssResult result = vss::solve(solvedView, mask.view(), *solver, solveRange, stop,
                                       before != nullptr ? &previousSolve : nullptr);
    SolvedFrame frame;
    frame.reusedRegions = result.stats.reusedRegions;
    frame.reusedPixels = result.stats.reusedPixels;
    if (keepRegions && !preview) {
        frame.regions = std::make_shared<const SolvedRegions>(
            SolvedRegions{std::move(result.labels), std::move(result.regions), options});
    }
    frame.key = key;
    frame.height = std::move(result.height);
    frame.dmin = result.dmin;
    frame.dmax = result.dmax;
    frame.preview = preview;
    frame.errorBound = result.errorBound;
    if (belowRenderSize) {
        if (!reduced) {
            *solved = std::move(reducedDepth);
        }
        frame.solvedDepth = std::move(solved);
    }
    if (!preview && !frame.height.empty() &&
        static_cast<long long>(frame.height.width()) * frame.height.height() <=
            kMaxCpuSlopePixels) {
        frame.slopes = vss::fittedSlopes(frame.height.view(), mask.view(), stop);
        if (std::isfinite(frame.dmin) && std::isfinite(frame.dmax) && inputPixelScale > 0.0F) {
            vss::addNormalCoherence(frame.slopes, frame.height.view(), mask.view(),
                                    vss::SlopeScale{frame.dmin, frame.dmax, inputPixelScale});
        }
    }
    frame.milliseconds =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    return frame;
}

SolveWorker::SolveWorker(std::function<void()> onSolved)
    : onSolved_(std::move(onSolved)), thread_([this](const std::stop_token& stop) { run(stop); }) {}

SolveWorker::~SolveWorker() {
    {
        std::lock_guard lock(mutex_);
        runningStop_.request_stop();
        pending_.reset();
    }
    thread_.request_stop();
    wake_.notify_all();
    thread_.join();
}

void SolveWorker::submit(Job job) {
    {
        std::lock_guard lock(mutex_);
        if (running_ && runningKey_ != job.key) {
            runningStop_.request_stop();
        }
        pending_ = std::move(job);
        ++counters_.submitted;
    }
    wake_.notify_all();
}

bool SolveWorker::requested(std::uint64_t key) const {
    std::lock_guard lock(mutex_);
    return (pending_ && pending_->key == key) ||
           (running_ && runningKey_ == key && !runningStop_.stop_requested());
}

bool SolveWorker::busy() const {
    std::lock_guard lock(mutex_);
    return pending_.has_value() || (running_ && !runningStop_.stop_requested());
}

std::pair<std::shared_ptr<const SolvedFrame>, std::uint64_t> SolveWorker::latest() const {
    std::lock_guard lock(mutex_);
    return {latest_, revision_};
}

SolveCounters SolveWorker::counters() const {
    std::lock_guard lock(mutex_);
    return counters_;
}

void SolveWorker::waitIdle() {
    std::unique_lock lock(mutex_);
    idle_.wait(lock, [this] { return !pending_ && !running_; });
}

void SolveWorker::run(const std::stop_token& stop) {
    for (;;) {
        Job job;
        std::stop_token jobStop;
        {
            std::unique_lock lock(mutex_);
            wake_.wait(lock, [&] { return pending_.has_value() || stop.stop_requested(); });
            if (stop.stop_requested()) {
                return;
            }
            job = std::move(*pending_);
            pending_.reset();
            runningStop_ = std::stop_source();
            jobStop = runningStop_.get_token();
            running_ = true;
            runningKey_ = job.key;
            ++counters_.started;
        }
        std::shared_ptr<const SolvedFrame> previous;
        {
            const std::lock_guard lock(mutex_);
            previous = latest_;  // kept alive here while its regions are read
        }
        std::shared_ptr<const SolvedFrame> solved;
        bool cancelled = false;
        try {
            solved = std::make_shared<const SolvedFrame>(
                solveFrame(job.key, *job.depth, job.options, job.preview, job.range, job.pixelScale,
                           job.reduction, job.solveSize, jobStop, previous.get(), true));
        } catch (const CancelledError&) {
            cancelled = true;
        } catch (const std::exception&) {
            // A failure: the view shows no new VSS; the next request tries again.
        }
        bool notify = false;
        {
            std::lock_guard lock(mutex_);
            running_ = false;
            if (solved) {
                latest_ = std::move(solved);
                ++revision_;
                ++counters_.completed;
                // A result that a queued request already supersedes is
                // kept (frames show it until the newer one arrives) but
                // wakes nobody: its repaint would be a wasted frame.
                notify = !pending_.has_value();
            }
            if (cancelled) {
                ++counters_.cancelled;
            }
        }
        idle_.notify_all();
        if (notify && onSolved_) {
            onSolved_();
        }
    }
}

}  // namespace vv::render
