// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <cstddef>
#include <cstdint>
#include <string_view>
#include <type_traits>

namespace vv {

/// A 64-bit hash fed piece by piece, for cache keys and content fingerprints
/// (not for security: collisions can be constructed): FNV-1a over the bytes
/// of small pieces (bytes(), value(), text()), and bulk() for large buffers.
/// The same pieces in the same order give the same result on every run of
/// one build; values hash by their object representation, so only types
/// without padding (integers, floats, glm vectors and matrices) give
/// well-defined keys.
class Hasher {
  public:
    static constexpr std::uint64_t kOffsetBasis = 14695981039346656037ULL;
    static constexpr std::uint64_t kPrime = 1099511628211ULL;

    /// Feeds `size` bytes from `data` (nullptr allowed when size is 0).
    constexpr Hasher& bytes(const void* data, std::size_t size) noexcept {
        const auto* p = static_cast<const unsigned char*>(data);
        for (std::size_t i = 0; i < size; ++i) {
            hash_ = (hash_ ^ p[i]) * kPrime;
        }
        return *this;
    }
    /// Feeds the bytes of a trivially copyable value.
    template <class T>
    Hasher& value(const T& v) noexcept {
        static_assert(std::is_trivially_copyable_v<T>, "hash the bytes of plain values only");
        return bytes(&v, sizeof v);
    }
    /// Feeds the characters of `text` (not its length: feed that first where
    /// two strings in a row must not run together).
    Hasher& text(std::string_view text) noexcept { return bytes(text.data(), text.size()); }
    /// Feeds a large buffer (vertex arrays, images) at about memory speed:
    /// its 8-byte words through four interleaved FNV-style lanes (each word
    /// xor-ed in and multiplied by the prime, the high half folded down),
    /// then the lanes, the size and the tail bytes as by bytes(). A different
    /// function from bytes(): a buffer fed by bulk() must always be fed by it.
    Hasher& bulk(const void* data, std::size_t size) noexcept;
    /// The hash of everything fed so far.
    [[nodiscard]] constexpr std::uint64_t result() const noexcept { return hash_; }

  private:
    std::uint64_t hash_ = kOffsetBasis;
};

}  // namespace vv
