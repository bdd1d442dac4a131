// SPDX-License-Identifier: GPL-3.0-or-later
// The legends' text as painted (PaintRecorder: what the painter draws, in
// pixels): one title, on as many lines as it needs, never shortened or cut; tick
// labels with the minimum and the maximum always shown, as many bin edges
// labelled as fit, and no two labels closer than LegendPainter.h's gap —
// for continuous and 2..12-bin legends, several ranges, the sizes of the
// GUI's view, a quarter of it (slice layout) and the PDF report's legend,
// in English and German number formats.
#include <gtest/gtest.h>

#include <QFont>
#include <QFontMetricsF>
#include <QLocale>
#include <QPainter>
#include <QRectF>
#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "PaintRecorder.h"
#include "RenderTestUtil.h"
#include "vv/colormaps/ColorMap.h"
#include "vv/colormaps/DepthScale.h"
#include "vv/render/FrameSettings.h"
#include "vv/render/LegendPainter.h"

namespace legend_text_test {

namespace {

using vv::test::PaintedText;
using vv::test::PaintRecorder;

/// What one legend box shows: its title lines, its tick marks (x) and its
/// tick labels, left to right.
struct PaintedLegend {
    std::vector<PaintedText> title;
    std::vector<double> ticks;
    std::vector<PaintedText> labels;
    double font = 0.0;
};

/// Paints `legends` into an area of `size` and reads back the box inside `box`.
PaintedLegend paintedLegend(const vv::render::Legends& legends, const QSizeF& size,
                            const QRectF& box) {
    PaintRecorder recorder(static_cast<int>(size.width()), static_cast<int>(size.height()));
    {
        QPainter painter(&recorder);
        vv::render::paintLegends(painter, QRectF(QPointF(0.0, 0.0), size), legends);
    }
    PaintedLegend legend;
    double tickTop = box.bottom();
    double tickBottom = box.top();
    for (const QLineF& line : recorder.lines()) {
        if (box.contains(line.p1()) && std::abs(line.dx()) < 1e-6) {
            legend.ticks.push_back(line.x1());
            tickTop = std::min(tickTop, std::min(line.y1(), line.y2()));
            tickBottom = std::max(tickBottom, std::max(line.y1(), line.y2()));
        }
    }
    std::sort(legend.ticks.begin(), legend.ticks.end());
    for (const PaintedText& text : recorder.texts()) {
        if (!box.contains(QPointF(text.centre(), text.baseline - 1.0))) {
            continue;
        }
        legend.font = text.pixelSize;
        (text.baseline < tickTop ? legend.title : legend.labels).push_back(text);
    }
    std::sort(legend.labels.begin(), legend.labels.end(),
              [](const PaintedText& a, const PaintedText& b) { return a.left < b.left; });
    return legend;
}

/// The least room between two tick labels (LegendPainter.h: 1.25 times the
/// font's pixel size, about two digits).
double leastGap(double font) {
    return 1.25 * font;
}

QString titleOf(const PaintedLegend& legend) {
    QStringList lines;
    for (const PaintedText& line : legend.title) {
        lines << line.text;
    }
    return lines.join(QLatin1Char(' '));
}

/// Checks the labels of a bar legend whose ticks are `ticks`.
void checkLabels(const PaintedLegend& painted, const std::vector<vv::render::LegendTick>& ticks,
                 const std::string& where) {
    ASSERT_EQ(painted.ticks.size(), ticks.size()) << where << ": a mark for every tick";
    ASSERT_GE(painted.labels.size(), ticks.size() > 1 ? 2U : 1U) << where;
    EXPECT_EQ(painted.labels.front().text, ticks.front().label) << where << ": the minimum shows";
    EXPECT_EQ(painted.labels.back().text, ticks.back().label) << where << ": the maximum shows";
    const double gap = leastGap(painted.font);
    for (std::size_t i = 1; i < painted.labels.size(); ++i) {
        EXPECT_GE(painted.labels[i].left - painted.labels[i - 1].right(), gap - 0.5)
            << where << ": \"" << painted.labels[i - 1].text.toStdString() << "\" and \""
            << painted.labels[i].text.toStdString() << "\" crowd";
    }
    // Every tick without a label: its label would come too close to a shown one.
    const double barLeft = painted.ticks.front();
    const double barRight = painted.ticks.back();
    QFont font;
    font.setPixelSize(static_cast<int>(std::lround(painted.font)));
    const QFontMetricsF metrics(font);
    for (std::size_t i = 1; i + 1 < ticks.size(); ++i) {
        const bool shown =
            std::any_of(painted.labels.begin(), painted.labels.end(),
                        [&](const PaintedText& t) { return t.text == ticks[i].label; });
        if (shown) {
            continue;
        }
        const double width = metrics.horizontalAdvance(ticks[i].label);
        const double centre = painted.ticks[i];
        const double left = std::max(centre - width / 2.0, barLeft - 2.0);
        const double right = std::min(centre + width / 2.0, barRight + 2.0);
        const bool collides =
            std::any_of(painted.labels.begin(), painted.labels.end(), [&](const PaintedText& t) {
                return left < t.right() + gap + 2.5 && right > t.left - gap - 2.5;
            });
        EXPECT_TRUE(collides) << where << ": the tick " << ticks[i].label.toStdString()
                              << " has room for its label but none is shown";
    }
}

struct Area {
    const char* name;
    QSizeF size;
};

/// The GUI's view at 1280 x 800, a quarter of it (the slice layout), and the
/// PDF report's legend coordinates (1100 wide).
const std::vector<Area> kAreas{
    {"view", QSizeF(900, 690)}, {"quarter", QSizeF(450, 345)}, {"pdf", QSizeF(1100, 620)}};

struct Range {
    double lo;
    double hi;
};
const std::vector<Range> kRanges{{0.0, 128.0}, {0.0, 101.3}, {0.25, 3.5}, {-2.5, 40.0}};

class LegendTextTest : public ::testing::TestWithParam<const char*> {
  protected:
    static void SetUpTestSuite() { vv::render::test::ensureGuiApplication(); }
    void SetUp() override {
        previous_ = QLocale();
        QLocale::setDefault(QLocale(QString::fromLatin1(GetParam())));
    }
    void TearDown() override { QLocale::setDefault(previous_); }

  private:
    QLocale previous_;
};

TEST_P(LegendTextTest, BinnedLegendsLabelEveryEdgeThatFitsWithBothEnds) {
    for (const Area& area : kAreas) {
        for (const Range& range : kRanges) {
            for (int bins = 2; bins <= 12; ++bins) {
                vv::render::Legends legends;
                legends.parameter = vv::render::ParameterLegend{"wss",
                                                                "Pa",
                                                                static_cast<float>(range.lo),
                                                                static_cast<float>(range.hi),
                                                                vv::colormaps::ColorMap::Viridis,
                                                                bins,
                                                                {},
                                                                {}};
                const QRectF box =
                    vv::render::legendLayout(QRectF(QPointF(), area.size), legends).parameter;
                const PaintedLegend painted = paintedLegend(legends, area.size, box);
                const auto ticks = vv::render::binEdgeTicks(static_cast<float>(range.lo),
                                                            static_cast<float>(range.hi), bins);
                const std::string where =
                    std::string(area.name) + " " + GetParam() + " " + std::to_string(range.lo) +
                    ".." + std::to_string(range.hi) + " in " + std::to_string(bins) + " bins";
                checkLabels(painted, ticks, where);
                EXPECT_EQ(titleOf(painted), QStringLiteral("wss (Pa)")) << where;
            }
        }
    }
}

TEST_P(LegendTextTest, DepthLegendsShowTheirEndsUncrowdedUnderTheOneTitle) {
    for (const Area& area : kAreas) {
        for (const Range& range : kRanges) {
            vv::render::Legends legends;
            legends.depth = vv::render::DepthLegend{vv::colormaps::DepthScale::Chromadepth,
                                                    300.0 + range.lo, 300.0 + range.hi, "mm"};
            legends.parameter = vv::render::ParameterLegend{
                "pressure", "mmHg", 80.0F, 120.0F, vv::colormaps::ColorMap::Viridis, 0, {}, {}};
            const auto layout = vv::render::legendLayout(QRectF(QPointF(), area.size), legends);
            const PaintedLegend painted = paintedLegend(legends, area.size, layout.depth);
            const std::string where = std::string(area.name) + " " + GetParam() + " depth " +
                                      std::to_string(range.hi - range.lo) + " mm";
            checkLabels(painted, vv::render::depthLegendTicks(*legends.depth), where);
            // The whole title, never shortened or cut; more lines where one is too narrow.
            EXPECT_EQ(titleOf(painted),
                      QString::fromStdString(vv::render::depthLegendTitle(*legends.depth)))
                << where;
            for (const PaintedText& line : painted.title) {
                EXPECT_LE(line.right(), layout.depth.right()) << where << ": title past the box";
            }
        }
    }
}

/// The depth legend of a frame whose VSS shows [300, 428] mm of viewing
/// distance, as painted (legendsFor(), paintLegends()): its title and its
/// tick labels, for each way the range was chosen. The visible range and a
/// view's range pinned for an export (vss::DepthRange::pinnedVisible) read
/// alike: the depth behind the frontmost vessel, 0 to 128; a fixed range the
/// user chose is the viewing distance, 300 to 428 (the VSS panel's near /
/// far); with the VSS off, the vessel cue spans the visible vessels.
TEST_P(LegendTextTest, TheDepthLegendSaysWhatItsNumbersMeasureFrom) {
    const QSizeF size(900, 690);
    vv::render::VssFrameStatus status;
    status.shown = true;
    status.dmin = 300.0;
    status.dmax = 428.0;
    const auto painted = [&](const vv::render::FrameSettings& settings,
                             const std::optional<std::pair<double, double>>& cue) {
        const vv::render::Legends legends =
            vv::render::legendsFor(nullptr, {}, std::nullopt, settings, status, cue);
        EXPECT_TRUE(legends.depth.has_value());
        const QRectF box = vv::render::legendLayout(QRectF(QPointF(), size), legends).depth;
        const PaintedLegend legend = paintedLegend(legends, size, box);
        QStringList labels;
        for (const PaintedText& label : legend.labels) {
            labels << label.text;
        }
        return std::pair{titleOf(legend), labels};
    };
    const QString behind =
        vv::render::depthQuantityName(vv::render::DepthReference::FrontmostVessel) +
        QStringLiteral(" (mm)");
    const QString distance =
        vv::render::depthQuantityName(vv::render::DepthReference::Camera) + QStringLiteral(" (mm)");
    const QLocale locale;
    const auto number = [&locale](int n) { return locale.toString(n); };

    vv::render::FrameSettings visible;
    const auto [visibleTitle, visibleLabels] = painted(visible, std::nullopt);
    EXPECT_EQ(visibleTitle, behind);
    ASSERT_GE(visibleLabels.size(), 2);
    EXPECT_EQ(visibleLabels.front(), number(0));
    EXPECT_EQ(visibleLabels.back(), number(128));

    vv::render::FrameSettings pinned;
    pinned.vss.range = {
        .mode = vv::vss::RangeMode::Fixed, .dmin = 300.0, .dmax = 428.0, .pinnedVisible = true};
    EXPECT_EQ(painted(pinned, std::nullopt), (std::pair{visibleTitle, visibleLabels}))
        << "a pinned export's legend is the screen's";

    vv::render::FrameSettings fixed;
    fixed.vss.range = {.mode = vv::vss::RangeMode::Fixed, .dmin = 300.0, .dmax = 428.0};
    const auto [fixedTitle, fixedLabels] = painted(fixed, std::nullopt);
    EXPECT_EQ(fixedTitle, distance);
    ASSERT_GE(fixedLabels.size(), 2);
    EXPECT_EQ(fixedLabels.front(), number(300));
    EXPECT_EQ(fixedLabels.back(), number(428));

    // VSS off, a fixed range left set: the cue's visible range, from the frontmost vessel.
    fixed.vss.enabled = false;
    fixed.cue.cue = vv::render::VesselCue::Chromadepth;
    const auto [cueTitle, cueLabels] = painted(fixed, std::pair{310.0, 350.0});
    EXPECT_EQ(cueTitle, behind);
    ASSERT_GE(cueLabels.size(), 2);
    EXPECT_EQ(cueLabels.front(), number(0));
    EXPECT_EQ(cueLabels.back(), number(40));
}

INSTANTIATE_TEST_SUITE_P(Locales, LegendTextTest, ::testing::Values("en_US", "de_DE"));

TEST(LegendTitleTest, TheDepthLegendHasOneTitleWithItsUnit) {
    vv::render::test::ensureGuiApplication();
    vv::render::DepthLegend legend;
    legend.unit = "mm";
    EXPECT_EQ(vv::render::depthLegendTitle(legend), "Depth behind the frontmost vessel (mm)");
    EXPECT_EQ(vv::render::depthQuantityName(vv::render::DepthReference::FrontmostVessel),
              QStringLiteral("Depth behind the frontmost vessel"));
    legend.unit.clear();
    EXPECT_EQ(vv::render::depthLegendTitle(legend), "Depth behind the frontmost vessel");
    legend.unit = "mm";
    legend.reference = vv::render::DepthReference::Camera;
    EXPECT_EQ(vv::render::depthLegendTitle(legend), "Viewing distance (mm)");
}

}  // namespace

}  // namespace legend_text_test
