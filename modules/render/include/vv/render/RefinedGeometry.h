// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <memory>

#include "vv/scene/Mesh.h"

namespace vv::render {

/// A refined (subdivided) copy of a scene, drawn where the scene's facets
/// are coarse for the view (FrameSettings::smoothCoarseMeshes), made
/// outside the renderer (meshio::subdividedScene), with what it is made
/// from and how far it lies from it.
struct RefinedGeometry {
    std::shared_ptr<const scene::Scene> scene;  ///< one mesh per scene mesh; null: none
    double sourceEdgeMm = 0.0;                  ///< the median edge of the scene's own meshes
    double largestDeviationMm = 0.0;            ///< the copy's points from the scene's triangles
    double meanDeviationMm = 0.0;
};

}  // namespace vv::render
