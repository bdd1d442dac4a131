// SPDX-License-Identifier: GPL-3.0-or-later
// The aneurysm phantom (a trunk with a fusiform bulge ending in two iliac
// branches) against its construction: the widest section's equivalent
// diameter within 1 % of the bulge's and where the bulge is widest, the
// centreline on the true axes away from the ends and the bifurcation, the
// two branches and their angle within 1 degree, the trunk's length within
// 1 %; closed and open ends, with and without jitter.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <utility>

#include "AnalysisAgreement.h"
#include "vv/analysis/Centerlines.h"
#include "vv/analysis/Sections.h"
#include "vv/core/Error.h"
#include "vv/demo/AneurysmPhantom.h"

namespace aneurysm_test {

namespace {

using vv::analysis::EndPoint;
using vv::bench::AneurysmAgreement;
using vv::demo::AneurysmPhantom;
using vv::demo::AneurysmPhantomOptions;
using vv::demo::makeAneurysmPhantom;

struct Measured {
    AneurysmPhantom truth;
    vv::analysis::CenterlineTree tree;
    AneurysmAgreement agreement;
};

Measured measure(const AneurysmPhantomOptions& options) {
    Measured m{makeAneurysmPhantom(options), {}, {}};
    m.tree = vv::analysis::computeCenterlines(m.truth.mesh);
    const auto sections = vv::analysis::computeSections(m.truth.mesh, m.tree);
    m.agreement = vv::bench::measureAneurysm(m.truth, m.tree, sections);
    return m;
}

void record(const char* name, double value) {
    ::testing::Test::RecordProperty(name, std::to_string(value));
}

/// The widest section: its equivalent diameter within 1 % of the bulge's
/// true maximum diameter, at a place where the true profile is within 0.2 %
/// of its maximum radius (the profile is flat there: the place itself is
/// known to a few mm only) and within 5 % of the bulge's length of its
/// centre.
void expectTheBulge(const Measured& m) {
    const AneurysmAgreement& a = m.agreement;
    const auto& o = m.truth.options;
    EXPECT_NEAR(a.maxDiameterError, 0.0, 0.01);
    EXPECT_NEAR(a.widestAbscissaMm, m.truth.maxDiameterAbscissaMm, 0.05 * o.bulgeLengthMm);
    EXPECT_GT(a.widestTrueRadiusMm, 0.998 * o.maxRadiusMm);
    record("max_diameter_error", a.maxDiameterError);
    record("widest_at_minus_truth_mm", a.widestAbscissaMm - m.truth.maxDiameterAbscissaMm);
}

/// Every centreline point two radii clear of the ends and the bifurcation
/// point lies within 2 % of its part's radius of the true axis (the
/// trunk's radius r on the trunk, the bulge included).
void expectOnTheAxes(const Measured& m) {
    EXPECT_GT(m.agreement.axisPoints, 400U);
    EXPECT_LT(m.agreement.worstAxisDistancePerR, 0.02);
    record("worst_axis_distance_per_r", m.agreement.worstAxisDistancePerR);
}

/// Three branches: the trunk from the source, two children ending towards
/// +x and -x; one bifurcation, its angle within 1 degree.
void expectTheBifurcation(const Measured& m) {
    const AneurysmAgreement& a = m.agreement;
    EXPECT_EQ(a.branches, 3U);
    EXPECT_EQ(a.ends, 3U);
    const auto& o = m.truth.options;
    const double reach = o.iliacLengthMm * m.truth.iliacDirections[0].x;
    EXPECT_GT(a.childEndMaxX, 0.9 * reach);
    EXPECT_LT(a.childEndMinX, -0.9 * reach);
    ASSERT_EQ(a.bifurcations, 1U);
    EXPECT_NEAR(a.angleErrorDeg, 0.0, 1.0);
    record("angle_error_deg", a.angleErrorDeg);
}

/// The trunk's length from the source's end to the bifurcation point's
/// plane within 1 % (closed: from the tip, one radius before the trunk's
/// start; open: from the open end).
void expectTheTrunkLength(const Measured& m) {
    EXPECT_NEAR(m.agreement.trunkLengthError, 0.0, 0.01);
    record("trunk_length_error", m.agreement.trunkLengthError);
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
    ASSERT_FALSE(m.tree.ends.empty());
    EXPECT_EQ(m.tree.ends[0].kind, EndPoint::Kind::Tip);
    EXPECT_NEAR(m.tree.ends[0].position.z, -m.truth.options.radiusMm,
                0.02 * m.truth.options.radiusMm);
    expectTheTrunkLength(m);
}

// Open ends (CFD-like): the centrelines start and end at the cut loops'
// centres, the trunk's length is exact from its open end.
TEST(Aneurysm, OpenEndsBulgeAxesAndTrunkLength) {
    const Measured m = measure(phantomOptions(true));
    ASSERT_FALSE(m.tree.ends.empty());
    for (const EndPoint& end : m.tree.ends) {
        EXPECT_EQ(end.kind, EndPoint::Kind::OpenEnd);
    }
    EXPECT_NEAR(glm::length(m.tree.ends[0].position), 0.0, 0.02 * m.truth.options.radiusMm);
    expectTheBulge(m);
    expectOnTheAxes(m);
    expectTheBifurcation(m);
    expectTheTrunkLength(m);
    // A fine wall gets no points added, its rims neither (their turn onto the
    // cap once read as a tiny radius there).
    for (const std::string& note : m.tree.notes) {
        EXPECT_EQ(note.find("points added"), std::string::npos) << note;
    }
}

// A jitter of 2 % of r (a noisy segmentation): the area averages it out.
TEST(Aneurysm, JitteredWidestSectionWithinOnePercent) {
    const Measured m = measure(phantomOptions(true, 0.02));
    expectTheBulge(m);
    expectOnTheAxes(m);
    expectTheBifurcation(m);
}

// Closed and jittered: the medial axis spikes towards the rough rounded
// cap the source sits in; none of the spikes reads as a vessel.
TEST(Aneurysm, ClosedJitteredFindsOnlyTheThreeVessels) {
    const Measured m = measure(phantomOptions(false, 0.02));
    expectTheBifurcation(m);
    expectTheBulge(m);
}

// A million triangles, closed and jittered: the rough cap's spikes are long
// against their own spheres, and the source's end, found by going two of
// their radii back, once ended 3 mm aside with the trunk 1.2 % long. Two
// radii of the widest sphere on the way keep it at the cap's apex.
TEST(Aneurysm, AMillionJitteredTrianglesKeepTheSourceAtTheApex) {
    AneurysmPhantomOptions o = phantomOptions(false, 0.02);
    o.targetTriangles = 1'000'000;
    Measured m{makeAneurysmPhantom(o), {}, {}};
    vv::analysis::VesselAnalysis analysis = vv::analysis::analyseVessels(m.truth.mesh);
    m.tree = std::move(analysis.tree);
    m.agreement = vv::bench::measureAneurysm(m.truth, m.tree, analysis.sections);
    ASSERT_FALSE(m.tree.ends.empty());
    const glm::dvec3 source = m.tree.ends[0].position;
    EXPECT_LT(glm::length(glm::dvec2(source.x, source.y)), 0.05 * o.radiusMm);
    EXPECT_NEAR(source.z, -o.radiusMm, 0.05 * o.radiusMm);
    expectTheTrunkLength(m);
}

// A thousand triangles (a coarse, decimated segmentation): the facets'
// chords and their uneven spacing around the lumen put the mesh's own wall
// 6 to 9 % of r off the true wall, so the 2 % axis goal cannot be checked
// against analytic truth here. The centreline is nearer the true axis than
// the wall is to the true wall; every other goal holds. The trunk ends at
// the bifurcation: on the symmetric open surface the minimal-path tree forked
// 40 mm before it and ran two paths 0.2 mm apart down the trunk, which made
// the bifurcation there and its angle 58 degrees off.
TEST(Aneurysm, AThousandTrianglesKeepTheAxisNearerTheTruthThanTheirOwnWall) {
    for (const bool open : {false, true}) {
        for (const double jitter : {0.0, 0.02}) {
            SCOPED_TRACE(std::string(open ? "open" : "closed") +
                         (jitter > 0.0 ? ", jittered" : ""));
            AneurysmPhantomOptions o = phantomOptions(open, jitter);
            o.targetTriangles = 1'000;
            const Measured m = measure(o);
            const AneurysmAgreement& a = m.agreement;
            EXPECT_GT(a.axisPoints, 50U);
            EXPECT_GT(a.worstWallDistancePerR, 0.02);
            EXPECT_LT(a.worstAxisDistancePerR, a.worstWallDistancePerR);
            EXPECT_EQ(a.branches, 3U);
            EXPECT_EQ(a.ends, 3U);
            EXPECT_NEAR(a.maxDiameterError, 0.0, 0.01);
            EXPECT_NEAR(a.trunkLengthError, 0.0, 0.01);
            ASSERT_EQ(a.bifurcations, 1U);
            EXPECT_NEAR(a.angleErrorDeg, 0.0, 1.0);
            ASSERT_FALSE(m.tree.branches.empty());
            EXPECT_NEAR(m.tree.branches[0].points.back().position.z, o.trunkLengthMm,
                        0.5 * o.radiusMm);
            record("worst_axis_distance_per_r", a.worstAxisDistancePerR);
            record("worst_wall_distance_per_r", a.worstWallDistancePerR);
        }
    }
}

// The same symmetric surface ten times smaller (a 1 mm trunk): the paths are
// compared in steps of the local radius, so they part at the bifurcation at
// every scale.
TEST(Aneurysm, PathsPartAtTheBifurcationAtATenthOfTheSize) {
    AneurysmPhantomOptions o = phantomOptions(true);
    o.targetTriangles = 1'000;
    AneurysmPhantom p = makeAneurysmPhantom(o);
    for (glm::vec3& position : p.mesh.positions) {
        position *= 0.1F;
    }
    const auto tree = vv::analysis::computeCenterlines(p.mesh);
    ASSERT_EQ(tree.branches.size(), 3U);
    EXPECT_NEAR(tree.branches[0].points.back().position.z, 0.1 * o.trunkLengthMm,
                0.05 * o.radiusMm);
}

// The wall measure itself: under 2 % of r on a wall of 20k triangles (its
// vertices on the truth, its chords a little inside), and the distance of a
// wall moved outward by a known amount.
TEST(AneurysmPhantom, TheWallsOwnDistanceMeasuresAKnownOffset) {
    AneurysmPhantomOptions o = phantomOptions();
    o.targetTriangles = 20'000;
    AneurysmPhantom p = makeAneurysmPhantom(o);
    const double before = vv::bench::measureAneurysm(p, {}, {}).worstWallDistancePerR;
    EXPECT_LT(before, 0.02);    // its vertices on the truth, its chords inside it
    const double offset = 0.5;  // mm: 5 % of the trunk's r, 8 % of an iliac's
    for (std::size_t i = 0; i < p.mesh.positions.size(); ++i) {
        p.mesh.positions[i] += static_cast<float>(offset) * glm::normalize(p.mesh.normals[i]);
    }
    const double after = vv::bench::measureAneurysm(p, {}, {}).worstWallDistancePerR;
    EXPECT_NEAR(after, offset / o.iliacRadiusMm, before + 0.005);
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

}  // namespace aneurysm_test
