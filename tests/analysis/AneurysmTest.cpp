// SPDX-License-Identifier: GPL-3.0-or-later
// The aneurysm phantom (a trunk with a fusiform bulge ending in two iliac
// branches) against its construction: the widest section's equivalent
// diameter within 1 % of the bulge's and where the bulge is widest, the
// centreline on the true axes away from the ends and the bifurcation, the
// two branches and their angle within 1 degree, the trunk's length within
// 1 %; closed and open ends, with and without jitter.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "vv/analysis/Bifurcations.h"
#include "vv/analysis/Centerlines.h"
#include "vv/analysis/Sections.h"
#include "vv/core/Error.h"
#include "vv/demo/AneurysmPhantom.h"

namespace {

using vv::analysis::CenterlineTree;
using vv::analysis::computeCenterlines;
using vv::analysis::computeSections;
using vv::analysis::CrossSection;
using vv::analysis::EndPoint;
using vv::analysis::findBifurcations;
using vv::demo::AneurysmPart;
using vv::demo::AneurysmPhantom;
using vv::demo::AneurysmPhantomOptions;
using vv::demo::makeAneurysmPhantom;

struct Measured {
    AneurysmPhantom truth;
    CenterlineTree tree;
    std::vector<std::vector<CrossSection>> sections;
};

Measured measure(const AneurysmPhantomOptions& options) {
    Measured m{makeAneurysmPhantom(options), {}, {}};
    m.tree = computeCenterlines(m.truth.mesh);
    m.sections = computeSections(m.truth.mesh, m.tree);
    return m;
}

/// The widest section of the trunk that measures the vessel.
const CrossSection* widestTrunkSection(const Measured& m) {
    const CrossSection* widest = nullptr;
    for (const auto& branch : m.sections) {
        for (const CrossSection& s : branch) {
            if (!s.measuresTheVessel() ||
                m.truth.nearestAxisPoint(s.centre).part != AneurysmPart::Trunk) {
                continue;
            }
            if (widest == nullptr || s.equivalentDiameterMm > widest->equivalentDiameterMm) {
                widest = &s;
            }
        }
    }
    return widest;
}

/// The widest section: its equivalent diameter within 1 % of the bulge's
/// true maximum diameter, at a place where the true profile is within 0.2 %
/// of its maximum radius (the profile is flat there: the place itself is
/// known to a few mm only) and within 5 % of the bulge's length of its
/// centre.
void expectTheBulge(const Measured& m) {
    const CrossSection* widest = widestTrunkSection(m);
    ASSERT_NE(widest, nullptr);
    const double truth = m.truth.maxDiameterMm;
    EXPECT_NEAR(widest->equivalentDiameterMm, truth, 0.01 * truth);
    const double at = m.truth.nearestAxisPoint(widest->centre).abscissaMm;
    EXPECT_NEAR(at, m.truth.maxDiameterAbscissaMm, 0.05 * m.truth.options.bulgeLengthMm);
    EXPECT_GT(m.truth.trunkRadiusAt(at), 0.998 * m.truth.options.maxRadiusMm);
    ::testing::Test::RecordProperty("max_diameter_error",
                                    std::to_string(widest->equivalentDiameterMm / truth - 1.0));
    ::testing::Test::RecordProperty("widest_at_minus_truth_mm",
                                    std::to_string(at - m.truth.maxDiameterAbscissaMm));
}

/// Every centreline point two radii clear of the ends and the bifurcation
/// point lies within 2 % of its part's radius of the true axis (the
/// trunk's radius r on the trunk, the bulge included).
void expectOnTheAxes(const Measured& m, double tolerance = 0.02) {
    const auto& o = m.truth.options;
    double worst = 0.0;
    int checked = 0;
    for (const auto& branch : m.tree.branches) {
        for (const auto& p : branch.points) {
            const auto axis = m.truth.nearestAxisPoint(p.position);
            if (glm::length(p.position - m.truth.bifurcationPoint) < 2.0 * o.radiusMm) {
                continue;
            }
            const bool trunk = axis.part == AneurysmPart::Trunk;
            const double r = trunk ? o.radiusMm : o.iliacRadiusMm;
            const double end = trunk ? 0.0 : o.iliacLengthMm;
            if (std::abs(axis.abscissaMm - end) < 2.0 * r) {
                continue;
            }
            EXPECT_LT(axis.distanceMm, tolerance * r)
                << "part " << static_cast<int>(axis.part) << " at s = " << axis.abscissaMm;
            worst = std::max(worst, axis.distanceMm / r);
            ++checked;
        }
    }
    EXPECT_GT(checked, 400);
    ::testing::Test::RecordProperty("worst_axis_distance_per_r", std::to_string(worst));
}

/// Along the path from the source, the abscissa where the centreline
/// crosses the plane of the bifurcation point (z = trunk length).
double abscissaAtBifurcationPlane(const Measured& m) {
    const double z = m.truth.options.trunkLengthMm;
    const auto& points = m.tree.branches[0].points;
    for (std::size_t i = 0; i + 1 < points.size(); ++i) {
        const double z0 = points[i].position.z;
        const double z1 = points[i + 1].position.z;
        if (z0 <= z && z1 > z) {
            const double t = (z - z0) / (z1 - z0);
            return points[i].abscissaMm + t * (points[i + 1].abscissaMm - points[i].abscissaMm);
        }
    }
    // The paths parted before the plane: continue the trunk's last point
    // along +z (the trunk is straight there).
    return points.back().abscissaMm + (z - points.back().position.z);
}

/// Three branches: the trunk from the source, two children ending towards
/// +x and -x; one bifurcation, its angle within 1 degree.
void expectTheBifurcation(const Measured& m) {
    ASSERT_EQ(m.tree.branches.size(), 3U);
    ASSERT_EQ(m.tree.branches[0].children.size(), 2U);
    double plusX = 0.0;
    double minusX = 0.0;
    for (const int child : m.tree.branches[0].children) {
        const double x = m.tree.branches[static_cast<std::size_t>(child)].points.back().position.x;
        plusX = std::max(plusX, x);
        minusX = std::min(minusX, x);
    }
    const auto& o = m.truth.options;
    const double reach = o.iliacLengthMm * m.truth.iliacDirections[0].x;
    EXPECT_GT(plusX, 0.9 * reach);
    EXPECT_LT(minusX, -0.9 * reach);
    const auto bifurcations = findBifurcations(m.tree);
    ASSERT_EQ(bifurcations.size(), 1U);
    EXPECT_NEAR(bifurcations[0].angleDeg, o.bifurcationAngleDeg, 1.0);
    ::testing::Test::RecordProperty(
        "angle_error_deg", std::to_string(bifurcations[0].angleDeg - o.bifurcationAngleDeg));
}

AneurysmPhantomOptions phantomOptions(bool open = false, double jitter = 0.0) {
    AneurysmPhantomOptions o;
    o.targetTriangles = 50'000;
    o.openEnds = open;
    o.jitterFraction = jitter;
    return o;
}

TEST(Aneurysm, ClosedWidestSectionIsTheBulge) {
    const Measured m = measure(phantomOptions());
    EXPECT_NEAR(static_cast<double>(m.truth.mesh.triangleCount()), 50'000.0, 5'000.0);
    expectTheBulge(m);
    expectOnTheAxes(m);
}

// Closed: the source is the trunk's tip, one radius before the trunk's
// start; the trunk's length from there to the bifurcation point's plane.
TEST(Aneurysm, ClosedBranchesAngleAndTrunkLength) {
    const Measured m = measure(phantomOptions());
    expectTheBifurcation(m);
    ASSERT_EQ(m.tree.ends.size(), 3U);
    EXPECT_EQ(m.tree.ends[0].kind, EndPoint::Kind::Tip);
    const auto& o = m.truth.options;
    const double truth = o.trunkLengthMm + o.radiusMm;
    const double measured = abscissaAtBifurcationPlane(m);
    EXPECT_NEAR(measured, truth, 0.01 * truth);
    ::testing::Test::RecordProperty("trunk_length_error", std::to_string(measured / truth - 1.0));
}

// Open ends (CFD-like): the centrelines start and end at the cut loops'
// centres, the trunk's length is exact from its open end.
TEST(Aneurysm, OpenEndsBulgeAxesAndTrunkLength) {
    const Measured m = measure(phantomOptions(true));
    ASSERT_EQ(m.tree.ends.size(), 3U);
    for (const EndPoint& end : m.tree.ends) {
        EXPECT_EQ(end.kind, EndPoint::Kind::OpenEnd);
    }
    EXPECT_NEAR(glm::length(m.tree.ends[0].position), 0.0, 0.02 * m.truth.options.radiusMm);
    expectTheBulge(m);
    expectOnTheAxes(m);
    expectTheBifurcation(m);
    const double truth = m.truth.options.trunkLengthMm;
    const double measured = abscissaAtBifurcationPlane(m);
    EXPECT_NEAR(measured, truth, 0.01 * truth);
    ::testing::Test::RecordProperty("trunk_length_error", std::to_string(measured / truth - 1.0));
}

// A jitter of 2 % of r (a noisy segmentation): the area averages it out.
// Open ends, as the jittered tubes of the benchmark: on a jittered rounded
// cap the tip search finds spurious tips around the source (an open
// question of the analysis, docs/benchmarks/analysis.md).
TEST(Aneurysm, JitteredWidestSectionWithinOnePercent) {
    const Measured m = measure(phantomOptions(true, 0.02));
    expectTheBulge(m);
    expectOnTheAxes(m);
    expectTheBifurcation(m);
}

TEST(AneurysmPhantom, IsDeterministicAndRefusesOptionsOutOfRange) {
    AneurysmPhantomOptions o;
    o.targetTriangles = 2'000;
    o.jitterFraction = 0.02;
    const AneurysmPhantom a = makeAneurysmPhantom(o);
    const AneurysmPhantom b = makeAneurysmPhantom(o);
    EXPECT_EQ(a.mesh.positions, b.mesh.positions);
    EXPECT_EQ(a.mesh.indices, b.mesh.indices);
    EXPECT_NEAR(a.trunkRadiusAt(o.bulgeCentreMm), o.maxRadiusMm, 1e-12);
    EXPECT_NEAR(a.trunkRadiusAt(o.bulgeCentreMm + o.bulgeLengthMm), o.radiusMm, 1e-12);

    const auto refused = [](auto change) {
        AneurysmPhantomOptions bad;
        change(bad);
        EXPECT_THROW((void)makeAneurysmPhantom(bad), vv::InvalidArgumentError);
    };
    refused([](AneurysmPhantomOptions& x) { x.radiusMm = 0.0; });
    refused([](AneurysmPhantomOptions& x) { x.maxRadiusMm = x.radiusMm; });
    refused([](AneurysmPhantomOptions& x) { x.bulgeLengthMm = 40.0; });  // too sharp a bulge
    refused([](AneurysmPhantomOptions& x) { x.bulgeCentreMm = 20.0; });  // past the start
    refused([](AneurysmPhantomOptions& x) { x.iliacRadiusMm = 2.0 * x.radiusMm; });
    refused([](AneurysmPhantomOptions& x) { x.bifurcationAngleDeg = 150.0; });
    refused([](AneurysmPhantomOptions& x) { x.iliacLengthMm = 10.0; });
    refused([](AneurysmPhantomOptions& x) { x.targetTriangles = 10; });
    refused([](AneurysmPhantomOptions& x) { x.jitterFraction = std::nan(""); });
}

}  // namespace
