// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// `vesselview-cli centerline --landmark KEY=X,Y,Z`: landmarks given as
// points, placed on the centrelines (vv::planning); `--json` writes them into
// the measurement file (common/MeasurementFile.h).

#include <glm/vec3.hpp>
#include <ostream>
#include <string>
#include <vector>

#include "common/MeasurementFile.h"
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

using app::PlacedLandmark;

/// Places each given landmark (planning::placeLandmark). Writes a note to
/// `err` for a point farther from the centreline than the vessel's
/// inscribed radius there (outside the vessel). Throws InvalidArgumentError
/// for a tree without points.
[[nodiscard]] std::vector<PlacedLandmark> placeLandmarks(const analysis::CenterlineTree& tree,
                                                         const std::vector<GivenLandmark>& given,
                                                         std::ostream& err);

}  // namespace vv::cli
