// SPDX-License-Identifier: GPL-3.0-or-later
// The debug dumps of a compiled RenderGraph, written from its public view
// (passes() and resources()) only.
#include <algorithm>
#include <iomanip>
#include <map>
#include <sstream>
#include <string>
#include <utility>

#include "vv/render/RenderGraph.h"

namespace vv::render {

namespace {

/// A Graphviz double-quoted string; a line break becomes Graphviz's \n escape.
std::string dotString(std::string_view text) {
    std::string out = "\"";
    for (const char c : text) {
        if (c == '\n') {
            out += "\\n";
            continue;
        }
        if (c == '"' || c == '\\') {
            out += '\\';
        }
        out += c;
    }
    return out + "\"";
}

std::string formatMilliseconds(double milliseconds) {
    std::ostringstream text;
    text << std::fixed << std::setprecision(3) << milliseconds << " ms";
    return text.str();
}

std::string versionLabel(const ResourceVersion& version) {
    return version.resource + " v" + std::to_string(version.version);
}

std::string passNodeId(const PassInfo& pass) {
    return dotString("pass:" + pass.name);
}

std::string versionNodeId(const ResourceVersion& version) {
    return dotString("resource:" + version.resource + "@" + std::to_string(version.version));
}

std::string joined(const std::vector<ResourceVersion>& versions) {
    if (versions.empty()) {
        return "-";
    }
    std::string text;
    for (const ResourceVersion& version : versions) {
        text += (text.empty() ? "" : ", ") + versionLabel(version);
    }
    return text;
}

/// Fill colour and style attributes of a pass box.
std::string passStyle(PassState state) {
    switch (state) {
        case PassState::Culled:
            return R"(style="rounded,filled,dashed", fillcolor="#e0e0e0", color="#9e9e9e", )"
                   R"(fontcolor="#9e9e9e")";
        case PassState::Executed:
            return R"(style="rounded,filled", fillcolor="#c8e6c9")";
        case PassState::Cached:
            return R"(style="rounded,filled", fillcolor="#bbdefb")";
        case PassState::Pending:
            break;
    }
    return R"(style="rounded,filled", fillcolor="#ffffff")";
}

}  // namespace

std::string RenderGraph::toDot() const {
    const std::vector<PassInfo> passList = passes();
    const std::vector<ResourceInfo> resourceList = resources();
    std::map<std::string, const ResourceInfo*, std::less<>> resourceByName;
    for (const ResourceInfo& resource : resourceList) {
        resourceByName.emplace(resource.name, &resource);
    }

    // Every resource version some pass touches, and whether a live pass does.
    std::map<std::pair<std::string, std::uint32_t>, bool> versions;
    for (const PassInfo& pass : passList) {
        const bool live = pass.state != PassState::Culled;
        for (const auto* refs : {&pass.reads, &pass.writes}) {
            for (const ResourceVersion& ref : *refs) {
                bool& anyLive = versions[{ref.resource, ref.version}];
                anyLive = anyLive || live;
            }
        }
    }

    std::string dot = "digraph RenderGraph {\n";
    dot += "  rankdir=LR;\n";
    dot += "  node [fontname=\"Helvetica\", fontsize=10];\n";
    dot += "  edge [fontname=\"Helvetica\", fontsize=9];\n";
    for (const PassInfo& pass : passList) {
        std::string label = pass.name + "\n" + std::string(toString(pass.state));
        if (pass.milliseconds.has_value()) {
            label += " " + formatMilliseconds(*pass.milliseconds);
        }
        if (pass.sideEffect) {
            label += "\nside effect";
        }
        dot += "  " + passNodeId(pass) + " [shape=box, " + passStyle(pass.state) +
               ", label=" + dotString(label) + "];\n";
    }
    for (const auto& [key, live] : versions) {
        const ResourceInfo& resource = *resourceByName.at(key.first);
        const ResourceVersion version{key.first, key.second};
        const bool target =
            std::find(resource.targetVersions.begin(), resource.targetVersions.end(), key.second) !=
            resource.targetVersions.end();
        std::string label = versionLabel(version) + "\n" + resource.description + "\n" +
                            std::string(toString(resource.kind));
        std::string style = live ? "" : R"(, style=dashed, color="#9e9e9e", fontcolor="#9e9e9e")";
        if (target) {
            label += ", target";
            style += ", peripheries=2";
        }
        dot += "  " + versionNodeId(version) + " [shape=ellipse" + style +
               ", label=" + dotString(label) + "];\n";
    }
    for (const PassInfo& pass : passList) {
        const std::string edgeStyle =
            pass.state == PassState::Culled ? R"( [style=dashed, color="#9e9e9e"])" : "";
        for (const ResourceVersion& read : pass.reads) {
            dot += "  " + versionNodeId(read) + " -> " + passNodeId(pass) + edgeStyle + ";\n";
        }
        for (const ResourceVersion& write : pass.writes) {
            dot += "  " + passNodeId(pass) + " -> " + versionNodeId(write) + edgeStyle + ";\n";
        }
    }
    dot += "}\n";
    return dot;
}

std::string RenderGraph::toText() const {
    const std::vector<PassInfo> passList = passes();
    const std::vector<ResourceInfo> resourceList = resources();
    const auto culled = std::count_if(passList.begin(), passList.end(), [](const PassInfo& pass) {
        return pass.state == PassState::Culled;
    });

    std::string text = "render graph: " + std::to_string(passList.size()) + " passes (" +
                       std::to_string(culled) + " culled), " + std::to_string(resourceList.size()) +
                       " resources\n";
    for (const PassInfo& pass : passList) {
        text += "pass '" + pass.name + "': " + std::string(toString(pass.state));
        if (pass.order.has_value()) {
            text += " #" + std::to_string(*pass.order);
        }
        if (pass.milliseconds.has_value()) {
            text += ", " + formatMilliseconds(*pass.milliseconds);
        }
        if (pass.sideEffect) {
            text += ", side effect";
        }
        if (!pass.reason.empty()) {
            text += " (" + pass.reason + ")";
        }
        text += "\n  reads:  " + joined(pass.reads) + "\n  writes: " + joined(pass.writes) + "\n";
        if (!pass.parameters.empty()) {
            std::string keys;
            for (const std::string& key : pass.parameters) {
                keys += (keys.empty() ? "" : ", ") + key;
            }
            text += "  depends on: " + keys + "\n";
        }
        if (!pass.renderTargets.empty()) {
            std::string names;
            for (const std::string& name : pass.renderTargets) {
                names += (names.empty() ? "" : ", ") + name;
            }
            text += "  render targets: " + names + "\n";
        }
    }
    text += "resources:\n";
    for (const ResourceInfo& resource : resourceList) {
        text += "  '" + resource.name + "': " + std::string(toString(resource.kind)) + ", " +
                resource.description + ", " + std::to_string(resource.versions) + " version" +
                (resource.versions == 1 ? "" : "s");
        for (const std::uint32_t version : resource.targetVersions) {
            text += ", target v" + std::to_string(version);
        }
        if (resource.firstUse.has_value()) {
            text += ", used from '" + *resource.firstUse + "' to '" + *resource.lastUse + "'";
        } else {
            text += ", unused";
        }
        text += "\n";
    }
    return text;
}

}  // namespace vv::render
