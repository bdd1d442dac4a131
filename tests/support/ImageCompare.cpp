// SPDX-License-Identifier: GPL-3.0-or-later
#include "ImageCompare.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <vector>

namespace vv::test {

namespace {

/// One channel of an image as doubles in [0, 1], row-major.
struct Plane {
    int width = 0;
    int height = 0;
    std::vector<double> values;
    [[nodiscard]] double at(int x, int y) const noexcept {
        return values[static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
                      static_cast<std::size_t>(x)];
    }
};

/// Y', Cb + 0.5, Cr + 0.5 (BT.709) of the sRGB-encoded pixels.
std::array<Plane, 3> toYCbCr(const QImage& image) {
    const QImage rgb = image.convertToFormat(QImage::Format_RGB32);
    std::array<Plane, 3> planes;
    for (Plane& p : planes) {
        p.width = rgb.width();
        p.height = rgb.height();
        p.values.resize(static_cast<std::size_t>(rgb.width()) *
                        static_cast<std::size_t>(rgb.height()));
    }
    std::size_t i = 0;
    for (int y = 0; y < rgb.height(); ++y) {
        const auto* line = reinterpret_cast<const QRgb*>(rgb.constScanLine(y));
        for (int x = 0; x < rgb.width(); ++x, ++i) {
            const double r = qRed(line[x]) / 255.0;
            const double g = qGreen(line[x]) / 255.0;
            const double b = qBlue(line[x]) / 255.0;
            const double luma = 0.2126 * r + 0.7152 * g + 0.0722 * b;
            planes[0].values[i] = luma;
            planes[1].values[i] = 0.5 + (b - luma) / 1.8556;
            planes[2].values[i] = 0.5 + (r - luma) / 1.5748;
        }
    }
    return planes;
}

/// Start positions of windows of `window` pixels every `stride` along `size`,
/// the last one flush with the end.
std::vector<int> windowStarts(int size, int window, int stride) {
    std::vector<int> starts;
    if (size <= window) {
        starts.push_back(0);
        return starts;
    }
    for (int s = 0; s + window <= size; s += stride) {
        starts.push_back(s);
    }
    if (starts.back() + window < size) {
        starts.push_back(size - window);
    }
    return starts;
}

/// Mean SSIM of two planes of the same size.
double meanSsim(const Plane& a, const Plane& b) {
    constexpr double kC1 = 0.01 * 0.01;
    constexpr double kC2 = 0.03 * 0.03;
    const int wx = std::min(kSsimWindow, a.width);
    const int wy = std::min(kSsimWindow, a.height);
    const std::vector<int> xs = windowStarts(a.width, wx, kSsimStride);
    const std::vector<int> ys = windowStarts(a.height, wy, kSsimStride);
    const double n = static_cast<double>(wx) * static_cast<double>(wy);
    double sum = 0.0;
    for (const int y0 : ys) {
        for (const int x0 : xs) {
            double sa = 0.0;
            double sb = 0.0;
            double saa = 0.0;
            double sbb = 0.0;
            double sab = 0.0;
            for (int y = y0; y < y0 + wy; ++y) {
                for (int x = x0; x < x0 + wx; ++x) {
                    const double va = a.at(x, y);
                    const double vb = b.at(x, y);
                    sa += va;
                    sb += vb;
                    saa += va * va;
                    sbb += vb * vb;
                    sab += va * vb;
                }
            }
            const double ma = sa / n;
            const double mb = sb / n;
            const double varA = std::max(0.0, saa / n - ma * ma);
            const double varB = std::max(0.0, sbb / n - mb * mb);
            const double cov = sab / n - ma * mb;
            sum += ((2.0 * ma * mb + kC1) * (2.0 * cov + kC2)) /
                   ((ma * ma + mb * mb + kC1) * (varA + varB + kC2));
        }
    }
    return sum / static_cast<double>(xs.size() * ys.size());
}

std::string describeSize(const QImage& image) {
    if (image.isNull()) {
        return "no image";
    }
    return std::to_string(image.width()) + "x" + std::to_string(image.height());
}

}  // namespace

ImageComparison compareImages(const QImage& candidate, const QImage& baseline) {
    ImageComparison result;
    if (candidate.isNull() || baseline.isNull() || candidate.size() != baseline.size()) {
        result.difference = std::numeric_limits<double>::infinity();
        result.message = "images differ in size: candidate " + describeSize(candidate) +
                         ", baseline " + describeSize(baseline);
        return result;
    }
    const auto a = toYCbCr(candidate);
    const auto b = toYCbCr(baseline);
    result.comparable = true;
    result.lumaDifference = std::max(0.0, 1.0 - meanSsim(a[0], b[0]));
    result.blueChromaDifference = std::max(0.0, 1.0 - meanSsim(a[1], b[1]));
    result.redChromaDifference = std::max(0.0, 1.0 - meanSsim(a[2], b[2]));
    result.difference =
        std::max({result.lumaDifference, result.blueChromaDifference, result.redChromaDifference});
    char buffer[160];
    std::snprintf(buffer, sizeof buffer, "difference %.4f (1 - SSIM: Y %.4f, Cb %.4f, Cr %.4f)",
                  result.difference, result.lumaDifference, result.blueChromaDifference,
                  result.redChromaDifference);
    result.message = buffer;
    return result;
}

QImage differenceImage(const QImage& candidate, const QImage& baseline) {
    if (candidate.isNull() || candidate.size() != baseline.size()) {
        return {};
    }
    const QImage a = candidate.convertToFormat(QImage::Format_RGB32);
    const QImage b = baseline.convertToFormat(QImage::Format_RGB32);
    QImage out(a.size(), QImage::Format_RGB32);
    for (int y = 0; y < a.height(); ++y) {
        const auto* la = reinterpret_cast<const QRgb*>(a.constScanLine(y));
        const auto* lb = reinterpret_cast<const QRgb*>(b.constScanLine(y));
        auto* lo = reinterpret_cast<QRgb*>(out.scanLine(y));
        for (int x = 0; x < a.width(); ++x) {
            const int d = std::max({std::abs(qRed(la[x]) - qRed(lb[x])),
                                    std::abs(qGreen(la[x]) - qGreen(lb[x])),
                                    std::abs(qBlue(la[x]) - qBlue(lb[x]))});
            const int v = std::min(255, 4 * d);
            lo[x] = qRgb(v, v, v);
        }
    }
    return out;
}

}  // namespace vv::test
