// SPDX-License-Identifier: GPL-3.0-or-later
// Label (categorical) arrays on the vessels and in the legends: one palette
// colour per label, flat per triangle (never a label between two others),
// arbitrary label values, and legends that list the labels; binned legends
// with every bin edge; legend numbers in the UI locale. GL tests: run under
// `xvfb-run -a` with QT_QPA_PLATFORM=xcb.
#include <gtest/gtest.h>

#include <QImage>
#include <QLocale>
#include <QPainter>
#include <cstdint>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "RenderTestUtil.h"
#include "vv/colormaps/ColorMap.h"
#include "vv/colormaps/LabelPalette.h"
#include "vv/core/Error.h"
#include "vv/render/FrameRenderer.h"
#include "vv/render/LegendPainter.h"
#include "vv/render/MeshStyle.h"

namespace {

using vv::render::MeshStyle;
using vv::render::test::FrameHarness;

QRgb rgbOf(const glm::vec3& c) {
    const glm::u8vec4 v = vv::colormaps::toRgba8(c);
    return qRgb(v.r, v.g, v.b);
}

/// Adds the integer point array "segment_id" to `mesh`: `label(vertex index)`.
template <typename F>
void addLabels(vv::scene::Mesh& mesh, F label) {
    vv::scene::DataArray array;
    array.name = "segment_id";
    array.components = 1;
    array.integer = true;
    for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
        array.values.push_back(label(i));
    }
    mesh.pointArrays.push_back(std::move(array));
}

class LabelArrayTest : public vv::render::test::GlRenderTest {
  protected:
    /// A 200 x 150 harness, or a test failure naming why there is none.
    static std::unique_ptr<FrameHarness> makeHarness() {
        try {
            return std::make_unique<FrameHarness>(200, 150);
        } catch (const vv::Error& e) {
            ADD_FAILURE() << e.what();
            return nullptr;
        }
    }
    static MeshStyle labelStyle() {
        MeshStyle style;
        style.array = "segment_id";
        style.lighting = false;  // exact colours
        return style;
    }
    /// The colours of the pixels of object `id` (1 + mesh index), counted.
    static std::map<QRgb, int> colours(const QImage& image, const std::vector<std::uint32_t>& ids,
                                       std::uint32_t id) {
        std::map<QRgb, int> out;
        for (int y = 0; y < image.height(); ++y) {
            for (int x = 0; x < image.width(); ++x) {
                if (ids[static_cast<std::size_t>(y * image.width() + x)] == id) {
                    ++out[image.pixel(x, y) | 0xff000000U];
                }
            }
        }
        return out;
    }
};

// A tube of one ring of quads whose first circle has label 1 and second
// label 3: every triangle has vertices of labels 1 and 3 only. Continuous
// colours (or interpolate-and-round) would show a colour between them; the
// flat lookup shows label 1's or label 3's colour and never label 2's,
// which a second tube carries.
TEST_F(LabelArrayTest, ATriangleBetweenTwoLabelsShowsNoLabelBetweenThem) {
    const auto harness = makeHarness();
    ASSERT_TRUE(harness);
    vv::scene::Scene scene;
    const int segments = 24;
    scene.meshes.push_back(vv::render::test::makeTube(2.0F, -8.0F, 16.0F, 3.0F, 0.0F, segments, 1));
    addLabels(scene.meshes[0], [&](std::size_t i) { return i < segments ? 1.0F : 3.0F; });
    scene.meshes.push_back(vv::render::test::makeTube(1.0F, -8.0F, 16.0F, -3.0F, 0.0F, 12, 4));
    addLabels(scene.meshes[1], [](std::size_t) { return 2.0F; });
    harness->setScene(scene);
    const QImage image = harness->render(labelStyle(), flatSettings());
    vv::render::test::saveImage(image, "labels-", "between");
    const auto ids = harness->objectIds();

    const QRgb label1 = rgbOf(vv::colormaps::labelColor(0));
    const QRgb label2 = rgbOf(vv::colormaps::labelColor(1));
    const QRgb label3 = rgbOf(vv::colormaps::labelColor(2));
    const auto mixed = colours(image, ids, 1);
    ASSERT_FALSE(mixed.empty());
    int total = 0;
    for (const auto& [rgb, count] : mixed) {
        total += count;
        EXPECT_TRUE(rgb == label1 || rgb == label3)
            << "a colour that is no label's: " << std::hex << rgb << " on " << std::dec << count
            << " pixels";
    }
    EXPECT_EQ(mixed.count(label2), 0U);
    EXPECT_GT(mixed.count(label1) + mixed.count(label3), 0U);
    const auto single = colours(image, ids, 2);
    ASSERT_EQ(single.size(), 1U);
    EXPECT_EQ(single.begin()->first, label2);
    EXPECT_GT(total, 500);
}

// Arbitrary ids (0, 5, 17, 200): label k in ascending order has palette colour k.
TEST_F(LabelArrayTest, ArbitraryLabelValuesTakeThePaletteInOrder) {
    const auto harness = makeHarness();
    ASSERT_TRUE(harness);
    const std::vector<float> values{200.0F, 0.0F, 17.0F, 5.0F};
    vv::scene::Scene scene;
    for (std::size_t m = 0; m < values.size(); ++m) {
        const float y = 6.0F - 4.0F * static_cast<float>(m);
        scene.meshes.push_back(vv::render::test::makeTube(1.2F, -8.0F, 16.0F, y, 0.0F, 16, 4));
        addLabels(scene.meshes[m], [&](std::size_t) { return values[m]; });
    }
    harness->setScene(scene);
    const QImage image = harness->render(labelStyle(), flatSettings());
    vv::render::test::saveImage(image, "labels-", "arbitrary");
    const auto ids = harness->objectIds();
    const std::map<float, std::size_t> order{{0.0F, 0}, {5.0F, 1}, {17.0F, 2}, {200.0F, 3}};
    for (std::size_t m = 0; m < values.size(); ++m) {
        const auto shown = colours(image, ids, static_cast<std::uint32_t>(m + 1));
        ASSERT_EQ(shown.size(), 1U) << "mesh " << m;
        EXPECT_EQ(shown.begin()->first, rgbOf(vv::colormaps::labelColor(order.at(values[m]))))
            << "label " << values[m];
    }
    // Told to read them as a measurement: the colour map again.
    MeshStyle continuous = labelStyle();
    continuous.values = vv::render::ArrayValues::Continuous;
    const QImage mapped = harness->render(continuous, flatSettings());
    const auto top = colours(mapped, harness->objectIds(), 1);  // 200: the map's last colour
    ASSERT_EQ(top.size(), 1U);
    EXPECT_EQ(top.begin()->first,
              rgbOf(vv::colormaps::sample(vv::colormaps::ColorMap::Viridis, 1.0F)));
}

TEST(LabelLegendTest, LegendsListEveryLabelWithItsNameOrValue) {
    vv::render::test::ensureGuiApplication();
    vv::scene::Scene scene;
    const std::vector<float> values{200.0F, 0.0F, 17.0F, 5.0F};
    for (std::size_t m = 0; m < values.size(); ++m) {
        scene.meshes.push_back(
            vv::render::test::makeTube(1.0F, -8.0F, 16.0F, static_cast<float>(m), 0.0F, 8, 2));
        addLabels(scene.meshes[m], [&](std::size_t) { return values[m]; });
    }
    scene.meshes[0].labelNames["segment_id"] = {{200, "Renal artery"}};
    MeshStyle style;
    style.array = "segment_id";
    vv::render::FrameSettings settings;
    settings.vss.enabled = false;
    const auto legends = vv::render::legendsFor(&scene, style, std::make_pair(0.0F, 200.0F),
                                                settings, {}, std::nullopt);
    ASSERT_TRUE(legends.parameter.has_value());
    const auto& labels = legends.parameter->labels;
    ASSERT_EQ(labels.size(), 4U);
    EXPECT_EQ(vv::render::labelName(labels[0]), QStringLiteral("Label 0"));
    EXPECT_EQ(vv::render::labelName(labels[2]), QStringLiteral("Label 17"));
    EXPECT_EQ(vv::render::labelName(labels[3]), QStringLiteral("Renal artery"));

    // Painted: one swatch of each label's colour, none of a colour map.
    QImage image(800, 600, QImage::Format_RGB32);
    image.fill(qRgb(255, 255, 255));
    vv::render::paintLegends(image, legends);
    vv::render::test::saveImage(image, "labels-", "legend");
    std::map<QRgb, int> seen;
    for (int y = 0; y < image.height(); ++y) {
        for (int x = 0; x < image.width(); ++x) {
            ++seen[image.pixel(x, y) | 0xff000000U];
        }
    }
    for (std::size_t i = 0; i < labels.size(); ++i) {
        EXPECT_GE(seen[rgbOf(vv::colormaps::labelColor(i))], 25) << "no swatch for label " << i;
    }
    EXPECT_EQ(seen[rgbOf(vv::colormaps::labelColor(4))], 0);  // only as many swatches as labels
}

TEST(ShownLabelsCacheTest, LabelsAreFoundAgainOnlyWhenWhatDecidesThemChanges) {
    // Finding labels reads every value: a view asks for them every frame and
    // on every style edit, so only the shown arrays and the Values mode count.
    vv::scene::Scene scene;
    scene.meshes.push_back(vv::render::test::makeTube(1.0F, -8.0F, 16.0F, 0.0F, 0.0F, 8, 2));
    addLabels(scene.meshes[0], [](std::size_t i) { return static_cast<float>(i % 3); });
    MeshStyle style;
    style.array = "segment_id";
    vv::render::ShownLabelsCache cache;
    ASSERT_NE(vv::render::labelsOf(cache.get(scene, style), "segment_id"), nullptr);
    EXPECT_EQ(vv::render::labelsOf(cache.get(scene, style), "segment_id")->size(), 3U);
    style.colorMap = vv::colormaps::ColorMap::Inferno;  // edits that do not decide labels
    style.bins = 4;
    (void)cache.get(scene, style);
    EXPECT_EQ(cache.computations(), 1U);

    style.values = vv::render::ArrayValues::Continuous;  // the mode decides
    EXPECT_EQ(vv::render::labelsOf(cache.get(scene, style), "segment_id"), nullptr);
    EXPECT_EQ(cache.computations(), 2U);
    style.values = vv::render::ArrayValues::Auto;
    style.array.clear();  // the shown arrays decide
    EXPECT_TRUE(cache.get(scene, style).empty());
    EXPECT_EQ(cache.computations(), 3U);

    style.array = "segment_id";
    (void)cache.get(scene, style);
    scene.meshes[0].pointArrays.clear();  // another scene's values
    addLabels(scene.meshes[0], [](std::size_t) { return 7.0F; });
    cache.invalidate();
    const auto* labels = vv::render::labelsOf(cache.get(scene, style), "segment_id");
    ASSERT_NE(labels, nullptr);
    EXPECT_EQ(labels->size(), 1U);
    EXPECT_EQ(cache.computations(), 5U);
}

TEST(LabelLegendTest, MoreLabelsThanColoursGetTwoLinesNotAMisleadingKey) {
    // 71 labels share 6 colours: a swatch list would pair one colour with
    // several names, so the legend says in two lines that the colours repeat.
    vv::render::test::ensureGuiApplication();
    vv::render::ParameterLegend many;
    many.name = "segment_id";
    for (int v = 0; v < 71; ++v) {
        many.labels.push_back(vv::scene::Label{v, {}});
    }
    vv::render::ParameterLegend one = many;
    one.labels.resize(1);
    const QRectF area(0, 0, 1200, 800);
    vv::render::Legends manyLegends;
    manyLegends.parameter = many;
    manyLegends.interactive = true;  // over the live view: "hover names a label" too
    vv::render::Legends oneLegend;
    oneLegend.parameter = one;
    oneLegend.interactive = true;
    const QRectF manyBox = vv::render::legendLayout(area, manyLegends).parameter;
    const QRectF oneBox = vv::render::legendLayout(area, oneLegend).parameter;
    EXPECT_GT(manyBox.height(), oneBox.height());  // two lines of text ...
    EXPECT_LT(manyBox.height(), 2.0 * oneBox.height()) << "the repeating key is a list";

    QImage image(1200, 800, QImage::Format_RGB32);
    image.fill(qRgb(255, 255, 255));
    vv::render::paintLegends(image, manyLegends);
    int swatchPixels = 0;
    for (int y = 0; y < image.height(); ++y) {
        for (int x = 0; x < image.width(); ++x) {
            for (std::size_t i = 0; i < vv::colormaps::labelPalette().size(); ++i) {
                swatchPixels +=
                    (image.pixel(x, y) | 0xff000000U) == rgbOf(vv::colormaps::labelColor(i));
            }
        }
    }
    EXPECT_EQ(swatchPixels, 0) << "swatches drawn although colours repeat";
}

TEST(LabelLegendTest, AnExportedLegendDoesNotSayHoverAndWrapsInsteadOfCutting) {
    // An exported image or report cannot be hovered: its legend of repeating
    // colours is the one summary line. In a narrow image that line is broken
    // into two, not elided: the box grows by a line.
    vv::render::test::ensureGuiApplication();
    vv::render::ParameterLegend many;
    many.name = "segment_id";
    for (int v = 0; v < 16; ++v) {
        many.labels.push_back(vv::scene::Label{v, {}});
    }
    vv::render::Legends exported;
    exported.parameter = many;
    vv::render::Legends live = exported;
    live.interactive = true;
    const QRectF wide(0, 0, 1200, 800);
    const double exportedWide = vv::render::legendLayout(wide, exported).parameter.height();
    const double liveWide = vv::render::legendLayout(wide, live).parameter.height();
    EXPECT_LT(exportedWide, liveWide) << "the exported legend has the hover line";
    // 400 px wide (same height, so the same font): the legend is 120 px,
    // narrower than the summary line.
    const QRectF narrow(0, 0, 400, 800);
    const double exportedNarrow = vv::render::legendLayout(narrow, exported).parameter.height();
    EXPECT_GT(exportedNarrow, exportedWide * 1.1) << "the summary was cut, not wrapped";
}

/// The x positions of the tick marks below a legend bar painted on black:
/// the row just below the bar's light frame, bright runs.
std::vector<int> tickMarks(const QImage& image, const QRectF& box) {
    // The bar's frame: the lowest row of the box with a long light run.
    int frame = -1;
    for (int y = static_cast<int>(box.top()); y < static_cast<int>(box.bottom()); ++y) {
        int light = 0;
        for (int x = static_cast<int>(box.left()); x < static_cast<int>(box.right()); ++x) {
            light += qGray(image.pixel(x, y)) > 90 ? 1 : 0;
        }
        if (light > box.width() * 0.8) {
            frame = y;
        }
    }
    std::vector<int> marks;
    if (frame < 0) {
        return marks;
    }
    const int y = frame + 2;
    bool inside = false;
    for (int x = static_cast<int>(box.left()); x < static_cast<int>(box.right()); ++x) {
        const bool bright = qGray(image.pixel(x, y)) > 60;
        if (bright && !inside) {
            marks.push_back(x);
        }
        inside = bright;
    }
    return marks;
}

TEST(BinnedLegendTest, EveryBinEdgeHasATickAndOnePrecision) {
    vv::render::test::ensureGuiApplication();
    const auto ticks = vv::render::binEdgeTicks(0.450075, 1.30846, 6);
    ASSERT_EQ(ticks.size(), 7U);
    std::set<QString> texts;
    for (const auto& t : ticks) {
        texts.insert(t.label);
        EXPECT_EQ(t.label.size() - t.label.indexOf('.'), 3) << t.label.toStdString();
    }
    EXPECT_EQ(texts.size(), 7U);  // neighbouring edges read differently
    EXPECT_EQ(ticks.front().label, QStringLiteral("0.45"));
    EXPECT_EQ(ticks.back().label, QStringLiteral("1.31"));
    // Narrow edges need more digits: 1.000, 1.001, ..., 1.004.
    const auto fine = vv::render::binEdgeTicks(1.0, 1.004, 4);
    ASSERT_EQ(fine.size(), 5U);
    EXPECT_EQ(fine[1].label, QStringLiteral("1.001"));
    EXPECT_EQ(fine[0].label, QStringLiteral("1.000"));

    // Painted: bins + 1 tick marks under the bar.
    vv::render::Legends legends;
    legends.parameter = vv::render::ParameterLegend{
        "wss", "Pa", 0.450075F, 1.30846F, vv::colormaps::ColorMap::Inferno, 6, {}, {}};
    QImage image(1200, 800, QImage::Format_RGB32);
    image.fill(qRgb(0, 0, 0));
    vv::render::paintLegends(image, legends);
    vv::render::test::saveImage(image, "labels-", "binned-legend");
    const auto layout = vv::render::legendLayout(QRectF(0, 0, 1200, 800), legends);
    EXPECT_EQ(tickMarks(image, layout.parameter).size(), 7U);
}

TEST(LabelledTicksTest, AsManyAsFitWithBothEnds) {
    const std::vector<double> centres{0, 10, 20, 30, 40, 50, 60};
    EXPECT_EQ(vv::render::labelledTicks(centres, std::vector<double>(7, 6.0), 2.0),
              (std::vector<std::size_t>{0, 1, 2, 3, 4, 5, 6}));
    EXPECT_EQ(vv::render::labelledTicks(centres, std::vector<double>(7, 14.0), 2.0),
              (std::vector<std::size_t>{0, 2, 4, 6}));
    // Every 4th would end at 4: 6 replaces it when they collide.
    const std::vector<double> eight{0, 10, 20, 30, 40, 50, 60, 65};
    const auto chosen = vv::render::labelledTicks(eight, std::vector<double>(8, 24.0), 2.0);
    EXPECT_EQ(chosen.front(), 0U);
    EXPECT_EQ(chosen.back(), 7U);
    // A depth legend 0, 50, 100, 121: only 100 collides with the end, so 50
    // keeps its label (the end replaces just its close neighbour).
    const std::vector<double> depth{0, 107, 235, 258};
    EXPECT_EQ(vv::render::labelledTicks(depth, std::vector<double>(4, 28.0), 3.0),
              (std::vector<std::size_t>{0, 1, 3}));
    // Five bins on a 258 px bar, 34 px labels, the ends held inside the bar:
    // neighbours collide, yet four labels fit (every second edge gave three:
    // 0, 2 and the end, which pushed 4 out).
    const std::vector<double> fiveBins{17.0, 51.6, 103.2, 154.8, 206.4, 241.0};
    const auto five = vv::render::labelledTicks(fiveBins, std::vector<double>(6, 34.0), 3.0);
    EXPECT_EQ(five.size(), 4U);
    EXPECT_EQ(five.front(), 0U);
    EXPECT_EQ(five.back(), 5U);
}

/// Sets the default locale for a test and restores it.
class LocaleGuard {
  public:
    explicit LocaleGuard(const QLocale& locale) { QLocale::setDefault(locale); }
    ~LocaleGuard() { QLocale::setDefault(previous_); }
    LocaleGuard(const LocaleGuard&) = delete;
    LocaleGuard& operator=(const LocaleGuard&) = delete;

  private:
    QLocale previous_;
};

TEST(LegendLocaleTest, TickLabelsUseTheUiLocale) {
    const LocaleGuard german{QLocale(QLocale::German, QLocale::Germany)};
    for (const auto& ticks :
         {vv::render::legendTicks(0.450075, 1.30846),
          vv::render::binEdgeTicks(0.450075, 1.30846, 6),
          vv::render::depthLegendTicks(vv::render::DepthLegend{.dmin = 10.0, .dmax = 33.4})}) {
        for (const auto& t : ticks) {
            EXPECT_FALSE(t.label.contains('.')) << t.label.toStdString();
        }
    }
    EXPECT_EQ(vv::render::legendTicks(0.450075, 1.30846).front().label, QStringLiteral("0,45"));
    EXPECT_EQ(vv::render::legendNumber(-0.001, 1), QStringLiteral("0,0"));
}

}  // namespace
