// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string_view>

#include "vv/render/RenderGraphDetail.h"
#include "vv/render/RenderGraphResources.h"

namespace vv::render {

struct RenderGraphCacheOptions {
    /// Pooled objects nobody used, persistent resources no graph declared and
    /// results of passes that did not survive culling are dropped after this
    /// many frames (>= 1; smaller values are taken as 1).
    int retainFrames = 5;
};

/// What survives from one frame's RenderGraph to the next: the pool of backend
/// objects (keyed by descriptor), the persistent resources (keyed by name)
/// and, per pass name, the signature of its last run (parameters, input
/// stamps, output storage) that decides whether the pass must run again.
///
/// One cache serves one sequence of frames: at most one graph executes with
/// it at a time, and pass and persistent-resource names are its keys (two
/// views need two caches). Not thread-safe. Must outlive every RenderGraph
/// made with it, and the allocator must outlive the cache.
class RenderGraphCache {
  public:
    explicit RenderGraphCache(ResourceAllocator& allocator, RenderGraphCacheOptions options = {});
    ~RenderGraphCache();
    RenderGraphCache(const RenderGraphCache&) = delete;
    RenderGraphCache& operator=(const RenderGraphCache&) = delete;
    RenderGraphCache(RenderGraphCache&&) = delete;
    RenderGraphCache& operator=(RenderGraphCache&&) = delete;

    /// Graphs executed with this cache so far.
    [[nodiscard]] std::uint64_t framesExecuted() const noexcept;
    /// Backend objects held now: pooled (free or in use) and persistent.
    [[nodiscard]] std::size_t objectsHeld() const noexcept;

    /// Forgets the last result of the pass named `pass`: it runs the next
    /// time it survives culling. Unknown names are ignored.
    void invalidate(std::string_view pass);
    /// Forgets every result and destroys every held object (e.g. before the
    /// GL context goes away). Throws RenderGraphError while a graph is
    /// executing with this cache.
    void clear();

  private:
    friend class RenderGraph;

    struct State;

    /// A persistent resource's storage for this frame.
    struct PersistentBinding {
        detail::ErasedResource* resource = nullptr;
        std::uint64_t generation = 0;  ///< changes whenever the storage is new
    };

    // Used by RenderGraph::execute(), in this order.
    std::uint64_t beginFrame();
    [[nodiscard]] PersistentBinding bindPersistent(std::string_view name,
                                                   const detail::ErasedDescriptor& descriptor);
    [[nodiscard]] detail::ErasedResource& acquire(const detail::ErasedDescriptor& descriptor);
    void release(detail::ErasedResource& resource) noexcept;
    [[nodiscard]] std::uint64_t newStamp() noexcept;
    [[nodiscard]] std::optional<std::uint64_t> versionStamp(std::string_view resource,
                                                            std::uint32_t version) const;
    void setVersionStamp(std::string_view resource, std::uint32_t version, std::uint64_t stamp);
    /// The signature of the pass's last run (null if none); keeps it alive.
    [[nodiscard]] const detail::PassSignature* lookupRun(std::string_view pass);
    void storeRun(std::string_view pass, detail::PassSignature signature);
    void endFrame() noexcept;

    std::unique_ptr<State> state_;
};

}  // namespace vv::render
