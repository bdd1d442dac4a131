// SPDX-License-Identifier: GPL-3.0-or-later
// The allocator of vv::Image's pixels: large buffers on transparent huge pages.
#pragma once

#include <cstddef>
#include <cstdlib>
#include <memory>
#include <new>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace vv {

/// std::allocator for image pixels, except that on Linux buffers of at least
/// kHugeBytes are aligned to 2 MiB and marked MADV_HUGEPAGE (the
/// kernel's "madvise" mode of transparent huge pages): the first touch of a
/// 4K image (33 MB of float) then takes ~16 page faults instead of ~8000,
/// which was a large share of a 3840x2160 VSS solve (issue 19; measured in
/// docs/benchmarks/vss.md). The hint changes no values. allocate throws
/// std::bad_alloc like std::allocator.
template <typename T>
struct PixelAllocator {
    using value_type = T;

    static constexpr std::size_t kHugePage = std::size_t{2} << 20U;
    static constexpr std::size_t kHugeBytes = std::size_t{4} << 20U;

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
            std::free(p);  // NOLINT(*-no-malloc, *-owning-memory)
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
