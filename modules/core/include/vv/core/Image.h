// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <cassert>
#include <cstddef>
#include <memory>
#include <new>
#include <span>
#include <type_traits>
#include <utility>
#include <vector>

#include "vv/core/Error.h"
#include "vv/core/PixelAllocator.h"

namespace vv {

/// Non-owning view of a W×H image of T with a row stride (in elements, >= width).
/// Views are cheap to copy; they never outlive the storage they point into.
template <typename T>
class ImageView {
  public:
    ImageView() = default;
    ImageView(T* data, int width, int height, std::ptrdiff_t stride)
        : data_(data), width_(width), height_(height), stride_(stride) {
        assert(width >= 0 && height >= 0 && stride >= width);
    }

    [[nodiscard]] int width() const noexcept { return width_; }
    [[nodiscard]] int height() const noexcept { return height_; }
    [[nodiscard]] std::ptrdiff_t stride() const noexcept { return stride_; }
    [[nodiscard]] bool empty() const noexcept { return width_ == 0 || height_ == 0; }
    [[nodiscard]] T* data() const noexcept { return data_; }

    [[nodiscard]] T* row(int y) const noexcept {
        assert(y >= 0 && y < height_);
        return data_ + static_cast<std::ptrdiff_t>(y) * stride_;
    }
    [[nodiscard]] T& operator()(int x, int y) const noexcept {
        assert(x >= 0 && x < width_);
        return row(y)[x];
    }

    /// The sub-rectangle [x, x+w) × [y, y+h). Throws InvalidArgumentError if it
    /// does not lie inside this view.
    [[nodiscard]] ImageView sub(int x, int y, int w, int h) const {
        if (x < 0 || y < 0 || w < 0 || h < 0 || x + w > width_ || y + h > height_) {
            throw InvalidArgumentError("sub-image outside the image");
        }
        return ImageView(data_ + static_cast<std::ptrdiff_t>(y) * stride_ + x, w, h, stride_);
    }

    /// Implicit conversion to a view of const T.
    operator ImageView<const T>() const noexcept {  // NOLINT(google-explicit-constructor)
        return ImageView<const T>(data_, width_, height_, stride_);
    }

  private:
    T* data_ = nullptr;
    int width_ = 0;
    int height_ = 0;
    std::ptrdiff_t stride_ = 0;
};

/// Tag of the Image constructor that leaves the pixels uninitialised.
struct UninitialisedPixels {};

namespace image_storage {

/// PixelAllocator (huge pages for large images) whose value-initialisation
/// (resize without a value) is a default-initialisation: plain pixels stay unwritten, so a large
/// image's pages are first touched by whoever writes them (in parallel), not by a serial fill.
template <typename T>
struct DefaultInitAllocator : PixelAllocator<T> {
    template <typename U>
    // NOLINTNEXTLINE(readability-identifier-naming): the name allocator_traits needs
    struct rebind {
        using other = DefaultInitAllocator<U>;
    };
    DefaultInitAllocator() = default;
    template <typename U>
    DefaultInitAllocator(const DefaultInitAllocator<U>& /*other*/) noexcept {}  // NOLINT
    template <typename U>
    void construct(U* p) noexcept(std::is_nothrow_default_constructible_v<U>) {
        ::new (static_cast<void*>(p)) U;
    }
    template <typename U, typename... Args>
    void construct(U* p, Args&&... args) {
        ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
    }
};

}  // namespace image_storage

/// Owning W×H image of T, rows contiguous with a stride of exactly `width`
/// unless a larger stride is asked for (e.g. for alignment).
template <typename T>
class Image {
  public:
    Image() = default;
    /// Throws InvalidArgumentError for negative sizes or stride < width.
    Image(int width, int height, T fill = T{}, std::ptrdiff_t stride = -1)
        : width_(width), height_(height), stride_(stride < 0 ? width : stride) {
        if (width < 0 || height < 0 || stride_ < width) {
            throw InvalidArgumentError("image size must be non-negative and stride >= width");
        }
        pixels_.assign(static_cast<std::size_t>(stride_) * static_cast<std::size_t>(height), fill);
    }
    /// A width x height image whose pixels are unspecified until written
    /// (for a plain T: every pixel must be written before it is read). For
    /// large images that a parallel loop fills completely anyway. Throws
    /// InvalidArgumentError for negative sizes.
    Image(int width, int height, UninitialisedPixels /*tag*/)
        : width_(width), height_(height), stride_(width) {
        if (width < 0 || height < 0) {
            throw InvalidArgumentError("image size must be non-negative");
        }
        pixels_.resize(static_cast<std::size_t>(width) * static_cast<std::size_t>(height));
    }

    [[nodiscard]] int width() const noexcept { return width_; }
    [[nodiscard]] int height() const noexcept { return height_; }
    [[nodiscard]] std::ptrdiff_t stride() const noexcept { return stride_; }
    [[nodiscard]] bool empty() const noexcept { return width_ == 0 || height_ == 0; }
    [[nodiscard]] std::size_t pixelCount() const noexcept {
        return static_cast<std::size_t>(width_) * static_cast<std::size_t>(height_);
    }

    [[nodiscard]] T* row(int y) noexcept { return view().row(y); }
    [[nodiscard]] const T* row(int y) const noexcept { return view().row(y); }
    [[nodiscard]] T& operator()(int x, int y) noexcept { return view()(x, y); }
    [[nodiscard]] const T& operator()(int x, int y) const noexcept { return view()(x, y); }
    [[nodiscard]] T* data() noexcept { return pixels_.data(); }
    [[nodiscard]] const T* data() const noexcept { return pixels_.data(); }

    [[nodiscard]] ImageView<T> view() noexcept {
        return ImageView<T>(pixels_.data(), width_, height_, stride_);
    }
    [[nodiscard]] ImageView<const T> view() const noexcept {
        return ImageView<const T>(pixels_.data(), width_, height_, stride_);
    }

    /// Sets every pixel (padding included) to `value`.
    void fill(const T& value) { std::fill(pixels_.begin(), pixels_.end(), value); }

  private:
    int width_ = 0;
    int height_ = 0;
    std::ptrdiff_t stride_ = 0;
    std::vector<T, image_storage::DefaultInitAllocator<T>> pixels_;
};

}  // namespace vv
