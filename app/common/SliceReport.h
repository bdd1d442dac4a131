// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// A slice of a volume as the slice views show it and as a report prints it:
// the grey values in a window with the segmentation overlaid, its orientation
// letters, and the caption a radiologist reads under it. Shared by the GUI's
// slice views (Export Report, Send to PACS) and `vesselview-cli report
// --slice`, so that both print the same page.

#include <QImage>
#include <QString>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "vv/core/Image.h"
#include "vv/scene/LabelMap.h"
#include "vv/scene/Volume.h"
#include "vv/slices/SliceOverlay.h"
#include "vv/slices/SlicePlane.h"
#include "vv/slices/WindowLevel.h"

class QPainter;
class QRectF;

namespace vv::app {

/// The grey values of `values` in `window` with `labels` overlaid in `style`
/// (slices::composeSlice; no overlay when `labels` is empty): one pixel per
/// sample, Format_RGB32.
[[nodiscard]] QImage sliceImage(ImageView<const float> values, ImageView<const std::uint8_t> labels,
                                const slices::Window& window, const slices::OverlayStyle& style);

/// Text with a dark outline, readable on any grey (the slice views' texts).
void drawShadowedText(QPainter& painter, const QRectF& rect, int flags, const QString& text);

/// The orientation letters of `plane` (slices::edgeLetters) at the middle of
/// each edge of `area`, in the painter's font.
void drawEdgeLetters(QPainter& painter, const QRectF& area, const slices::SlicePlane& plane);

/// The width of a printed slice, pixels: wider than a report's content at
/// 300 dpi on A4 and Letter, so that it is printed at least at that resolution.
inline constexpr int kPrintedSliceWidth = 2400;

/// `slice` (sliceImage() of `plane`) scaled to `width` pixels wide at its
/// aspect, without smoothing (voxels stay sharp), with its orientation
/// letters on its edges: the slice in a report. Null for a null `slice` or
/// width < 1.
[[nodiscard]] QImage slicePrintImage(const QImage& slice, const slices::SlicePlane& plane,
                                     int width);

/// What the caption under a printed slice says.
struct SliceFacts {
    slices::SliceOrientation orientation = slices::SliceOrientation::Axial;
    int axis = 2;           ///< world axis of the slice position (SliceStack::axis)
    double position = 0.0;  ///< slice position, mm along that axis (LPS)
    slices::Window window;
    /// The preset the window is (nullopt: chosen by hand).
    std::optional<slices::WindowPreset> preset;
    std::string unit;  ///< of the values, e.g. "HU"; empty when unknown
    /// The segmentation drawn over the slice (nullopt: none shown).
    std::optional<slices::OverlayStyle> overlay;
};

/// The caption of a printed slice, in the UI language and locale: plane,
/// position along its normal, window / level with the preset's name, and
/// what the colours are: "Axial slice at S 12.5 mm, window W 600 HU  L 300 HU
/// (CTA preset). Coloured fill and outline: the segmentation."
[[nodiscard]] QString sliceCaption(const SliceFacts& facts);

/// A slice for a report: its print image and caption.
struct PrintedSlice {
    QImage image;
    QString caption;
};

/// How a printed slice looks when not as the slice views open: a window
/// (with the preset it is, if any) and the overlay style, e.g. a session's.
struct SliceLook {
    slices::Window window;
    std::optional<slices::WindowPreset> preset;
    slices::OverlayStyle overlay;
};

/// The slice of `volume` in `orientation` at `position` (mm along the
/// plane's world axis, LPS; the nearest slice; nullopt: the middle one, as
/// the slice views open), `labelMap` (may be null) overlaid: as the GUI's
/// slice view shows it, printed `width` pixels wide. `look` nullopt: the
/// volume's default window preset (slices::windowPresets), fill and outline.
/// Throws InvalidArgumentError when `position` lies outside the volume's
/// slices (naming the range) or the volume has no slices
/// (slices::sliceStack), and what slices::reslice throws.
[[nodiscard]] PrintedSlice printedSlice(const scene::Volume& volume,
                                        const scene::LabelMap* labelMap,
                                        slices::SliceOrientation orientation,
                                        std::optional<double> position,
                                        const std::optional<SliceLook>& look = std::nullopt,
                                        int width = kPrintedSliceWidth);

/// "axial", "coronal", "sagittal" (ASCII case-insensitive); nullopt otherwise.
[[nodiscard]] std::optional<slices::SliceOrientation> sliceOrientationFromName(
    std::string_view name) noexcept;

}  // namespace vv::app
