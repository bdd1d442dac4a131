// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// Re-segmenting a loaded volume on a worker thread: the Segmentation panel's
// live preview (a downsampled copy, coarse surface) and its Apply (full
// resolution).

#include <QObject>
#include <QString>
#include <cstddef>
#include <glm/glm.hpp>
#include <memory>
#include <optional>
#include <stop_token>

#include "gui/WorkerRun.h"
#include "vv/core/Progress.h"
#include "vv/io/Mesh.h"
#include "vv/io/Volume.h"
#include "vv/io/VolumeSegmentation.h"
#include "vv/io/VolumeSurface.h"

namespace vv::gui {

/// Voxels a preview segments at most: with the surface, about 0.1 s on a
/// busy 2-core machine (a full 256 x 256 x 200 CTA took 0.35 s there).
inline constexpr std::size_t kPreviewVoxels = 2000000;

/// Every `step`-th voxel of `volume` along each axis: voxel (i, j, k) of the
/// result is voxel (step i, step j, step k) of `volume`; dims are
/// ceil(dims / step); indexToWorld is scaled by `step`, so world positions
/// stay where they were; voxel type, modality and unit are kept. step 1
/// copies. Throws InvalidArgumentError for step < 1 or an empty volume.
[[nodiscard]] io::Volume downsampledVolume(const io::Volume& volume, int step);

/// The step of a preview of a `dims` volume: the smallest step >= 2 that
/// leaves at most `voxelBudget` voxels, but 1 when every second voxel would
/// leave an axis with fewer than 8 voxels.
[[nodiscard]] int previewStep(glm::ivec3 dims, std::size_t voxelBudget = kPreviewVoxels) noexcept;

/// The voxel of `volume` with a value in [lower, upper] nearest to the
/// continuous voxel index `ijk`, among the voxels at most `radius` away along
/// each axis; nullopt when there is none (or `ijk` is not finite).
[[nodiscard]] std::optional<glm::ivec3> nearestVoxelInRange(const io::Volume& volume,
                                                            const glm::dvec3& ijk, float lower,
                                                            float upper, int radius);

/// What to segment and how.
struct SegmentationRequest {
    std::shared_ptr<const io::Volume> volume;
    /// The options in full-resolution voxels (seed, range). No range: the
    /// modality default of the full volume.
    io::SegmentationOptions segmentation;
    io::SurfaceOptions surface;
    /// 1: full resolution; n > 1: a preview of every n-th voxel per axis.
    int step = 1;
};

/// What a segmentation produced: one mesh "vessels" (or "vessels (preview)").
struct SegmentationOutcome {
    std::shared_ptr<const io::Scene> scene;
    io::ThresholdRange range;  ///< the range used
    std::size_t componentsFound = 0;
    std::size_t componentsKept = 0;
    std::size_t boneComponents = 0;
    std::size_t triangles = 0;
    int step = 1;
    double milliseconds = 0.0;  ///< segmentation and surface, wall clock
};

/// Runs `request` on the calling thread: downsamples when step > 1 (the seed
/// then moves to the nearest in-range voxel of the coarse grid within one
/// coarse voxel), segments (io::segmentVessels) and extracts the surface
/// (io::extractSurface). Throws InvalidArgumentError (no volume, bad
/// options, a seed outside the range or, in a preview, on a structure too
/// thin for the coarse grid), FormatError (no voxel in range), CancelledError.
[[nodiscard]] SegmentationOutcome runSegmentation(const SegmentationRequest& request,
                                                  const Progress& progress = {});

/// runSegmentation() on a worker thread (QtConcurrent), never on the GUI
/// thread. Progress arrives through progressChanged() (queued, at most every
/// 50 ms per stage); exactly one of succeeded(), failed() or cancelled()
/// follows on the GUI thread, then finished(). cancel() stops the worker at
/// its next progress report (std::stop_source) and discards a result that
/// arrives anyway. The destructor cancels and waits for the worker.
class SegmentationTask : public QObject {
    Q_OBJECT

  public:
    explicit SegmentationTask(SegmentationRequest request, QObject* parent = nullptr);

    /// Starts the worker; a second call does nothing.
    void start();
    void cancel() noexcept { run_.cancel(); }
    [[nodiscard]] bool isRunning() const { return run_.isRunning(); }
    [[nodiscard]] const SegmentationRequest& request() const noexcept { return request_; }

  signals:
    void progressChanged(double fraction, const QString& stage);
    void succeeded(std::shared_ptr<const vv::gui::SegmentationOutcome> outcome);
    /// `problem`: why (the engine's message).
    void failed(const QString& problem);
    void cancelled();
    /// After succeeded(), failed() or cancelled().
    void finished();

  private:
    struct Result {
        std::shared_ptr<const SegmentationOutcome> outcome;
        QString problem;
        bool cancelled = false;
    };
    [[nodiscard]] Result work(std::stop_token stop);
    void deliver();

    SegmentationRequest request_;
    WorkerRun<Result> run_;  ///< after request_: waits for the worker before it goes
};

}  // namespace vv::gui
