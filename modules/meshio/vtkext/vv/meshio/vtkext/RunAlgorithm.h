// SPDX-License-Identifier: GPL-3.0-or-later
// vv::meshio's VTK extension (vtkext: for meshio, demo and segmentation only): running a VTK reader
// or filter with the loader's progress, cancellation and error reporting.
#pragma once

#include <filesystem>
#include <string>

#include "vv/core/Progress.h"

class vtkAlgorithm;

namespace vv::meshio::detail {

/// Runs `algorithm` (a reader or filter) with progress, cancellation and VTK
/// messages captured; throws FormatError naming `file` when it reports an error.
/// Its progress maps onto [begin, end] of `progress` under `stage`; `what`
/// names the content in messages ("STL"). Also throws FormatError when it
/// fails or throws (std::bad_alloc included), CancelledError when cancelled,
/// and rethrows anything else `progress` throws.
void runAlgorithm(vtkAlgorithm* algorithm, const std::filesystem::path& file,
                  const std::string& what, const Progress& progress, double begin, double end,
                  const std::string& stage);

}  // namespace vv::meshio::detail
