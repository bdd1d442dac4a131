// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// The state of a RenderGraph between its declaration, compile() and
// execute(). Internal to vv::render: RenderGraph.cpp (declaring, executing),
// RenderGraphCompile.cpp (checks, culling, order) and RenderGraphAccess.cpp
// (what passes and callers read).

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <typeindex>
#include <vector>

#include "vv/render/RenderGraph.h"

namespace vv::render::detail {

/// One version of one resource, by index.
struct VersionRef {
    std::uint32_t index = 0;
    std::uint32_t version = 0;
    friend bool operator==(const VersionRef&, const VersionRef&) = default;
};

[[nodiscard]] inline std::string inQuotes(std::string_view name) {
    return "'" + std::string(name) + "'";
}

[[nodiscard]] inline bool contains(const std::vector<VersionRef>& refs, VersionRef ref) {
    return std::find(refs.begin(), refs.end(), ref) != refs.end();
}

}  // namespace vv::render::detail

namespace vv::render {

struct RenderGraph::Impl {
    using VersionRef = detail::VersionRef;

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

    // ---- building ------------------------------------------------------------

    void requireBuilding() const;
    void requireNewResourceName(std::string_view name) const;
    /// The resource behind a handle, checked. `user` describes who uses it.
    Resource& checkedResource(std::uint32_t index, std::type_index type, const std::string& user);
    [[nodiscard]] static std::uint32_t latestVersion(const Resource& resource) noexcept;

    // ---- compiling -----------------------------------------------------------

    void validateReads() const;
    void checkPersistentWriters() const;
    void markImportedTargets();
    /// All passes in an order that respects every dependency: writer before
    /// readers, readers of a version before the writer of the next one,
    /// writers of one resource in version order. Among ready passes the one
    /// declared first goes first, so without stale reads this is declaration
    /// order. Throws RenderGraphError naming a cycle.
    [[nodiscard]] std::vector<std::size_t> sortPasses() const;
    /// Every pass left over by the sort has a left-over predecessor, so
    /// walking predecessors from one of them must come back to a pass seen.
    [[nodiscard]] std::string describeCycle(
        const std::vector<std::vector<std::size_t>>& predecessors,
        const std::vector<bool>& done) const;
    /// Reference-count culling: a pass counts its written versions (+1 for
    /// side effects), a version counts its readers (+1 for targets); what
    /// drops to zero is culled and releases what it reads.
    void cull();
    void computeLifetimes();

    // ---- executing -----------------------------------------------------------

    /// Storage for persistent and imported resources used this frame.
    void bindLongLivedResources();
    void releaseTransients() noexcept;
    [[nodiscard]] detail::PassSignature signatureOf(const Pass& pass) const;
    /// Why `pass` must run this frame; nullopt when its cached result holds.
    [[nodiscard]] std::optional<std::string> reasonToRun(const Pass& pass,
                                                         const detail::PassSignature& now) const;
    [[nodiscard]] static std::optional<std::string> parameterChange(
        const std::vector<detail::PassParameter>& last,
        const std::vector<detail::PassParameter>& now);
    [[nodiscard]] static std::optional<std::string> inputChange(
        const std::vector<detail::InputStamp>& last, const std::vector<detail::InputStamp>& now);
    /// A skipped pass's outputs keep the content stamps of its last run.
    void reuseOutputs(Pass& pass);
    /// A pass that ran gave its outputs new content.
    void stampOutputs(Pass& pass);
    [[nodiscard]] std::vector<ResourceVersion> named(const std::vector<VersionRef>& refs) const;
    void requireCompiled() const;
};

}  // namespace vv::render
