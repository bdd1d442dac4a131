// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "vv/core/Progress.h"
#include "vv/scene/Mesh.h"

namespace vv::meshio {

/// The low-pass filter's settings (smoothedMesh()).
struct SmoothingOptions {
    /// Iterations of the filter's polynomial, in [1, 500].
    int iterations = 20;
    /// The pass band, of the mesh's own spectrum (VTK normalises it), in
    /// (0, 2): the lower, the smoother; 0.1 removes what varies from one
    /// vertex to the next and keeps what varies over a dozen of them.
    double passBand = 0.1;
    /// Boundary (open-edge) vertices stay where they are (to float
    /// precision: 1e-7 of the mesh's size).
    bool keepBoundary = true;
};

/// A copy of `mesh` with its points moved by a windowed-sinc low-pass
/// filter over the mesh (VTK's vtkWindowedSincPolyDataFilter; Taubin, Zhang
/// and Golub 1996): noise at the scale of the triangles goes, the shape at
/// the scale of many triangles stays, without the shrinking of Laplacian
/// smoothing (VTK 9.1's filter scales every point by a gain near 1, which is
/// measured and divided out). Points keep their order and count, triangles
/// and arrays are the same, normals are computed afresh; name and source are
/// kept.
/// Progress is reported on [0, 1]; a stop request throws CancelledError.
/// Throws InvalidArgumentError for options out of range, FormatError
/// (naming the mesh's source) for no triangles, indices out of range,
/// non-finite coordinates, or when VTK fails.
[[nodiscard]] scene::Mesh smoothedMesh(const scene::Mesh& mesh,
                                       const SmoothingOptions& options = {},
                                       const Progress& progress = {});

}  // namespace vv::meshio
