// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/slices/WindowLevel.h"

#include <algorithm>
#include <cmath>

#include "vv/core/Error.h"
#include "vv/core/Parallel.h"

namespace vv::slices {

namespace {

constexpr double kMinWidth = 1e-6;
constexpr std::size_t kHistogramSamples = 1U << 20U;
constexpr int kHistogramBins = 4096;

bool isCt(const scene::Volume& volume) {
    return volume.modality() == "CT" || volume.unit() == "HU";
}

Window windowBetween(double lo, double hi, double span) {
    const double width = std::max({hi - lo, 1e-3 * span, kMinWidth});
    return {0.5 * (lo + hi), width};
}

// Percentiles of the values of `volume` from a histogram of at most about
// kHistogramSamples voxels taken at a fixed stride.
class ValueHistogram {
  public:
    /// `lo`, `hi`: the volume's value range.
    ValueHistogram(const scene::Volume& volume, double lo, double hi) : lo_(lo), hi_(hi) {
        const std::size_t n = volume.voxelCount();
        const std::size_t stride = std::max<std::size_t>(1, n / kHistogramSamples);
        const double scale = hi_ > lo_ ? kHistogramBins / (hi_ - lo_) : 0.0;
        for (std::size_t i = 0; i < n; i += stride) {
            const float v = volume.valueAt(i);
            if (std::isfinite(v)) {
                const int bin =
                    std::clamp(static_cast<int>((v - lo_) * scale), 0, kHistogramBins - 1);
                ++bins_[static_cast<std::size_t>(bin)];
                ++total_;
            }
        }
    }
    [[nodiscard]] double lo() const noexcept { return lo_; }
    [[nodiscard]] double hi() const noexcept { return hi_; }
    /// The value below which `fraction` of the samples lie (bin centre).
    [[nodiscard]] double percentile(double fraction) const noexcept {
        const auto target = static_cast<std::size_t>(fraction * static_cast<double>(total_));
        std::size_t seen = 0;
        for (int b = 0; b < kHistogramBins; ++b) {
            seen += bins_[static_cast<std::size_t>(b)];
            if (seen > target) {
                return lo_ + (b + 0.5) * (hi_ - lo_) / kHistogramBins;
            }
        }
        return hi_;
    }

  private:
    double lo_ = 0.0;
    double hi_ = 0.0;
    std::vector<std::size_t> bins_ = std::vector<std::size_t>(kHistogramBins, 0);
    std::size_t total_ = 0;
};

}  // namespace

std::uint8_t windowGray(float value, const Window& window) noexcept {
    if (std::isnan(value)) {
        return 0;
    }
    const double width = std::max(window.width, kMinWidth);
    const double t = (static_cast<double>(value) - (window.center - 0.5 * width)) / width;
    return static_cast<std::uint8_t>(std::lround(std::clamp(t, 0.0, 1.0) * 255.0));
}

Image<std::uint8_t> applyWindow(ImageView<const float> values, const Window& window) {
    Image<std::uint8_t> out(values.width(), values.height(), UninitialisedPixels{});
    const double width = std::max(window.width, kMinWidth);
    const auto lo = static_cast<float>(window.center - 0.5 * width);
    const auto scale = static_cast<float>(255.0 / width);
    parallelFor(0, values.height(), 16, [&](long r0, long r1) {
        for (long r = r0; r < r1; ++r) {
            const float* in = values.row(static_cast<int>(r));
            std::uint8_t* o = out.row(static_cast<int>(r));
            for (int c = 0; c < values.width(); ++c) {
                const float v = in[c];
                // NaN fails both comparisons of clamp's branches: map it to 0 first.
                const float t = std::isnan(v) ? 0.0F : std::clamp((v - lo) * scale, 0.0F, 255.0F);
                // t >= 0: truncating t + 0.5 rounds (std::lrint is a library call).
                o[c] = static_cast<std::uint8_t>(t + 0.5F);  // NOLINT(bugprone-incorrect-roundings)
            }
        }
    });
    return out;
}

std::string_view presetKey(WindowPreset preset) noexcept {
    switch (preset) {
        case WindowPreset::Cta:
            return "cta";
        case WindowPreset::Mra:
            return "mra";
        case WindowPreset::SoftTissue:
            return "soft-tissue";
        case WindowPreset::Bone:
            return "bone";
        case WindowPreset::FullRange:
            break;
    }
    return "full-range";
}

std::vector<PresetWindow> windowPresets(const scene::Volume& volume) {
    if (volume.empty()) {
        throw InvalidArgumentError("no volume for window presets");
    }
    const auto [lo, hi] = volume.valueRange();
    const double span = static_cast<double>(hi) - static_cast<double>(lo);
    const PresetWindow full{WindowPreset::FullRange, windowBetween(lo, hi, span)};
    if (isCt(volume)) {
        return {{WindowPreset::Cta, {300.0, 600.0}},
                {WindowPreset::SoftTissue, {40.0, 400.0}},
                {WindowPreset::Bone, {400.0, 1800.0}},
                full};
    }
    const ValueHistogram histogram(volume, lo, hi);
    return {{WindowPreset::Mra,
             windowBetween(histogram.percentile(0.5), histogram.percentile(0.999), span)},
            {WindowPreset::SoftTissue,
             windowBetween(histogram.percentile(0.01), histogram.percentile(0.99), span)},
            full};
}

Window dragWindow(const Window& start, double dx, double dy, double valueSpan) noexcept {
    const double span = std::max(valueSpan, kMinWidth);
    const double width = std::max(start.width + dx * span / 500.0, span / 1000.0);
    return {start.center + dy * span / 1000.0, width};
}

}  // namespace vv::slices
