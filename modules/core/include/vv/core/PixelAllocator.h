// SPDX-License-Identifier: GPL-3.0-or-later
// The allocator of vv::Image's pixels: large buffers on transparent huge pages.
#pragma once

#include <array>
#include <cstddef>
#include <cstdlib>
#include <memory>
#include <mutex>
#include <new>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace vv {

/// A few freed large pixel buffers (the huge-page path of PixelAllocator),
/// kept for the next image of the same rounded size: a solve at 3840x2160
/// allocates its z, vessel and label images anew every time, and each fresh
/// mapping costs the kernel's page clearing and faults on the first touch
/// (issue 19; docs/benchmarks/vss.md, "Fourth step"); so does one at
/// 1280x720, whose 3.7 MB images went to malloc's fresh mappings: 1 800
/// page faults a solve before they were kept here (issue 36). At most
/// kMaxBuffers buffers and kMaxBytes in all; a buffer that does not fit is freed. Thread
/// safe; never destroyed (images with static storage may return buffers at
/// exit). Throws nothing.
class LargeBufferPool {
  public:
    static constexpr std::size_t kMaxBuffers = 16;
    static constexpr std::size_t kMaxBytes = std::size_t{256} << 20U;

    static LargeBufferPool& instance() noexcept {
        // never freed (a few bytes): images with static storage may return buffers at exit
        // NOLINTNEXTLINE(*-owning-memory,*-non-const-global-variables,*-exception-at-new)
        static auto* const pool = new LargeBufferPool();
        return *pool;
    }

    /// A kept buffer of exactly `bytes` bytes (its contents are left over),
    /// or nullptr.
    void* take(std::size_t bytes) noexcept {
        const std::lock_guard<std::mutex> lock(mutex_);
        for (Slot& s : slots_) {
            if (s.p != nullptr && s.bytes == bytes) {
                void* p = s.p;
                s = Slot{};
                held_ -= bytes;
                return p;
            }
        }
        return nullptr;
    }

    /// Keeps p (`bytes` bytes, from std::aligned_alloc), or frees it when the
    /// pool is full. Out of line: GCC's allocation-pairing warning would
    /// otherwise pair this free with the small-buffer path of the allocator.
    [[gnu::noinline]] void release(void* p, std::size_t bytes) noexcept {
        {
            const std::lock_guard<std::mutex> lock(mutex_);
            if (held_ + bytes <= kMaxBytes) {
                for (Slot& s : slots_) {
                    if (s.p == nullptr) {
                        s = Slot{p, bytes};
                        held_ += bytes;
                        return;
                    }
                }
            }
        }
        std::free(p);  // NOLINT(*-no-malloc, *-owning-memory)
    }

    /// Bytes kept now.
    std::size_t heldBytes() noexcept {
        const std::lock_guard<std::mutex> lock(mutex_);
        return held_;
    }

  private:
    struct Slot {
        void* p = nullptr;
        std::size_t bytes = 0;
    };
    LargeBufferPool() = default;
    std::mutex mutex_;
    std::array<Slot, kMaxBuffers> slots_{};
    std::size_t held_ = 0;
};

/// std::allocator for image pixels, except that on Linux buffers of at least
/// kHugeBytes (512 KiB: a 1280x720 mask of bytes and up) are aligned to 2 MiB
/// and marked MADV_HUGEPAGE (the
/// kernel's "madvise" mode of transparent huge pages): the first touch of a
/// 4K image (33 MB of float) then takes ~16 page faults instead of ~8000,
/// which was a large share of a 3840x2160 VSS solve (issue 19; measured in
/// docs/benchmarks/vss.md). The hint changes no values. Freed large buffers go
/// to LargeBufferPool and are handed out again for the same size (a new
/// image's pixels are initialised by Image / std::vector as always). allocate
/// throws std::bad_alloc like std::allocator.
template <typename T>
struct PixelAllocator {
    using value_type = T;

    static constexpr std::size_t kHugePage = std::size_t{2} << 20U;
    static constexpr std::size_t kHugeBytes = std::size_t{512} << 10U;

    PixelAllocator() noexcept = default;
    template <typename U>
    PixelAllocator(const PixelAllocator<U>& /*other*/) noexcept {}  // NOLINT(*-explicit-*)

    [[nodiscard]] T* allocate(std::size_t n) {
        if (n > static_cast<std::size_t>(-1) / sizeof(T)) {
            throw std::bad_alloc();
        }
#if defined(__linux__) && defined(MADV_HUGEPAGE)
        const std::size_t bytes = n * sizeof(T);
        if (bytes >= kHugeBytes) {
            const std::size_t rounded = roundedBytes(bytes);
            if (void* kept = LargeBufferPool::instance().take(rounded)) {
                return static_cast<T*>(kept);
            }
            void* p = std::aligned_alloc(kHugePage, rounded);
            if (p == nullptr) {
                throw std::bad_alloc();
            }
            (void)madvise(p, rounded, MADV_HUGEPAGE);  // a hint: failure changes nothing
            return static_cast<T*>(p);
        }
#endif
        return std::allocator<T>().allocate(n);
    }

    void deallocate(T* p, std::size_t n) noexcept {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
        if (n * sizeof(T) >= kHugeBytes) {
            LargeBufferPool::instance().release(p, roundedBytes(n * sizeof(T)));
            return;
        }
#endif
        std::allocator<T>().deallocate(p, n);
    }

    template <typename U>
    bool operator==(const PixelAllocator<U>& /*other*/) const noexcept {
        return true;
    }

  private:
    static std::size_t roundedBytes(std::size_t bytes) noexcept {
        return (bytes + kHugePage - 1) / kHugePage * kHugePage;
    }
};

}  // namespace vv
