// SPDX-License-Identifier: GPL-3.0-or-later
// Centreline trees of known geometry for the planning tests: polylines
// sampled every millimetre, abscissae from the source, radii from a given
// function, and sections whose sizes follow the radius.
#pragma once

#include <cmath>
#include <functional>
#include <glm/geometric.hpp>
#include <vector>

#include "vv/analysis/Centerlines.h"
#include "vv/analysis/Sections.h"

namespace vv::planning::test {

constexpr double kPi = 3.14159265358979323846;

/// Unit direction `degrees` from +z towards +x (negative: towards -x).
inline glm::dvec3 tilted(double degrees) {
    const double a = degrees * kPi / 180.0;
    return {std::sin(a), 0.0, std::cos(a)};
}

/// Radius of the vessel at a tree abscissa, mm.
using RadiusAt = std::function<double(double)>;

class TreeBuilder {
  public:
    /// Adds a branch from `start` along the unit directions of `legs` (each
    /// `lengthMm` long), leaving `parent`'s end (-1: the source). Returns its id.
    int add(int parent, const glm::dvec3& start,
            const std::vector<std::pair<glm::dvec3, double>>& legs, const RadiusAt& radius) {
        analysis::Branch b;
        b.id = static_cast<int>(tree_.branches.size());
        b.parent = parent;
        double s = parent < 0
                       ? 0.0
                       : tree_.branches[static_cast<std::size_t>(parent)].points.back().abscissaMm;
        glm::dvec3 p = start;
        const auto push = [&](const glm::dvec3& tangent) {
            analysis::CenterlinePoint point;
            point.position = p;
            point.abscissaMm = s;
            point.tangent = tangent;
            point.radiusMm = radius(s);
            b.points.push_back(point);
        };
        push(legs.front().first);
        for (const auto& [direction, length] : legs) {
            const int steps = static_cast<int>(std::lround(length));
            for (int i = 0; i < steps; ++i) {
                p += direction * (length / steps);
                s += length / steps;
                push(direction);
            }
        }
        b.lengthMm = s - b.points.front().abscissaMm;
        b.chordMm = glm::length(b.points.back().position - b.points.front().position);
        if (parent >= 0) {
            tree_.branches[static_cast<std::size_t>(parent)].children.push_back(b.id);
        }
        tree_.branches.push_back(b);
        return b.id;
    }

    /// Marks the ends: the source and every branch without children.
    analysis::CenterlineTree finish() {
        tree_.ends.clear();
        analysis::EndPoint source;
        source.position = tree_.branches.front().points.front().position;
        tree_.ends.push_back(source);
        for (auto& b : tree_.branches) {
            if (b.children.empty()) {
                b.endIndex = static_cast<int>(tree_.ends.size());
                analysis::EndPoint end;
                end.position = b.points.back().position;
                tree_.ends.push_back(end);
            }
        }
        return tree_;
    }

  private:
    analysis::CenterlineTree tree_;
};

/// One round section per centreline point, of the point's radius; those
/// within `junctionMm` of a branch's start or end are in its end zones.
inline std::vector<std::vector<analysis::CrossSection>> roundSections(
    const analysis::CenterlineTree& tree, double junctionMm = 5.0) {
    std::vector<std::vector<analysis::CrossSection>> all;
    for (const auto& b : tree.branches) {
        std::vector<analysis::CrossSection> sections;
        for (std::size_t i = 0; i < b.points.size(); ++i) {
            const auto& p = b.points[i];
            analysis::CrossSection s;
            s.status = analysis::CrossSection::Status::Ok;
            s.branch = b.id;
            s.pointIndex = i;
            s.abscissaMm = p.abscissaMm;
            s.centre = p.position;
            s.normal = p.tangent;
            const double d = 2.0 * p.radiusMm;
            s.equivalentDiameterMm = d;
            s.minDiameterMm = d;
            s.maxDiameterMm = d;
            s.areaMm2 = M_PI * p.radiusMm * p.radiusMm;
            s.inEndZone = p.abscissaMm - b.points.front().abscissaMm < junctionMm ||
                          b.points.back().abscissaMm - p.abscissaMm < junctionMm;
            sections.push_back(s);
        }
        all.push_back(std::move(sections));
    }
    return all;
}

}  // namespace vv::planning::test
