// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>

#include <QColor>
#include <QImage>
#include <QPainter>
#include <QPainterPath>
#include <QPen>
#include <QRadialGradient>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <random>
#include <string>

#include "ImageCompare.h"

namespace {

using vv::test::compareImages;

/// A render-like picture: a smooth shaded backdrop with a few anti-aliased
/// "vessels" (thick curves) in saturated colours.
QImage scene(int width = 320, int height = 240) {
    QImage image(width, height, QImage::Format_RGB32);
    QPainter painter(&image);
    painter.setRenderHint(QPainter::Antialiasing);
    QRadialGradient backdrop(QPointF(width * 0.4, height * 0.45), width * 0.7);
    backdrop.setColorAt(0.0, QColor(220, 60, 40));
    backdrop.setColorAt(0.5, QColor(120, 200, 80));
    backdrop.setColorAt(1.0, QColor(40, 60, 200));
    painter.fillRect(image.rect(), backdrop);
    painter.setPen(QPen(QColor(235, 225, 215), width / 40.0, Qt::SolidLine, Qt::RoundCap));
    for (int i = 0; i < 5; ++i) {
        QPainterPath path(QPointF(width * (0.1 + 0.18 * i), height * 0.05));
        path.cubicTo(QPointF(width * (0.3 + 0.1 * i), height * 0.4),
                     QPointF(width * (0.05 + 0.2 * i), height * 0.6),
                     QPointF(width * (0.2 + 0.15 * i), height * 0.95));
        painter.drawPath(path);
    }
    painter.end();
    return image;
}

/// `image` with uniform noise of +-amplitude grey levels added to every
/// channel independently (fixed seed).
QImage withNoise(const QImage& image, int amplitude, unsigned seed = 7) {
    QImage out = image.convertToFormat(QImage::Format_RGB32);
    std::mt19937 random(seed);
    const auto jitter = [&](int v) {
        const int n =
            static_cast<int>(random() % static_cast<unsigned>(2 * amplitude + 1)) - amplitude;
        return std::clamp(v + n, 0, 255);
    };
    for (int y = 0; y < out.height(); ++y) {
        auto* line = reinterpret_cast<QRgb*>(out.scanLine(y));
        for (int x = 0; x < out.width(); ++x) {
            line[x] = qRgb(jitter(qRed(line[x])), jitter(qGreen(line[x])), jitter(qBlue(line[x])));
        }
    }
    return out;
}

/// `image` moved right by `dx` pixels (the left columns repeat the edge).
QImage shifted(const QImage& image, int dx) {
    QImage out = image.copy();
    for (int y = 0; y < out.height(); ++y) {
        for (int x = 0; x < out.width(); ++x) {
            out.setPixel(x, y, image.pixel(std::max(0, x - dx), y));
        }
    }
    return out;
}

/// `image` with red and blue swapped: hue changes, brightness barely.
QImage recoloured(const QImage& image) {
    return image.convertToFormat(QImage::Format_RGB32).rgbSwapped();
}

TEST(ImageCompareTest, IdenticalImagesGiveZero) {
    const QImage a = scene();
    const auto r = compareImages(a, a.copy());
    EXPECT_TRUE(r.comparable);
    EXPECT_NEAR(r.difference, 0.0, 1e-12);
    EXPECT_NEAR(r.lumaDifference, 0.0, 1e-12);
    EXPECT_NE(r.message.find("difference 0.0000"), std::string::npos) << r.message;
    // Other pixel formats with the same colours are the same image.
    EXPECT_NEAR(compareImages(a, a.convertToFormat(QImage::Format_RGB888)).difference, 0.0, 1e-12);
    // A flat image compared with itself (no structure at all) too.
    QImage flat(40, 30, QImage::Format_RGB32);
    flat.fill(QColor(30, 35, 40));
    EXPECT_NEAR(compareImages(flat, flat).difference, 0.0, 1e-12);
}

TEST(ImageCompareTest, SizeMismatchIsAFailureWithAMessage) {
    const auto r = compareImages(scene(320, 240), scene(321, 240));
    EXPECT_FALSE(r.comparable);
    EXPECT_TRUE(std::isinf(r.difference));
    EXPECT_NE(r.message.find("321x240"), std::string::npos) << r.message;
    EXPECT_NE(r.message.find("320x240"), std::string::npos) << r.message;
    const auto none = compareImages(QImage(), scene());
    EXPECT_FALSE(none.comparable);
    EXPECT_NE(none.message.find("no image"), std::string::npos) << none.message;
    EXPECT_TRUE(vv::test::differenceImage(scene(320, 240), scene(100, 100)).isNull());
}

TEST(ImageCompareTest, SmallNoiseIsSmallAndGrowsWithItsAmplitude) {
    const QImage a = scene();
    double previous = 0.0;
    for (const int amplitude : {1, 2, 4, 8, 16, 32}) {
        const double d = compareImages(withNoise(a, amplitude), a).difference;
        std::printf("noise +-%d grey levels: difference %.4f\n", amplitude, d);
        EXPECT_GT(d, previous) << "amplitude " << amplitude;
        previous = d;
        if (amplitude <= 2) {
            EXPECT_LT(d, 0.04) << "invisible noise must be below the 'indistinguishable' mark";
        }
    }
    EXPECT_GT(previous, 0.1) << "+-32 grey levels of noise is clearly visible";
    // Symmetric in its arguments.
    const QImage n = withNoise(a, 8);
    EXPECT_NEAR(compareImages(n, a).difference, compareImages(a, n).difference, 1e-12);
}

TEST(ImageCompareTest, ShiftsAndRecolouringAreLargerThanNoise) {
    const QImage a = scene();
    const double noise = compareImages(withNoise(a, 2), a).difference;
    const double shift1 = compareImages(shifted(a, 1), a).difference;
    const double shift4 = compareImages(shifted(a, 4), a).difference;
    const double hue = compareImages(recoloured(a), a).difference;
    std::printf("shift 1 px %.4f, shift 4 px %.4f, red/blue swapped %.4f\n", shift1, shift4, hue);
    EXPECT_GT(shift1, noise);
    EXPECT_GT(shift4, shift1);
    EXPECT_GT(shift4, 0.1);
    EXPECT_GT(hue, 0.1);
    // The hue change shows in the chroma channels more than in luma.
    const auto r = compareImages(recoloured(a), a);
    EXPECT_GT(std::max(r.blueChromaDifference, r.redChromaDifference), r.lumaDifference);
}

TEST(ImageCompareTest, DifferenceImageMarksWhereTheImagesDiffer) {
    QImage a(20, 10, QImage::Format_RGB32);
    a.fill(QColor(100, 100, 100));
    QImage b = a.copy();
    b.setPixel(3, 4, qRgb(110, 100, 100));
    const QImage d = vv::test::differenceImage(b, a);
    ASSERT_EQ(d.size(), a.size());
    EXPECT_EQ(qRed(d.pixel(3, 4)), 40);
    EXPECT_EQ(qRed(d.pixel(4, 4)), 0);
    const auto r = compareImages(b, a);
    EXPECT_GT(r.difference, 0.0);
    EXPECT_LT(r.difference, 0.04);
}

/// The scale on real renders: a committed baseline image (when present)
/// against noisy and shifted copies of itself. Prints the values documented
/// in ImageCompare.h and tests/baselines/README.md.
TEST(ImageCompareTest, ScaleOnABaselineRender) {
    const std::filesystem::path file =
        std::filesystem::path(VV_SOURCE_DIR) / "tests/baselines/scale-cd.png";
    if (!std::filesystem::exists(file)) {
        GTEST_SKIP() << "no " << file.string();
    }
    const QImage a(QString::fromStdString(file.string()));
    ASSERT_FALSE(a.isNull());
    for (const int amplitude : {1, 2, 4, 8, 16}) {
        std::printf("render + noise +-%d: %.4f\n", amplitude,
                    compareImages(withNoise(a, amplitude), a).difference);
    }
    const double shift1 = compareImages(shifted(a, 1), a).difference;
    const double shift3 = compareImages(shifted(a, 3), a).difference;
    std::printf("render shifted 1 px: %.4f, 3 px: %.4f, red/blue swapped: %.4f\n", shift1, shift3,
                compareImages(recoloured(a), a).difference);
    EXPECT_LT(compareImages(withNoise(a, 2), a).difference, 0.04);
    EXPECT_GT(shift3, shift1);
    EXPECT_GT(compareImages(recoloured(a), a).difference, 0.1);
}

}  // namespace
