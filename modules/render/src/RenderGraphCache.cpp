// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/render/RenderGraphCache.h"

#include <algorithm>
#include <functional>
#include <map>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "vv/render/RenderGraphHandle.h"

namespace vv::render {

namespace {

/// One backend object of the pool, free or in use (by a transient resource
/// for part of a frame, or by a persistent resource across frames).
struct PoolSlot {
    std::unique_ptr<detail::ErasedDescriptor> descriptor;
    std::unique_ptr<detail::ErasedResource> resource;
    bool inUse = false;
    std::uint64_t lastUsedFrame = 0;
};

/// The storage and content stamps of one persistent resource.
struct PersistentRecord {
    PoolSlot* slot = nullptr;
    std::uint64_t generation = 0;
    std::vector<std::uint64_t> stamps;  ///< per version; 0 = no known content
    std::uint64_t lastUsedFrame = 0;
};

/// The last run of one pass.
struct RunRecord {
    detail::PassSignature signature;
    std::uint64_t lastUsedFrame = 0;
};

/// True when something last used in `lastUsed` has been idle for `retain` frames at `frame`.
bool expired(std::uint64_t lastUsed, int retain, std::uint64_t frame) noexcept {
    return lastUsed + static_cast<std::uint64_t>(retain) <= frame;
}

}  // namespace

struct RenderGraphCache::State {
    ResourceAllocator* allocator = nullptr;
    int retainFrames = 1;
    std::uint64_t frame = 0;
    std::uint64_t stampCounter = 0;
    std::uint64_t generationCounter = 0;
    bool executing = false;
    /// The pool: slots bucketed by descriptor hash, matched by descriptor equality.
    std::unordered_map<std::size_t, std::vector<std::unique_ptr<PoolSlot>>> pool;
    std::unordered_map<const detail::ErasedResource*, PoolSlot*> inUse;
    std::map<std::string, PersistentRecord, std::less<>> persistent;
    std::map<std::string, RunRecord, std::less<>> runs;

    PoolSlot& acquireSlot(const detail::ErasedDescriptor& descriptor) {
        auto& bucket = pool[descriptor.hash()];
        for (const auto& slot : bucket) {
            if (!slot->inUse && slot->descriptor->equals(descriptor)) {
                // Another resource (or an expired one) held it: its content is stale.
                slot->descriptor->recycle(*slot->resource);
                markInUse(*slot);
                return *slot;
            }
        }
        auto slot = std::make_unique<PoolSlot>();
        slot->descriptor = descriptor.clone();
        slot->resource = descriptor.create(*allocator);
        bucket.push_back(std::move(slot));
        markInUse(*bucket.back());
        return *bucket.back();
    }

    void markInUse(PoolSlot& slot) {
        inUse.emplace(slot.resource.get(), &slot);
        slot.inUse = true;
        slot.lastUsedFrame = frame;
    }

    void releaseSlot(const detail::ErasedResource& resource) noexcept {
        const auto found = inUse.find(&resource);
        if (found == inUse.end()) {
            return;
        }
        found->second->inUse = false;
        found->second->lastUsedFrame = frame;
        inUse.erase(found);
    }

    void collectGarbage() noexcept {
        for (auto it = persistent.begin(); it != persistent.end();) {
            if (expired(it->second.lastUsedFrame, retainFrames, frame)) {
                if (it->second.slot != nullptr) {
                    // Idle as long as the record: the pool sweep below frees it.
                    releaseSlot(*it->second.slot->resource);
                    it->second.slot->lastUsedFrame = it->second.lastUsedFrame;
                }
                it = persistent.erase(it);
            } else {
                ++it;
            }
        }
        std::erase_if(runs, [this](const auto& entry) {
            return expired(entry.second.lastUsedFrame, retainFrames, frame);
        });
        for (auto it = pool.begin(); it != pool.end();) {
            std::erase_if(it->second, [this](const std::unique_ptr<PoolSlot>& slot) {
                return !slot->inUse && expired(slot->lastUsedFrame, retainFrames, frame);
            });
            it = it->second.empty() ? pool.erase(it) : std::next(it);
        }
    }
};

RenderGraphCache::RenderGraphCache(ResourceAllocator& allocator, RenderGraphCacheOptions options)
    : state_(std::make_unique<State>()) {
    state_->allocator = &allocator;
    state_->retainFrames = std::max(options.retainFrames, 1);
}

RenderGraphCache::~RenderGraphCache() = default;

std::uint64_t RenderGraphCache::framesExecuted() const noexcept {
    return state_->frame;
}

std::size_t RenderGraphCache::objectsHeld() const noexcept {
    std::size_t count = 0;
    for (const auto& entry : state_->pool) {
        count += entry.second.size();
    }
    return count;
}

void RenderGraphCache::invalidate(std::string_view pass) {
    const auto found = state_->runs.find(pass);
    if (found != state_->runs.end()) {
        state_->runs.erase(found);
    }
}

void RenderGraphCache::clear() {
    if (state_->executing) {
        throw RenderGraphError("render graph cache: cannot clear while a graph executes");
    }
    state_->persistent.clear();
    state_->runs.clear();
    state_->inUse.clear();
    state_->pool.clear();
}

std::uint64_t RenderGraphCache::beginFrame() {
    if (state_->executing) {
        throw RenderGraphError("render graph cache: another graph is executing with this cache");
    }
    state_->executing = true;
    return ++state_->frame;
}

RenderGraphCache::PersistentBinding RenderGraphCache::bindPersistent(
    std::string_view name, const detail::ErasedDescriptor& descriptor) {
    auto found = state_->persistent.find(name);
    if (found == state_->persistent.end()) {
        found = state_->persistent.emplace(std::string(name), PersistentRecord{}).first;
    }
    PersistentRecord& record = found->second;
    if (record.slot == nullptr || !record.slot->descriptor->equals(descriptor)) {
        if (record.slot != nullptr) {
            state_->releaseSlot(*record.slot->resource);
            record.slot = nullptr;
        }
        record.slot = &state_->acquireSlot(descriptor);
        record.generation = ++state_->generationCounter;
        record.stamps.clear();
    }
    record.lastUsedFrame = state_->frame;
    record.slot->lastUsedFrame = state_->frame;
    return PersistentBinding{record.slot->resource.get(), record.generation};
}

detail::ErasedResource& RenderGraphCache::acquire(const detail::ErasedDescriptor& descriptor) {
    return *state_->acquireSlot(descriptor).resource;
}

void RenderGraphCache::release(detail::ErasedResource& resource) noexcept {
    state_->releaseSlot(resource);
}

std::uint64_t RenderGraphCache::newStamp() noexcept {
    return ++state_->stampCounter;
}

std::optional<std::uint64_t> RenderGraphCache::versionStamp(std::string_view resource,
                                                            std::uint32_t version) const {
    const auto found = state_->persistent.find(resource);
    if (found == state_->persistent.end() || version >= found->second.stamps.size() ||
        found->second.stamps[version] == 0) {
        return std::nullopt;
    }
    return found->second.stamps[version];
}

void RenderGraphCache::setVersionStamp(std::string_view resource, std::uint32_t version,
                                       std::uint64_t stamp) {
    const auto found = state_->persistent.find(resource);
    if (found == state_->persistent.end()) {
        return;
    }
    auto& stamps = found->second.stamps;
    if (version >= stamps.size()) {
        stamps.resize(static_cast<std::size_t>(version) + 1, 0);
    }
    stamps[version] = stamp;
}

const detail::PassSignature* RenderGraphCache::lookupRun(std::string_view pass) {
    const auto found = state_->runs.find(pass);
    if (found == state_->runs.end()) {
        return nullptr;
    }
    found->second.lastUsedFrame = state_->frame;
    return &found->second.signature;
}

void RenderGraphCache::storeRun(std::string_view pass, detail::PassSignature signature) {
    auto found = state_->runs.find(pass);
    if (found == state_->runs.end()) {
        found = state_->runs.emplace(std::string(pass), RunRecord{}).first;
    }
    found->second.signature = std::move(signature);
    found->second.lastUsedFrame = state_->frame;
}

void RenderGraphCache::endFrame() noexcept {
    state_->collectGarbage();
    state_->executing = false;
}

}  // namespace vv::render
