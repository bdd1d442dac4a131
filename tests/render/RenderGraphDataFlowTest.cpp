// SPDX-License-Identifier: GPL-3.0-or-later
// How passes hand each other data, without GL: CPU values as graph resources,
// the blackboard, results read after execute(), declared render targets.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "vv/render/RenderGraph.h"

namespace {

using ::testing::AllOf;
using ::testing::HasSubstr;
using ::testing::ThrowsMessage;
using vv::render::Blackboard;
using vv::render::CpuResourceAllocator;
using vv::render::CpuTexture;
using vv::render::CpuValue;
using vv::render::Handle;
using vv::render::ImportOptions;
using vv::render::PassInfo;
using vv::render::PassState;
using vv::render::RenderGraph;
using vv::render::RenderGraphCache;
using vv::render::RenderGraphError;
using vv::render::RenderTarget;
using vv::render::RenderTargetAttachments;
using vv::render::RenderTargetId;
using vv::render::Texture;
using vv::render::TextureDescriptor;
using vv::render::TextureFormat;
using Builder = RenderGraph::Builder;
using Resources = RenderGraph::Resources;

/// A depth range handed from one pass to another, as the renderer's is.
struct Range {
    double lo = 0.0;
    double hi = 0.0;
    friend bool operator==(const Range&, const Range&) = default;
};
using RangeValue = CpuValue<Range>;

const TextureDescriptor kColour{8, 4, TextureFormat::RGBA8};

PassState stateOf(const RenderGraph& graph, const std::string& pass) {
    for (const PassInfo& info : graph.passes()) {
        if (info.name == pass) {
            return info.state;
        }
    }
    throw std::runtime_error("no pass " + pass);
}

/// Two passes joined by a persistent CPU value, found on the blackboard:
/// "measure" computes the range from `lo` (a parameter), "shade" writes
/// lo + hi into a persistent texture of its own. Counts the runs and keeps
/// what "shade" saw.
class TwoPasses {
  public:
    TwoPasses() : cache_(allocator_) {}

    std::unique_ptr<RenderGraph> frame(double lo) {
        auto graph = std::make_unique<RenderGraph>(cache_);
        struct Measure {
            Handle<RangeValue> range;
        };
        const auto& measure = graph->addPass<Measure>(
            "measure",
            [&](Builder& b, Measure& d) {
                b.dependsOn("lo", lo);
                d.range = b.write(b.createPersistent<RangeValue>("range", {}));
            },
            [this, lo](const Resources& r, const Measure& d) {
                r.getForWrite(d.range).set(Range{lo, lo + 10.0});
                ++measureRuns_;
            });
        graph->blackboard().put("range", measure.range);
        struct Shade {
            Handle<RangeValue> range;
            Handle<Texture> colour;
        };
        const auto& shade = graph->addPass<Shade>(
            "shade",
            [&](Builder& b, Shade& d) {
                d.range = b.read<RangeValue>("range");
                d.colour = b.write(b.createPersistent<Texture>("colour", kColour));
            },
            [this](const Resources& r, const Shade& d) {
                const Range& range = r.get(d.range).value();
                seen_ = range;
                r.getForWrite(d.colour).objectAs<CpuTexture>().texels()[0] =
                    static_cast<float>(range.lo + range.hi);
                ++shadeRuns_;
            });
        graph->markTarget(shade.colour);
        graph->execute();
        rangeHandle_ = measure.range;
        return graph;
    }

    [[nodiscard]] int measureRuns() const { return measureRuns_; }
    [[nodiscard]] int shadeRuns() const { return shadeRuns_; }
    [[nodiscard]] const std::optional<Range>& seen() const { return seen_; }
    [[nodiscard]] Handle<RangeValue> rangeHandle() const { return rangeHandle_; }

  private:
    CpuResourceAllocator allocator_;
    RenderGraphCache cache_;
    int measureRuns_ = 0;
    int shadeRuns_ = 0;
    std::optional<Range> seen_;
    Handle<RangeValue> rangeHandle_;
};

// ---- CPU values ------------------------------------------------------------------

TEST(RenderGraphCpuValue, RoundTripsFromWriterToReaderAndToTheCaller) {
    TwoPasses passes;
    const auto graph = passes.frame(2.0);
    ASSERT_TRUE(passes.seen().has_value());
    EXPECT_EQ(*passes.seen(), (Range{2.0, 12.0}));
    const RangeValue* result = graph->result(passes.rangeHandle());
    ASSERT_NE(result, nullptr);
    ASSERT_TRUE(result->hasValue());
    EXPECT_EQ(result->value(), (Range{2.0, 12.0}));
}

TEST(RenderGraphCpuValue, ReaderReRunsExactlyWhenTheValueChanges) {
    TwoPasses passes;
    static_cast<void>(passes.frame(1.0));
    EXPECT_EQ(passes.measureRuns(), 1);
    EXPECT_EQ(passes.shadeRuns(), 1);

    // Nothing changed: both cached, and the cached value is still there.
    auto graph = passes.frame(1.0);
    EXPECT_EQ(stateOf(*graph, "measure"), PassState::Cached);
    EXPECT_EQ(stateOf(*graph, "shade"), PassState::Cached);
    EXPECT_EQ(passes.shadeRuns(), 1);
    ASSERT_NE(graph->result(passes.rangeHandle()), nullptr);
    EXPECT_EQ(graph->result(passes.rangeHandle())->value(), (Range{1.0, 11.0}));

    // The writer's parameter changed: the writer runs, and so does the reader.
    graph = passes.frame(3.0);
    EXPECT_EQ(stateOf(*graph, "measure"), PassState::Executed);
    EXPECT_EQ(stateOf(*graph, "shade"), PassState::Executed);
    EXPECT_EQ(passes.shadeRuns(), 2);
    EXPECT_EQ(*passes.seen(), (Range{3.0, 13.0}));
    for (const PassInfo& info : graph->passes()) {
        if (info.name == "shade") {
            EXPECT_THAT(info.reason, HasSubstr("'range'"));
        }
    }

    graph = passes.frame(3.0);
    EXPECT_EQ(stateOf(*graph, "shade"), PassState::Cached);
    EXPECT_EQ(passes.shadeRuns(), 2);
}

TEST(RenderGraphCpuValue, AValueIsEmptyUntilItsWriterSetsItEvenInReusedStorage) {
    CpuResourceAllocator allocator;
    RenderGraphCache cache(allocator);
    struct Data {
        Handle<RangeValue> value;
    };
    // Frame 1 sets the transient value; frame 2's writer forgets to: the
    // reader must not see frame 1's range in the pooled storage.
    for (const bool set : {true, false}) {
        RenderGraph graph(cache);
        const auto& writer = graph.addPass<Data>(
            "writer",
            [&](Builder& b, Data& d) { d.value = b.write(b.create<RangeValue>("value", {})); },
            [set](const Resources& r, const Data& d) {
                if (set) {
                    r.getForWrite(d.value).set(Range{1.0, 2.0});
                }
            });
        std::optional<Range> read;
        graph.addPass<Data>(
            "reader",
            [&](Builder& b, Data& d) {
                d.value = b.read(writer.value);
                b.sideEffect();
            },
            [&read](const Resources& r, const Data& d) { read = r.get(d.value).value(); });
        if (set) {
            graph.execute();
            EXPECT_EQ(read, (Range{1.0, 2.0}));
        } else {
            EXPECT_THAT([&] { graph.execute(); },
                        ThrowsMessage<RenderGraphError>(HasSubstr("before its writer set it")));
        }
    }
}

TEST(RenderGraphCpuValue, ValuesOfDifferentTypesNeverShareStorage) {
    CpuResourceAllocator allocator;
    RenderGraphCache cache(allocator);
    RenderGraph graph(cache);
    struct Data {
        Handle<RangeValue> range;
        Handle<CpuValue<int>> count;
    };
    const auto& data = graph.addPass<Data>(
        "both",
        [](Builder& b, Data& d) {
            d.range = b.write(b.createPersistent<RangeValue>("range", {}));
            d.count = b.write(b.createPersistent<CpuValue<int>>("count", {}));
        },
        [](const Resources& r, const Data& d) {
            r.getForWrite(d.range).set(Range{4.0, 5.0});
            r.getForWrite(d.count).set(7);
        });
    graph.markTarget(data.range);
    graph.markTarget(data.count);
    graph.execute();
    EXPECT_EQ(graph.result(data.range)->value(), (Range{4.0, 5.0}));
    EXPECT_EQ(graph.result(data.count)->value(), 7);
    const auto resources = graph.resources();
    EXPECT_EQ(resources.front().description, "CPU value");
}

TEST(RenderGraphCpuValue, APassReadingAValueItDidNotDeclareIsRefused) {
    CpuResourceAllocator allocator;
    RenderGraphCache cache(allocator);
    RenderGraph graph(cache);
    struct Data {
        Handle<RangeValue> value;
    };
    const auto& writer = graph.addPass<Data>(
        "measure",
        [](Builder& b, Data& d) { d.value = b.write(b.create<RangeValue>("range", {})); },
        [](const Resources& r, const Data& d) { r.getForWrite(d.value).set(Range{}); });
    const Handle<RangeValue> range = writer.value;
    graph.addPass<Data>(
        "vessel-shading", [](Builder& b, Data&) { b.sideEffect(); },  // declares nothing
        [range](const Resources& r, const Data&) { static_cast<void>(r.get(range).value()); });
    graph.markTarget(writer.value);
    EXPECT_THAT([&] { graph.execute(); },
                ThrowsMessage<RenderGraphError>(
                    AllOf(HasSubstr("'vessel-shading'"), HasSubstr("'range'"))));
}

// ---- the blackboard --------------------------------------------------------------

TEST(RenderGraphBlackboard, PutGetFindAndReplace) {
    CpuResourceAllocator allocator;
    RenderGraphCache cache(allocator);
    RenderGraph graph(cache);
    const auto screen = graph.importResource(
        "screen", Texture(kColour, std::make_shared<CpuTexture>(kColour)), ImportOptions{});
    Blackboard& board = graph.blackboard();
    EXPECT_FALSE(board.contains("screen"));
    EXPECT_FALSE(board.find<Texture>("screen").has_value());
    board.put("screen", screen);
    EXPECT_TRUE(board.contains("screen"));
    EXPECT_EQ(board.get<Texture>("screen"), screen);
    EXPECT_EQ(board.find<Texture>("screen"), screen);
    EXPECT_EQ(board.names(), std::vector<std::string>{"screen"});
    EXPECT_THAT([&] { static_cast<void>(board.get<Texture>("depth")); },
                ThrowsMessage<RenderGraphError>(HasSubstr("'depth'")));
    EXPECT_THAT([&] { static_cast<void>(board.get<RangeValue>("screen")); },
                ThrowsMessage<RenderGraphError>(
                    AllOf(HasSubstr("'screen'"), HasSubstr("another resource type"))));
    EXPECT_THROW(board.put("nothing", Handle<Texture>{}), RenderGraphError);
    EXPECT_THROW(board.put("", screen), RenderGraphError);
    board.remove("screen");
    EXPECT_FALSE(board.contains("screen"));
}

TEST(RenderGraphBlackboard, ReadingANameNobodyPutIsRefusedNamingPassAndResource) {
    CpuResourceAllocator allocator;
    RenderGraphCache cache(allocator);
    RenderGraph graph(cache);
    struct Data {
        Handle<RangeValue> range;
    };
    EXPECT_THAT(
        [&] {
            graph.addPass<Data>(
                "vessel-shading",
                [](Builder& b, Data& d) { d.range = b.read<RangeValue>("visible-depth-range"); },
                [](const Resources&, const Data&) {});
        },
        ThrowsMessage<RenderGraphError>(AllOf(HasSubstr("'vessel-shading'"),
                                              HasSubstr("'visible-depth-range'"),
                                              HasSubstr("blackboard"))));
    // The failed setup leaves the graph unusable, naming the pass.
    EXPECT_THAT([&] { graph.compile(); },
                ThrowsMessage<RenderGraphError>(HasSubstr("'vessel-shading'")));
}

// ---- results after execute() --------------------------------------------------

TEST(RenderGraphResult, OnlyPersistentOrImportedLatestVersionsAfterExecute) {
    CpuResourceAllocator allocator;
    RenderGraphCache cache(allocator);
    RenderGraph graph(cache);
    struct Data {
        Handle<RangeValue> kept;
        Handle<RangeValue> pooled;
    };
    const auto& data = graph.addPass<Data>(
        "measure",
        [](Builder& b, Data& d) {
            d.kept = b.write(b.createPersistent<RangeValue>("kept", {}));
            d.pooled = b.write(b.create<RangeValue>("pooled", {}));
        },
        [](const Resources& r, const Data& d) {
            r.getForWrite(d.kept).set(Range{1.0, 2.0});
            r.getForWrite(d.pooled).set(Range{3.0, 4.0});
        });
    struct Unread {
        Handle<RangeValue> value;
    };
    const auto& culled = graph.addPass<Unread>(
        "culled",
        [](Builder& b, Unread& d) {
            d.value = b.write(b.createPersistent<RangeValue>("never", {}));
        },
        [](const Resources& r, const Unread& d) { r.getForWrite(d.value).set(Range{}); });
    const auto screen = graph.importResource(
        "screen", Texture(kColour, std::make_shared<CpuTexture>(kColour)), ImportOptions{});
    graph.markTarget(data.kept);
    graph.markTarget(data.pooled);
    EXPECT_THAT([&] { static_cast<void>(graph.result(data.kept)); },
                ThrowsMessage<RenderGraphError>(HasSubstr("execute()")));
    graph.execute();
    ASSERT_NE(graph.result(data.kept), nullptr);
    EXPECT_EQ(graph.result(data.kept)->value(), (Range{1.0, 2.0}));
    EXPECT_THAT(
        [&] { static_cast<void>(graph.result(data.pooled)); },
        ThrowsMessage<RenderGraphError>(AllOf(HasSubstr("'pooled'"), HasSubstr("transient"))));
    EXPECT_EQ(graph.result(culled.value), nullptr);  // its writer was culled
    EXPECT_NE(graph.result(screen), nullptr);        // imported: the caller's own object
}

TEST(RenderGraphResult, AnOlderVersionIsRefused) {
    CpuResourceAllocator allocator;
    RenderGraphCache cache(allocator);
    RenderGraph graph(cache);
    const auto screen = graph.importResource(
        "screen", Texture(kColour, std::make_shared<CpuTexture>(kColour)), ImportOptions{});
    struct Data {
        Handle<Texture> texture;
    };
    const auto& present = graph.addPass<Data>(
        "present", [&](Builder& b, Data& d) { d.texture = b.write(screen); },
        [](const Resources&, const Data&) {});
    graph.markTarget(present.texture);
    graph.execute();
    EXPECT_NE(graph.result(present.texture), nullptr);
    EXPECT_THAT([&] { static_cast<void>(graph.result(screen)); },
                ThrowsMessage<RenderGraphError>(AllOf(HasSubstr("'screen'"), HasSubstr("latest"))));
}

// ---- render targets --------------------------------------------------------------

TEST(RenderGraphRenderTarget, ResolvesToTheWrittenTexturesInAttachmentOrder) {
    CpuResourceAllocator allocator;
    RenderGraphCache cache(allocator);
    RenderGraph graph(cache);
    struct GBuffer {
        Handle<Texture> depth;
        Handle<Texture> normal;
        Handle<Texture> zbuffer;
        RenderTargetId target;
    };
    std::optional<RenderTarget> resolved;
    std::vector<const Texture*> written;
    const auto& gbuffer = graph.addPass<GBuffer>(
        "geometry",
        [](Builder& b, GBuffer& d) {
            d.depth = b.write(b.create<Texture>("linear-depth", {8, 4, TextureFormat::R32F}));
            d.normal = b.write(b.create<Texture>("normal", {8, 4, TextureFormat::RGBA16F}));
            d.zbuffer = b.write(b.create<Texture>("depth", {8, 4, TextureFormat::Depth32F}));
            d.target = b.declareRenderTarget(
                "gbuffer", RenderTargetAttachments{{d.depth, d.normal}, d.zbuffer});
        },
        [&](const Resources& r, const GBuffer& d) {
            resolved = r.renderTarget(d.target);
            written = {&r.get(d.depth), &r.get(d.normal), &r.get(d.zbuffer)};
        });
    graph.markTarget(gbuffer.depth);
    graph.markTarget(gbuffer.normal);
    graph.markTarget(gbuffer.zbuffer);
    graph.execute();
    ASSERT_TRUE(resolved.has_value());
    EXPECT_EQ(resolved->name, "gbuffer");
    ASSERT_EQ(resolved->colors.size(), 2U);
    EXPECT_EQ(resolved->colors[0], written[0]);
    EXPECT_EQ(resolved->colors[1], written[1]);
    EXPECT_EQ(resolved->depth, written[2]);
    EXPECT_EQ(resolved->width, 8);
    EXPECT_EQ(resolved->height, 4);
    EXPECT_EQ(graph.passes().front().renderTargets, std::vector<std::string>{"gbuffer"});
    EXPECT_THAT(graph.toText(), HasSubstr("render targets: gbuffer"));
}

TEST(RenderGraphRenderTarget, AnAttachmentThePassDoesNotWriteIsRefused) {
    CpuResourceAllocator allocator;
    RenderGraphCache cache(allocator);
    RenderGraph graph(cache);
    struct Data {
        Handle<Texture> texture;
    };
    const auto& source = graph.addPass<Data>(
        "source",
        [](Builder& b, Data& d) { d.texture = b.write(b.create<Texture>("layer", kColour)); },
        [](const Resources&, const Data&) {});
    const Handle<Texture> layer = source.texture;
    EXPECT_THAT(
        [&] {
            graph.addPass<Data>(
                "translucent",
                [layer](Builder& b, Data&) {
                    b.read(layer);
                    static_cast<void>(
                        b.declareRenderTarget("blend", RenderTargetAttachments{{layer}, {}}));
                },
                [](const Resources&, const Data&) {});
        },
        ThrowsMessage<RenderGraphError>(
            AllOf(HasSubstr("'translucent'"), HasSubstr("'blend'"), HasSubstr("'layer'"))));

    RenderGraph other(cache);
    EXPECT_THROW(
        other.addPass<Data>(
            "empty",
            [](Builder& b, Data&) { static_cast<void>(b.declareRenderTarget("none", {})); },
            [](const Resources&, const Data&) {}),
        RenderGraphError);
}

TEST(RenderGraphRenderTarget, AttachmentsOfDifferentSizesAreRefusedWhenResolved) {
    CpuResourceAllocator allocator;
    RenderGraphCache cache(allocator);
    RenderGraph graph(cache);
    struct Data {
        Handle<Texture> a;
        Handle<Texture> b;
        RenderTargetId target;
    };
    const auto& data = graph.addPass<Data>(
        "mismatch",
        [](Builder& builder, Data& d) {
            d.a = builder.write(builder.create<Texture>("a", {8, 4, TextureFormat::RGBA8}));
            d.b = builder.write(builder.create<Texture>("b", {4, 4, TextureFormat::RGBA8}));
            d.target = builder.declareRenderTarget("both", RenderTargetAttachments{{d.a, d.b}, {}});
        },
        [](const Resources& r, const Data& d) { static_cast<void>(r.renderTarget(d.target)); });
    graph.markTarget(data.a);
    EXPECT_THAT([&] { graph.execute(); },
                ThrowsMessage<RenderGraphError>(
                    AllOf(HasSubstr("'both'"), HasSubstr("'mismatch'"), HasSubstr("sizes"))));
}

}  // namespace
