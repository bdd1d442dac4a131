// SPDX-License-Identifier: GPL-3.0-or-later
// A CT series whose vessels say where the patient's sides are, for the tests
// of the anatomical views: a rod along the body axis (head to foot, as an
// aorta runs) with a ball at its superior end, a branch to the patient's left
// ending in a ball, and a branch to the anterior side ending in a smaller
// ball. Written on grids of several orientations (head first and feet first
// axial, oblique), always in the same patient (LPS) frame, so that every one
// must be shown the same way. And what a rendered image of it shows: where
// its parts lie on the screen.
#pragma once

#include <gtest/gtest.h>

#include <QImage>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <ostream>
#include <string>
#include <vector>

#include "vv/dicom/SeriesWriter.h"
#include "vv/scene/Volume.h"

namespace vv::test {

/// The phantom's parts in LPS mm (+x left, +y posterior, +z superior).
struct AnatomyPhantom {
    static constexpr float kRodRadius = 4.0F;
    static constexpr float kRodBottom = -40.0F;  ///< inferior end of the rod
    static constexpr float kRodTop = 40.0F;      ///< superior end of the rod
    /// The superior marker: a ball on the rod's top.
    static constexpr glm::vec3 kSuperiorBall{0.0F, 0.0F, 46.0F};
    static constexpr float kSuperiorRadius = 8.0F;
    /// The left marker: a branch along +x at this height, ending in a ball.
    static constexpr glm::vec3 kLeftBall{30.0F, 0.0F, -20.0F};
    static constexpr float kLeftRadius = 6.0F;
    /// The anterior marker: a branch along -y, ending in a smaller ball.
    static constexpr glm::vec3 kAnteriorBall{0.0F, -25.0F, 15.0F};
    static constexpr float kAnteriorRadius = 5.0F;
    static constexpr float kBranchRadius = 3.0F;

    /// Signed distance (mm) of `p` to the vessels (< 0 inside).
    static float distance(const glm::vec3& p) {
        const auto capsule = [&](glm::vec3 a, glm::vec3 b, float r) {
            const glm::vec3 ab = b - a;
            const float t = std::clamp(glm::dot(p - a, ab) / glm::dot(ab, ab), 0.0F, 1.0F);
            return glm::length(p - (a + t * ab)) - r;
        };
        const auto ball = [&](glm::vec3 c, float r) { return glm::length(p - c) - r; };
        return std::min({capsule({0.0F, 0.0F, kRodBottom}, {0.0F, 0.0F, kRodTop}, kRodRadius),
                         ball(kSuperiorBall, kSuperiorRadius),
                         capsule({0.0F, 0.0F, kLeftBall.z}, kLeftBall, kBranchRadius),
                         ball(kLeftBall, kLeftRadius),
                         capsule({0.0F, 0.0F, kAnteriorBall.z}, kAnteriorBall, kBranchRadius),
                         ball(kAnteriorBall, kAnteriorRadius)});
    }
};

/// How a series' grid lies in the patient: its row, column and slice
/// directions (unit, LPS) and the Patient Position it records.
struct PhantomGrid {
    std::string name;  ///< for test messages
    glm::dvec3 row{1.0, 0.0, 0.0};
    glm::dvec3 column{0.0, 1.0, 0.0};
    glm::dvec3 slice{0.0, 0.0, 1.0};
    std::string patientPosition = "HFS";
};

/// gtest's name for a grid in messages.
inline void PrintTo(const PhantomGrid& grid, std::ostream* out) {
    *out << grid.name;
}

/// Head first supine, axial: rows to the patient's left, columns posterior,
/// slices from the feet to the head.
inline PhantomGrid headFirstGrid() {
    return {"head first (HFS)", {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, "HFS"};
}

/// Feet first supine as scanners write it: rows to the patient's right,
/// columns posterior, slices from the head to the feet (the table moves the
/// other way).
inline PhantomGrid feetFirstGrid() {
    return {"feet first (FFS)", {-1, 0, 0}, {0, 1, 0}, {0, 0, -1}, "FFS"};
}

/// Head first, the grid turned 35 degrees about an oblique axis.
inline PhantomGrid obliqueGrid() {
    const glm::dmat3 turn(
        glm::rotate(glm::dmat4(1.0), glm::radians(35.0), glm::normalize(glm::dvec3(1, 0.5, 0.3))));
    return {"oblique", turn * glm::dvec3(1, 0, 0), turn * glm::dvec3(0, 1, 0),
            turn * glm::dvec3(0, 0, 1), "HFS"};
}

/// The phantom on `grid`: a cube of 80 voxels of 1.6 mm a side around the
/// point (0, 0, 5), tissue 40 HU, vessels 400 HU with a one-voxel partial
/// volume ramp.
inline scene::Volume makePhantomVolume(const PhantomGrid& grid) {
    constexpr int kN = 80;
    constexpr double kSpacing = 1.6;
    scene::Volume volume({kN, kN, kN}, scene::VoxelType::Int16);
    const glm::dvec3 centre(0.0, 0.0, 5.0);
    const double half = 0.5 * (kN - 1) * kSpacing;
    const glm::dvec3 origin = centre - half * (grid.row + grid.column + grid.slice);
    glm::dmat4 m(1.0);
    m[0] = glm::dvec4(grid.row * kSpacing, 0.0);
    m[1] = glm::dvec4(grid.column * kSpacing, 0.0);
    m[2] = glm::dvec4(grid.slice * kSpacing, 0.0);
    m[3] = glm::dvec4(origin, 1.0);
    volume.setIndexToWorld(m);
    for (int k = 0; k < kN; ++k) {
        for (int j = 0; j < kN; ++j) {
            for (int i = 0; i < kN; ++i) {
                const glm::vec3 p(volume.worldPosition(glm::dvec3(i, j, k)));
                const double inside = std::clamp(
                    0.5 - static_cast<double>(AnatomyPhantom::distance(p)) / kSpacing, 0.0, 1.0);
                volume.setValueAt(volume.index(i, j, k), static_cast<float>(40.0 + 360.0 * inside));
            }
        }
    }
    return volume;
}

/// Writes the phantom on `grid` as a CT series into `folder` (emptied
/// first); returns its Series Instance UID.
inline std::string writePhantomSeries(const std::filesystem::path& folder,
                                      const PhantomGrid& grid) {
    std::filesystem::remove_all(folder);
    dicom::CtSeriesWriteOptions options;
    options.seriesDescription = "anatomy phantom, " + grid.name;
    options.patientPosition = grid.patientPosition;
    return dicom::writeCtSeries(folder, makePhantomVolume(grid), options);
}

/// Where the drawn vessels lie in a rendered image: the pixels that differ
/// from the background, measured in their bounding box (u: 0 left .. 1
/// right, v: 0 top .. 1 bottom).
class DrawnShape {
  public:
    DrawnShape(const QImage& image, QRgb background) {
        const QImage rgb = image.convertToFormat(QImage::Format_RGB32);
        rows_.assign(static_cast<std::size_t>(rgb.height()), {});
        for (int y = 0; y < rgb.height(); ++y) {
            for (int x = 0; x < rgb.width(); ++x) {
                const QRgb p = rgb.pixel(x, y);
                const int d = std::max({std::abs(qRed(p) - qRed(background)),
                                        std::abs(qGreen(p) - qGreen(background)),
                                        std::abs(qBlue(p) - qBlue(background))});
                if (d > 12) {
                    rows_[static_cast<std::size_t>(y)].push_back(x);
                    left_ = std::min(left_, x);
                    right_ = std::max(right_, x);
                    top_ = std::min(top_, y);
                    bottom_ = std::max(bottom_, y);
                }
            }
        }
    }

    [[nodiscard]] bool empty() const noexcept { return right_ < left_; }
    [[nodiscard]] int width() const noexcept { return right_ - left_ + 1; }
    [[nodiscard]] int height() const noexcept { return bottom_ - top_ + 1; }

    /// The mean u of the drawn pixels in the rows from v0 to v1.
    [[nodiscard]] double meanU(double v0, double v1) const {
        double sum = 0.0;
        long n = 0;
        forRows(v0, v1, [&](const std::vector<int>& xs) {
            for (const int x : xs) {
                sum += static_cast<double>(x - left_) / std::max(1, width() - 1);
                ++n;
            }
        });
        return n > 0 ? sum / static_cast<double>(n) : -1.0;
    }

    /// The v of the row with the most drawn pixels (the widest part).
    [[nodiscard]] double widestRowV() const {
        int best = top_;
        for (int y = top_; y <= bottom_; ++y) {
            if (rows_[static_cast<std::size_t>(y)].size() >
                rows_[static_cast<std::size_t>(best)].size()) {
                best = y;
            }
        }
        return static_cast<double>(best - top_) / std::max(1, height() - 1);
    }

    /// What it shows, for messages.
    [[nodiscard]] std::string describe() const {
        return "drawn " + std::to_string(width()) + " x " + std::to_string(height()) + " px at (" +
               std::to_string(left_) + ", " + std::to_string(top_) + "), widest row at v " +
               std::to_string(widestRowV()) + ", top rows at u " +
               std::to_string(meanU(0.0, 0.08)) + ", bottom rows at u " +
               std::to_string(meanU(0.92, 1.0));
    }

  private:
    template <typename Visit>
    void forRows(double v0, double v1, Visit visit) const {
        const int y0 = top_ + static_cast<int>(std::floor(v0 * (height() - 1)));
        const int y1 = top_ + static_cast<int>(std::ceil(v1 * (height() - 1)));
        for (int y = std::max(top_, y0); y <= std::min(bottom_, y1); ++y) {
            visit(rows_[static_cast<std::size_t>(y)]);
        }
    }

    std::vector<std::vector<int>> rows_;
    int left_ = 1 << 30;
    int right_ = -1;
    int top_ = 1 << 30;
    int bottom_ = -1;
};

/// The anterior view of the phantom, as a radiologist expects it: the body
/// axis upright (taller than wide, not end-on), the superior ball at the top
/// (the widest row, the left branch, in the lower half), the patient's left
/// on the screen's right (the rod and its top ball at the left of the shape).
inline ::testing::AssertionResult showsAnteriorView(const DrawnShape& shape) {
    if (shape.empty()) {
        return ::testing::AssertionFailure() << "nothing drawn";
    }
    if (shape.height() < 1.6 * shape.width()) {
        return ::testing::AssertionFailure() << "not upright (end-on?): " << shape.describe();
    }
    if (shape.widestRowV() < 0.6) {
        return ::testing::AssertionFailure() << "the head is not up: " << shape.describe();
    }
    if (shape.meanU(0.0, 0.08) > 0.4) {
        return ::testing::AssertionFailure()
               << "the patient's left is not on the right: " << shape.describe();
    }
    return ::testing::AssertionSuccess();
}

/// The posterior view: upright, head up, the patient's left on the left.
inline ::testing::AssertionResult showsPosteriorView(const DrawnShape& shape) {
    if (shape.empty() || shape.height() < 1.6 * shape.width() || shape.widestRowV() < 0.6 ||
        shape.meanU(0.0, 0.08) < 0.6) {
        return ::testing::AssertionFailure() << "not the posterior view: " << shape.describe();
    }
    return ::testing::AssertionSuccess();
}

/// The superior (`fromHead`) or inferior view: anterior up (the superior
/// ball and the left branch, the widest row, in the lower part, the
/// anterior branch above them); from the head the patient's left is on the
/// screen's left, from the feet on its right.
inline ::testing::AssertionResult showsAxialView(const DrawnShape& shape, bool fromHead) {
    if (shape.empty()) {
        return ::testing::AssertionFailure() << "nothing drawn";
    }
    if (shape.widestRowV() < 0.6) {
        return ::testing::AssertionFailure() << "anterior is not up: " << shape.describe();
    }
    const double ballU = shape.meanU(0.92, 1.0);  // the bottom of the superior ball
    if (fromHead ? ballU < 0.6 : ballU > 0.4) {
        return ::testing::AssertionFailure()
               << "the patient's left is not on the " << (fromHead ? "left" : "right") << ": "
               << shape.describe();
    }
    return ::testing::AssertionSuccess();
}

}  // namespace vv::test
