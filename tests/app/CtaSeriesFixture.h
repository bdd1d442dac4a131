// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// The synthetic CT angiography series the GUI tests of DICOM scenes open.

#include <filesystem>
#include <memory>
#include <system_error>

#include "SyntheticCta.h"
#include "vv/dicom/SeriesWriter.h"

namespace vv::test {

/// A 64 x 64 x 48 synthetic CTA of a 3-generation tree with a bone block
/// beside it, written as a CT series into `dir` (whatever was there is
/// removed first). Throws what writeCtSeries throws.
inline std::unique_ptr<SyntheticCta> writeTestCtaSeries(const std::filesystem::path& dir) {
    std::filesystem::remove_all(dir);
    auto cta = std::make_unique<SyntheticCta>(makeSyntheticCta({64, 64, 48}, 3));
    dicom::writeCtSeries(dir, cta->volume);
    return cta;
}

/// Removes the series folder `dir` and releases `cta`; never throws.
inline void removeTestCtaSeries(const std::filesystem::path& dir,
                                std::unique_ptr<SyntheticCta>& cta) noexcept {
    std::error_code ec;
    std::filesystem::remove_all(dir, ec);
    cta.reset();
}

}  // namespace vv::test
