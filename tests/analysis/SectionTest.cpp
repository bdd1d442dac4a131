// SPDX-License-Identifier: GPL-3.0-or-later
// Cross-sections of the tube phantoms against their exact sections: every
// section perpendicular to the axis is a circle of the radius the truth
// gives (equivalent, minimum and maximum diameter within 1 %), centred on
// the centreline; a faceted tube's section is exactly its polygon; a plane
// that also cuts another part of the vessel keeps to its own lumen.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "TubeOptions.h"
#include "vv/analysis/Centerlines.h"
#include "vv/analysis/Sections.h"
#include "vv/demo/TubePhantom.h"

namespace {

using vv::analysis::CenterlineTree;
using vv::analysis::computeCenterlines;
using vv::analysis::computeSections;
using vv::analysis::CrossSection;
using vv::demo::makeTubePhantom;
using vv::demo::TubePhantom;
using vv::demo::TubePhantomOptions;
using vv::demo::TubeShape;

constexpr double kPi = std::numbers::pi;

struct Measured {
    TubePhantom truth;
    CenterlineTree tree;
    std::vector<std::vector<CrossSection>> sections;
};

Measured measure(const TubePhantomOptions& options) {
    Measured m{makeTubePhantom(options), {}, {}};
    m.tree = computeCenterlines(m.truth.mesh);
    m.sections = computeSections(m.truth.mesh, m.tree);
    return m;
}

using vv::test::tubeOptions;

/// Checks every section at least one radius from the ends against the true
/// radius there (the equivalent diameter within `tolerance`, the Feret
/// widths within `feretTolerance`); returns how many were checked.
int expectCircles(const Measured& m, double tolerance, double feretTolerance = 0.01,
                  double minCircularity = 0.98) {
    int checked = 0;
    const double r0 = m.truth.options.radiusMm;
    for (const auto& branch : m.sections) {
        for (const CrossSection& s : branch) {
            const auto [offAxis, at] = m.truth.distanceToAxis(s.centre);
            if (at < r0 || at > m.truth.lengthMm - r0) {
                continue;
            }
            const double d = 2.0 * m.truth.axisAt(at).radiusMm;
            EXPECT_EQ(s.status, CrossSection::Status::Ok) << "at s = " << at;
            EXPECT_NEAR(s.equivalentDiameterMm, d, tolerance * d) << "at s = " << at;
            EXPECT_NEAR(s.minDiameterMm, d, feretTolerance * d) << "at s = " << at;
            EXPECT_NEAR(s.maxDiameterMm, d, feretTolerance * d) << "at s = " << at;
            // The inscribed sphere touches the faceted surface, the contour
            // lies on the curved wall its normals describe: within 0.1 %.
            EXPECT_LE(s.inscribedDiameterMm, s.minDiameterMm * (1.0 + 1e-3)) << "at s = " << at;
            EXPECT_GT(s.circularity, minCircularity) << "at s = " << at;
            EXPECT_LT(s.centreOffsetMm, 0.02 * r0) << "at s = " << at;
            EXPECT_NEAR(std::abs(glm::dot(s.normal, m.truth.axisAt(at).tangent)), 1.0, 1e-3);
            ++checked;
        }
    }
    return checked;
}

TEST(Sections, OfCylindersAreCirclesOfTheirDiameter) {
    for (const double r : {1.0, 5.0, 15.0}) {
        const Measured m = measure(tubeOptions(TubeShape::Cylinder, r, 50'000));
        EXPECT_GT(expectCircles(m, 0.01), 30) << "r = " << r;
    }
}

// Jitter of 2 % of r: the area (the equivalent diameter) averages it out;
// the Feret widths are those of the rough contour, as calipers would take
// them (up to twice the jitter wider), and the rough contour is longer.
TEST(Sections, OfANoisyCylinderWithinOnePercent) {
    const Measured m = measure(tubeOptions(TubeShape::Cylinder, 5.0, 50'000, 0.02));
    EXPECT_GT(expectCircles(m, 0.01, 0.04, 0.9), 100);
}

// The torus' sections perpendicular to the bend are circles too; a plane
// through a 300 degree bend also cuts the far side of the bend, and each
// section keeps to its own lumen.
TEST(Sections, OfABendKeepToTheirOwnLumen) {
    TubePhantomOptions o = tubeOptions(TubeShape::TorusSegment, 5.0, 100'000);
    o.bendAngleDeg = 300.0;
    const Measured m = measure(o);
    EXPECT_GT(expectCircles(m, 0.01), 300);
}

// At a 50 % stenosis the equivalent diameter follows the narrowing: half the
// normal diameter at the throat.
TEST(Sections, FollowAStenosis) {
    const Measured m = measure(tubeOptions(TubeShape::Stenosis, 5.0, 50'000));
    EXPECT_GT(expectCircles(m, 0.01), 100);
    double narrowest = 1e9;
    for (const auto& s : m.sections[0]) {
        if (s.status == CrossSection::Status::Ok) {
            narrowest = std::min(narrowest, s.equivalentDiameterMm);
        }
    }
    EXPECT_NEAR(narrowest, 2.0 * m.truth.narrowestRadiusMm, 0.01 * 2.0 * m.truth.narrowestRadiusMm);
}

// A coarse tube (1k triangles, a dozen or so sides) is a polygon inside the
// circle it stands for: the section is cut from the curved wall its normals
// describe, so it measures the circle, whichever way the plane meets the
// facets, where the polygon alone is about 2 % small in diameter.
TEST(Sections, OfAFacetedTubeMeasureTheCurvedWall) {
    const Measured m = measure(tubeOptions(TubeShape::Cylinder, 5.0, 1'000));
    const int n = m.truth.sides;
    ASSERT_GE(n, 8);
    const double polygonArea = 0.5 * n * 25.0 * std::sin(2.0 * kPi / n);
    const double circleArea = kPi * 25.0;
    int checked = 0;
    double worst = 0.0;
    for (const auto& s : m.sections[0]) {
        const double at = m.truth.distanceToAxis(s.centre).second;
        if (at < 5.0 || at > m.truth.lengthMm - 5.0) {
            continue;
        }
        ASSERT_EQ(s.status, CrossSection::Status::Ok);
        EXPECT_GT(s.areaMm2, polygonArea + 0.5 * (circleArea - polygonArea)) << "at s = " << at;
        EXPECT_NEAR(s.equivalentDiameterMm, 10.0, 0.002 * 10.0) << "at s = " << at;
        EXPECT_NEAR(s.perimeterMm, 10.0 * kPi, 0.005 * 10.0 * kPi) << "at s = " << at;
        worst = std::max(worst, std::abs(s.equivalentDiameterMm / 10.0 - 1.0));
        ++checked;
    }
    EXPECT_GT(checked, 100);
    RecordProperty("faceted_equivalent_diameter_error", std::to_string(worst));
    RecordProperty("polygon_equivalent_diameter_error",
                   std::to_string(std::sqrt(polygonArea / kPi) / 5.0 - 1.0));
}

// One section per centreline point, in order, with frames that follow the
// centreline's.
TEST(Sections, OnePerCentrelinePoint) {
    const Measured m = measure(tubeOptions(TubeShape::TorusSegment, 5.0, 20'000));
    ASSERT_EQ(m.sections.size(), m.tree.branches.size());
    for (std::size_t b = 0; b < m.sections.size(); ++b) {
        ASSERT_EQ(m.sections[b].size(), m.tree.branches[b].points.size());
        for (std::size_t i = 0; i < m.sections[b].size(); ++i) {
            const auto& s = m.sections[b][i];
            const auto& p = m.tree.branches[b].points[i];
            EXPECT_EQ(s.pointIndex, i);
            EXPECT_EQ(s.centre, p.position);
            EXPECT_NEAR(glm::dot(s.axisU, s.normal), 0.0, 1e-9);
            EXPECT_NEAR(glm::dot(s.axisV, s.normal), 0.0, 1e-9);
            if (s.status == CrossSection::Status::Ok) {
                double twiceArea = 0.0;  // counter-clockwise about the normal
                for (std::size_t k = 0; k < s.contour.size(); ++k) {
                    const auto& a = s.contour[k];
                    const auto& c = s.contour[(k + 1) % s.contour.size()];
                    twiceArea += a.x * c.y - c.x * a.y;
                }
                EXPECT_GT(twiceArea, 0.0);
            }
        }
    }
}

}  // namespace
