// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/render/RenderGraph.h"

#include <algorithm>
#include <functional>
#include <queue>
#include <string>
#include <utility>
#include <variant>
#include <vector>

namespace vv::render {

namespace {

/// One version of one resource, by index.
struct VersionRef {
    std::uint32_t index = 0;
    std::uint32_t version = 0;
    friend bool operator==(const VersionRef&, const VersionRef&) = default;
};

std::string inQuotes(std::string_view name) {
    return "'" + std::string(name) + "'";
}

bool contains(const std::vector<VersionRef>& refs, VersionRef ref) {
    return std::find(refs.begin(), refs.end(), ref) != refs.end();
}

}  // namespace

std::string_view toString(PassState state) noexcept {
    switch (state) {
        case PassState::Pending:
            return "pending";
        case PassState::Culled:
            return "culled";
        case PassState::Executed:
            return "executed";
        case PassState::Cached:
            return "cached";
    }
    return "unknown";
}

std::string_view toString(ResourceKind kind) noexcept {
    switch (kind) {
        case ResourceKind::Transient:
            return "transient";
        case ResourceKind::Persistent:
            return "persistent";
        case ResourceKind::Imported:
            return "imported";
    }
    return "unknown";
}

struct RenderGraph::Impl {
    /// One version of a resource: who writes it, who reads it.
    struct Version {
        std::optional<std::size_t> writer;  ///< none for version 0
        std::vector<std::size_t> readers;
        bool target = false;
        int refCount = 0;         ///< compile(): consumers left after culling
        std::uint64_t stamp = 0;  ///< execute(): identifies the content
    };

    struct Resource {
        Resource(std::string_view resourceName, std::type_index resourceType,
                 ResourceKind resourceKind)
            : name(resourceName), type(resourceType), kind(resourceKind) {}

        std::string name;
        std::type_index type;
        ResourceKind kind = ResourceKind::Transient;
        std::unique_ptr<detail::ErasedDescriptor> descriptor;  ///< created resources
        std::unique_ptr<detail::ErasedResource> imported;      ///< imported resources
        std::string description;
        ImportOptions importOptions;
        std::vector<Version> versions;
        std::optional<std::size_t> firstUse;  ///< positions in `order`
        std::optional<std::size_t> lastUse;
        detail::ErasedResource* bound = nullptr;  ///< storage while executing
        std::uint64_t generation = 0;             ///< persistent storage generation
    };

    /// A render target a pass declared: attachments it writes.
    struct DeclaredTarget {
        std::string name;
        std::vector<VersionRef> colors;
        std::optional<VersionRef> depth;
    };

    struct Pass {
        std::string name;
        std::unique_ptr<PassCallback> callback;
        std::vector<VersionRef> reads;
        std::vector<VersionRef> writes;
        std::vector<detail::PassParameter> parameters;
        std::vector<DeclaredTarget> renderTargets;
        bool sideEffect = false;
        int refCount = 0;
        bool culled = false;
        std::optional<std::size_t> order;
        PassState state = PassState::Pending;
        std::string reason;
        std::optional<double> milliseconds;
    };

    explicit Impl(RenderGraphCache& graphCache) : cache(&graphCache) {}

    RenderGraphCache* cache;
    std::vector<Pass> passes;
    std::vector<Resource> resources;
    std::vector<std::size_t> order;  ///< surviving passes in execution order
    std::optional<std::string> brokenBy;
    bool compiled = false;
    bool executed = false;
    bool executeFailed = false;
    CpuPassTimer timer;
    Blackboard blackboard;

    // ---- building --------------------------------------------------------

    void requireBuilding() const {
        if (compiled) {
            throw RenderGraphError(
                "render graph: cannot declare passes or resources after compile()");
        }
    }

    void requireNewResourceName(std::string_view name) const {
        if (name.empty()) {
            throw RenderGraphError("render graph: a resource needs a name");
        }
        for (const Resource& resource : resources) {
            if (resource.name == name) {
                throw RenderGraphError("render graph: two resources are named " + inQuotes(name));
            }
        }
    }

    /// The resource behind a handle, checked. `user` describes who uses it.
    Resource& checkedResource(std::uint32_t index, std::type_index type, const std::string& user) {
        if (index >= resources.size() || resources[index].type != type) {
            throw RenderGraphError(
                "render graph: " + user +
                " uses a handle that is invalid, of another type or of another graph");
        }
        return resources[index];
    }

    [[nodiscard]] static std::uint32_t latestVersion(const Resource& resource) noexcept {
        return static_cast<std::uint32_t>(resource.versions.size() - 1);
    }

    // ---- compiling -------------------------------------------------------

    void validateReads() const {
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

    void checkPersistentWriters() const {
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

    void markImportedTargets() {
        for (Resource& resource : resources) {
            if (resource.kind == ResourceKind::Imported && resource.importOptions.target) {
                resource.versions.back().target = true;
            }
        }
    }

    /// All passes in an order that respects every dependency: writer before
    /// readers, readers of a version before the writer of the next one,
    /// writers of one resource in version order. Among ready passes the one
    /// declared first goes first, so without stale reads this is declaration
    /// order. Throws RenderGraphError naming a cycle.
    [[nodiscard]] std::vector<std::size_t> sortPasses() const {
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

    /// Every pass left over by the sort has a left-over predecessor, so
    /// walking predecessors from one of them must come back to a pass seen.
    [[nodiscard]] std::string describeCycle(
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

    /// Reference-count culling: a pass counts its written versions (+1 for
    /// side effects), a version counts its readers (+1 for targets); what
    /// drops to zero is culled and releases what it reads.
    void cull() {
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
                const std::size_t writer =
                    *resources[version->index].versions[version->version].writer;
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

    void computeLifetimes() {
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

    // ---- executing -------------------------------------------------------

    /// Storage for persistent and imported resources used this frame.
    void bindLongLivedResources() {
        for (Resource& resource : resources) {
            if (!resource.firstUse.has_value()) {
                continue;
            }
            if (resource.kind == ResourceKind::Persistent) {
                const auto binding = cache->bindPersistent(resource.name, *resource.descriptor);
                resource.bound = binding.resource;
                resource.generation = binding.generation;
            } else if (resource.kind == ResourceKind::Imported) {
                resource.bound = resource.imported.get();
                resource.versions.front().stamp = resource.importOptions.revision;
            }
        }
    }

    void releaseTransients() noexcept {
        for (Resource& resource : resources) {
            if (resource.kind == ResourceKind::Transient && resource.bound != nullptr) {
                cache->release(*resource.bound);
                resource.bound = nullptr;
            }
        }
    }

    [[nodiscard]] detail::PassSignature signatureOf(const Pass& pass) const {
        detail::PassSignature signature;
        signature.parameters = pass.parameters;
        for (const VersionRef& read : pass.reads) {
            const Resource& resource = resources[read.index];
            signature.inputs.push_back(
                {resource.name, read.version, resource.versions[read.version].stamp});
        }
        for (const VersionRef& write : pass.writes) {
            const Resource& resource = resources[write.index];
            if (resource.kind == ResourceKind::Persistent) {
                signature.outputs.push_back({resource.name, write.version, resource.generation});
            }
        }
        return signature;
    }

    /// Why `pass` must run this frame; nullopt when its cached result holds.
    [[nodiscard]] std::optional<std::string> reasonToRun(const Pass& pass,
                                                         const detail::PassSignature& now) const {
        if (pass.sideEffect) {
            return "has side effects";
        }
        for (const VersionRef& write : pass.writes) {
            const Resource& resource = resources[write.index];
            if (resource.kind != ResourceKind::Persistent) {
                return "writes " + std::string(toString(resource.kind)) + " " +
                       inQuotes(resource.name);
            }
        }
        const detail::PassSignature* last = cache->lookupRun(pass.name);
        if (last == nullptr) {
            return std::string("first run");
        }
        if (auto change = parameterChange(last->parameters, now.parameters)) {
            return change;
        }
        if (auto change = inputChange(last->inputs, now.inputs)) {
            return change;
        }
        if (last->outputs != now.outputs) {
            return std::string("its persistent outputs have new storage");
        }
        for (const VersionRef& write : pass.writes) {
            const Resource& resource = resources[write.index];
            if (!cache->versionStamp(resource.name, write.version).has_value()) {
                return "no cached content for " + inQuotes(resource.name);
            }
        }
        return std::nullopt;
    }

    [[nodiscard]] static std::optional<std::string> parameterChange(
        const std::vector<detail::PassParameter>& last,
        const std::vector<detail::PassParameter>& now) {
        for (const auto& parameter : now) {
            const auto before = std::find_if(last.begin(), last.end(), [&](const auto& old) {
                return old.key == parameter.key;
            });
            if (before == last.end()) {
                return "new parameter " + inQuotes(parameter.key);
            }
            if (before->value != parameter.value) {
                return "parameter " + inQuotes(parameter.key) + " changed";
            }
        }
        if (last.size() != now.size()) {
            return std::string("a parameter was dropped");
        }
        return std::nullopt;
    }

    [[nodiscard]] static std::optional<std::string> inputChange(
        const std::vector<detail::InputStamp>& last, const std::vector<detail::InputStamp>& now) {
        for (const auto& input : now) {
            const auto before = std::find_if(last.begin(), last.end(), [&](const auto& old) {
                return old.resource == input.resource && old.version == input.version;
            });
            const std::string name =
                inQuotes(input.resource) + " v" + std::to_string(input.version);
            if (before == last.end()) {
                return "new input " + name;
            }
            if (before->stamp != input.stamp) {
                return "input " + name + " changed";
            }
        }
        if (last.size() != now.size()) {
            return std::string("an input was dropped");
        }
        return std::nullopt;
    }

    /// A skipped pass's outputs keep the content stamps of its last run.
    void reuseOutputs(Pass& pass) {
        for (const VersionRef& write : pass.writes) {
            Resource& resource = resources[write.index];
            resource.versions[write.version].stamp =
                cache->versionStamp(resource.name, write.version).value_or(0);
        }
    }

    /// A pass that ran gave its outputs new content.
    void stampOutputs(Pass& pass) {
        for (const VersionRef& write : pass.writes) {
            Resource& resource = resources[write.index];
            const std::uint64_t stamp = cache->newStamp();
            resource.versions[write.version].stamp = stamp;
            if (resource.kind == ResourceKind::Persistent) {
                cache->setVersionStamp(resource.name, write.version, stamp);
            }
        }
    }

    [[nodiscard]] std::vector<ResourceVersion> named(const std::vector<VersionRef>& refs) const {
        std::vector<ResourceVersion> result;
        result.reserve(refs.size());
        for (const VersionRef& ref : refs) {
            result.push_back({resources[ref.index].name, ref.version});
        }
        return result;
    }

    void requireCompiled() const {
        if (!compiled) {
            throw RenderGraphError("render graph: compile() first");
        }
    }
};

RenderGraph::RenderGraph(RenderGraphCache& cache) : impl_(std::make_unique<Impl>(cache)) {}

RenderGraph::~RenderGraph() = default;

std::size_t RenderGraph::beginPass(std::string_view name, std::unique_ptr<PassCallback> callback) {
    impl_->requireBuilding();
    if (name.empty()) {
        throw RenderGraphError("render graph: a pass needs a name");
    }
    for (const Impl::Pass& pass : impl_->passes) {
        if (pass.name == name) {
            throw RenderGraphError("render graph: two passes are named " + inQuotes(name));
        }
    }
    Impl::Pass pass;
    pass.name = std::string(name);
    pass.callback = std::move(callback);
    impl_->passes.push_back(std::move(pass));
    return impl_->passes.size() - 1;
}

void RenderGraph::failSetup(std::size_t pass) noexcept {
    if (!impl_->brokenBy.has_value()) {
        try {
            impl_->brokenBy = impl_->passes[pass].name;
        } catch (...) {
            impl_->brokenBy = std::string();
        }
    }
}

std::uint32_t RenderGraph::declareCreated(std::string_view name,
                                          std::unique_ptr<detail::ErasedDescriptor> descriptor,
                                          ResourceKind kind) {
    impl_->requireBuilding();
    impl_->requireNewResourceName(name);
    Impl::Resource resource(name, descriptor->type(), kind);
    resource.description = descriptor->describe();
    resource.descriptor = std::move(descriptor);
    resource.versions.emplace_back();
    impl_->resources.push_back(std::move(resource));
    return static_cast<std::uint32_t>(impl_->resources.size() - 1);
}

std::uint32_t RenderGraph::declareImported(std::string_view name,
                                           std::unique_ptr<detail::ErasedResource> resource,
                                           std::type_index type, std::string description,
                                           const ImportOptions& options) {
    impl_->requireBuilding();
    impl_->requireNewResourceName(name);
    Impl::Resource imported(name, type, ResourceKind::Imported);
    imported.imported = std::move(resource);
    imported.description = std::move(description);
    imported.importOptions = options;
    imported.versions.emplace_back();
    impl_->resources.push_back(std::move(imported));
    return static_cast<std::uint32_t>(impl_->resources.size() - 1);
}

void RenderGraph::declareRead(std::size_t pass, std::uint32_t index, std::uint32_t version,
                              std::type_index type) {
    impl_->requireBuilding();
    Impl::Pass& reader = impl_->passes[pass];
    Impl::Resource& resource = impl_->checkedResource(index, type, "pass " + inQuotes(reader.name));
    if (version > impl_->latestVersion(resource)) {
        throw RenderGraphError("render graph: pass " + inQuotes(reader.name) + " reads " +
                               inQuotes(resource.name) + " version " + std::to_string(version) +
                               ", which does not exist");
    }
    const VersionRef ref{index, version};
    if (contains(reader.reads, ref)) {
        return;
    }
    reader.reads.push_back(ref);
    resource.versions[version].readers.push_back(pass);
}

std::uint32_t RenderGraph::declareWrite(std::size_t pass, std::uint32_t index,
                                        std::uint32_t version, std::type_index type) {
    impl_->requireBuilding();
    Impl::Pass& writer = impl_->passes[pass];
    Impl::Resource& resource = impl_->checkedResource(index, type, "pass " + inQuotes(writer.name));
    const std::uint32_t latest = impl_->latestVersion(resource);
    if (version != latest) {
        throw RenderGraphError("render graph: pass " + inQuotes(writer.name) + " writes " +
                               inQuotes(resource.name) + " version " + std::to_string(version) +
                               ", but version " + std::to_string(latest) +
                               " exists: write the latest version");
    }
    for (const VersionRef& written : writer.writes) {
        if (written.index == index) {
            throw RenderGraphError("render graph: pass " + inQuotes(writer.name) + " writes " +
                                   inQuotes(resource.name) + " twice");
        }
    }
    Impl::Version next;
    next.writer = pass;
    resource.versions.push_back(std::move(next));
    writer.writes.push_back({index, latest + 1});
    return latest + 1;
}

void RenderGraph::declareSideEffect(std::size_t pass) {
    impl_->requireBuilding();
    impl_->passes[pass].sideEffect = true;
}

void RenderGraph::declareParameter(std::size_t pass, std::string_view key,
                                   std::span<const std::byte> value) {
    impl_->requireBuilding();
    Impl::Pass& owner = impl_->passes[pass];
    for (const auto& parameter : owner.parameters) {
        if (parameter.key == key) {
            throw RenderGraphError("render graph: pass " + inQuotes(owner.name) +
                                   " declares parameter " + inQuotes(key) + " twice");
        }
    }
    owner.parameters.push_back(
        {std::string(key), std::vector<std::byte>(value.begin(), value.end())});
}

void RenderGraph::declareTarget(std::uint32_t index, std::uint32_t version, std::type_index type) {
    impl_->requireBuilding();
    Impl::Resource& resource = impl_->checkedResource(index, type, "markTarget()");
    if (version > impl_->latestVersion(resource)) {
        throw RenderGraphError("render graph: markTarget(): " + inQuotes(resource.name) +
                               " has no version " + std::to_string(version));
    }
    resource.versions[version].target = true;
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

void RenderGraph::execute(PassObserver* observer) {
    Impl& impl = *impl_;
    if (impl.executed) {
        throw RenderGraphError("render graph: execute() runs once; build a new graph per frame");
    }
    compile();
    impl.executed = true;
    RenderGraphCache& cache = *impl.cache;
    cache.beginFrame();
    try {
        impl.timer.beginFrame();
        if (observer != nullptr) {
            observer->beginFrame();
        }
        impl.bindLongLivedResources();
        for (std::size_t position = 0; position < impl.order.size(); ++position) {
            for (Impl::Resource& resource : impl.resources) {
                if (resource.kind == ResourceKind::Transient && resource.firstUse == position) {
                    resource.bound = &cache.acquire(*resource.descriptor);
                }
            }

            const std::size_t index = impl.order[position];
            Impl::Pass& pass = impl.passes[index];
            detail::PassSignature signature = impl.signatureOf(pass);
            const std::optional<std::string> reason = impl.reasonToRun(pass, signature);
            if (!reason.has_value()) {
                impl.reuseOutputs(pass);
                pass.state = PassState::Cached;
                pass.reason = "nothing it depends on changed";
            } else {
                pass.reason = *reason;
                const Resources resources(*this, index);
                impl.timer.beginPass(pass.name);
                if (observer != nullptr) {
                    observer->beginPass(pass.name);
                }
                try {
                    pass.callback->run(resources);
                } catch (...) {
                    impl.timer.endPass(pass.name);
                    if (observer != nullptr) {
                        try {
                            observer->endPass(pass.name);
                        } catch (...) {  // NOLINT(bugprone-empty-catch): the pass's error wins
                        }
                    }
                    cache.invalidate(pass.name);
                    pass.state = PassState::Executed;
                    pass.reason += "; threw";
                    throw;
                }
                impl.timer.endPass(pass.name);
                if (observer != nullptr) {
                    observer->endPass(pass.name);
                }
                pass.milliseconds = impl.timer.milliseconds(pass.name);
                pass.state = PassState::Executed;
                impl.stampOutputs(pass);
                cache.storeRun(pass.name, std::move(signature));
            }

            for (Impl::Resource& resource : impl.resources) {
                if (resource.kind == ResourceKind::Transient && resource.lastUse == position &&
                    resource.bound != nullptr) {
                    cache.release(*resource.bound);
                    resource.bound = nullptr;
                }
            }
        }
        if (observer != nullptr) {
            observer->endFrame();
        }
    } catch (...) {
        impl.executeFailed = true;
        impl.releaseTransients();
        cache.endFrame();
        throw;
    }
    cache.endFrame();
}

Blackboard& RenderGraph::blackboard() noexcept {
    return impl_->blackboard;
}

const Blackboard& RenderGraph::blackboard() const noexcept {
    return impl_->blackboard;
}

void RenderGraph::throwMissingEntry(std::size_t pass, std::string_view name) const {
    throw RenderGraphError("render graph: pass " + inQuotes(impl_->passes[pass].name) + " reads " +
                           inQuotes(name) + ", which no pass put on the blackboard");
}

std::uint32_t RenderGraph::declareRenderTarget(std::size_t pass, std::string_view name,
                                               const RenderTargetAttachments& attachments) {
    impl_->requireBuilding();
    Impl::Pass& owner = impl_->passes[pass];
    const std::string what = "pass " + inQuotes(owner.name) + " declares render target ";
    if (name.empty()) {
        throw RenderGraphError("render graph: " + what + "without a name");
    }
    for (const auto& declared : owner.renderTargets) {
        if (declared.name == name) {
            throw RenderGraphError("render graph: " + what + inQuotes(name) + " twice");
        }
    }
    if (attachments.colors.empty() && !attachments.depth.valid()) {
        throw RenderGraphError("render graph: " + what + inQuotes(name) + " without attachments");
    }
    const auto written = [&](Handle<Texture> handle) {
        const std::string user = what + inQuotes(name);
        impl_->checkedResource(handle.index(), typeid(Texture), user);
        const VersionRef ref{handle.index(), handle.version()};
        if (!contains(owner.writes, ref)) {
            throw RenderGraphError("render graph: " + user + " with " +
                                   inQuotes(impl_->resources[ref.index].name) + " version " +
                                   std::to_string(ref.version) +
                                   ", which it does not write (write() it first)");
        }
        return ref;
    };
    Impl::DeclaredTarget target;
    target.name = std::string(name);
    for (const Handle<Texture>& color : attachments.colors) {
        target.colors.push_back(written(color));
    }
    if (attachments.depth.valid()) {
        target.depth = written(attachments.depth);
    }
    owner.renderTargets.push_back(std::move(target));
    return static_cast<std::uint32_t>(owner.renderTargets.size() - 1);
}

RenderTarget RenderGraph::resolveRenderTarget(std::size_t pass, RenderTargetId id) const {
    const Impl::Pass& owner = impl_->passes[pass];
    if (!id.valid() || id.index_ >= owner.renderTargets.size()) {
        throw RenderGraphError("render graph: pass " + inQuotes(owner.name) +
                               " uses a render target it did not declare");
    }
    const Impl::DeclaredTarget& declared = owner.renderTargets[id.index_];
    const auto texture = [&](VersionRef ref) {
        return static_cast<const Texture*>(
            access(pass, ref.index, ref.version, typeid(Texture), true));
    };
    RenderTarget target;
    target.name = declared.name;
    for (const VersionRef& color : declared.colors) {
        target.colors.push_back(texture(color));
    }
    if (declared.depth.has_value()) {
        target.depth = texture(*declared.depth);
    }
    const Texture& first = target.colors.empty() ? *target.depth : *target.colors.front();
    target.width = first.descriptor().width;
    target.height = first.descriptor().height;
    const auto sameSize = [&](const Texture* t) {
        return t->descriptor().width == target.width && t->descriptor().height == target.height;
    };
    if (!std::all_of(target.colors.begin(), target.colors.end(), sameSize) ||
        (target.depth != nullptr && !sameSize(target.depth))) {
        throw RenderGraphError("render graph: render target " + inQuotes(declared.name) +
                               " of pass " + inQuotes(owner.name) +
                               " has attachments of different sizes");
    }
    return target;
}

const void* RenderGraph::resultOf(std::uint32_t index, std::uint32_t version,
                                  std::type_index type) const {
    const Impl& impl = *impl_;
    if (!impl.executed || impl.executeFailed) {
        throw RenderGraphError("render graph: results exist after a successful execute()");
    }
    if (index >= impl.resources.size() || impl.resources[index].type != type) {
        throw RenderGraphError(
            "render graph: result() of a handle that is invalid, of another type or of another "
            "graph");
    }
    const Impl::Resource& resource = impl.resources[index];
    if (resource.kind == ResourceKind::Transient) {
        throw RenderGraphError("render graph: " + inQuotes(resource.name) +
                               " is transient: its storage went back to the pool after the "
                               "frame (make it persistent to read it afterwards)");
    }
    if (version != Impl::latestVersion(resource)) {
        throw RenderGraphError("render graph: result() of " + inQuotes(resource.name) +
                               " version " + std::to_string(version) + ", but version " +
                               std::to_string(Impl::latestVersion(resource)) + " is its latest");
    }
    const Impl::Version& latest = resource.versions[version];
    if (latest.writer.has_value()) {
        const PassState state = impl.passes[*latest.writer].state;
        if (state != PassState::Executed && state != PassState::Cached) {
            return nullptr;
        }
    } else if (resource.kind != ResourceKind::Imported) {
        return nullptr;
    }
    if (resource.kind == ResourceKind::Imported) {
        return resource.imported->get();
    }
    return resource.bound != nullptr ? resource.bound->get() : nullptr;
}

bool RenderGraph::compiled() const noexcept {
    return impl_->compiled;
}

std::vector<PassInfo> RenderGraph::passes() const {
    impl_->requireCompiled();
    std::vector<PassInfo> infos;
    infos.reserve(impl_->passes.size());
    for (const Impl::Pass& pass : impl_->passes) {
        PassInfo info;
        info.name = pass.name;
        info.state = pass.state;
        info.sideEffect = pass.sideEffect;
        info.order = pass.order;
        info.reads = impl_->named(pass.reads);
        info.writes = impl_->named(pass.writes);
        for (const auto& parameter : pass.parameters) {
            info.parameters.push_back(parameter.key);
        }
        for (const auto& target : pass.renderTargets) {
            info.renderTargets.push_back(target.name);
        }
        info.reason = pass.reason;
        info.milliseconds = pass.milliseconds;
        infos.push_back(std::move(info));
    }
    return infos;
}

std::vector<ResourceInfo> RenderGraph::resources() const {
    impl_->requireCompiled();
    std::vector<ResourceInfo> infos;
    infos.reserve(impl_->resources.size());
    for (const Impl::Resource& resource : impl_->resources) {
        ResourceInfo info;
        info.name = resource.name;
        info.kind = resource.kind;
        info.description = resource.description;
        info.versions = static_cast<std::uint32_t>(resource.versions.size());
        for (std::uint32_t v = 0; v < resource.versions.size(); ++v) {
            if (resource.versions[v].target) {
                info.targetVersions.push_back(v);
            }
        }
        if (resource.firstUse.has_value()) {
            info.firstUse = impl_->passes[impl_->order[*resource.firstUse]].name;
            info.lastUse = impl_->passes[impl_->order[*resource.lastUse]].name;
        }
        infos.push_back(std::move(info));
    }
    return infos;
}

const std::vector<PassTiming>& RenderGraph::timings() const noexcept {
    return impl_->timer.timings();
}

void* RenderGraph::access(std::size_t pass, std::uint32_t index, std::uint32_t version,
                          std::type_index type, bool forWrite) const {
    const Impl::Pass& user = impl_->passes[pass];
    if (index >= impl_->resources.size() || impl_->resources[index].type != type) {
        throw RenderGraphError("render graph: pass " + inQuotes(user.name) +
                               " uses a handle that is invalid, of another type or of another "
                               "graph");
    }
    const Impl::Resource& resource = impl_->resources[index];
    const VersionRef ref{index, version};
    const bool declared = contains(user.writes, ref) || (!forWrite && contains(user.reads, ref));
    const std::string what = inQuotes(resource.name) + " version " + std::to_string(version);
    if (!declared) {
        throw RenderGraphError("render graph: pass " + inQuotes(user.name) + " accesses " + what +
                               (forWrite ? " for writing, but its setup did not write it"
                                         : ", but its setup neither reads nor writes it"));
    }
    if (resource.bound == nullptr) {
        throw RenderGraphError("render graph: pass " + inQuotes(user.name) + " accesses " + what +
                               " outside execute()");
    }
    return resource.bound->get();
}

std::string_view RenderGraph::passName(std::size_t pass) const {
    return impl_->passes[pass].name;
}

}  // namespace vv::render
