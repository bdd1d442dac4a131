// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <cstddef>
#include <cstdint>
#include <glm/glm.hpp>

#include "passes/PassContext.h"
#include "vv/render/Camera.h"
#include "vv/render/RenderGraph.h"

namespace vv::render {

struct GeometryInputs {
    PassContext context;
    Camera camera;
    glm::ivec2 size{1, 1};  ///< render size
    /// Everything that changes the rasterised geometry besides the camera.
    std::uint64_t sceneRevision = 0;  ///< the scene, told apart per mesh level
    std::uint64_t arrayKey = 0;       ///< MeshStyle::geometryKey()
    std::uint64_t volumeRevision = 0;
    float volumeIso = 0.0F;
    std::size_t meshLevel = 0;    ///< 0 = the scene's meshes, k = preview level k
    unsigned volumeObjectId = 1;  ///< the ray-cast volume's id: 1 + mesh count
};

/// The G-buffer, persistent (cached while camera, size and scene stay).
struct GeometryOutputs {
    Handle<Texture> linearDepth;  ///< R32F, +Inf on background
    Handle<Texture> normal;       ///< RGBA16F, w = 1 where the parameter is valid
    Handle<Texture> objectId;     ///< R32UI, 0 = background
    Handle<Texture> parameter;    ///< R32F, NaN = no data
    Handle<Texture> depth;        ///< Depth32F
};

/// "geometry": rasterises the meshes (MeshRenderer::drawGBuffer) and the
/// ray-cast volume into the G-buffer, one render target "gbuffer" of
/// "linear-depth", "normal", "object-id", "parameter" and "depth". Reads
/// nothing.
GeometryOutputs addGeometryPass(RenderGraph& graph, const GeometryInputs& inputs);

}  // namespace vv::render
