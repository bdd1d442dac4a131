// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <memory>

#include "vv/vss/Solver.h"

namespace vv::vss::detail {

/// The `fast` solver (FastSolver.cpp): a treecode / FMM hybrid with rigorous
/// error bounds; meets options.tolerance on every void pixel for every p.
/// Throws InvalidArgumentError for p <= 0 or non-finite, tolerance <= 0 or non-finite.
std::unique_ptr<Solver> makeFastSolver(const SolverOptions& options);

}  // namespace vv::vss::detail
