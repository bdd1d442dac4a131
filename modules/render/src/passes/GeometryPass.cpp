// SPDX-License-Identifier: GPL-3.0-or-later
#include "passes/GeometryPass.h"

#include <QOpenGLFunctions_4_1_Core>
#include <limits>

namespace vv::render {

GeometryOutputs addGeometryPass(RenderGraph& graph, const GeometryInputs& inputs) {
    struct Data {
        GeometryOutputs out;
        RenderTargetId target;
    };
    const auto& data = graph.addPass<Data>(
        "geometry",
        [&](RenderGraph::Builder& b, Data& d) {
            b.dependsOn("view", inputs.camera.viewMatrix());
            b.dependsOn("projection", inputs.camera.projectionMatrix());
            b.dependsOn("viewport", inputs.size);
            b.dependsOn("scene", inputs.sceneRevision);
            b.dependsOn("array", inputs.arrayKey);
            b.dependsOn("volume", inputs.volumeRevision);  // volume depth source
            b.dependsOn("iso", inputs.volumeIso);
            GeometryOutputs& out = d.out;
            out.linearDepth = b.write(b.createPersistent<Texture>(
                "linear-depth", sized(inputs.size, TextureFormat::R32F)));
            out.normal = b.write(
                b.createPersistent<Texture>("normal", sized(inputs.size, TextureFormat::RGBA16F)));
            out.objectId = b.write(
                b.createPersistent<Texture>("object-id", sized(inputs.size, TextureFormat::R32UI)));
            out.parameter = b.write(
                b.createPersistent<Texture>("parameter", sized(inputs.size, TextureFormat::R32F)));
            out.depth = b.write(
                b.createPersistent<Texture>("depth", sized(inputs.size, TextureFormat::Depth32F)));
            d.target = b.declareRenderTarget(
                "gbuffer",
                RenderTargetAttachments{{out.linearDepth, out.normal, out.objectId, out.parameter},
                                        out.depth});
        },
        [inputs](const RenderGraph::Resources& r, const Data& d) {
            const PassContext& context = inputs.context;
            auto& g = *context.gl;
            context.bindRenderTarget(r, d.target);
            g.glViewport(0, 0, inputs.size.x, inputs.size.y);
            g.glDepthMask(GL_TRUE);
            const float far[4] = {std::numeric_limits<float>::infinity(), 0.0F, 0.0F, 0.0F};
            const float zero[4] = {0.0F, 0.0F, 0.0F, 0.0F};
            const GLuint noObject[4] = {0U, 0U, 0U, 0U};
            const float one = 1.0F;
            g.glClearBufferfv(GL_COLOR, 0, far);
            g.glClearBufferfv(GL_COLOR, 1, zero);
            const float noData[4] = {std::numeric_limits<float>::quiet_NaN(), 0.0F, 0.0F, 0.0F};
            g.glClearBufferuiv(GL_COLOR, 2, noObject);
            g.glClearBufferfv(GL_COLOR, 3, noData);
            g.glClearBufferfv(GL_DEPTH, 0, &one);
            context.meshes->drawGBuffer(inputs.camera, inputs.meshLevel);
            // Volume depth source: after the meshes, depth-tested against them.
            context.volume->drawGBuffer(inputs.camera, inputs.volumeIso, inputs.volumeObjectId);
            checkGlError(g, "geometry pass");
        });
    return data.out;
}

}  // namespace vv::render
