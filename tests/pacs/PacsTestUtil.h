// SPDX-License-Identifier: GPL-3.0-or-later
// Shared by the networking tests: the synthetic CTA series written as DICOM
// files, a folder's files in order, a port that accepts connections and never
// answers, and a Progress that acts once at the first report.
#pragma once

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "SyntheticCta.h"
#include "WaitUntil.h"
#include "vv/core/Progress.h"
#include "vv/dicom/SeriesWriter.h"

namespace vv::test {

/// The files of `folder`, sorted by name.
inline std::vector<std::filesystem::path> filesOf(const std::filesystem::path& folder) {
    std::vector<std::filesystem::path> files;
    for (const auto& e : std::filesystem::directory_iterator(folder)) {
        files.push_back(e.path());
    }
    std::sort(files.begin(), files.end());
    return files;
}

/// A synthetic CTA of `size` x `size` x `slices` voxels (slices at least 8)
/// written as a CT series of patient `patientId` into `folder` (emptied
/// first); returns its files.
inline std::vector<std::filesystem::path> writeCtaFiles(const std::filesystem::path& folder,
                                                        const std::string& patientId, int slices,
                                                        int size = 16) {
    std::filesystem::remove_all(folder);
    const auto cta = makeSyntheticCta({size, size, slices}, 2, 0.0, 0.0);
    dicom::CtSeriesWriteOptions options;
    options.patientId = patientId;
    dicom::writeCtSeries(folder, cta.volume, options);
    return filesOf(folder);
}

/// pollUntil() with a bound (for a broken program, never a timing claim).
inline bool waitUntil(const std::function<bool()>& done,
                      std::chrono::milliseconds bound = std::chrono::seconds(30)) {
    return pollUntil(done, bound);
}

/// A Progress that calls `action` once, at the first report (`*done` tells
/// whether it happened; it must outlive the Progress).
inline Progress atFirstReport(bool* done, std::function<void()> action) {
    return Progress(
        [done, action = std::move(action)](double, std::string_view) {
            if (!*done) {
                *done = true;
                action();
            }
        },
        {});
}

}  // namespace vv::test
