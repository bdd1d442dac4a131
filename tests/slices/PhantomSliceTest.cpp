// SPDX-License-Identifier: GPL-3.0-or-later
// Balls at known LPS positions appear at the right slice and pixel in axial,
// coronal and sagittal views of axis-aligned, oblique and sheared grids, also
// after a round trip through the project's CT series writer and loader.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>

#include "Phantom.h"
#include "vv/dicom/Dicom.h"
#include "vv/dicom/SeriesWriter.h"
#include "vv/slices/OrientationLetters.h"
#include "vv/slices/Reslice.h"
#include "vv/slices/SlicePlane.h"

namespace {

using vv::slices::SliceOrientation;
using vv::test::Ball;

const std::vector<Ball> kBalls{{{-12.0, 8.0, 20.0}, 5.0}, {{10.0, -6.0, 40.0}, 4.0}};

struct DiskStats {
    double area = 0.0;  ///< pixels >= 500 HU
    glm::dvec2 centroid{0.0};
};

// Area and centroid of the bright pixels of `image` within `radiusPx` of `near`.
DiskStats brightDisk(const vv::Image<float>& image, glm::dvec2 near, double radiusPx) {
    DiskStats s;
    for (int r = 0; r < image.height(); ++r) {
        for (int c = 0; c < image.width(); ++c) {
            if (glm::distance(glm::dvec2(c, r), near) <= radiusPx && image(c, r) >= 500.0F) {
                s.area += 1.0;
                s.centroid += glm::dvec2(c, r);
            }
        }
    }
    if (s.area > 0.0) {
        s.centroid /= s.area;
    }
    return s;
}

// Checks every ball in every orientation: the nearest slice to the ball's
// centre shows a disk centred (within half a pixel) at the centre's pixel,
// with the largest area of the slices around it, and no bright pixel near
// that pixel one radius plus two slice steps away.
void expectBallsInPlace(const vv::scene::Volume& volume) {
    for (const SliceOrientation o :
         {SliceOrientation::Axial, SliceOrientation::Coronal, SliceOrientation::Sagittal}) {
        const vv::slices::SliceStack stack = vv::slices::sliceStack(volume, o);
        for (const Ball& b : kBalls) {
            SCOPED_TRACE(testing::Message()
                         << "orientation " << static_cast<int>(o) << ", ball at z " << b.centre.z);
            const int k = stack.nearestIndex(b.centre[stack.axis]);
            ASSERT_LE(std::abs(stack.position(k) - b.centre[stack.axis]), 0.5 * stack.step + 1e-9);
            const vv::slices::SlicePlane plane = stack.planeAt(k);
            const glm::dvec2 expected = plane.pixelAt(b.centre);
            const double radiusPx = b.radius / plane.pixelSpacing + 2.0;
            const DiskStats here =
                brightDisk(vv::slices::reslice(volume, plane), expected, radiusPx);
            ASSERT_GT(here.area, 0.0);
            EXPECT_NEAR(here.centroid.x, expected.x, 0.5);
            EXPECT_NEAR(here.centroid.y, expected.y, 0.5);
            // The disk is largest at the ball's slice.
            for (const int dk : {-2, 2}) {
                const DiskStats other = brightDisk(
                    vv::slices::reslice(volume, stack.planeAt(k + dk)), expected, radiusPx);
                EXPECT_LT(other.area, here.area) << "slice offset " << dk;
            }
            // Nothing one radius and two steps away.
            const int away = static_cast<int>(std::ceil(b.radius / stack.step)) + 2;
            const DiskStats gone = brightDisk(vv::slices::reslice(volume, stack.planeAt(k + away)),
                                              expected, radiusPx);
            EXPECT_EQ(gone.area, 0.0);
        }
    }
}

vv::scene::Volume axisAligned() {
    return vv::test::ballPhantom(
        {64, 60, 70},
        vv::test::gridGeometry({0.8, 0.9, 1.0}, glm::dmat3(1.0), 0.0, {-30.0, -25.0, 0.0}), kBalls);
}

vv::scene::Volume oblique() {
    const glm::dmat3 r = vv::test::rotationAbout({0.3, 0.2, 1.0}, 28.0);
    return vv::test::ballPhantom(
        {80, 80, 80}, vv::test::gridGeometry({0.8, 0.75, 1.1}, r, 0.0, {-32.0, -30.0, -5.0}),
        kBalls);
}

vv::scene::Volume sheared() {
    // A gantry tilt: each slice moves 0.35 mm along the row direction.
    const glm::dmat3 r = vv::test::rotationAbout({0.0, 0.0, 1.0}, 12.0);
    return vv::test::ballPhantom(
        {72, 64, 64}, vv::test::gridGeometry({0.8, 0.9, 1.0}, r, 0.35, {-40.0, -28.0, 2.0}),
        kBalls);
}

TEST(PhantomSliceTest, BallsInAxisAlignedGrid) {
    expectBallsInPlace(axisAligned());
}

TEST(PhantomSliceTest, BallsInObliqueGrid) {
    expectBallsInPlace(oblique());
}

TEST(PhantomSliceTest, BallsInShearedGrid) {
    const vv::scene::Volume volume = sheared();
    ASSERT_TRUE(volume.sheared());
    expectBallsInPlace(volume);
}

TEST(PhantomSliceTest, BallsAfterCtSeriesRoundTrip) {
    // Oblique and sheared at once, written as DICOM files and loaded again:
    // the loader's geometry and the reslicer agree on where the balls are.
    const glm::dmat3 r = vv::test::rotationAbout({1.0, 0.4, 0.2}, 18.0);
    const vv::scene::Volume written = vv::test::ballPhantom(
        {72, 72, 70}, vv::test::gridGeometry({0.85, 0.85, 1.0}, r, 0.3, {-32.0, -30.0, -4.0}),
        kBalls);
    const std::filesystem::path dir =
        std::filesystem::temp_directory_path() /
        ("vv_slices_phantom_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()));
    std::filesystem::remove_all(dir);
    vv::dicom::CtSeriesWriteOptions options;
    options.patientName = "Phantom^Slices";
    vv::dicom::writeCtSeries(dir, written, options);
    const vv::dicom::DicomVolume loaded = vv::dicom::loadDicomVolume(dir);
    std::filesystem::remove_all(dir);
    EXPECT_TRUE(loaded.volume.sheared());
    expectBallsInPlace(loaded.volume);
}

TEST(PhantomSliceTest, StackCoversTheVolumeAtItsSpacing) {
    const vv::scene::Volume volume = axisAligned();
    const auto axial = vv::slices::sliceStack(volume, SliceOrientation::Axial);
    EXPECT_EQ(axial.count, 70);
    EXPECT_DOUBLE_EQ(axial.step, 1.0);
    EXPECT_DOUBLE_EQ(axial.first, 0.0);
    EXPECT_NEAR(axial.plane.pixelSpacing, 0.8, 1e-12);
    const auto coronal = vv::slices::sliceStack(volume, SliceOrientation::Coronal);
    EXPECT_EQ(coronal.count, 60);
    EXPECT_NEAR(coronal.step, 0.9, 1e-12);
    // Coronal: superior up, so row 0 is the highest slice (z = 69 mm).
    EXPECT_NEAR(coronal.plane.origin.z, 69.0, 1e-9);
    const auto sagittal = vv::slices::sliceStack(volume, SliceOrientation::Sagittal);
    EXPECT_EQ(sagittal.count, 64);
    // Sagittal: anterior (-y) on the left, so column 0 is the most anterior voxel.
    EXPECT_NEAR(sagittal.plane.origin.y, -25.0, 1e-9);
    EXPECT_EQ(sagittal.nearestIndex(-1000.0), 0);
    EXPECT_EQ(sagittal.nearestIndex(1000.0), 63);
}

TEST(PhantomSliceTest, OutsideIsNanAndNearestKeepsVoxelValues) {
    const vv::scene::Volume volume = oblique();
    const auto stack = vv::slices::sliceStack(volume, SliceOrientation::Axial);
    const auto plane = stack.planeAt(stack.count / 2);
    const auto nearest = vv::slices::reslice(volume, plane, vv::slices::Interpolation::Nearest);
    // The oblique grid leaves the box's corners empty.
    EXPECT_TRUE(std::isnan(nearest(0, 0)));
    int inside = 0;
    for (int r = 0; r < nearest.height(); ++r) {
        for (int c = 0; c < nearest.width(); ++c) {
            const float v = nearest(c, r);
            if (!std::isnan(v)) {
                ++inside;
                EXPECT_TRUE(v == 0.0F || v == 1000.0F) << v;
            }
        }
    }
    EXPECT_GT(inside, nearest.width() * nearest.height() / 3);
}

TEST(PhantomSliceTest, StandardViewLetters) {
    const vv::scene::Volume volume = oblique();
    const auto axial =
        vv::slices::edgeLetters(vv::slices::sliceStack(volume, SliceOrientation::Axial).plane);
    EXPECT_EQ(axial.left + axial.right + axial.top + axial.bottom, "RLAP");
    const auto coronal =
        vv::slices::edgeLetters(vv::slices::sliceStack(volume, SliceOrientation::Coronal).plane);
    EXPECT_EQ(coronal.left + coronal.right + coronal.top + coronal.bottom, "RLSI");
    const auto sagittal =
        vv::slices::edgeLetters(vv::slices::sliceStack(volume, SliceOrientation::Sagittal).plane);
    EXPECT_EQ(sagittal.left + sagittal.right + sagittal.top + sagittal.bottom, "APSI");
}

TEST(PhantomSliceTest, BadInputsThrow) {
    const vv::scene::Volume volume = axisAligned();
    vv::slices::SlicePlane plane = vv::slices::sliceStack(volume, SliceOrientation::Axial).plane;
    plane.width = 0;
    EXPECT_THROW((void)vv::slices::reslice(volume, plane), vv::InvalidArgumentError);
    plane.width = 10;
    plane.pixelSpacing = 0.0;
    EXPECT_THROW((void)vv::slices::reslice(volume, plane), vv::InvalidArgumentError);
    EXPECT_THROW((void)vv::slices::sliceStack(vv::scene::Volume(), SliceOrientation::Axial),
                 vv::InvalidArgumentError);
    std::stop_source stop;
    stop.request_stop();
    EXPECT_THROW((void)vv::slices::reslice(
                     volume, vv::slices::sliceStack(volume, SliceOrientation::Axial).plane,
                     vv::slices::Interpolation::Linear, stop.get_token()),
                 vv::CancelledError);
}

}  // namespace
