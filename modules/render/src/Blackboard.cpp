// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/render/Blackboard.h"

namespace vv::render {

bool Blackboard::contains(std::string_view name) const {
    return entries_.find(name) != entries_.end();
}

void Blackboard::remove(std::string_view name) {
    const auto found = entries_.find(name);
    if (found != entries_.end()) {
        entries_.erase(found);
    }
}

std::vector<std::string> Blackboard::names() const {
    std::vector<std::string> result;
    result.reserve(entries_.size());
    for (const auto& entry : entries_) {
        result.push_back(entry.first);
    }
    return result;
}

void Blackboard::checkEntry(std::string_view name, bool validHandle) {
    if (name.empty()) {
        throw RenderGraphError("render graph blackboard: an entry needs a name");
    }
    if (!validHandle) {
        throw RenderGraphError("render graph blackboard: '" + std::string(name) +
                               "' would hold an invalid handle");
    }
}

const std::any& Blackboard::entry(std::string_view name) const {
    const auto found = entries_.find(name);
    if (found == entries_.end()) {
        throw RenderGraphError("render graph blackboard: nothing is put under '" +
                               std::string(name) + "'");
    }
    return found->second;
}

void Blackboard::throwWrongType(std::string_view name) {
    throw RenderGraphError("render graph blackboard: '" + std::string(name) +
                           "' holds a handle of another resource type");
}

}  // namespace vv::render
