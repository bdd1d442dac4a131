// SPDX-License-Identifier: GPL-3.0-or-later
// Declaring passes and resources, and executing the compiled graph.
#include "vv/render/RenderGraph.h"

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

#include "RenderGraphImpl.h"

namespace vv::render {

using detail::contains;
using detail::inQuotes;
using detail::VersionRef;

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

void RenderGraph::Impl::requireBuilding() const {
    if (compiled) {
        throw RenderGraphError("render graph: cannot declare passes or resources after compile()");
    }
}

void RenderGraph::Impl::requireNewResourceName(std::string_view name) const {
    if (name.empty()) {
        throw RenderGraphError("render graph: a resource needs a name");
    }
    for (const Resource& resource : resources) {
        if (resource.name == name) {
            throw RenderGraphError("render graph: two resources are named " + inQuotes(name));
        }
    }
}

RenderGraph::Impl::Resource& RenderGraph::Impl::checkedResource(std::uint32_t index,
                                                                std::type_index type,
                                                                const std::string& user) {
    if (index >= resources.size() || resources[index].type != type) {
        throw RenderGraphError(
            "render graph: " + user +
            " uses a handle that is invalid, of another type or of another graph");
    }
    return resources[index];
}

std::uint32_t RenderGraph::Impl::latestVersion(const Resource& resource) noexcept {
    return static_cast<std::uint32_t>(resource.versions.size() - 1);
}

void RenderGraph::Impl::bindLongLivedResources() {
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

void RenderGraph::Impl::releaseTransients() noexcept {
    for (Resource& resource : resources) {
        if (resource.kind == ResourceKind::Transient && resource.bound != nullptr) {
            cache->release(*resource.bound);
            resource.bound = nullptr;
        }
    }
}

detail::PassSignature RenderGraph::Impl::signatureOf(const Pass& pass) const {
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

std::optional<std::string> RenderGraph::Impl::reasonToRun(const Pass& pass,
                                                          const detail::PassSignature& now) const {
    if (pass.sideEffect) {
        return "has side effects";
    }
    for (const VersionRef& write : pass.writes) {
        const Resource& resource = resources[write.index];
        if (resource.kind != ResourceKind::Persistent) {
            return "writes " + std::string(toString(resource.kind)) + " " + inQuotes(resource.name);
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

std::optional<std::string> RenderGraph::Impl::parameterChange(
    const std::vector<detail::PassParameter>& last, const std::vector<detail::PassParameter>& now) {
    for (const auto& parameter : now) {
        const auto before = std::find_if(last.begin(), last.end(),
                                         [&](const auto& old) { return old.key == parameter.key; });
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

std::optional<std::string> RenderGraph::Impl::inputChange(
    const std::vector<detail::InputStamp>& last, const std::vector<detail::InputStamp>& now) {
    for (const auto& input : now) {
        const auto before = std::find_if(last.begin(), last.end(), [&](const auto& old) {
            return old.resource == input.resource && old.version == input.version;
        });
        const std::string name = inQuotes(input.resource) + " v" + std::to_string(input.version);
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

void RenderGraph::Impl::reuseOutputs(Pass& pass) {
    for (const VersionRef& write : pass.writes) {
        Resource& resource = resources[write.index];
        resource.versions[write.version].stamp =
            cache->versionStamp(resource.name, write.version).value_or(0);
    }
}

void RenderGraph::Impl::stampOutputs(Pass& pass) {
    for (const VersionRef& write : pass.writes) {
        Resource& resource = resources[write.index];
        const std::uint64_t stamp = cache->newStamp();
        resource.versions[write.version].stamp = stamp;
        if (resource.kind == ResourceKind::Persistent) {
            cache->setVersionStamp(resource.name, write.version, stamp);
        }
    }
}

std::vector<ResourceVersion> RenderGraph::Impl::named(const std::vector<VersionRef>& refs) const {
    std::vector<ResourceVersion> result;
    result.reserve(refs.size());
    for (const VersionRef& ref : refs) {
        result.push_back({resources[ref.index].name, ref.version});
    }
    return result;
}

void RenderGraph::Impl::requireCompiled() const {
    if (!compiled) {
        throw RenderGraphError("render graph: compile() first");
    }
}

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

}  // namespace vv::render
