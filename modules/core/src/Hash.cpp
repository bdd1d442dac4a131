// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/core/Hash.h"

#include <array>
#include <cstring>

namespace vv {

namespace {

/// One lane step of bulk(): the word in, the prime's spread, the high half down.
constexpr std::uint64_t mixWord(std::uint64_t lane, std::uint64_t word) noexcept {
    const std::uint64_t h = (lane ^ word) * Hasher::kPrime;
    return h ^ (h >> 32);
}

}  // namespace

Hasher& Hasher::bulk(const void* data, std::size_t size) noexcept {
    const auto* p = static_cast<const unsigned char*>(data);
    constexpr std::size_t kLanes = 4;
    constexpr std::size_t kStride = kLanes * sizeof(std::uint64_t);
    // Independent lanes: the multiplications overlap instead of waiting for
    // each other, as they do in bytes().
    std::array<std::uint64_t, kLanes> lanes = {hash_, hash_ + 1, hash_ + 2, hash_ + 3};
    std::size_t i = 0;
    for (; i + kStride <= size; i += kStride) {
        for (std::size_t k = 0; k < kLanes; ++k) {
            std::uint64_t word = 0;
            std::memcpy(&word, p + i + k * sizeof word, sizeof word);
            lanes[k] = mixWord(lanes[k], word);
        }
    }
    value(lanes);
    value(size);
    return bytes(p + i, size - i);
}

}  // namespace vv
