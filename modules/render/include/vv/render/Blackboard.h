// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <any>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "vv/render/RenderGraphHandle.h"

namespace vv::render {

/// Handles of a frame's resources by name: how passes find what earlier
/// passes made without being handed every handle (Filament's Blackboard).
///
/// A pass that writes a resource puts its newest handle under a well-known
/// name; a later pass reads it by that name (RenderGraph::Builder::read(name)
/// checks the entry exists and names the pass when it does not). A name holds
/// one handle at a time: putting it again replaces the entry, e.g. with the
/// version a later write made. Each RenderGraph owns one
/// (RenderGraph::blackboard()); it lives as long as the graph.
class Blackboard {
  public:
    /// Puts `handle` under `name`, replacing what was there. Throws
    /// RenderGraphError for an empty name or an invalid handle.
    template <class R>
    void put(std::string_view name, Handle<R> handle) {
        checkEntry(name, handle.valid());
        entries_.insert_or_assign(std::string(name), std::any(handle));
    }

    /// The handle under `name`. Throws RenderGraphError naming the entry when
    /// nothing is there or it holds a handle of another resource type.
    template <class R>
    [[nodiscard]] Handle<R> get(std::string_view name) const {
        const std::any& held = entry(name);
        const auto* handle = std::any_cast<Handle<R>>(&held);
        if (handle == nullptr) {
            throwWrongType(name);
        }
        return *handle;
    }

    /// As get(), but nullopt when nothing is under `name` (still throws for
    /// another resource type).
    template <class R>
    [[nodiscard]] std::optional<Handle<R>> find(std::string_view name) const {
        if (!contains(name)) {
            return std::nullopt;
        }
        return get<R>(name);
    }

    [[nodiscard]] bool contains(std::string_view name) const;
    /// Forgets `name`; nothing happens when it is not there.
    void remove(std::string_view name);
    /// Every name, sorted.
    [[nodiscard]] std::vector<std::string> names() const;

  private:
    static void checkEntry(std::string_view name, bool validHandle);
    [[nodiscard]] const std::any& entry(std::string_view name) const;
    [[noreturn]] static void throwWrongType(std::string_view name);

    std::map<std::string, std::any, std::less<>> entries_;
};

}  // namespace vv::render
