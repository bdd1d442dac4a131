// SPDX-License-Identifier: GPL-3.0-or-later
#include "passes/DepthRangePass.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace vv::render {

std::optional<std::pair<float, float>> finiteDepthRange(const Image<float>& depth) {
    float lo = std::numeric_limits<float>::infinity();
    float hi = -std::numeric_limits<float>::infinity();
    for (int y = 0; y < depth.height(); ++y) {
        const float* row = depth.row(y);
        for (int x = 0; x < depth.width(); ++x) {
            if (std::isfinite(row[x])) {
                lo = std::min(lo, row[x]);
                hi = std::max(hi, row[x]);
            }
        }
    }
    if (lo > hi) {
        return std::nullopt;
    }
    return std::make_pair(lo, hi);
}

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
                d.depth = b.read<CpuValue<DepthImage>>(board::kLinearDepthImage);
            }
            d.out.range = b.write(
                b.createPersistent<CpuValue<VisibleDepthRange>>(board::kVisibleDepthRange, {}));
        },
        [external = inputs.external](const RenderGraph::Resources& r, const Data& d) {
            VisibleDepthRange visible;
            if (!external) {
                if (const auto range = finiteDepthRange(*r.get(d.depth).value().image)) {
                    visible.range = std::make_pair(static_cast<double>(range->first),
                                                   static_cast<double>(range->second));
                }
            } else if (const auto& whole = r.get(d.external).visibleRange;
                       whole && whole->first <= whole->second) {
                visible.range = whole;  // the whole frame's range, not this part's
            }
            r.getForWrite(d.out.range).set(visible);
        });
    graph.blackboard().put(board::kVisibleDepthRange, data.out.range);
    return data.out;
}

}  // namespace vv::render
