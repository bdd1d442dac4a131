// SPDX-License-Identifier: GPL-3.0-or-later
// The aneurysm phantom's truth for lengths measured along a centreline tree
// (vv/demo/AneurysmPhantom.h): what the planning tests compare with.
#pragma once

#include <cmath>

#include "vv/analysis/Centerlines.h"
#include "vv/demo/AneurysmPhantom.h"
#include "vv/planning/VesselPath.h"

namespace vv::test {

/// The length along the phantom's axes between the axis points nearest to
/// two places of the tree: the truth a length along the centreline between
/// landmarks there is measured against (a centreline branches a little
/// before the axes meet, so a bifurcation's landmark is not at the axes'
/// meeting point).
inline double truthAlongAxes(const demo::AneurysmPhantom& phantom,
                             const analysis::CenterlineTree& tree, const planning::TreeLocation& a,
                             const planning::TreeLocation& b) {
    const auto pa = phantom.nearestAxisPoint(planning::sampleAt(tree, a).position);
    const auto pb = phantom.nearestAxisPoint(planning::sampleAt(tree, b).position);
    const double trunk = phantom.options.trunkLengthMm;
    const auto fromTheFork = [trunk](const demo::AneurysmAxisPoint& p) {
        return p.part == demo::AneurysmPart::Trunk ? trunk - p.abscissaMm : p.abscissaMm;
    };
    if (pa.part == pb.part) {
        return std::abs(pa.abscissaMm - pb.abscissaMm);
    }
    return fromTheFork(pa) + fromTheFork(pb);  // through the point where the axes meet
}

}  // namespace vv::test
