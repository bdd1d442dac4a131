// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QImage>
#include <string>

namespace vv::test {

/// Result of compareImages().
struct ImageComparison {
    /// False when the images cannot be compared (size mismatch, null image);
    /// `message` says why and `difference` is +Inf.
    bool comparable = false;
    /// The SSIM-like difference: 0 = identical, larger = more different (at most 2).
    double difference = 0.0;
    /// The three parts it is made of: 1 - mean SSIM of luma Y and of the
    /// chroma channels Cb and Cr.
    double lumaDifference = 0.0;
    double blueChromaDifference = 0.0;
    double redChromaDifference = 0.0;
    /// One line for a person: the difference and its parts, or why not comparable.
    std::string message;
};

/// Side of the square SSIM windows, in pixels.
inline constexpr int kSsimWindow = 8;
/// Distance between the starts of neighbouring windows (they overlap by half).
inline constexpr int kSsimStride = 4;

/// Compares `candidate` with `baseline` by an SSIM-like metric (Wang et al.
/// 2004, "Image quality assessment: from error visibility to structural
/// similarity"), the way f3d's image tests do:
///
///  - Both images are converted to BT.709 Y'CbCr from their 8-bit sRGB
///    values scaled to [0, 1] (Cb and Cr offset by 0.5); alpha is ignored.
///  - Per channel, SSIM is computed over 8x8 windows placed every 4 pixels
///    (the last row / column of windows aligned with the image's edge; an
///    image smaller than 8 in one direction uses its whole size there), with
///    the usual constants C1 = (0.01)^2, C2 = (0.03)^2 for a value range of 1,
///    and averaged over the windows with equal weights.
///  - The difference of a channel is 1 - mean SSIM; the reported
///    `difference` is the largest of the three, so a change of hue at the
///    same brightness (e.g. one depth colour scale for another) counts too.
///
/// Scale (measured: tests/support/ImageCompareTest.cpp on tests/baselines/
/// scale-cd.png, a 320x240 render of the demo tree with the VSS; more in
/// tests/baselines/README.md):
///  - 0: identical. llvmpipe gives bit-identical renders run after run.
///  - 0.004 / 0.012 / 0.039: uniform noise of +-1 / +-2 / +-4 grey levels
///    per channel (invisible / invisible / indistinguishable at a glance).
///  - ~0.1: a small visible difference: noise +-8 (0.13), the image shifted
///    by 1 pixel (0.10), iso-lines off instead of 8 (0.11).
///  - 0.2 and more: clearly different: shifted by 3 pixels (0.24), p = 2.5
///    instead of 2 (0.20), dark-means-deep instead of chromadepth (0.29),
///    red and blue swapped (0.23).
/// Sparse images (thin vessels on a flat background) dilute changes: the fog
/// cue against none is only 0.025 there, so such tests need low thresholds.
///
/// Images of different sizes (or null images) are not comparable: the
/// result says so and its difference is +Inf. Never throws.
[[nodiscard]] ImageComparison compareImages(const QImage& candidate, const QImage& baseline);

/// A picture of where two images of the same size differ: per pixel the
/// largest absolute channel difference, amplified 4 times, as grey on black.
/// A null image when the sizes differ.
[[nodiscard]] QImage differenceImage(const QImage& candidate, const QImage& baseline);

}  // namespace vv::test
