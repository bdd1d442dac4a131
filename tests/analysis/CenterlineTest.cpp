// SPDX-License-Identifier: GPL-3.0-or-later
// Centrelines of the tube phantoms against their analytic axes: position
// (within 2 % of the radius away from the ends), length (1 %), curvature
// (5 %), the inscribed radius, the ends; and the errors of surfaces that
// cannot be analysed.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stop_token>
#include <string>

#include "TubeOptions.h"
#include "vv/analysis/Centerlines.h"
#include "vv/demo/TubePhantom.h"

namespace {

using vv::analysis::AnalysisError;
using vv::analysis::CenterlineOptions;
using vv::analysis::CenterlineTree;
using vv::analysis::computeCenterlines;
using vv::analysis::EndPoint;
using vv::demo::makeTubePhantom;
using vv::demo::TubePhantom;
using vv::demo::TubePhantomOptions;
using vv::demo::TubeShape;

TubePhantom phantom(TubeShape shape, double radius, std::size_t triangles, double jitter = 0.0,
                    bool capped = false) {
    TubePhantomOptions o = vv::test::tubeOptions(shape, radius, triangles, jitter);
    o.capped = capped;
    return makeTubePhantom(o);
}

double totalLength(const CenterlineTree& tree) {
    double length = 0.0;
    for (const auto& branch : tree.branches) {
        length += branch.lengthMm;
    }
    return length;
}

struct TubeCase {
    const char* name;
    TubeShape shape;
    double radius;
    std::size_t triangles;
    double jitter;
};

class TubeCenterline : public ::testing::TestWithParam<TubeCase> {};

// An open tube gives one branch from one open end to the other, on the true
// axis within 2 % of r, as long as the axis within 1 %.
TEST_P(TubeCenterline, FollowsTheTrueAxis) {
    const TubeCase c = GetParam();
    const TubePhantom truth = phantom(c.shape, c.radius, c.triangles, c.jitter);
    const CenterlineTree tree = computeCenterlines(truth.mesh);
    ASSERT_EQ(tree.branches.size(), 1U);
    ASSERT_EQ(tree.ends.size(), 2U);
    for (const EndPoint& end : tree.ends) {
        EXPECT_EQ(end.kind, EndPoint::Kind::OpenEnd);
        EXPECT_NEAR(end.radiusMm, c.radius, 0.05 * c.radius);
    }
    const double worst = vv::test::worstAxisDistance(tree, truth, c.radius);
    RecordProperty("worst_axis_distance_per_r", std::to_string(worst / c.radius));
    RecordProperty("length_error", std::to_string(totalLength(tree) / truth.lengthMm - 1.0));
    EXPECT_LT(worst, 0.02 * c.radius);
    EXPECT_NEAR(totalLength(tree), truth.lengthMm, 0.01 * truth.lengthMm);
    // The ends are the open loops' centres: the axis' ends.
    const auto& points = tree.branches[0].points;
    const double startError = std::min(truth.distanceToAxis(points.front().position).first,
                                       truth.distanceToAxis(points.back().position).first);
    EXPECT_LT(startError, 0.05 * c.radius);
    EXPECT_LT(std::min(glm::length(points.front().position - truth.axis.front().position),
                       glm::length(points.front().position - truth.axis.back().position)),
              0.05 * c.radius);
}

INSTANTIATE_TEST_SUITE_P(
    Phantoms, TubeCenterline,
    ::testing::Values(TubeCase{"cylinder_r1_fine", TubeShape::Cylinder, 1.0, 50'000, 0.0},
                      TubeCase{"cylinder_r5_coarse", TubeShape::Cylinder, 5.0, 1'000, 0.0},
                      TubeCase{"cylinder_r5", TubeShape::Cylinder, 5.0, 50'000, 0.0},
                      TubeCase{"cylinder_r15_noisy", TubeShape::Cylinder, 15.0, 50'000, 0.02},
                      TubeCase{"cylinder_r5_coarse_noisy", TubeShape::Cylinder, 5.0, 1'000, 0.02},
                      TubeCase{"torus_r5", TubeShape::TorusSegment, 5.0, 50'000, 0.0},
                      TubeCase{"torus_r5_noisy", TubeShape::TorusSegment, 5.0, 50'000, 0.02},
                      TubeCase{"stenosis_r5", TubeShape::Stenosis, 5.0, 50'000, 0.0}),
    [](const ::testing::TestParamInfo<TubeCase>& tube) { return std::string(tube.param.name); });

// The torus segment's curvature is 1 / bend radius everywhere along it.
TEST(Centerline, CurvatureOfATorusSegmentWithinFivePercent) {
    const TubePhantom truth = phantom(TubeShape::TorusSegment, 5.0, 50'000);
    const CenterlineTree tree = computeCenterlines(truth.mesh);
    ASSERT_EQ(tree.branches.size(), 1U);
    const double expected = 1.0 / truth.options.bendRadiusMm;
    int checked = 0;
    for (const auto& p : tree.branches[0].points) {
        if (p.abscissaMm > 2.0 * truth.options.radiusMm &&
            p.abscissaMm < truth.lengthMm - 2.0 * truth.options.radiusMm) {
            EXPECT_NEAR(p.curvature, expected, 0.05 * expected) << "at s = " << p.abscissaMm;
            EXPECT_NEAR(p.torsion, 0.0, 0.05 * expected) << "a planar bend has no torsion";
            ++checked;
        }
    }
    EXPECT_GT(checked, 100);
    EXPECT_NEAR(tree.branches[0].tortuosity(), truth.lengthMm / truth.chordMm - 1.0, 0.01);
}

// Points every step, frames that stay perpendicular and never twist about
// the tangent (a planar bend: the binormal stays the bend's axis).
TEST(Centerline, ResampledWithRotationMinimisingFrames) {
    const TubePhantom truth = phantom(TubeShape::TorusSegment, 5.0, 50'000);
    CenterlineOptions options;
    options.stepMm = 0.5;
    const CenterlineTree tree = computeCenterlines(truth.mesh, options);
    ASSERT_EQ(tree.branches.size(), 1U);
    const auto& points = tree.branches[0].points;
    // The bend lies in the x-z plane: a frame that does not twist keeps its
    // angle to the plane's normal.
    const glm::dvec3 planeNormal(0.0, 1.0, 0.0);
    const double angle = glm::dot(points.front().normal, planeNormal);
    for (std::size_t i = 0; i < points.size(); ++i) {
        EXPECT_NEAR(glm::length(points[i].tangent), 1.0, 1e-9);
        EXPECT_NEAR(glm::length(points[i].normal), 1.0, 1e-9);
        EXPECT_NEAR(glm::dot(points[i].tangent, points[i].normal), 0.0, 1e-9);
        if (i + 2 < points.size()) {
            EXPECT_NEAR(points[i + 1].abscissaMm - points[i].abscissaMm, 0.5, 1e-6);
        }
        if (i + 1 < points.size()) {
            EXPECT_LE(points[i + 1].abscissaMm - points[i].abscissaMm, 0.5 + 1e-6);
            // No turn about the tangent from one point to the next.
            const glm::dvec3 binormal = glm::cross(points[i].tangent, points[i].normal);
            EXPECT_NEAR(glm::dot(points[i + 1].normal, binormal), 0.0, 1e-3) << "twisted at " << i;
        }
        EXPECT_NEAR(glm::dot(points[i].normal, planeNormal), angle, 0.01) << "at " << i;
    }
}

// The inscribed sphere's radius is the section's radius on a tube, and the
// narrowed one at a stenosis' throat.
TEST(Centerline, InscribedRadiusAtAStenosisThroat) {
    const TubePhantom truth = phantom(TubeShape::Stenosis, 5.0, 50'000);
    const CenterlineTree tree = computeCenterlines(truth.mesh);
    ASSERT_EQ(tree.branches.size(), 1U);
    double narrowest = 1e9;
    double narrowestAt = 0.0;
    for (const auto& p : tree.branches[0].points) {
        if (p.radiusMm < narrowest && p.abscissaMm > 5.0 && p.abscissaMm < truth.lengthMm - 5.0) {
            narrowest = p.radiusMm;
            narrowestAt = truth.distanceToAxis(p.position).second;
        }
        const double s = truth.distanceToAxis(p.position).second;
        if (std::abs(s - truth.lengthMm / 2.0) > 15.0 && s > 5.0 && s < truth.lengthMm - 5.0) {
            EXPECT_NEAR(p.radiusMm, 5.0, 0.02 * 5.0) << "at s = " << s;
        }
    }
    EXPECT_NEAR(narrowest, truth.narrowestRadiusMm, 0.02 * truth.narrowestRadiusMm);
    EXPECT_NEAR(narrowestAt, truth.narrowestAbscissaMm, 1.0);
}

// A closed tube (flat caps) has no open ends: its two tips are found and the
// centreline runs from cap to cap.
TEST(Centerline, ClosedTubeEndsAtItsTips) {
    const TubePhantom truth = phantom(TubeShape::Cylinder, 5.0, 50'000, 0.0, true);
    const CenterlineTree tree = computeCenterlines(truth.mesh);
    ASSERT_EQ(tree.branches.size(), 1U);
    ASSERT_EQ(tree.ends.size(), 2U);
    for (const EndPoint& end : tree.ends) {
        EXPECT_EQ(end.kind, EndPoint::Kind::Tip);
    }
    EXPECT_LT(vv::test::worstAxisDistance(tree, truth, 5.0), 0.02 * 5.0);
    EXPECT_NEAR(totalLength(tree), truth.lengthMm, 0.01 * truth.lengthMm);
}

// Given ends: a source near one open end snaps to its centre; a target in
// the middle of the tube ends the centreline at the inscribed sphere there.
TEST(Centerline, GivenEndsAreUsedAndTheirOffsetReported) {
    const TubePhantom truth = phantom(TubeShape::Cylinder, 5.0, 20'000);
    CenterlineOptions options;
    options.source = glm::dvec3(5.5, 0.0, 0.5);       // just outside the rim of the z = 0 end
    options.targets = {glm::dvec3(0.0, -6.0, 60.0)};  // 1 mm outside the wall at z = 60
    const CenterlineTree tree = computeCenterlines(truth.mesh, options);
    ASSERT_EQ(tree.ends.size(), 2U);
    EXPECT_EQ(tree.ends[0].kind, EndPoint::Kind::Given);
    EXPECT_LT(glm::length(tree.ends[0].position - truth.axis.front().position), 0.05);
    EXPECT_NEAR(tree.ends[0].offsetMm, 0.5, 0.05);
    EXPECT_EQ(tree.ends[1].kind, EndPoint::Kind::Given);
    EXPECT_NEAR(tree.ends[1].offsetMm, 1.0, 0.05);
    EXPECT_NEAR(tree.ends[1].position.z, 60.0, 1.0);
    EXPECT_NEAR(totalLength(tree), 60.0, 1.0);
}

TEST(Centerline, ATargetFarFromTheSurfaceIsAClearError) {
    const TubePhantom truth = phantom(TubeShape::Cylinder, 5.0, 5'000);
    CenterlineOptions options;
    options.targets = {glm::dvec3(200.0, 0.0, 50.0)};
    try {
        static_cast<void>(computeCenterlines(truth.mesh, options));
        FAIL() << "no error";
    } catch (const AnalysisError& e) {
        EXPECT_NE(std::string(e.what()).find("from the analysed surface"), std::string::npos)
            << e.what();
        EXPECT_NE(std::string(e.what()).find("cylinder phantom"), std::string::npos) << e.what();
    }
}

TEST(Centerline, SurfacesWithoutAnInsideAreClearErrors) {
    vv::scene::Mesh empty;
    empty.name = "empty";
    EXPECT_THROW(static_cast<void>(computeCenterlines(empty)), AnalysisError);

    vv::scene::Mesh flat;  // one triangle: no inside
    flat.name = "flat";
    flat.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    flat.indices = {0, 1, 2};
    EXPECT_THROW(static_cast<void>(computeCenterlines(flat)), AnalysisError);

    vv::scene::Mesh bad = phantom(TubeShape::Cylinder, 5.0, 1'000).mesh;
    bad.positions[3].x = std::numeric_limits<float>::quiet_NaN();
    try {
        static_cast<void>(computeCenterlines(bad));
        FAIL() << "no error";
    } catch (const AnalysisError& e) {
        EXPECT_NE(std::string(e.what()).find("non-finite"), std::string::npos) << e.what();
    }
}

TEST(Centerline, OptionsOutOfRangeAreRejected) {
    const TubePhantom truth = phantom(TubeShape::Cylinder, 5.0, 1'000);
    CenterlineOptions options;
    options.stepMm = 0.0;
    EXPECT_THROW(static_cast<void>(computeCenterlines(truth.mesh, options)),
                 vv::InvalidArgumentError);
    options.stepMm = 0.5;
    options.source = glm::dvec3(std::nan(""), 0.0, 0.0);
    EXPECT_THROW(static_cast<void>(computeCenterlines(truth.mesh, options)),
                 vv::InvalidArgumentError);
}

// Of two separate tubes the larger is analysed, and the user is told.
TEST(Centerline, OfSeveralPiecesTheLargestIsTakenAndNoted) {
    vv::scene::Mesh mesh = phantom(TubeShape::Cylinder, 5.0, 20'000).mesh;
    const vv::scene::Mesh small = phantom(TubeShape::Cylinder, 2.0, 2'000).mesh;
    const auto offset = static_cast<std::uint32_t>(mesh.positions.size());
    for (const auto& p : small.positions) {
        mesh.positions.push_back(p + glm::vec3(40.0F, 0.0F, 0.0F));
        mesh.normals.emplace_back(0, 0, 1);
    }
    for (const auto index : small.indices) {
        mesh.indices.push_back(index + offset);
    }
    const CenterlineTree tree = computeCenterlines(mesh);
    ASSERT_EQ(tree.branches.size(), 1U);
    EXPECT_NEAR(tree.branches[0].points[10].radiusMm, 5.0, 0.1);
    ASSERT_FALSE(tree.notes.empty());
    EXPECT_NE(tree.notes.front().find("2 separate pieces"), std::string::npos)
        << tree.notes.front();
}

TEST(Centerline, AStopRequestCancels) {
    const TubePhantom truth = phantom(TubeShape::Cylinder, 5.0, 50'000);
    std::stop_source stop;
    stop.request_stop();
    EXPECT_THROW(
        static_cast<void>(computeCenterlines(truth.mesh, {}, vv::Progress({}, stop.get_token()))),
        vv::CancelledError);
}

}  // namespace
