// SPDX-License-Identifier: GPL-3.0-or-later
#include "passes/DepthRangePass.h"

#include "vv/core/ImageRange.h"

namespace vv::render {

DepthRangeOutputs addDepthRangePass(RenderGraph& graph, const DepthRangeInputs& inputs) {
    struct Data {
        Handle<CpuValue<DepthImage>> depth;
        Handle<ExternalFrame> external;
        DepthRangeOutputs out;
    };
    const auto& data = graph.addPass<Data>(
        "depth-range",
        [&](RenderGraph::Builder& b, Data& d) {
            d.external = b.read<ExternalFrame>(board::kExternalVss);
            if (!inputs.external) {
                d.depth = b.read(inputs.depth);
            }
            d.out.range =
                b.write(b.createPersistent<CpuValue<VisibleDepthRange>>("visible-depth-range", {}));
        },
        [external = inputs.external](const RenderGraph::Resources& r, const Data& d) {
            VisibleDepthRange visible;
            if (!external) {
                if (const auto range = finiteRange(r.get(d.depth).value().image->view())) {
                    visible.range = std::make_pair(static_cast<double>(range->first),
                                                   static_cast<double>(range->second));
                }
            } else if (const auto& whole = r.get(d.external).visibleRange;
                       whole && whole->first <= whole->second) {
                visible.range = whole;  // the whole frame's range, not this part's
            }
            r.getForWrite(d.out.range).set(visible);
        });
    return data.out;
}

}  // namespace vv::render
