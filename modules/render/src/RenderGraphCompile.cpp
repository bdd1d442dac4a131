// SPDX-License-Identifier: GPL-3.0-or-later
// compile(): the rules checked, reference-count culling, execution order and
// transient lifetimes.
#include <algorithm>
#include <functional>
#include <queue>
#include <string>
#include <variant>
#include <vector>

#include "RenderGraphImpl.h"
#include "vv/render/RenderGraph.h"

namespace vv::render {

using detail::inQuotes;

void RenderGraph::Impl::validateReads() const {
    for (const Pass& pass : passes) {
        for (const VersionRef& read : pass.reads) {
            const Resource& resource = resources[read.index];
            if (read.version == 0 && resource.kind != ResourceKind::Imported) {
                throw RenderGraphError("render graph: pass " + inQuotes(pass.name) + " reads " +
                                       inQuotes(resource.name) +
                                       " version 0, which no pass writes (write it before "
                                       "reading it)");
            }
        }
    }
}

void RenderGraph::Impl::checkPersistentWriters() const {
    for (const Resource& resource : resources) {
        if (resource.kind != ResourceKind::Persistent || resource.versions.size() <= 2) {
            continue;
        }
        throw RenderGraphError("render graph: persistent resource " + inQuotes(resource.name) +
                               " is written by " +
                               inQuotes(passes[*resource.versions[1].writer].name) + " and " +
                               inQuotes(passes[*resource.versions[2].writer].name) +
                               "; a persistent resource may have one writer per frame");
    }
}

void RenderGraph::Impl::markImportedTargets() {
    for (Resource& resource : resources) {
        if (resource.kind == ResourceKind::Imported && resource.importOptions.target) {
            resource.versions.back().target = true;
        }
    }
}

std::vector<std::size_t> RenderGraph::Impl::sortPasses() const {
    const std::size_t count = passes.size();
    std::vector<std::vector<std::size_t>> successors(count);
    std::vector<std::vector<std::size_t>> predecessors(count);
    auto addEdge = [&](std::size_t from, std::size_t to) {
        successors[from].push_back(to);
        predecessors[to].push_back(from);
    };
    for (const Resource& resource : resources) {
        for (std::size_t v = 0; v < resource.versions.size(); ++v) {
            const Version& version = resource.versions[v];
            if (version.writer.has_value()) {
                for (const std::size_t reader : version.readers) {
                    addEdge(*version.writer, reader);
                }
            }
            if (v + 1 < resource.versions.size()) {
                const std::size_t nextWriter = *resource.versions[v + 1].writer;
                for (const std::size_t reader : version.readers) {
                    if (reader != nextWriter) {
                        addEdge(reader, nextWriter);
                    }
                }
                if (version.writer.has_value() && *version.writer != nextWriter) {
                    addEdge(*version.writer, nextWriter);
                }
            }
        }
    }

    std::vector<std::size_t> inDegree(count);
    std::priority_queue<std::size_t, std::vector<std::size_t>, std::greater<>> ready;
    for (std::size_t p = 0; p < count; ++p) {
        inDegree[p] = predecessors[p].size();
        if (inDegree[p] == 0) {
            ready.push(p);
        }
    }
    std::vector<std::size_t> sorted;
    std::vector<bool> done(count, false);
    while (!ready.empty()) {
        const std::size_t p = ready.top();
        ready.pop();
        sorted.push_back(p);
        done[p] = true;
        for (const std::size_t next : successors[p]) {
            if (--inDegree[next] == 0) {
                ready.push(next);
            }
        }
    }
    if (sorted.size() < count) {
        throw RenderGraphError("render graph: the passes form a cycle: " +
                               describeCycle(predecessors, done));
    }
    return sorted;
}

std::string RenderGraph::Impl::describeCycle(
    const std::vector<std::vector<std::size_t>>& predecessors,
    const std::vector<bool>& done) const {
    std::size_t current = 0;
    while (done[current]) {
        ++current;
    }
    std::vector<std::size_t> path{current};
    while (true) {
        const auto& preds = predecessors[current];
        const auto pred =
            *std::find_if(preds.begin(), preds.end(), [&](std::size_t p) { return !done[p]; });
        const auto seen = std::find(path.begin(), path.end(), pred);
        if (seen != path.end()) {
            // path runs against the edges: path[i + 1] -> path[i].
            const auto start = static_cast<std::size_t>(seen - path.begin());
            std::string text = inQuotes(passes[path[start]].name);
            for (std::size_t i = path.size() - 1; i > start; --i) {
                text += " -> " + inQuotes(passes[path[i]].name);
            }
            text += " -> " + inQuotes(passes[path[start]].name);
            return text +
                   " (a pass reads what it writes, or reads a version older than one "
                   "that must be written before it runs)";
        }
        path.push_back(pred);
        current = pred;
    }
}

void RenderGraph::Impl::cull() {
    struct VersionNode {
        std::uint32_t index;
        std::uint32_t version;
    };
    std::vector<std::variant<std::size_t, VersionNode>> unused;
    for (std::size_t p = 0; p < passes.size(); ++p) {
        Pass& pass = passes[p];
        pass.culled = false;
        pass.refCount = static_cast<int>(pass.writes.size()) + (pass.sideEffect ? 1 : 0);
        if (pass.refCount == 0) {
            unused.emplace_back(p);
        }
    }
    for (std::uint32_t r = 0; r < resources.size(); ++r) {
        auto& versions = resources[r].versions;
        for (std::uint32_t v = 0; v < versions.size(); ++v) {
            versions[v].refCount =
                static_cast<int>(versions[v].readers.size()) + (versions[v].target ? 1 : 0);
            if (versions[v].refCount == 0 && versions[v].writer.has_value()) {
                unused.emplace_back(VersionNode{r, v});
            }
        }
    }
    while (!unused.empty()) {
        const auto node = unused.back();
        unused.pop_back();
        if (const auto* version = std::get_if<VersionNode>(&node)) {
            const std::size_t writer = *resources[version->index].versions[version->version].writer;
            if (--passes[writer].refCount == 0) {
                unused.emplace_back(writer);
            }
            continue;
        }
        Pass& pass = passes[std::get<std::size_t>(node)];
        pass.culled = true;
        for (const VersionRef& read : pass.reads) {
            Version& version = resources[read.index].versions[read.version];
            if (--version.refCount == 0 && version.writer.has_value()) {
                unused.emplace_back(VersionNode{read.index, read.version});
            }
        }
    }
}

void RenderGraph::Impl::computeLifetimes() {
    for (Resource& resource : resources) {
        resource.firstUse.reset();
        resource.lastUse.reset();
    }
    for (std::size_t position = 0; position < order.size(); ++position) {
        const Pass& pass = passes[order[position]];
        for (const auto* refs : {&pass.reads, &pass.writes}) {
            for (const VersionRef& ref : *refs) {
                Resource& resource = resources[ref.index];
                if (!resource.firstUse.has_value()) {
                    resource.firstUse = position;
                }
                resource.lastUse = position;
            }
        }
    }
}

void RenderGraph::compile() {
    Impl& impl = *impl_;
    if (impl.compiled) {
        return;
    }
    if (impl.brokenBy.has_value()) {
        throw RenderGraphError("render graph: the setup of pass " + inQuotes(*impl.brokenBy) +
                               " threw; build a new graph");
    }
    impl.validateReads();
    impl.checkPersistentWriters();
    impl.markImportedTargets();
    const std::vector<std::size_t> sorted = impl.sortPasses();
    impl.cull();
    impl.order.clear();
    for (const std::size_t p : sorted) {
        Impl::Pass& pass = impl.passes[p];
        if (pass.culled) {
            pass.state = PassState::Culled;
            pass.reason = "nothing reads its outputs";
        } else {
            pass.order = impl.order.size();
            impl.order.push_back(p);
        }
    }
    impl.computeLifetimes();
    impl.compiled = true;
}

}  // namespace vv::render
