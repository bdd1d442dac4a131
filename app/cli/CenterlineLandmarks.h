// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// `vesselview-cli centerline --landmark KEY=X,Y,Z`: landmarks given as
// points, placed on the centrelines (vv::planning), and what `--json` says
// of them: each landmark's place and section, the lengths between every
// pair, and, with any preset of aortic planning, the aortic sizing table.

#include <glm/vec3.hpp>
#include <ostream>
#include <string>
#include <vector>

#include "cli/JsonWriter.h"
#include "vv/analysis/Sections.h"
#include "vv/planning/Landmarks.h"

namespace vv::cli {

/// A landmark as given on the command line.
struct GivenLandmark {
    planning::LandmarkKind kind = planning::LandmarkKind::Free;
    std::string name;  ///< a preset's English name, or the free name given
    glm::dvec3 point{0.0};
};

/// Parses `KEY=X,Y,Z`: KEY a preset's key (lowest_renal_artery, ...) or
/// `free:NAME`. Throws UsageError naming the option and listing the keys.
[[nodiscard]] GivenLandmark parseLandmark(const std::string& text);

/// A landmark placed on the tree, and how far the given point was from the
/// centreline.
struct PlacedLandmark {
    planning::Landmark landmark;
    glm::dvec3 given{0.0};
    double distanceMm = 0.0;  ///< from the given point to the centreline
};

/// Places each given landmark (planning::placeLandmark). Writes a note to
/// `err` for a point farther from the centreline than the vessel's
/// inscribed radius there (outside the vessel). Throws InvalidArgumentError
/// for a tree without points.
[[nodiscard]] std::vector<PlacedLandmark> placeLandmarks(const analysis::CenterlineTree& tree,
                                                         const std::vector<GivenLandmark>& given,
                                                         std::ostream& err);

/// Writes the members "landmarks", "landmark_pairs" and, when a preset is
/// among them, "aortic_sizing" into the open JSON object.
void writeLandmarksJson(JsonWriter& json, const analysis::CenterlineTree& tree,
                        const std::vector<std::vector<analysis::CrossSection>>& sections,
                        const std::vector<PlacedLandmark>& placed);

}  // namespace vv::cli
