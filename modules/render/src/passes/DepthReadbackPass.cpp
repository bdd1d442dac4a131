// SPDX-License-Identifier: GPL-3.0-or-later
#include "passes/DepthReadbackPass.h"

#include <memory>

namespace vv::render {

DepthReadbackOutputs addDepthReadbackPass(RenderGraph& graph, const DepthReadbackInputs& inputs) {
    struct Data {
        Handle<Texture> depth;
        DepthReadbackOutputs out;
    };
    const auto& data = graph.addPass<Data>(
        "depth-readback",
        [&](RenderGraph::Builder& b, Data& d) {
            d.depth = b.read(inputs.linearDepth);
            d.out.image =
                b.write(b.createPersistent<CpuValue<DepthImage>>("linear-depth-image", {}));
        },
        [context = inputs.context](const RenderGraph::Resources& r, const Data& d) {
            r.getForWrite(d.out.image)
                .set(DepthImage{std::make_shared<const Image<float>>(
                    readRedChannel(*context.gl, glTex(r.get(d.depth))))});
        });
    return data.out;
}

}  // namespace vv::render
