// SPDX-License-Identifier: GPL-3.0-or-later
// Internal: decoding one DICOM file's pixel data (native, RLE, JPEG, JPEG-LS)
// into rescaled frames, with DCMTK. No DCMTK type leaks out of this header.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "DicomHeader.h"

namespace vv::dicom::detail {

/// Reads frames of one file's pixel data as rescaled values. Keeps the file
/// open between calls (frames of one file are read in any order).
class FrameReader {
  public:
    FrameReader();
    ~FrameReader();
    FrameReader(const FrameReader&) = delete;
    FrameReader& operator=(const FrameReader&) = delete;
    FrameReader(FrameReader&& other) noexcept;
    FrameReader& operator=(FrameReader&& other) noexcept;

    /// Decodes frame `frame` of `header.file` into `out` (rows * columns
    /// values, row by row) as stored * slope + intercept. Throws FormatError
    /// (cannot decode, truncated) or IoError naming the file.
    void read(const FileHeader& header, std::uint64_t frame, double slope, double intercept,
              std::vector<float>& out);

  private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace vv::dicom::detail
