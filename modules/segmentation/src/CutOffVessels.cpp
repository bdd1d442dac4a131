// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/segmentation/CutOffVessels.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <optional>
#include <unordered_map>

#include "VolumeSampling.h"
#include "vv/core/Error.h"
#include "vv/segmentation/IntensityCorrection.h"
#include "vv/segmentation/VolumeSegmentation.h"

namespace vv::segmentation {

namespace {

constexpr const char* kStage = "Checking the segmentation's ends";
/// Samples per block for its median (about).
constexpr double kBlockSamples = 4096.0;
/// A multiplicative contrast must exceed this (the vessels brighter than around them).
constexpr double kMinimumRatio = 1.5;

bool absoluteValues(const scene::Volume& volume) {
    return volume.modality() == "CT" || volume.unit() == "HU";
}

double median(std::vector<double>& values) {
    const auto mid = static_cast<std::ptrdiff_t>(values.size() / 2);
    std::nth_element(values.begin(), values.begin() + mid, values.end());
    return values[static_cast<std::size_t>(mid)];
}

/// The local level: medians of the unsegmented body voxels in blocks,
/// interpolated trilinearly between block centres.
class LocalLevel {
  public:
    LocalLevel(const scene::Volume& volume, const scene::LabelMap& map, float air, float upper,
               double blockMm)
        : dims_(volume.dims()) {
        const glm::dvec3 spacing = volume.spacing();
        for (int c = 0; c < 3; ++c) {
            blocks_[c] = std::max(
                1, static_cast<int>(std::lround(dims_[c] * spacing[c] / std::max(blockMm, 1.0))));
            blocks_[c] = std::min(blocks_[c], dims_[c]);
        }
        levels_.assign(static_cast<std::size_t>(blocks_.x) * blocks_.y * blocks_.z,
                       std::numeric_limits<double>::quiet_NaN());
        std::vector<double> values;
        for (int bz = 0; bz < blocks_.z; ++bz) {
            for (int by = 0; by < blocks_.y; ++by) {
                for (int bx = 0; bx < blocks_.x; ++bx) {
                    const glm::ivec3 b(bx, by, bz);
                    const glm::ivec3 lo = begin(b);
                    const glm::ivec3 hi = begin(b + 1);
                    const glm::dvec3 size(hi - lo);
                    const int step = std::max(
                        1, static_cast<int>(std::cbrt(size.x * size.y * size.z / kBlockSamples)));
                    values.clear();
                    for (int k = lo.z; k < hi.z; k += step) {
                        for (int j = lo.y; j < hi.y; j += step) {
                            for (int i = lo.x; i < hi.x; i += step) {
                                const std::size_t n = volume.index(i, j, k);
                                const float v = volume.valueAt(n);
                                if (map.labels[n] == 0 && v > air && v <= upper &&
                                    std::isfinite(v)) {
                                    values.push_back(static_cast<double>(v));
                                }
                            }
                        }
                    }
                    if (!values.empty()) {
                        levels_[slot(b)] = median(values);
                    }
                }
            }
        }
    }

    /// The level at voxel `ijk`: NaN where no block around it has body voxels.
    [[nodiscard]] double at(const glm::ivec3& ijk) const {
        std::array<int, 3> b0{};
        std::array<double, 3> t{};
        for (int c = 0; c < 3; ++c) {
            // Block centre b lies at (b + 0.5) * dims / blocks - 0.5.
            const double x =
                (ijk[c] + 0.5) * static_cast<double>(blocks_[c]) / static_cast<double>(dims_[c]) -
                0.5;
            const double clamped = std::clamp(x, 0.0, static_cast<double>(blocks_[c] - 1));
            b0[static_cast<std::size_t>(c)] =
                std::min(static_cast<int>(std::floor(clamped)), std::max(blocks_[c] - 2, 0));
            t[static_cast<std::size_t>(c)] = clamped - b0[static_cast<std::size_t>(c)];
        }
        double sum = 0.0;
        double weights = 0.0;
        for (int corner = 0; corner < 8; ++corner) {
            glm::ivec3 b(b0[0], b0[1], b0[2]);
            double w = 1.0;
            for (int c = 0; c < 3; ++c) {
                const bool far = ((corner >> c) & 1) != 0;
                const double tc = t[static_cast<std::size_t>(c)];
                if (far) {
                    b[c] = std::min(b[c] + 1, blocks_[c] - 1);
                }
                w *= far ? tc : 1.0 - tc;
            }
            const double level = levels_[slot(b)];
            if (w > 0.0 && std::isfinite(level)) {
                sum += w * level;
                weights += w;
            }
        }
        return weights > 0.0 ? sum / weights : std::numeric_limits<double>::quiet_NaN();
    }

  private:
    [[nodiscard]] glm::ivec3 begin(const glm::ivec3& block) const {
        return {glm::dvec3(block) * glm::dvec3(dims_) / glm::dvec3(blocks_)};
    }
    [[nodiscard]] std::size_t slot(const glm::ivec3& b) const {
        return (static_cast<std::size_t>(b.z) * static_cast<std::size_t>(blocks_.y) +
                static_cast<std::size_t>(b.y)) *
                   static_cast<std::size_t>(blocks_.x) +
               static_cast<std::size_t>(b.x);
    }

    glm::ivec3 dims_;
    glm::ivec3 blocks_{1};
    std::vector<double> levels_;
};

/// One grown voxel and the segmented voxel its growth started from.
struct Grown {
    std::size_t voxel;
    std::size_t origin;
};

/// A voxel's contrast over its local level `l`: the difference for absolute
/// values (CT), else the ratio (NaN where the level is not positive).
double contrastOver(bool additive, double v, double l) {
    return additive ? v - l : (l > 0.0 ? v / l : std::numeric_limits<double>::quiet_NaN());
}

/// The median contrast of the segmented voxels (`segmented` of them, about
/// kSampledVoxels sampled) over their local level; none when no sampled
/// voxel has a level.
std::optional<double> referenceContrast(const scene::Volume& volume, const scene::LabelMap& map,
                                        const LocalLevel& level, bool additive,
                                        std::size_t segmented) {
    const glm::ivec3 dims = volume.dims();
    std::vector<double> contrasts;
    const std::size_t stride = std::max<std::size_t>(1, segmented / detail::kSampledVoxels);
    std::size_t seen = 0;
    for (int k = 0; k < dims.z; ++k) {
        for (int j = 0; j < dims.y; ++j) {
            for (int i = 0; i < dims.x; ++i) {
                const std::size_t n = volume.index(i, j, k);
                if (map.labels[n] != 0 && seen++ % stride == 0) {
                    const double c = contrastOver(additive, volume.valueAt(n), level.at({i, j, k}));
                    if (std::isfinite(c)) {
                        contrasts.push_back(c);
                    }
                }
            }
        }
    }
    if (contrasts.empty()) {
        return std::nullopt;
    }
    return median(contrasts);
}

/// Whether a voxel continues the segmentation: above air, not above the
/// range, and with at least `share` of the reference contrast (of the
/// reference's excess over 1 for ratios).
class Continuation {
  public:
    Continuation(const scene::Volume& volume, const LocalLevel& level, float air, float upper,
                 bool additive, double reference, double share)
        : volume_(&volume),
          level_(&level),
          air_(air),
          upper_(upper),
          additive_(additive),
          reference_(reference),
          share_(share) {}

    [[nodiscard]] bool operator()(std::size_t n, const glm::ivec3& ijk) const {
        const float v = volume_->valueAt(n);
        if (!(v > air_) || v > upper_ || !std::isfinite(v)) {
            return false;
        }
        const double c = contrastOver(additive_, v, level_->at(ijk));
        return std::isfinite(c) &&
               (additive_ ? c >= share_ * reference_ : c - 1.0 >= share_ * (reference_ - 1.0));
    }

  private:
    const scene::Volume* volume_;
    const LocalLevel* level_;
    float air_;
    float upper_;
    bool additive_;
    double reference_;
    double share_;
};

/// A volume's voxels by index: their grid positions, world positions and
/// face neighbours.
class VoxelGrid {
  public:
    explicit VoxelGrid(const scene::Volume& volume)
        : volume_(&volume),
          dims_(volume.dims()),
          sx_(static_cast<std::size_t>(dims_.x)),
          sxy_(sx_ * static_cast<std::size_t>(dims_.y)) {}

    [[nodiscard]] glm::ivec3 position(std::size_t n) const {
        return {static_cast<int>(n % sx_), static_cast<int>((n % sxy_) / sx_),
                static_cast<int>(n / sxy_)};
    }

    [[nodiscard]] glm::dvec3 world(std::size_t n) const {
        return volume_->worldPosition(glm::dvec3(position(n)));
    }

    /// Calls visit(index, position) for the face neighbours of voxel `n`
    /// inside the grid.
    template <typename Visit>
    void forNeighbours(std::size_t n, Visit&& visit) const {
        constexpr std::array<glm::ivec3, 6> kSteps = {glm::ivec3(1, 0, 0), glm::ivec3(-1, 0, 0),
                                                      glm::ivec3(0, 1, 0), glm::ivec3(0, -1, 0),
                                                      glm::ivec3(0, 0, 1), glm::ivec3(0, 0, -1)};
        const glm::ivec3 p = position(n);
        for (const glm::ivec3& step : kSteps) {
            const glm::ivec3 q = p + step;
            if (glm::any(glm::lessThan(q, glm::ivec3(0))) ||
                glm::any(glm::greaterThanEqual(q, dims_))) {
                continue;
            }
            visit(volume_->index(q.x, q.y, q.z), q);
        }
    }

  private:
    const scene::Volume* volume_;
    glm::ivec3 dims_;
    std::size_t sx_;
    std::size_t sxy_;
};

/// Grows from the segmentation's surface through unsegmented voxels that
/// continue it (face neighbours, breadth first), each grown voxel keeping the
/// segmented voxel its growth started from; none when more than `limit`
/// grow (a bright region, not vessels). Reports progress from 0.3 to 0.6.
std::optional<std::vector<Grown>> growFromSurface(const scene::Volume& volume,
                                                  const scene::LabelMap& map,
                                                  const Continuation& continues, std::size_t limit,
                                                  const Progress& progress) {
    const VoxelGrid grid(volume);
    std::vector<std::uint64_t> visited((volume.voxelCount() + 63) / 64, 0);
    const auto visit = [&visited](std::size_t n) {
        const std::uint64_t bit = std::uint64_t{1} << (n % 64);
        const bool was = (visited[n / 64] & bit) != 0;
        visited[n / 64] |= bit;
        return !was;
    };
    std::vector<Grown> grown;
    const auto spread = [&](std::size_t from, std::size_t origin) {
        grid.forNeighbours(from, [&](std::size_t m, const glm::ivec3& q) {
            if (map.labels[m] == 0 && continues(m, q) && visit(m)) {
                grown.push_back({m, origin});
            }
        });
    };
    const glm::ivec3 dims = volume.dims();
    for (int k = 0; k < dims.z; ++k) {
        progress.report(0.3 + 0.3 * k / dims.z, kStage);
        for (int j = 0; j < dims.y; ++j) {
            for (int i = 0; i < dims.x; ++i) {
                const std::size_t n = volume.index(i, j, k);
                if (map.labels[n] != 0) {
                    spread(n, n);
                }
            }
        }
    }
    for (std::size_t at = 0; at < grown.size(); ++at) {
        if (grown.size() > limit) {
            return std::nullopt;
        }
        spread(grown[at].voxel, grown[at].origin);
    }
    return grown;
}

/// A connected piece of grown voxels: how many, and the one farthest from
/// the segmented voxel its growth started from.
struct Piece {
    std::size_t count = 0;
    double length = -1.0;  ///< that farthest distance (mm)
    std::size_t far = 0;   ///< its slot in the grown voxels
};

/// Floods the piece of grown voxel `s` (face neighbours), marking its slots
/// in `done`; `slotOf` finds a voxel's slot, `stack` is scratch space.
Piece floodPiece(std::size_t s, const std::vector<Grown>& grown,
                 const std::unordered_map<std::size_t, std::size_t>& slotOf, const VoxelGrid& grid,
                 std::vector<std::uint8_t>& done, std::vector<std::size_t>& stack) {
    Piece piece;
    piece.far = s;
    done[s] = 1;
    stack.assign(1, s);
    while (!stack.empty()) {
        const std::size_t t = stack.back();
        stack.pop_back();
        ++piece.count;
        const double d = glm::length(grid.world(grown[t].voxel) - grid.world(grown[t].origin));
        if (d > piece.length) {
            piece.length = d;
            piece.far = t;
        }
        grid.forNeighbours(grown[t].voxel, [&](std::size_t m, const glm::ivec3& /*q*/) {
            const auto it = slotOf.find(m);
            if (it != slotOf.end() && done[it->second] == 0) {
                done[it->second] = 1;
                stack.push_back(it->second);
            }
        });
    }
    return piece;
}

/// The connected pieces of the grown voxels that look like cut-off vessels:
/// long enough (minimumLengthMm, three voxels), thick enough
/// (minimumRadiusVoxels) and elongated; the longest first.
std::vector<CutOffVessel> vesselPieces(const scene::Volume& volume, const std::vector<Grown>& grown,
                                       const CutOffOptions& options) {
    std::unordered_map<std::size_t, std::size_t> slotOf;
    slotOf.reserve(grown.size());
    for (std::size_t s = 0; s < grown.size(); ++s) {
        slotOf.emplace(grown[s].voxel, s);
    }
    const VoxelGrid grid(volume);
    const double voxelVolume = std::abs(glm::determinant(glm::dmat3(volume.indexToWorld())));
    const double h = std::cbrt(voxelVolume);
    std::vector<std::uint8_t> done(grown.size(), 0);
    std::vector<std::size_t> stack;
    std::vector<CutOffVessel> found;
    for (std::size_t s = 0; s < grown.size(); ++s) {
        if (done[s] != 0) {
            continue;
        }
        const Piece piece = floodPiece(s, grown, slotOf, grid, done, stack);
        const double length = piece.length;
        if (length < std::max(options.minimumLengthMm, 3.0 * h)) {
            continue;
        }
        const double radius =
            std::sqrt(static_cast<double>(piece.count) * voxelVolume / (std::numbers::pi * length));
        if (radius < options.minimumRadiusVoxels * h || length < options.elongation * radius) {
            continue;
        }
        found.push_back({grid.world(grown[piece.far].origin), grid.world(grown[piece.far].voxel),
                         length, radius});
    }
    std::sort(found.begin(), found.end(),
              [](const CutOffVessel& a, const CutOffVessel& b) { return a.lengthMm > b.lengthMm; });
    return found;
}

}  // namespace

PatientDirection dominantDirection(const glm::dvec3& v) noexcept {
    const glm::dvec3 a = glm::abs(v);
    if (a.x > a.y && a.x > a.z) {
        return v.x > 0.0 ? PatientDirection::Left : PatientDirection::Right;
    }
    if (a.y > a.z) {
        return v.y > 0.0 ? PatientDirection::Posterior : PatientDirection::Anterior;
    }
    return v.z >= 0.0 ? PatientDirection::Superior : PatientDirection::Inferior;
}

const char* directionName(PatientDirection direction) noexcept {
    switch (direction) {
        case PatientDirection::Left:
            return "left";
        case PatientDirection::Right:
            return "right";
        case PatientDirection::Posterior:
            return "posterior";
        case PatientDirection::Anterior:
            return "anterior";
        case PatientDirection::Superior:
            return "superior";
        case PatientDirection::Inferior:
            return "inferior";
    }
    return "superior";
}

std::vector<CutOffVessel> findCutOffVessels(const scene::Volume& volume, const scene::LabelMap& map,
                                            const ThresholdRange& range,
                                            const CutOffOptions& options,
                                            const Progress& progress) {
    if (map.dims != volume.dims() || map.labels.size() != volume.voxelCount()) {
        throw InvalidArgumentError("the label map is not on the volume's grid");
    }
    progress.report(0.0, kStage);
    const auto segmented = static_cast<std::size_t>(
        std::count_if(map.labels.begin(), map.labels.end(), [](std::uint8_t l) { return l != 0; }));
    if (segmented == 0) {
        return {};
    }
    const float air = airThreshold(volume);
    const LocalLevel level(volume, map, air, range.upper, options.blockMm);
    progress.report(0.3, kStage);

    // The segmented voxels' contrast over their local level.
    const bool additive = absoluteValues(volume);
    const std::optional<double> reference =
        referenceContrast(volume, map, level, additive, segmented);
    if (!reference) {
        return {};
    }
    if (additive ? !(*reference > 0.0) : !(*reference > kMinimumRatio)) {
        return {};  // the segmentation is not brighter than around it
    }
    const Continuation continues(volume, level, air, range.upper, additive, *reference,
                                 options.relativeContrast);

    // Grow from the segmentation's surface through voxels that continue it.
    const std::size_t limit = std::max(options.maximumVoxels, 2 * segmented);
    const std::optional<std::vector<Grown>> grown =
        growFromSurface(volume, map, continues, limit, progress);
    if (!grown) {
        return {};  // a bright region, not vessels: nothing to say
    }
    progress.report(0.8, kStage);

    // Connected pieces of the grown voxels.
    std::vector<CutOffVessel> found = vesselPieces(volume, *grown, options);
    progress.report(1.0, kStage);
    return found;
}

}  // namespace vv::segmentation
