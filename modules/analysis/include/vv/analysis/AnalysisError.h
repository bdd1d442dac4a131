// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "vv/core/Error.h"

namespace vv::analysis {

/// A surface that cannot be analysed (no inside, fewer than two ends, an end
/// point on another piece, ...): what() names the mesh and the reason. The
/// CLI's exit code 3.
class AnalysisError : public Error {
    using Error::Error;
};

}  // namespace vv::analysis
