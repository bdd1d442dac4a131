// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <filesystem>

#include "vv/core/Image.h"

namespace vv::vss {

/// Largest accepted PFM side and pixel count: checked before anything is allocated.
inline constexpr int kPfmMaxSide = 32768;
inline constexpr long long kPfmMaxPixels = 1LL << 28;

/// Reads a grayscale Portable Float Map ("Pf"): the header "Pf", width,
/// height and scale as ASCII tokens separated by whitespace, then exactly one
/// whitespace character, then width * height 32-bit floats, rows from the
/// bottom of the image to its top. A negative scale means little-endian data,
/// a positive one big-endian; the magnitude of the scale is ignored (values
/// are returned as stored). Values may be NaN or ±Inf.
/// Row 0 of the returned image is the top row.
/// Strict: trailing bytes after the pixel data are refused (they mean the
/// header does not describe the file).
/// Throws IoError (naming the file) when it cannot be opened or read, and
/// FormatError (naming the file) for a wrong magic (colour "PF" included),
/// a non-numeric, negative or zero size, a side above kPfmMaxSide or more than
/// kPfmMaxPixels pixels, a zero / non-finite / non-numeric scale, truncated
/// data or trailing bytes.
[[nodiscard]] Image<float> readPfm(const std::filesystem::path& file);

/// Writes `image` as a little-endian grayscale PFM (scale -1), rows bottom to
/// top, atomically (writeAtomically: readers never see a partial file).
/// Throws InvalidArgumentError for an empty image, IoError (naming the file)
/// when it cannot be written.
void writePfm(const std::filesystem::path& file, ImageView<const float> image);

}  // namespace vv::vss
