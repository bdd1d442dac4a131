// SPDX-License-Identifier: GPL-3.0-or-later
#include "cli/CenterlineLandmarks.h"

#include <string>

#include "cli/Arguments.h"
#include "cli/Cli.h"
#include "vv/core/NumberText.h"

namespace vv::cli {

namespace {

using planning::LandmarkKind;

std::string presetKeys() {
    std::string keys;
    for (const LandmarkKind kind : planning::landmarkPresets()) {
        keys += (keys.empty() ? "" : ", ") + std::string(planning::landmarkKey(kind));
    }
    return keys;
}

}  // namespace

GivenLandmark parseLandmark(const std::string& text) {
    const auto equals = text.rfind('=');
    if (equals == std::string::npos || equals == 0) {
        throw UsageError("--landmark must be KEY=X,Y,Z, got '" + text + "'");
    }
    const std::string key = text.substr(0, equals);
    const std::vector<std::string> items = splitList(text.substr(equals + 1), "--landmark");
    if (items.size() != 3) {
        throw UsageError("--landmark must be KEY=X,Y,Z (mm), got '" + text + "'");
    }
    GivenLandmark given;
    given.point = {parseNumber(items[0], "--landmark"), parseNumber(items[1], "--landmark"),
                   parseNumber(items[2], "--landmark")};
    if (key.rfind("free:", 0) == 0) {
        given.name = key.substr(5);
        if (given.name.empty()) {
            throw UsageError("--landmark free:NAME needs a name");
        }
        return given;
    }
    const auto kind = planning::landmarkKindOfKey(key);
    if (!kind || *kind == LandmarkKind::Free) {
        throw UsageError("--landmark: unknown key '" + key + "' (one of " + presetKeys() +
                         ", or free:NAME)");
    }
    given.kind = *kind;
    given.name = std::string(planning::landmarkEnglishName(*kind));
    return given;
}

std::vector<PlacedLandmark> placeLandmarks(const analysis::CenterlineTree& tree,
                                           const std::vector<GivenLandmark>& given,
                                           std::ostream& err) {
    std::vector<PlacedLandmark> placed;
    for (const GivenLandmark& g : given) {
        const planning::NearestLocation nearest = planning::nearestLocation(tree, g.point);
        const planning::TreeLocation at = planning::placeLandmark(tree, g.kind, g.point);
        const double radius = planning::sampleAt(tree, nearest.location).radiusMm;
        if (nearest.distanceMm > radius) {
            err << "vesselview-cli: note: the landmark '" << g.name << "' ("
                << fixedText(g.point.x, 2) << ", " << fixedText(g.point.y, 2) << ", "
                << fixedText(g.point.z, 2) << ") is " << fixedText(nearest.distanceMm, 2)
                << " mm from the nearest centreline, outside its vessel (radius "
                << fixedText(radius, 2) << " mm)\n";
        }
        placed.push_back({{g.name, g.kind, at}, g.point, nearest.distanceMm});
    }
    return placed;
}

}  // namespace vv::cli
