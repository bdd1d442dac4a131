// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <cstdint>
#include <limits>

#include "vv/core/Error.h"

namespace vv::render {

/// A render graph was declared or used against its rules: a cycle, a read of
/// a resource version that no pass writes, an access in execute() to a
/// resource the pass did not declare, a duplicate name, a stale write.
/// `what()` names the passes and resources involved.
class RenderGraphError : public Error {
    using Error::Error;
};

class RenderGraph;

/// A typed, versioned reference to one resource of one RenderGraph.
///
/// Only the graph makes valid handles: RenderGraph::importResource(), and the
/// pass builder's create() and write(). Every write() returns a handle with a
/// higher version, so a handle names one state of the resource's content. A
/// default-constructed handle is invalid. Handles are plain values: cheap to
/// copy, comparable, meaningless outside the graph that made them.
template <class R>
class Handle {
  public:
    constexpr Handle() noexcept = default;

    /// False for a default-constructed handle.
    [[nodiscard]] constexpr bool valid() const noexcept { return index_ != kInvalidIndex; }
    /// The resource's position in its graph.
    [[nodiscard]] constexpr std::uint32_t index() const noexcept { return index_; }
    /// 0 for the state at creation / import, +1 per write.
    [[nodiscard]] constexpr std::uint32_t version() const noexcept { return version_; }

    friend constexpr bool operator==(Handle, Handle) noexcept = default;

  private:
    friend class RenderGraph;
    static constexpr std::uint32_t kInvalidIndex = std::numeric_limits<std::uint32_t>::max();

    constexpr Handle(std::uint32_t index, std::uint32_t version) noexcept
        : index_(index), version_(version) {}

    std::uint32_t index_ = kInvalidIndex;
    std::uint32_t version_ = 0;
};

}  // namespace vv::render
