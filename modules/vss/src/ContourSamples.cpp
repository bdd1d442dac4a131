// SPDX-License-Identifier: GPL-3.0-or-later
#include "ContourSamples.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "vv/core/Parallel.h"

namespace vv::vss::detail {

namespace {

constexpr int kSampleRows = 2 * kContourReach + 1;
constexpr int kBoxRows = 2 * kSampleRadius + 1;
constexpr std::size_t kPad = static_cast<std::size_t>(kSampleRadius) * 2;  // zero columns

}  // namespace

Image<std::uint8_t> nearGaps(ImageView<const float> height, ImageView<const std::uint8_t> vessels) {
    const int w = vessels.width();
    const int h = vessels.height();
    constexpr int reach = kContourReach;
    // Along each row: 1 where a gap lies within `reach` columns.
    Image<std::uint8_t> rows(w, h, UninitialisedPixels{});
    parallelFor(0, h, 64, [&](long b, long e) {
        for (int y = static_cast<int>(b); y < static_cast<int>(e); ++y) {
            const auto gap = [&](int x) { return fittable(height, vessels, x, y) ? 0 : 1; };
            std::uint8_t* out = rows.row(y);
            int count = 0;  // gaps over [x - reach, x + reach]
            for (int x = 0; x < std::min(w, reach); ++x) {
                count += gap(x);
            }
            for (int x = 0; x < w; ++x) {
                if (x + reach < w) {
                    count += gap(x + reach);
                }
                out[x] = count > 0 ? 1 : 0;
                if (x - reach >= 0) {
                    count -= gap(x - reach);
                }
            }
        }
    });
    // Down the columns: per band of rows, a running count per column over
    // rows [y - reach, y + reach].
    Image<std::uint8_t> near(w, h, UninitialisedPixels{});
    parallelFor(0, h, 64, [&](long b, long e) {
        const auto uw = static_cast<std::size_t>(w);
        std::vector<std::int16_t> count(uw, 0);
        const auto add = [&](int r, std::int16_t sign) {
            const std::uint8_t* in = rows.row(r);
            std::int16_t* c = count.data();
            for (std::size_t x = 0; x < uw; ++x) {
                c[x] = static_cast<std::int16_t>(c[x] + sign * in[x]);
            }
        };
        const int y0 = static_cast<int>(b);
        for (int r = std::max(0, y0 - reach); r < std::min(h, y0 + reach); ++r) {
            add(r, 1);
        }
        for (int y = y0; y < static_cast<int>(e); ++y) {
            if (y + reach < h) {
                add(y + reach, 1);
            }
            std::uint8_t* out = near.row(y);
            for (std::size_t x = 0; x < uw; ++x) {
                out[x] = count[x] > 0 ? 1 : 0;
            }
            if (y - reach >= 0) {
                add(y - reach, -1);
            }
        }
    });
    return near;
}

SampleRing::SampleRing(ImageView<const float> height, ImageView<const std::uint8_t> vessels)
    : height_(height),
      vessels_(vessels),
      width_(static_cast<std::size_t>(height.width())),
      box_(static_cast<std::size_t>(kBoxRows) * 3 * width_, 0.0F),
      samples_(static_cast<std::size_t>(kSampleRows) * width_,
               glm::vec3(std::numeric_limits<float>::quiet_NaN())),
      mask_(width_ + kPad, 0.0F),
      maskedHeight_(width_ + kPad, 0.0F) {}

std::size_t SampleRing::boxSlot(int r) {
    return static_cast<std::size_t>(((r % kBoxRows) + kBoxRows) % kBoxRows);
}

std::size_t SampleRing::sampleSlot(int j) {
    return static_cast<std::size_t>(((j % kSampleRows) + kSampleRows) % kSampleRows);
}

const glm::vec3* SampleRing::row(int j) const {
    return samples_.data() + sampleSlot(j) * width_;
}

void SampleRing::loadBoxRow(int r) {
    if (r < 0 || r >= height_.height()) {
        return;  // never read: the column sums skip rows outside the image
    }
    for (std::size_t x = 0; x < width_; ++x) {
        const bool fit = fittable(height_, vessels_, static_cast<int>(x), r);
        mask_[x + kSampleRadius] = fit ? 1.0F : 0.0F;
        maskedHeight_[x + kSampleRadius] = fit ? height_(static_cast<int>(x), r) : 0.0F;
    }
    float* c = box_.data() + boxSlot(r) * 3 * width_;
    float* ox = c + width_;
    float* z = ox + width_;
    const float* m = mask_.data();
    const float* mh = maskedHeight_.data();
    const std::size_t n = width_;
#pragma omp simd
    for (std::size_t x = 0; x < n; ++x) {
        float sc = 0.0F;
        float so = 0.0F;
        float sz = 0.0F;
        for (int k = 0; k <= 2 * kSampleRadius; ++k) {
            const float mk = m[x + static_cast<std::size_t>(k)];
            sc += mk;
            so += mk * static_cast<float>(k - kSampleRadius);
            sz += mh[x + static_cast<std::size_t>(k)];
        }
        c[x] = sc;
        ox[x] = so;
        z[x] = sz;
    }
}

void SampleRing::start(int j0) {
    for (int r = j0 - kSampleRadius; r < j0 + kSampleRadius; ++r) {
        loadBoxRow(r);
    }
}

void SampleRing::advance(int j) {
    loadBoxRow(j + kSampleRadius);
    const int h = height_.height();
    if (j < 0 || j >= h) {
        return;
    }
    // The rows j - kSampleRadius .. j + kSampleRadius inside the image, in
    // that order, summed per column in one pass.
    std::array<const float*, kBoxRows> count{};
    std::array<float, kBoxRows> offsetY{};
    int rows = 0;
    for (int r = std::max(0, j - kSampleRadius); r <= std::min(h - 1, j + kSampleRadius); ++r) {
        count[static_cast<std::size_t>(rows)] = box_.data() + boxSlot(r) * 3 * width_;
        offsetY[static_cast<std::size_t>(rows)] = static_cast<float>(r - j);
        ++rows;
    }
    const float* hr = height_.row(j);
    const std::uint8_t* vr = vessels_.row(j);
    glm::vec3* out = samples_.data() + sampleSlot(j) * width_;
    constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
    for (std::size_t x = 0; x < width_; ++x) {
        float sc = 0.0F;
        float sx = 0.0F;
        float sy = 0.0F;
        float sz = 0.0F;
        for (std::size_t k = 0; k < static_cast<std::size_t>(rows); ++k) {
            const float* c = count[k];
            const float c0 = c[x];
            sc += c0;
            sx += c[width_ + x];
            sy += c0 * offsetY[k];
            sz += c[2 * width_ + x];
        }
        out[x] = vr[x] == 0 && std::isfinite(hr[x]) ? glm::vec3(sx, sy, sz) / sc : glm::vec3(kNaN);
    }
}

}  // namespace vv::vss::detail
