// SPDX-License-Identifier: GPL-3.0-or-later
// What passes and callers read from a graph: its blackboard, resources and
// render targets in execute(), results after it, pass and resource infos.
#include <algorithm>
#include <string>
#include <vector>

#include "RenderGraphImpl.h"
#include "vv/render/RenderGraph.h"

namespace vv::render {

using detail::contains;
using detail::inQuotes;
using detail::VersionRef;

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
