// SPDX-License-Identifier: GPL-3.0-or-later
// The render graph core without GL: passes work on CpuTexture objects.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <array>
#include <chrono>
#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <memory>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "vv/core/Error.h"
#include "vv/render/RenderGraph.h"

namespace {

using ::testing::HasSubstr;
using ::testing::Not;
using vv::render::CpuPassTimer;
using vv::render::CpuResourceAllocator;
using vv::render::CpuTexture;
using vv::render::Handle;
using vv::render::ImportOptions;
using vv::render::PassInfo;
using vv::render::PassObserver;
using vv::render::PassState;
using vv::render::RenderGraph;
using vv::render::RenderGraphCache;
using vv::render::RenderGraphCacheOptions;
using vv::render::RenderGraphError;
using vv::render::Texture;
using vv::render::TextureDescriptor;
using vv::render::TextureFormat;
using Builder = RenderGraph::Builder;
using Resources = RenderGraph::Resources;

const TextureDescriptor kColour{16, 8, TextureFormat::RGBA8};
const TextureDescriptor kDepth{16, 8, TextureFormat::R32F};
const TextureDescriptor kNormals{16, 8, TextureFormat::RGBA16F};

/// The first texel of a texture the pass may read.
float firstTexel(const Resources& resources, Handle<Texture> handle) {
    return resources.get(handle).objectAs<CpuTexture>().texels()[0];
}

/// Sets the first texel of a texture the pass writes.
void setFirstTexel(const Resources& resources, Handle<Texture> handle, float value) {
    resources.getForWrite(handle).objectAs<CpuTexture>().texels()[0] = value;
}

/// A window-system framebuffer stand-in that the test owns and can look at.
class Screen {
  public:
    Screen() : object_(std::make_shared<CpuTexture>(kColour)) {}

    [[nodiscard]] Handle<Texture> import(RenderGraph& graph) const {
        return graph.importResource("screen", Texture(kColour, object_),
                                    ImportOptions{.target = true});
    }
    [[nodiscard]] float value() const { return object_->texels()[0]; }

  private:
    std::shared_ptr<CpuTexture> object_;
};

struct TextureData {
    Handle<Texture> texture;
};

/// Adds a pass that writes `value` into a new transient texture `name`.
const TextureData& addSource(RenderGraph& graph, const std::string& pass, const std::string& name,
                             const TextureDescriptor& descriptor, float value,
                             int* runs = nullptr) {
    return graph.addPass<TextureData>(
        pass,
        [&](Builder& builder, TextureData& data) {
            data.texture = builder.write(builder.create<Texture>(name, descriptor));
        },
        [=](const Resources& resources, const TextureData& data) {
            setFirstTexel(resources, data.texture, value);
            if (runs != nullptr) {
                ++*runs;
            }
        });
}

/// Adds a pass that copies `input` into the screen.
void addPresent(RenderGraph& graph, Handle<Texture> input, Handle<Texture> screen,
                int* runs = nullptr) {
    graph.addPass<TextureData>(
        "present",
        [&](Builder& builder, TextureData& data) {
            builder.read(input);
            data.texture = builder.write(screen);
        },
        [=](const Resources& resources, const TextureData& data) {
            setFirstTexel(resources, data.texture, firstTexel(resources, input));
            if (runs != nullptr) {
                ++*runs;
            }
        });
}

const PassInfo& infoOf(const std::vector<PassInfo>& passes, const std::string& name) {
    for (const PassInfo& pass : passes) {
        if (pass.name == name) {
            return pass;
        }
    }
    throw std::runtime_error("no pass " + name);
}

// ---- culling -----------------------------------------------------------------

TEST(RenderGraphCulling, PassWhoseOutputNobodyReadsNeverExecutesTransitively) {
    CpuResourceAllocator allocator;
    RenderGraphCache cache(allocator);
    Screen screen;
    RenderGraph graph(cache);
    const auto screenHandle = screen.import(graph);

    int source = 0;
    int unread = 0;
    int readsUnread = 0;
    int present = 0;
    int sideEffect = 0;
    const auto& used = addSource(graph, "source", "colour", kColour, 3.0F, &source);
    const auto& orphan = addSource(graph, "orphan", "ao", kDepth, 1.0F, &unread);
    graph.addPass<TextureData>(
        "blur-orphan",
        [&](Builder& builder, TextureData& data) {
            builder.read(orphan.texture);
            data.texture = builder.write(builder.create<Texture>("ao-blurred", kDepth));
        },
        [&](const Resources&, const TextureData&) { ++readsUnread; });
    graph.addPass<TextureData>(
        "log", [](Builder& builder, TextureData&) { builder.sideEffect(); },
        [&](const Resources&, const TextureData&) { ++sideEffect; });
    addPresent(graph, used.texture, screenHandle, &present);

    graph.execute();

    EXPECT_EQ(source, 1);
    EXPECT_EQ(present, 1);
    EXPECT_EQ(sideEffect, 1);
    EXPECT_EQ(unread, 0);
    EXPECT_EQ(readsUnread, 0);
    EXPECT_FLOAT_EQ(screen.value(), 3.0F);
    const auto passes = graph.passes();
    EXPECT_EQ(infoOf(passes, "orphan").state, PassState::Culled);
    EXPECT_EQ(infoOf(passes, "blur-orphan").state, PassState::Culled);
    EXPECT_FALSE(infoOf(passes, "orphan").order.has_value());
    EXPECT_EQ(infoOf(passes, "log").state, PassState::Executed);
    EXPECT_EQ(infoOf(passes, "present").state, PassState::Executed);
    // A culled pass's transient is never allocated.
    EXPECT_EQ(allocator.texturesCreated(), 1);
}

TEST(RenderGraphCulling, WithoutTargetEvenThePresentPassIsCulled) {
    CpuResourceAllocator allocator;
    RenderGraphCache cache(allocator);
    RenderGraph graph(cache);
    const auto screen = graph.importResource(
        "screen", Texture(kColour, std::make_shared<CpuTexture>(kColour)), ImportOptions{});
    int source = 0;
    int present = 0;
    const auto& colour = addSource(graph, "source", "colour", kColour, 1.0F, &source);
    addPresent(graph, colour.texture, screen, &present);
    graph.execute();
    EXPECT_EQ(source, 0);
    EXPECT_EQ(present, 0);
}

TEST(RenderGraphCulling, MarkTargetKeepsTheWriterAlive) {
    CpuResourceAllocator allocator;
    RenderGraphCache cache(allocator);
    RenderGraph graph(cache);
    int runs = 0;
    const auto& exported = addSource(graph, "export", "depth-out", kDepth, 1.0F, &runs);
    graph.markTarget(exported.texture);
    graph.execute();
    EXPECT_EQ(runs, 1);
    EXPECT_EQ(graph.resources().front().targetVersions, std::vector<std::uint32_t>{1});
}

// ---- caching: the VSS scenario of issue 4 -------------------------------------

struct Settings {
    float cameraAngle = 0.0F;
    int width = 64;
    int height = 48;
    int meshRevision = 1;
    bool vss = true;
    float p = 2.0F;
    std::string solver = "reference";
    int colourScale = 0;
    int isoLines = 8;
};

struct Runs {
    int geometry = 0;
    int solve = 0;
    int shading = 0;
    int present = 0;
    friend bool operator==(const Runs&, const Runs&) = default;
};

void PrintTo(const Runs& runs, std::ostream* out) {
    *out << "{geometry " << runs.geometry << ", solve " << runs.solve << ", shading "
         << runs.shading << ", present " << runs.present << "}";
}

/// What each pass computes into its first texel, so the test can check that
/// skipped passes' results are reused, not recomputed or lost.
float depthValue(const Settings& s) {
    return s.cameraAngle + 100.0F * static_cast<float>(s.meshRevision);
}
float solveValue(const Settings& s) {
    return depthValue(s) * s.p;
}
float shadeValue(const Settings& s) {
    return solveValue(s) + 1000.0F * static_cast<float>(s.colourScale) +
           10000.0F * static_cast<float>(s.isoLines);
}

/// One frame of the viewer, built from the current settings like the GUI does:
/// geometry (camera, viewport, mesh) -> VSS solve (depth, p, solver) ->
/// VSS shading (VSS result, colour scale, iso-lines) -> present.
class Viewer {
  public:
    Viewer() : cache_(allocator_) {}

    std::unique_ptr<RenderGraph> frame(const Settings& s) {
        auto graph = std::make_unique<RenderGraph>(cache_);
        const auto screen = screen_.import(*graph);
        const TextureDescriptor depthFormat{s.width, s.height, TextureFormat::R32F};
        const TextureDescriptor colourFormat{s.width, s.height, TextureFormat::RGBA8};
        const glm::mat4 view = glm::rotate(glm::mat4(1.0F), s.cameraAngle, glm::vec3(0, 1, 0));

        const auto& geometry = graph->addPass<TextureData>(
            "geometry",
            [&](Builder& builder, TextureData& data) {
                builder.dependsOn("camera", view);
                builder.dependsOn("viewport", std::array<int, 2>{s.width, s.height});
                builder.dependsOn("mesh", s.meshRevision);
                data.texture =
                    builder.write(builder.createPersistent<Texture>("depth", depthFormat));
            },
            [this, value = depthValue(s)](const Resources& resources, const TextureData& data) {
                setFirstTexel(resources, data.texture, value);
                ++runs_.geometry;
            });
        // Like the GUI, the VSS passes are always declared: when VSS is off
        // nothing reads them and they are culled.
        const auto& solve = graph->addPass<TextureData>(
            "vss-solve",
            [&](Builder& builder, TextureData& data) {
                builder.read(geometry.texture);
                builder.dependsOn("p", s.p);
                builder.dependsOn("solver", s.solver);
                data.texture =
                    builder.write(builder.createPersistent<Texture>("vss-height", depthFormat));
            },
            [this, depth = geometry.texture, p = s.p](const Resources& resources,
                                                      const TextureData& data) {
                setFirstTexel(resources, data.texture, firstTexel(resources, depth) * p);
                ++runs_.solve;
            });
        const auto& shading = graph->addPass<TextureData>(
            "vss-shading",
            [&](Builder& builder, TextureData& data) {
                builder.read(solve.texture);
                builder.dependsOn("colour scale", s.colourScale);
                builder.dependsOn("iso-lines", s.isoLines);
                data.texture =
                    builder.write(builder.createPersistent<Texture>("vss-colour", colourFormat));
            },
            [this, height = solve.texture, scale = s.colourScale, lines = s.isoLines](
                const Resources& resources, const TextureData& data) {
                setFirstTexel(resources, data.texture,
                              firstTexel(resources, height) + 1000.0F * static_cast<float>(scale) +
                                  10000.0F * static_cast<float>(lines));
                ++runs_.shading;
            });
        addPresent(*graph, s.vss ? shading.texture : geometry.texture, screen, &runs_.present);
        graph->execute();
        return graph;
    }

    [[nodiscard]] const Runs& runs() const { return runs_; }
    [[nodiscard]] float shown() const { return screen_.value(); }
    void invalidate(std::string_view pass) { cache_.invalidate(pass); }

  private:
    CpuResourceAllocator allocator_;
    RenderGraphCache cache_;
    Screen screen_;
    Runs runs_;
};

TEST(RenderGraphCaching, VssScenarioReRunsOnlyWhatChanged) {
    struct Step {
        const char* change;
        void (*apply)(Settings&);
        Runs expected;  // cumulative executions
    };
    const std::vector<Step> steps = {
        {"first frame", [](Settings&) {}, {1, 1, 1, 1}},
        {"nothing", [](Settings&) {}, {1, 1, 1, 2}},
        {"colour scale", [](Settings& s) { s.colourScale = 2; }, {1, 1, 2, 3}},
        {"iso-line count", [](Settings& s) { s.isoLines = 12; }, {1, 1, 3, 4}},
        {"camera rotation", [](Settings& s) { s.cameraAngle = 0.25F; }, {2, 2, 4, 5}},
        {"resize", [](Settings& s) { s.width = 80; }, {3, 3, 5, 6}},
        {"p", [](Settings& s) { s.p = 3.0F; }, {3, 4, 6, 7}},
        {"solver", [](Settings& s) { s.solver = "fast"; }, {3, 5, 7, 8}},
        {"colour scale back", [](Settings& s) { s.colourScale = 0; }, {3, 5, 8, 9}},
        {"mesh", [](Settings& s) { s.meshRevision = 2; }, {4, 6, 9, 10}},
    };
    Viewer viewer;
    Settings settings;
    for (const Step& step : steps) {
        SCOPED_TRACE(step.change);
        step.apply(settings);
        const auto graph = viewer.frame(settings);
        EXPECT_EQ(viewer.runs(), step.expected);
        // Whatever was reused, the screen shows the result of the current settings.
        EXPECT_FLOAT_EQ(viewer.shown(), shadeValue(settings));
    }
}

TEST(RenderGraphCaching, ReasonsNameTheChange) {
    Viewer viewer;
    Settings settings;
    static_cast<void>(viewer.frame(settings));
    settings.isoLines = 3;
    const auto graph = viewer.frame(settings);
    const auto passes = graph->passes();
    EXPECT_EQ(infoOf(passes, "geometry").state, PassState::Cached);
    EXPECT_EQ(infoOf(passes, "vss-solve").state, PassState::Cached);
    EXPECT_EQ(infoOf(passes, "vss-shading").state, PassState::Executed);
    EXPECT_THAT(infoOf(passes, "vss-shading").reason, HasSubstr("'iso-lines'"));
    EXPECT_THAT(infoOf(passes, "present").reason, HasSubstr("'screen'"));

    settings.cameraAngle = 1.0F;
    const auto rotated = viewer.frame(settings);
    EXPECT_THAT(infoOf(rotated->passes(), "geometry").reason, HasSubstr("'camera'"));
    EXPECT_THAT(infoOf(rotated->passes(), "vss-solve").reason, HasSubstr("'depth'"));
}

TEST(RenderGraphCaching, VssOffCullsTheVssPassesAndKeepsTheirResults) {
    Viewer viewer;
    Settings settings;
    static_cast<void>(viewer.frame(settings));
    settings.vss = false;
    const auto off = viewer.frame(settings);
    EXPECT_EQ(viewer.runs(), (Runs{1, 1, 1, 2}));
    EXPECT_EQ(infoOf(off->passes(), "vss-solve").state, PassState::Culled);
    EXPECT_EQ(infoOf(off->passes(), "vss-shading").state, PassState::Culled);
    EXPECT_FLOAT_EQ(viewer.shown(), depthValue(settings));

    // Back on within the cache's retention: nothing changed, nothing re-solved.
    settings.vss = true;
    static_cast<void>(viewer.frame(settings));
    EXPECT_EQ(viewer.runs(), (Runs{1, 1, 1, 3}));
    EXPECT_FLOAT_EQ(viewer.shown(), shadeValue(settings));
}

TEST(RenderGraphCaching, ResultsExpireAfterTheRetentionPeriod) {
    CpuResourceAllocator allocator;
    RenderGraphCache cache(allocator, RenderGraphCacheOptions{.retainFrames = 2});
    Screen screen;
    int runs = 0;
    auto frame = [&](bool withPass) {
        RenderGraph graph(cache);
        const auto target = screen.import(graph);
        const auto& cached = graph.addPass<TextureData>(
            "cached",
            [&](Builder& builder, TextureData& data) {
                data.texture = builder.write(builder.createPersistent<Texture>("result", kDepth));
            },
            [&](const Resources& resources, const TextureData& data) {
                setFirstTexel(resources, data.texture, 7.0F);
                ++runs;
            });
        if (withPass) {
            addPresent(graph, cached.texture, target);
        } else {
            graph.addPass<TextureData>(
                "idle", [](Builder& builder, TextureData&) { builder.sideEffect(); },
                [](const Resources&, const TextureData&) {});
        }
        graph.execute();
    };
    frame(true);
    frame(true);
    EXPECT_EQ(runs, 1);
    EXPECT_EQ(allocator.texturesAlive(), 1);
    frame(false);
    frame(false);  // two idle frames: the result and its storage are dropped
    EXPECT_EQ(allocator.texturesAlive(), 0);
    EXPECT_EQ(cache.objectsHeld(), 0U);
    frame(true);
    EXPECT_EQ(runs, 2);
    EXPECT_FLOAT_EQ(screen.value(), 7.0F);
}

TEST(RenderGraphCaching, NewStorageForAPersistentOutputReRunsItsWriter) {
    CpuResourceAllocator allocator;
    RenderGraphCache cache(allocator);
    Screen screen;
    int runs = 0;
    auto frame = [&](const TextureDescriptor& descriptor) {
        RenderGraph graph(cache);
        const auto target = screen.import(graph);
        // No dependsOn(): only the descriptor tells the graph what changed.
        const auto& result = graph.addPass<TextureData>(
            "result",
            [&](Builder& builder, TextureData& data) {
                data.texture =
                    builder.write(builder.createPersistent<Texture>("result", descriptor));
            },
            [&](const Resources& resources, const TextureData& data) {
                setFirstTexel(resources, data.texture, static_cast<float>(++runs));
            });
        addPresent(graph, result.texture, target);
        graph.execute();
        return infoOf(graph.passes(), "result");
    };
    EXPECT_EQ(frame(kDepth).state, PassState::Executed);
    EXPECT_EQ(frame(kDepth).state, PassState::Cached);
    const PassInfo resized = frame(TextureDescriptor{32, 8, TextureFormat::R32F});
    EXPECT_EQ(resized.state, PassState::Executed);
    EXPECT_THAT(resized.reason, HasSubstr("new storage"));
    EXPECT_EQ(runs, 2);
    EXPECT_FLOAT_EQ(screen.value(), 2.0F);
    // Back to the first size: its object is still pooled, but its content is
    // not trusted (the storage was given up), so the pass runs again.
    EXPECT_EQ(frame(kDepth).state, PassState::Executed);
    EXPECT_EQ(allocator.texturesCreated(), 2);

    cache.clear();
    EXPECT_EQ(allocator.texturesAlive(), 0);
    EXPECT_EQ(frame(kDepth).state, PassState::Executed);
    EXPECT_EQ(runs, 4);
}

TEST(RenderGraphCaching, InvalidateForcesARun) {
    Viewer viewer;
    Settings settings;
    static_cast<void>(viewer.frame(settings));
    viewer.invalidate("vss-solve");
    viewer.invalidate("no such pass");
    static_cast<void>(viewer.frame(settings));
    EXPECT_EQ(viewer.runs(), (Runs{1, 2, 2, 2}));
    EXPECT_FLOAT_EQ(viewer.shown(), shadeValue(settings));
}

TEST(RenderGraphCaching, APassThatThrowsRunsAgainNextFrame) {
    CpuResourceAllocator allocator;
    RenderGraphCache cache(allocator);
    Screen screen;
    int attempts = 0;
    auto frame = [&] {
        RenderGraph graph(cache);
        const auto target = screen.import(graph);
        // Held from here to "present", so it is in use when "flaky" throws.
        const auto& scratch = addSource(graph, "scratch", "scratch", kColour, 1.0F);
        const auto& flaky = graph.addPass<TextureData>(
            "flaky",
            [&](Builder& builder, TextureData& data) {
                data.texture = builder.write(builder.createPersistent<Texture>("result", kDepth));
            },
            [&](const Resources& resources, const TextureData& data) {
                ++attempts;
                if (attempts == 1) {
                    throw vv::Error("solver failed");
                }
                setFirstTexel(resources, data.texture, 5.0F);
            });
        graph.addPass<TextureData>(
            "present",
            [&](Builder& builder, TextureData& data) {
                builder.read(flaky.texture);
                builder.read(scratch.texture);
                data.texture = builder.write(target);
            },
            [target = flaky.texture](const Resources& resources, const TextureData& data) {
                setFirstTexel(resources, data.texture, firstTexel(resources, target));
            });
        graph.execute();
    };
    EXPECT_THROW(frame(), vv::Error);
    EXPECT_EQ(attempts, 1);
    frame();
    EXPECT_EQ(attempts, 2);
    EXPECT_FLOAT_EQ(screen.value(), 5.0F);
    frame();
    EXPECT_EQ(attempts, 2);
    // The aborted frame gave its transient back: one scratch object in all.
    EXPECT_EQ(allocator.texturesCreated(), 2);
}

// ---- rules -------------------------------------------------------------------

TEST(RenderGraphRules, CycleIsRejectedNamingItsPasses) {
    CpuResourceAllocator allocator;
    RenderGraphCache cache(allocator);
    Screen screen;
    RenderGraph graph(cache);
    const auto target = screen.import(graph);
    struct Two {
        Handle<Texture> x;
        Handle<Texture> y;
    };
    const auto& init = graph.addPass<Two>(
        "init",
        [](Builder& builder, Two& data) {
            data.x = builder.write(builder.create<Texture>("x", kColour));
            data.y = builder.write(builder.create<Texture>("y", kColour));
        },
        [](const Resources&, const Two&) {});
    // blur-x reads x1 and writes y2; blur-y reads the old y1 and writes x2:
    // each must run before the other.
    const auto& blurX = graph.addPass<TextureData>(
        "blur-x",
        [&](Builder& builder, TextureData& data) {
            builder.read(init.x);
            data.texture = builder.write(init.y);
        },
        [](const Resources&, const TextureData&) {});
    const auto& blurY = graph.addPass<TextureData>(
        "blur-y",
        [&](Builder& builder, TextureData& data) {
            builder.read(init.y);
            data.texture = builder.write(init.x);
        },
        [](const Resources&, const TextureData&) {});
    graph.addPass<TextureData>(
        "final",
        [&](Builder& builder, TextureData& data) {
            builder.read(blurX.texture);
            builder.read(blurY.texture);
            data.texture = builder.write(target);
        },
        [](const Resources&, const TextureData&) {});
    try {
        graph.compile();
        FAIL() << "a cycle was accepted";
    } catch (const RenderGraphError& error) {
        const std::string message = error.what();
        EXPECT_THAT(message, HasSubstr("cycle"));
        EXPECT_THAT(message, HasSubstr("'blur-x'"));
        EXPECT_THAT(message, HasSubstr("'blur-y'"));
        EXPECT_THAT(message, Not(HasSubstr("'init'")));
        EXPECT_THAT(message, Not(HasSubstr("'final'")));
    }
    EXPECT_THROW(graph.execute(), RenderGraphError);
}

TEST(RenderGraphRules, PassReadingItsOwnOutputIsACycle) {
    CpuResourceAllocator allocator;
    RenderGraphCache cache(allocator);
    RenderGraph graph(cache);
    graph.addPass<TextureData>(
        "feedback",
        [](Builder& builder, TextureData& data) {
            data.texture = builder.write(builder.create<Texture>("x", kColour));
            builder.read(data.texture);
            builder.sideEffect();
        },
        [](const Resources&, const TextureData&) {});
    EXPECT_THAT([&] { graph.compile(); },
                ::testing::ThrowsMessage<RenderGraphError>(HasSubstr("'feedback' -> 'feedback'")));
}

TEST(RenderGraphRules, StaleReadIsOrderedBeforeTheNextWrite) {
    CpuResourceAllocator allocator;
    RenderGraphCache cache(allocator);
    Screen screen;
    RenderGraph graph(cache);
    const auto target = screen.import(graph);
    const auto& first = addSource(graph, "first", "x", kColour, 1.0F);
    const auto& second = graph.addPass<TextureData>(
        "overwrite",
        [&](Builder& builder, TextureData& data) { data.texture = builder.write(first.texture); },
        [](const Resources& resources, const TextureData& data) {
            setFirstTexel(resources, data.texture, 2.0F);
        });
    float seen = 0.0F;
    const auto& late = graph.addPass<TextureData>(
        "late-reader",
        [&](Builder& builder, TextureData& data) {
            builder.read(first.texture);  // version 1, although version 2 exists
            data.texture = builder.write(builder.create<Texture>("copy", kColour));
        },
        [&seen, old = first.texture](const Resources& resources, const TextureData& data) {
            seen = firstTexel(resources, old);
            setFirstTexel(resources, data.texture, seen);
        });
    graph.addPass<TextureData>(
        "present",
        [&](Builder& builder, TextureData& data) {
            builder.read(second.texture);
            builder.read(late.texture);
            data.texture = builder.write(target);
        },
        [x = second.texture](const Resources& resources, const TextureData& data) {
            setFirstTexel(resources, data.texture, firstTexel(resources, x));
        });
    graph.execute();
    const auto passes = graph.passes();
    EXPECT_LT(*infoOf(passes, "late-reader").order, *infoOf(passes, "overwrite").order);
    EXPECT_FLOAT_EQ(seen, 1.0F);
    EXPECT_FLOAT_EQ(screen.value(), 2.0F);
}

TEST(RenderGraphRules, ReadingAVersionNobodyWritesIsRejected) {
    CpuResourceAllocator allocator;
    RenderGraphCache cache(allocator);
    RenderGraph graph(cache);
    graph.addPass<TextureData>(
        "reader",
        [](Builder& builder, TextureData& data) {
            data.texture = builder.create<Texture>("never-written", kColour);
            builder.read(data.texture);
            builder.sideEffect();
        },
        [](const Resources&, const TextureData&) {});
    try {
        graph.compile();
        FAIL() << "an unwritten read was accepted";
    } catch (const RenderGraphError& error) {
        EXPECT_THAT(error.what(), HasSubstr("'reader'"));
        EXPECT_THAT(error.what(), HasSubstr("'never-written'"));
        EXPECT_THAT(error.what(), HasSubstr("no pass writes"));
    }
}

TEST(RenderGraphRules, ReadingAnUndeclaredHandleIsRejected) {
    CpuResourceAllocator allocator;
    RenderGraphCache cache(allocator);
    RenderGraph graph(cache);
    EXPECT_THROW(
        graph.addPass<TextureData>(
            "reader", [](Builder& builder, TextureData&) { builder.read(Handle<Texture>{}); },
            [](const Resources&, const TextureData&) {}),
        RenderGraphError);
    // The graph is now incomplete and says which setup failed.
    EXPECT_THAT([&] { graph.compile(); },
                ::testing::ThrowsMessage<RenderGraphError>(HasSubstr("'reader'")));
}

TEST(RenderGraphRules, AccessingAnUndeclaredResourceInExecuteThrows) {
    CpuResourceAllocator allocator;
    RenderGraphCache cache(allocator);
    Screen screen;
    RenderGraph graph(cache);
    const auto target = screen.import(graph);
    const auto& declared = addSource(graph, "a", "declared", kColour, 1.0F);
    const auto& other = addSource(graph, "b", "other", kColour, 2.0F);
    graph.addPass<TextureData>(
        "sneaky",
        [&](Builder& builder, TextureData& data) {
            builder.read(declared.texture);
            builder.read(other.texture);
            data.texture = builder.write(target);
        },
        [&](const Resources& resources, const TextureData&) {
            // Reads declared; writing a read-only resource is not.
            static_cast<void>(resources.getForWrite(declared.texture));
        });
    EXPECT_THAT([&] { graph.execute(); },
                ::testing::ThrowsMessage<RenderGraphError>(
                    ::testing::AllOf(HasSubstr("'sneaky'"), HasSubstr("'declared'"))));

    RenderGraph second(cache);
    const auto target2 = screen.import(second);
    const auto& a = addSource(second, "a", "declared", kColour, 1.0F);
    const auto& b = addSource(second, "b", "undeclared", kColour, 2.0F);
    second.addPass<TextureData>(
        "sneaky",
        [&](Builder& builder, TextureData& data) {
            builder.read(a.texture);
            data.texture = builder.write(target2);
        },
        [&](const Resources& resources, const TextureData&) {
            static_cast<void>(resources.get(b.texture));
        });
    second.markTarget(b.texture);  // keep "b" alive: its texture exists, just not for "sneaky"
    EXPECT_THAT([&] { second.execute(); },
                ::testing::ThrowsMessage<RenderGraphError>(
                    ::testing::AllOf(HasSubstr("'sneaky'"), HasSubstr("'undeclared'"))));
}

TEST(RenderGraphRules, DeclarationMistakesAreRejected) {
    CpuResourceAllocator allocator;
    RenderGraphCache cache(allocator);
    auto noop = [](const Resources&, const TextureData&) {};
    {
        RenderGraph graph(cache);
        const auto& a = addSource(graph, "a", "x", kColour, 1.0F);
        EXPECT_THROW(addSource(graph, "a", "y", kColour, 1.0F), RenderGraphError);  // pass name
        RenderGraph other(cache);
        EXPECT_THROW(
            {
                addSource(other, "p", "dup", kColour, 1.0F);
                addSource(other, "q", "dup", kColour, 1.0F);  // resource name
            },
            RenderGraphError);
        // Writing a stale version.
        RenderGraph stale(cache);
        const auto& s = addSource(stale, "first", "x", kColour, 1.0F);
        stale.addPass<TextureData>(
            "second",
            [&](Builder& builder, TextureData& data) { data.texture = builder.write(s.texture); },
            noop);
        EXPECT_THROW(stale.addPass<TextureData>(
                         "third",
                         [&](Builder& builder, TextureData& data) {
                             data.texture = builder.write(s.texture);
                         },
                         noop),
                     RenderGraphError);
        // A parameter declared twice.
        EXPECT_THROW(graph.addPass<TextureData>(
                         "params",
                         [](Builder& builder, TextureData&) {
                             builder.dependsOn("p", 1);
                             builder.dependsOn("p", 2);
                         },
                         noop),
                     RenderGraphError);
        static_cast<void>(a);
    }
    {
        // Two writers of one persistent resource.
        RenderGraph graph(cache);
        const auto& first = graph.addPass<TextureData>(
            "w1",
            [](Builder& builder, TextureData& data) {
                data.texture = builder.write(builder.createPersistent<Texture>("history", kColour));
            },
            noop);
        const auto& second = graph.addPass<TextureData>(
            "w2",
            [&](Builder& builder, TextureData& data) {
                data.texture = builder.write(first.texture);
            },
            noop);
        graph.markTarget(second.texture);
        EXPECT_THAT([&] { graph.compile(); },
                    ::testing::ThrowsMessage<RenderGraphError>(::testing::AllOf(
                        HasSubstr("'history'"), HasSubstr("'w1'"), HasSubstr("'w2'"))));
    }
    {
        // Declaring after compile(), executing twice.
        RenderGraph graph(cache);
        const auto& a = addSource(graph, "a", "x", kColour, 1.0F);
        graph.markTarget(a.texture);
        graph.execute();
        EXPECT_THROW(addSource(graph, "b", "y", kColour, 1.0F), RenderGraphError);
        EXPECT_THROW(graph.execute(), RenderGraphError);
        // A texture with a bad size.
        RenderGraph bad(cache);
        EXPECT_THROW(addSource(bad, "a", "x", TextureDescriptor{0, 4, TextureFormat::R8}, 1.0F),
                     vv::InvalidArgumentError);
    }
}

// ---- transient allocation ----------------------------------------------------------

/// a -> t1 -> b -> t2 -> c -> t3 -> d -> screen: t1 lives over [a, b], t2
/// over [b, c], t3 over [c, d]; t1 and t3 have disjoint lifetimes.
struct Chain {
    const vv::render::TextureObject* t1 = nullptr;
    const vv::render::TextureObject* t2 = nullptr;
    const vv::render::TextureObject* t3 = nullptr;
    float shown = 0.0F;
};

Chain runChain(RenderGraphCache& cache, const TextureDescriptor& d1, const TextureDescriptor& d2,
               const TextureDescriptor& d3) {
    Chain chain;
    Screen screen;
    RenderGraph graph(cache);
    const auto target = screen.import(graph);
    const auto& a = graph.addPass<TextureData>(
        "a",
        [&](Builder& builder, TextureData& data) {
            data.texture = builder.write(builder.create<Texture>("t1", d1));
        },
        [&chain](const Resources& resources, const TextureData& data) {
            chain.t1 = &resources.get(data.texture).object();
            setFirstTexel(resources, data.texture, 1.0F);
        });
    const auto& b = graph.addPass<TextureData>(
        "b",
        [&](Builder& builder, TextureData& data) {
            builder.read(a.texture);
            data.texture = builder.write(builder.create<Texture>("t2", d2));
        },
        [&chain, in = a.texture](const Resources& resources, const TextureData& data) {
            chain.t2 = &resources.get(data.texture).object();
            setFirstTexel(resources, data.texture, firstTexel(resources, in) + 10.0F);
        });
    const auto& c = graph.addPass<TextureData>(
        "c",
        [&](Builder& builder, TextureData& data) {
            builder.read(b.texture);
            data.texture = builder.write(builder.create<Texture>("t3", d3));
        },
        [&chain, in = b.texture](const Resources& resources, const TextureData& data) {
            chain.t3 = &resources.get(data.texture).object();
            setFirstTexel(resources, data.texture, firstTexel(resources, in) + 100.0F);
        });
    addPresent(graph, c.texture, target);
    graph.execute();
    const auto resources = graph.resources();
    EXPECT_EQ(resources[1].firstUse, "a");
    EXPECT_EQ(resources[1].lastUse, "b");
    EXPECT_EQ(resources[3].firstUse, "c");
    EXPECT_EQ(resources[3].lastUse, "present");
    chain.shown = screen.value();
    return chain;
}

TEST(RenderGraphAllocation, DisjointLifetimesWithTheSameDescriptorShareOneObject) {
    CpuResourceAllocator allocator;
    RenderGraphCache cache(allocator);
    const Chain chain = runChain(cache, kColour, kDepth, kColour);
    EXPECT_EQ(allocator.texturesCreated(), 2);
    EXPECT_EQ(chain.t1, chain.t3);
    EXPECT_NE(chain.t1, chain.t2);
    EXPECT_FLOAT_EQ(chain.shown, 111.0F);  // aliasing did not mix up contents
}

TEST(RenderGraphAllocation, LaterFramesReuseThePool) {
    CpuResourceAllocator allocator;
    RenderGraphCache cache(allocator);
    const Chain first = runChain(cache, kColour, kDepth, kColour);
    for (int frame = 0; frame < 4; ++frame) {
        const Chain again = runChain(cache, kColour, kDepth, kColour);
        EXPECT_EQ(again.t1, first.t1);
        EXPECT_EQ(again.t2, first.t2);
    }
    EXPECT_EQ(allocator.texturesCreated(), 2);
    EXPECT_EQ(cache.framesExecuted(), 5U);
}

TEST(RenderGraphAllocation, DifferentDescriptorsDoNotAlias) {
    CpuResourceAllocator allocator;
    RenderGraphCache cache(allocator);
    const Chain chain = runChain(cache, kColour, kDepth, kNormals);
    EXPECT_EQ(allocator.texturesCreated(), 3);
    EXPECT_NE(chain.t1, chain.t3);
    EXPECT_NE(chain.t2, chain.t3);
    // Another size is another descriptor too.
    static_cast<void>(
        runChain(cache, kColour, kDepth, TextureDescriptor{32, 8, TextureFormat::RGBA8}));
    EXPECT_EQ(allocator.texturesCreated(), 4);
}

TEST(RenderGraphAllocation, OverlappingLifetimesDoNotAlias) {
    CpuResourceAllocator allocator;
    RenderGraphCache cache(allocator);
    const Chain chain = runChain(cache, kColour, kColour, kColour);
    EXPECT_NE(chain.t1, chain.t2);  // both alive in "b"
    EXPECT_NE(chain.t2, chain.t3);  // both alive in "c"
    EXPECT_EQ(chain.t1, chain.t3);
    EXPECT_EQ(allocator.texturesCreated(), 2);
    EXPECT_FLOAT_EQ(chain.shown, 111.0F);
}

// ---- timings and observers -----------------------------------------------------

class RecordingObserver final : public PassObserver {
  public:
    void beginFrame() override { events.emplace_back("frame"); }
    void beginPass(std::string_view pass) override {
        events.push_back("begin " + std::string(pass));
    }
    void endPass(std::string_view pass) override { events.push_back("end " + std::string(pass)); }
    void endFrame() override { events.emplace_back("/frame"); }

    std::vector<std::string> events;  // NOLINT: test helper
};

TEST(RenderGraphTimings, RecordedForExecutedPassesOnly) {
    CpuResourceAllocator allocator;
    RenderGraphCache cache(allocator);
    Screen screen;
    auto frame = [&](RecordingObserver& observer) {
        RenderGraph graph(cache);
        const auto target = screen.import(graph);
        const auto& slow = graph.addPass<TextureData>(
            "slow",
            [](Builder& builder, TextureData& data) {
                data.texture =
                    builder.write(builder.createPersistent<Texture>("slow-result", kDepth));
            },
            [](const Resources&, const TextureData&) {
                std::this_thread::sleep_for(std::chrono::milliseconds(3));
            });
        static_cast<void>(addSource(graph, "culled", "unused", kColour, 1.0F));
        addPresent(graph, slow.texture, target);
        graph.execute(&observer);
        return std::make_pair(graph.timings(), graph.passes());
    };

    RecordingObserver first;
    const auto [timings, passes] = frame(first);
    ASSERT_EQ(timings.size(), 2U);
    EXPECT_EQ(timings[0].pass, "slow");
    EXPECT_GE(timings[0].milliseconds, 3.0);
    EXPECT_EQ(timings[1].pass, "present");
    EXPECT_GE(timings[1].milliseconds, 0.0);
    EXPECT_FALSE(infoOf(passes, "culled").milliseconds.has_value());
    EXPECT_EQ(infoOf(passes, "slow").milliseconds, timings[0].milliseconds);
    EXPECT_EQ(first.events, (std::vector<std::string>{"frame", "begin slow", "end slow",
                                                      "begin present", "end present", "/frame"}));

    RecordingObserver second;  // "slow" is cached now
    const auto [cachedTimings, cachedPasses] = frame(second);
    ASSERT_EQ(cachedTimings.size(), 1U);
    EXPECT_EQ(cachedTimings[0].pass, "present");
    EXPECT_FALSE(infoOf(cachedPasses, "slow").milliseconds.has_value());
    EXPECT_EQ(second.events,
              (std::vector<std::string>{"frame", "begin present", "end present", "/frame"}));
}

TEST(RenderGraphTimings, CpuPassTimerMeasuresBetweenBeginAndEnd) {
    CpuPassTimer timer;
    timer.beginFrame();
    timer.beginPass("x");
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
    timer.endPass("x");
    timer.endPass("y");  // no matching begin: ignored
    ASSERT_EQ(timer.timings().size(), 1U);
    EXPECT_GE(*timer.milliseconds("x"), 2.0);
    EXPECT_FALSE(timer.milliseconds("y").has_value());
    timer.beginFrame();
    EXPECT_TRUE(timer.timings().empty());
}

// ---- dumps -----------------------------------------------------------------------

TEST(RenderGraphDump, DotAndTextShowEveryPassAndMarkCulledOnes) {
    CpuResourceAllocator allocator;
    RenderGraphCache cache(allocator);
    Screen screen;
    RenderGraph graph(cache);
    const auto target = screen.import(graph);
    const auto& colour = addSource(graph, "shade \"vessels\"", "colour", kColour, 1.0F);
    static_cast<void>(addSource(graph, "ambient-occlusion", "ao", kDepth, 1.0F));
    addPresent(graph, colour.texture, target);
    EXPECT_THROW(static_cast<void>(graph.toDot()), RenderGraphError);  // not compiled yet
    graph.compile();

    const std::string dot = graph.toDot();
    EXPECT_THAT(dot, HasSubstr("digraph"));
    EXPECT_THAT(dot, HasSubstr("\"pass:shade \\\"vessels\\\"\""));
    EXPECT_THAT(dot, HasSubstr("\"pass:present\""));
    EXPECT_THAT(dot, HasSubstr("label=\"colour v1\\nRGBA8 16x8\\ntransient\""));
    EXPECT_THAT(dot, HasSubstr("screen v1"));
    EXPECT_THAT(dot, HasSubstr("peripheries=2"));  // the target
    // The culled pass is drawn, dashed and grey; the others are not.
    const auto culledLine = dot.substr(dot.find("\"pass:ambient-occlusion\""));
    EXPECT_THAT(culledLine.substr(0, culledLine.find('\n')), HasSubstr("dashed"));
    EXPECT_THAT(culledLine.substr(0, culledLine.find('\n')), HasSubstr("culled"));
    const auto liveLine = dot.substr(dot.find("\"pass:present\" [shape"));
    EXPECT_THAT(liveLine.substr(0, liveLine.find('\n')), Not(HasSubstr("dashed")));

    graph.execute();
    const std::string text = graph.toText();
    EXPECT_THAT(text, HasSubstr("pass 'ambient-occlusion': culled"));
    EXPECT_THAT(text, HasSubstr("pass 'present': executed #1"));
    EXPECT_THAT(text, HasSubstr("'colour': transient, RGBA8 16x8, 2 versions"));
    EXPECT_THAT(text, HasSubstr("'ao': transient, R32F 16x8, 2 versions, unused"));
    EXPECT_THAT(text, HasSubstr("'screen': imported, RGBA8 16x8, 2 versions, target v1"));
}

}  // namespace
