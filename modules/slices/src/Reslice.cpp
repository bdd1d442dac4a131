// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/slices/Reslice.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "vv/core/Error.h"
#include "vv/core/Parallel.h"

namespace vv::slices {

namespace {

constexpr int kMaxSide = 16384;
constexpr long kRowsPerChunk = 8;

void checkPlane(const SlicePlane& plane) {
    if (plane.width < 1 || plane.height < 1 || plane.width > kMaxSide || plane.height > kMaxSide) {
        throw InvalidArgumentError("slice plane must have 1 to 16384 pixels along each side");
    }
    if (!(plane.pixelSpacing > 0.0) || !std::isfinite(plane.pixelSpacing)) {
        throw InvalidArgumentError("slice pixel spacing must be positive and finite");
    }
    const glm::dvec3 all = plane.origin + plane.right + plane.down;
    if (!std::isfinite(all.x) || !std::isfinite(all.y) || !std::isfinite(all.z)) {
        throw InvalidArgumentError("slice plane is not finite");
    }
}

// Where one row of the plane runs through voxel index space: the index of
// its pixel 0 and the index step per column.
struct RowWalk {
    glm::dvec3 start;
    glm::dvec3 step;
};

// The mapping of plane pixels to continuous voxel indices of a grid.
struct PlaneToIndex {
    glm::dmat4 worldToIndex{1.0};
    glm::dvec3 columnStep{0.0};  // index change per column
    glm::dvec3 rowStep{0.0};     // index change per row
    glm::dvec3 origin{0.0};      // index of pixel (0, 0)

    PlaneToIndex(const glm::dmat4& indexToWorld, const SlicePlane& plane) {
        const double det = glm::determinant(glm::dmat3(indexToWorld));
        if (!std::isfinite(det) || std::abs(det) < 1e-12) {
            throw InvalidArgumentError("volume geometry is singular or not finite");
        }
        worldToIndex = glm::inverse(indexToWorld);
        const glm::dmat3 linear(worldToIndex);
        columnStep = linear * (plane.right * plane.pixelSpacing);
        rowStep = linear * (plane.down * plane.pixelSpacing);
        origin = glm::dvec3(worldToIndex * glm::dvec4(plane.origin, 1.0));
    }
    [[nodiscard]] RowWalk row(int r) const noexcept {
        return {origin + static_cast<double>(r) * rowStep, columnStep};
    }
};

// The columns [first, last] of a row of `width` pixels whose index lies in
// [-0.5, dims - 0.5] on every axis; first > last when none does.
std::pair<int, int> insideColumns(const RowWalk& walk, glm::ivec3 dims, int width) {
    double lo = 0.0;
    double hi = width - 1.0;
    constexpr double kSlack = 1e-9;
    for (int a = 0; a < 3; ++a) {
        const double minIndex = -0.5 - kSlack;
        const double maxIndex = dims[a] - 0.5 + kSlack;
        const double s = walk.step[a];
        const double p = walk.start[a];
        if (std::abs(s) < 1e-15) {
            if (p < minIndex || p > maxIndex) {
                return {1, 0};
            }
            continue;
        }
        double t0 = (minIndex - p) / s;
        double t1 = (maxIndex - p) / s;
        if (t0 > t1) {
            std::swap(t0, t1);
        }
        lo = std::max(lo, t0);
        hi = std::min(hi, t1);
    }
    if (lo > hi) {
        return {1, 0};
    }
    return {static_cast<int>(std::ceil(lo - 1e-9)), static_cast<int>(std::floor(hi + 1e-9))};
}

template <typename T>
struct Grid {
    const T* voxels;
    glm::ivec3 dims;
    std::ptrdiff_t strideY;
    std::ptrdiff_t strideZ;

    [[nodiscard]] float at(int i, int j, int k) const noexcept {
        return static_cast<float>(voxels[k * strideZ + j * strideY + i]);
    }
    [[nodiscard]] float nearest(const glm::dvec3& p) const noexcept {
        // Inside samples have p >= -0.5, so truncating p + 0.5 rounds halves up
        // (std::lround / std::lrint are library calls here: 4x slower).
        // NOLINTBEGIN(bugprone-incorrect-roundings)
        const int i = std::clamp(static_cast<int>(p.x + 0.5), 0, dims.x - 1);
        const int j = std::clamp(static_cast<int>(p.y + 0.5), 0, dims.y - 1);
        const int k = std::clamp(static_cast<int>(p.z + 0.5), 0, dims.z - 1);
        // NOLINTEND(bugprone-incorrect-roundings)
        return at(i, j, k);
    }
    [[nodiscard]] float linear(const glm::dvec3& p) const noexcept {
        const double x = std::clamp(p.x, 0.0, dims.x - 1.0);
        const double y = std::clamp(p.y, 0.0, dims.y - 1.0);
        const double z = std::clamp(p.z, 0.0, dims.z - 1.0);
        const int i0 = std::min(static_cast<int>(x), std::max(dims.x - 2, 0));
        const int j0 = std::min(static_cast<int>(y), std::max(dims.y - 2, 0));
        const int k0 = std::min(static_cast<int>(z), std::max(dims.z - 2, 0));
        const auto fx = static_cast<float>(x - i0);
        const auto fy = static_cast<float>(y - j0);
        const auto fz = static_cast<float>(z - k0);
        const std::ptrdiff_t di = dims.x > 1 ? 1 : 0;
        const std::ptrdiff_t dj = dims.y > 1 ? strideY : 0;
        const std::ptrdiff_t dk = dims.z > 1 ? strideZ : 0;
        const T* v = voxels + k0 * strideZ + j0 * strideY + i0;
        const auto f = [](T value) { return static_cast<float>(value); };
        const float c00 = f(v[0]) + fx * (f(v[di]) - f(v[0]));
        const float c10 = f(v[dj]) + fx * (f(v[dj + di]) - f(v[dj]));
        const float c01 = f(v[dk]) + fx * (f(v[dk + di]) - f(v[dk]));
        const float c11 = f(v[dk + dj]) + fx * (f(v[dk + dj + di]) - f(v[dk + dj]));
        const float c0 = c00 + fy * (c10 - c00);
        const float c1 = c01 + fy * (c11 - c01);
        return c0 + fz * (c1 - c0);
    }
};

template <typename T, typename Out, typename Sample>
Image<Out> resample(const Grid<T>& grid, const PlaneToIndex& map, const SlicePlane& plane,
                    Out outside, const Sample& sample, const std::stop_token& stop) {
    Image<Out> out(plane.width, plane.height, UninitialisedPixels{});
    parallelFor(
        0, plane.height, kRowsPerChunk,
        [&](long r0, long r1) {
            for (long r = r0; r < r1; ++r) {
                const RowWalk walk = map.row(static_cast<int>(r));
                Out* row = out.row(static_cast<int>(r));
                const auto [first, last] = insideColumns(walk, grid.dims, plane.width);
                if (first > last) {
                    std::fill(row, row + plane.width, outside);
                    continue;
                }
                std::fill(row, row + first, outside);
                for (int c = first; c <= last; ++c) {
                    row[c] = sample(grid, walk.start + static_cast<double>(c) * walk.step);
                }
                std::fill(row + last + 1, row + plane.width, outside);
            }
        },
        stop);
    return out;
}

template <typename T>
Grid<T> gridOf(const T* voxels, glm::ivec3 dims) {
    return {voxels, dims, dims.x, static_cast<std::ptrdiff_t>(dims.x) * dims.y};
}

template <typename T>
Image<float> resliceTyped(const Grid<T>& grid, const PlaneToIndex& map, const SlicePlane& plane,
                          Interpolation interpolation, const std::stop_token& stop) {
    constexpr float kOutside = std::numeric_limits<float>::quiet_NaN();
    if (interpolation == Interpolation::Nearest) {
        return resample<T, float>(
            grid, map, plane, kOutside,
            [](const Grid<T>& g, const glm::dvec3& p) { return g.nearest(p); }, stop);
    }
    return resample<T, float>(
        grid, map, plane, kOutside,
        [](const Grid<T>& g, const glm::dvec3& p) { return g.linear(p); }, stop);
}

}  // namespace

Image<float> reslice(const scene::Volume& volume, const SlicePlane& plane,
                     Interpolation interpolation, const std::stop_token& stop) {
    if (volume.empty()) {
        throw InvalidArgumentError("no volume to slice");
    }
    checkPlane(plane);
    const PlaneToIndex map(volume.indexToWorld(), plane);
    if (volume.voxelType() == scene::VoxelType::Int16) {
        return resliceTyped(gridOf(volume.int16Voxels().data(), volume.dims()), map, plane,
                            interpolation, stop);
    }
    return resliceTyped(gridOf(volume.floatVoxels().data(), volume.dims()), map, plane,
                        interpolation, stop);
}

Image<std::uint8_t> resliceLabels(const scene::LabelMap& map, const SlicePlane& plane,
                                  const std::stop_token& stop) {
    const glm::ivec3 d = map.dims;
    if (d.x < 1 || d.y < 1 || d.z < 1 ||
        map.labels.size() != static_cast<std::size_t>(d.x) * static_cast<std::size_t>(d.y) *
                                 static_cast<std::size_t>(d.z)) {
        throw InvalidArgumentError("label map does not match its dimensions");
    }
    checkPlane(plane);
    const PlaneToIndex toIndex(map.indexToWorld, plane);
    const Grid<std::uint8_t> grid = gridOf(map.labels.data(), d);
    return resample<std::uint8_t, std::uint8_t>(
        grid, toIndex, plane, std::uint8_t{0},
        [](const Grid<std::uint8_t>& g, const glm::dvec3& p) {
            return static_cast<std::uint8_t>(g.nearest(p));
        },
        stop);
}

}  // namespace vv::slices
