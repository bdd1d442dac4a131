// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/scene/Volume.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <new>

namespace vv::scene {

Volume::Volume(glm::ivec3 dims, VoxelType type) : dims_(dims), type_(type) {
    if (dims.x < 1 || dims.y < 1 || dims.z < 1) {
        throw InvalidArgumentError("volume dimensions must be >= 1, not " + std::to_string(dims.x) +
                                   " x " + std::to_string(dims.y) + " x " + std::to_string(dims.z));
    }
    try {
        if (type == VoxelType::Int16) {
            int16_.assign(voxelCount(), 0);
        } else {
            float_.assign(voxelCount(), 0.0F);
        }
    } catch (const std::bad_alloc&) {
        dims_ = glm::ivec3(0);
        throw MemoryError("not enough memory for a volume of " + std::to_string(dims.x) + " x " +
                          std::to_string(dims.y) + " x " + std::to_string(dims.z) + " voxels");
    }
}

std::uint64_t Volume::byteSize(std::uint64_t x, std::uint64_t y, std::uint64_t z,
                               VoxelType type) noexcept {
    constexpr std::uint64_t kMax = std::numeric_limits<std::uint64_t>::max();
    std::uint64_t n = voxelBytes(type);
    for (const std::uint64_t d : {x, y, z}) {
        if (d != 0 && n > kMax / d) {
            return kMax;
        }
        n *= d;
    }
    return n;
}

void Volume::setValueAt(std::size_t n, float v) noexcept {
    if (type_ == VoxelType::Int16) {
        const float r = std::nearbyint(v);
        int16_[n] = static_cast<std::int16_t>(std::clamp(r, -32768.0F, 32767.0F));
    } else {
        float_[n] = v;
    }
}

std::pair<float, float> Volume::valueRange() const noexcept {
    if (empty()) {
        return {0.0F, 0.0F};
    }
    if (type_ == VoxelType::Int16) {
        const auto [lo, hi] = std::minmax_element(int16_.begin(), int16_.end());
        return {static_cast<float>(*lo), static_cast<float>(*hi)};
    }
    float lo = std::numeric_limits<float>::infinity();
    float hi = -lo;
    for (const float v : float_) {
        if (std::isfinite(v)) {
            lo = std::min(lo, v);
            hi = std::max(hi, v);
        }
    }
    return lo <= hi ? std::pair{lo, hi} : std::pair{0.0F, 0.0F};
}

glm::dmat3 Volume::orientation() const noexcept {
    const glm::dvec3 r = glm::dvec3(indexToWorld_[0]);
    const glm::dvec3 c = glm::dvec3(indexToWorld_[1]);
    const double lr = glm::length(r);
    const double lc = glm::length(c);
    const glm::dvec3 rn = lr > 0 ? r / lr : glm::dvec3(1, 0, 0);
    const glm::dvec3 cn = lc > 0 ? c / lc : glm::dvec3(0, 1, 0);
    glm::dvec3 n = glm::cross(rn, cn);
    const double ln = glm::length(n);
    n = ln > 0 ? n / ln : glm::dvec3(0, 0, 1);
    return {rn, cn, n};
}

glm::dvec3 Volume::spacing() const noexcept {
    const glm::dmat3 o = orientation();
    return {glm::length(glm::dvec3(indexToWorld_[0])), glm::length(glm::dvec3(indexToWorld_[1])),
            std::abs(glm::dot(glm::dvec3(indexToWorld_[2]), o[2]))};
}

bool Volume::sheared() const noexcept {
    const glm::dvec3 step = glm::dvec3(indexToWorld_[2]);
    const double len = glm::length(step);
    if (len <= 0) {
        return false;
    }
    const double along = std::abs(glm::dot(step, orientation()[2]));
    return std::sqrt(std::max(0.0, len * len - along * along)) > 1e-6 * len;
}

Aabb Volume::worldBounds() const noexcept {
    Aabb box;
    if (empty()) {
        return box;
    }
    const glm::dvec3 hi(dims_.x - 1, dims_.y - 1, dims_.z - 1);
    for (int c = 0; c < 8; ++c) {
        const glm::dvec3 ijk((c & 1) != 0 ? hi.x : 0.0, (c & 2) != 0 ? hi.y : 0.0,
                             (c & 4) != 0 ? hi.z : 0.0);
        box.extend(glm::vec3(worldPosition(ijk)));
    }
    return box;
}

}  // namespace vv::scene
