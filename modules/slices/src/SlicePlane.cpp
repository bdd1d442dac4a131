// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/slices/SlicePlane.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "vv/core/Error.h"

namespace vv::slices {

namespace {

constexpr int kMaxPlaneSide = 16384;

// The eight corner voxel centres of `volume` in world coordinates.
std::array<glm::dvec3, 8> cornerCentres(const scene::Volume& volume) {
    const glm::dvec3 last = glm::dvec3(volume.dims() - 1);
    std::array<glm::dvec3, 8> corners{};
    for (int n = 0; n < 8; ++n) {
        const glm::dvec3 ijk((n & 1) != 0 ? last.x : 0.0, (n & 2) != 0 ? last.y : 0.0,
                             (n & 4) != 0 ? last.z : 0.0);
        corners[static_cast<std::size_t>(n)] = volume.worldPosition(ijk);
    }
    return corners;
}

// Smallest and largest projection of the corners onto `direction`.
std::pair<double, double> projectedRange(const std::array<glm::dvec3, 8>& corners,
                                         const glm::dvec3& direction) {
    double lo = std::numeric_limits<double>::max();
    double hi = std::numeric_limits<double>::lowest();
    for (const glm::dvec3& c : corners) {
        const double p = glm::dot(c, direction);
        lo = std::min(lo, p);
        hi = std::max(hi, p);
    }
    return {lo, hi};
}

// Samples at `spacing` needed to cover [lo, hi] (voxel centres at both ends
// when the extent is a multiple of the spacing).
int samplesOver(double lo, double hi, double spacing) {
    const double n = std::floor((hi - lo) / spacing + 1e-6) + 1.0;
    if (!(n <= kMaxPlaneSide)) {
        throw InvalidArgumentError("slice plane of more than 16384 pixels along a side");
    }
    return static_cast<int>(n);
}

}  // namespace

int SliceStack::nearestIndex(double mm) const noexcept {
    const double t = std::round((mm - first) / step);
    if (!(t > 0.0)) {
        return 0;
    }
    return t >= count - 1 ? count - 1 : static_cast<int>(t);
}

SlicePlane SliceStack::planeAt(int index) const noexcept {
    SlicePlane p = plane;
    const int k = std::clamp(index, 0, count - 1);
    p.origin[axis] = position(k);
    return p;
}

int sliceAxis(SliceOrientation orientation) noexcept {
    switch (orientation) {
        case SliceOrientation::Sagittal:
            return 0;
        case SliceOrientation::Coronal:
            return 1;
        case SliceOrientation::Axial:
            break;
    }
    return 2;
}

glm::dvec3 sliceRight(SliceOrientation orientation) noexcept {
    // Axial and coronal: patient left (+x) to the right; sagittal: posterior (+y).
    return orientation == SliceOrientation::Sagittal ? glm::dvec3(0.0, 1.0, 0.0)
                                                     : glm::dvec3(1.0, 0.0, 0.0);
}

glm::dvec3 sliceDown(SliceOrientation orientation) noexcept {
    // Axial: posterior (+y) down; coronal and sagittal: inferior (-z) down.
    return orientation == SliceOrientation::Axial ? glm::dvec3(0.0, 1.0, 0.0)
                                                  : glm::dvec3(0.0, 0.0, -1.0);
}

double samplingDistance(const scene::Volume& volume, const glm::dvec3& direction) {
    const glm::dmat3 toIndex = glm::inverse(glm::dmat3(volume.indexToWorld()));
    const glm::dvec3 perMm = glm::abs(toIndex * direction);
    const double m = std::max({perMm.x, perMm.y, perMm.z});
    if (!std::isfinite(m) || m <= 0.0) {
        throw InvalidArgumentError("volume geometry is singular or not finite");
    }
    return 1.0 / m;
}

SliceStack sliceStack(const scene::Volume& volume, SliceOrientation orientation) {
    if (volume.empty()) {
        throw InvalidArgumentError("no volume to slice");
    }
    const double det = glm::determinant(glm::dmat3(volume.indexToWorld()));
    if (!std::isfinite(det) || std::abs(det) < 1e-12) {
        throw InvalidArgumentError("volume geometry is singular or not finite");
    }
    SliceStack stack;
    stack.orientation = orientation;
    stack.axis = sliceAxis(orientation);
    glm::dvec3 axisDir(0.0);
    axisDir[stack.axis] = 1.0;
    const glm::dvec3 right = sliceRight(orientation);
    const glm::dvec3 down = sliceDown(orientation);

    const auto corners = cornerCentres(volume);
    const double pixel = std::min(samplingDistance(volume, right), samplingDistance(volume, down));
    const auto [rLo, rHi] = projectedRange(corners, right);
    const auto [dLo, dHi] = projectedRange(corners, down);
    const auto [aLo, aHi] = projectedRange(corners, axisDir);

    stack.step = samplingDistance(volume, axisDir);
    stack.first = aLo;
    stack.count = samplesOver(aLo, aHi, stack.step);
    stack.plane.right = right;
    stack.plane.down = down;
    stack.plane.pixelSpacing = pixel;
    stack.plane.width = samplesOver(rLo, rHi, pixel);
    stack.plane.height = samplesOver(dLo, dHi, pixel);
    stack.plane.origin = rLo * right + dLo * down + aLo * axisDir;
    return stack;
}

}  // namespace vv::slices
