// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <concepts>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <ranges>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <typeindex>
#include <typeinfo>
#include <utility>
#include <vector>

#include "vv/render/Blackboard.h"
#include "vv/render/RenderGraphCache.h"
#include "vv/render/RenderGraphDetail.h"
#include "vv/render/RenderGraphHandle.h"
#include "vv/render/RenderGraphObserver.h"
#include "vv/render/RenderGraphResources.h"

namespace vv::render {

/// How an imported resource takes part in the frame.
struct ImportOptions {
    /// The resource's final version is a result of the frame (the screen, a
    /// file): the passes that produce it are never culled for lack of readers.
    bool target = false;
    /// Bump it whenever the content changes outside the graph: passes that
    /// read the resource then run again instead of reusing cached results.
    std::uint64_t revision = 0;
};

/// What happened to a pass.
enum class PassState {
    Pending,   ///< compiled, survives culling, not executed yet
    Culled,    ///< nothing consumes its outputs; never runs
    Executed,  ///< ran in this frame
    Cached,    ///< survived, but nothing it depends on changed: skipped, outputs reused
};

/// How a resource's storage is provided.
enum class ResourceKind {
    Transient,   ///< from the pool for the passes between its first and last use
    Persistent,  ///< kept across frames under its name, for cached passes
    Imported,    ///< provided by the caller (screen, file sink, ...)
};

[[nodiscard]] std::string_view toString(PassState state) noexcept;
[[nodiscard]] std::string_view toString(ResourceKind kind) noexcept;

/// One version of one resource, by name.
struct ResourceVersion {
    std::string resource;
    std::uint32_t version = 0;
    friend bool operator==(const ResourceVersion&, const ResourceVersion&) = default;
};

/// The attachments of a render target that a pass declares
/// (RenderGraph::Builder::declareRenderTarget): textures the pass writes,
/// drawn into at once. The backend gives a framebuffer for the set.
struct RenderTargetAttachments {
    std::vector<Handle<Texture>> colors;  ///< colour attachment i draws into colors[i]
    Handle<Texture> depth;                ///< invalid = no depth attachment
};

/// Names one render target of one pass; made by Builder::declareRenderTarget.
class RenderTargetId {
  public:
    constexpr RenderTargetId() noexcept = default;
    [[nodiscard]] constexpr bool valid() const noexcept { return index_ != kInvalid; }
    friend constexpr bool operator==(RenderTargetId, RenderTargetId) noexcept = default;

  private:
    friend class RenderGraph;
    static constexpr std::uint32_t kInvalid = 0xFFFFFFFFU;
    constexpr explicit RenderTargetId(std::uint32_t index) noexcept : index_(index) {}
    std::uint32_t index_ = kInvalid;
};

/// A declared render target while its pass executes: the textures behind
/// its attachments (all of one size) — what a backend needs to bind it.
struct RenderTarget {
    std::string_view name;
    std::vector<const Texture*> colors;  ///< in attachment order
    const Texture* depth = nullptr;      ///< null = none
    int width = 0;
    int height = 0;
};

/// A pass of a compiled graph, for tests, dumps and the UI.
struct PassInfo {
    std::string name;
    PassState state = PassState::Pending;
    bool sideEffect = false;
    std::optional<std::size_t> order;  ///< position in execution order; none when culled
    std::vector<ResourceVersion> reads;
    std::vector<ResourceVersion> writes;
    std::vector<std::string> parameters;     ///< keys given to dependsOn()
    std::vector<std::string> renderTargets;  ///< names given to declareRenderTarget()
    std::string reason;                      ///< after execute(): why it ran or was skipped
    std::optional<double> milliseconds;      ///< CPU time, when it ran
};

/// A resource of a compiled graph.
struct ResourceInfo {
    std::string name;
    ResourceKind kind = ResourceKind::Transient;
    std::string description;                    ///< e.g. "R32F 640x360"
    std::uint32_t versions = 1;                 ///< 1 + number of writes
    std::vector<std::uint32_t> targetVersions;  ///< versions that are results of the frame
    /// Surviving passes that first and last use it (transient: its lifetime
    /// in the pool); none when no surviving pass uses it.
    std::optional<std::string> firstUse;
    std::optional<std::string> lastUse;
};

/// A frame graph: passes declare what they read and write, compile() culls
/// what nothing consumes and orders the rest, execute() runs them, reusing
/// the results of passes whose inputs did not change since the last frame.
///
/// Build a new graph every frame from the current settings; what must
/// survive between frames lives in the RenderGraphCache given here:
///
///     RenderGraph graph(cache);
///     auto screen = graph.importResource("screen", screenTexture, {.target = true});
///     struct Geo { Handle<Texture> depth; RenderTargetId target; };
///     const auto& geo = graph.addPass<Geo>("geometry",
///         [&](RenderGraph::Builder& b, Geo& d) {
///             b.dependsOn("camera", camera.viewMatrix());
///             d.depth = b.write(b.createPersistent<Texture>("depth", depthFormat));
///             d.target = b.declareRenderTarget("gbuffer", {{d.depth}, {}});
///         },
///         [camera](const RenderGraph::Resources& r, const Geo& d) {
///             bind(r.renderTarget(d.target));
///             draw(camera);
///         });
///     graph.blackboard().put("depth", geo.depth);
///     ... more passes, each reading what it needs: b.read<Texture>("depth") ...
///     graph.execute(&glObserver);
///
/// Rules (RenderGraphError unless said otherwise):
/// - Pass names are unique, resource names are unique within a graph.
/// - write() takes the latest version of a resource and returns the next one;
///   a pass writes a resource at most once. Reads of older versions are
///   allowed: the graph then orders the reader before the next writer.
/// - Every version read must be written by a pass, or be version 0 of an
///   imported resource (checked by compile()).
/// - A persistent resource is written by at most one pass per frame.
/// - A pass survives culling if it has side effects (Builder::sideEffect())
///   or writes a version that a surviving pass reads or that is a target.
/// - A surviving pass runs when it has side effects, writes anything that is
///   not persistent, ran never before, or when one of its parameters
///   (dependsOn), the content of a version it reads or the storage of a
///   persistent version it writes changed since its last run. Otherwise it is
///   skipped and its persistent outputs keep last frame's content.
///   Everything an execute callback uses must therefore come through the
///   resources it reads or the parameters it declares.
/// - What one pass hands another travels as a resource: textures, and values
///   on the CPU as CpuValue<T>. Passes find each other's outputs by name on
///   the graph's blackboard(); Builder::read(name) refuses a name nobody put.
/// - A pass draws into render targets it declares (declareRenderTarget) from
///   textures it writes; the backend makes the framebuffer.
/// - After execute(), result() hands persistent and imported outputs to the
///   caller (a frame's status): passes never write the caller's state.
/// - After addPass() throws (its setup threw), the graph cannot be compiled.
/// - Not thread-safe; passes run on the calling thread, in order.
class RenderGraph {
  public:
    class Builder;
    class Resources;

    /// The graph uses (and must not outlive) `cache`.
    explicit RenderGraph(RenderGraphCache& cache);
    ~RenderGraph();
    RenderGraph(const RenderGraph&) = delete;
    RenderGraph& operator=(const RenderGraph&) = delete;
    RenderGraph(RenderGraph&&) = delete;
    RenderGraph& operator=(RenderGraph&&) = delete;

    /// Adds a pass named `name` with its own `Data` (default-constructed) and
    /// runs `setup(Builder&, Data&)` at once to declare its resources.
    /// `execute(const Resources&, const Data&)` is kept and called by
    /// execute() if the pass runs. Returns the pass's Data so that later
    /// passes can use the handles it holds; the reference lives as long as
    /// the graph. Throws RenderGraphError for a duplicate or empty name or
    /// after compile(); rethrows what setup throws (the graph is then
    /// unusable).
    template <class Data, class Setup, class Execute>
        const Data& addPass(std::string_view name, Setup&& setup,
                            Execute&& execute) requires std::default_initializable<Data> &&
        std::invocable<Setup&, Builder&, Data&> && std::invocable < std::decay_t<Execute>
    &, const Resources&, const Data& > ;

    /// Hands an existing resource to the graph as version 0 of a resource
    /// named `name`. Throws RenderGraphError for a duplicate or empty name or
    /// after compile().
    template <ImportableResource R>
    [[nodiscard]] Handle<R> importResource(std::string_view name, R resource,
                                           ImportOptions options = {});

    /// Marks a resource version as a result of the frame, like a target
    /// import (e.g. a texture the CLI writes out after the frame). Throws
    /// RenderGraphError for a handle of another graph or after compile().
    template <class R>
    void markTarget(Handle<R> handle);

    /// Checks the rules above, culls, orders the surviving passes and
    /// computes each transient resource's first and last use. Idempotent.
    /// Throws RenderGraphError for a cycle (naming its passes), a read of a
    /// version nobody writes (naming pass and resource), a second writer of a
    /// persistent resource, or a graph whose building threw.
    void compile();

    /// Compiles if needed, then runs the surviving passes in order (skipping
    /// cached ones): transient resources are taken from the cache's pool
    /// before their first use and returned after their last, and each run is
    /// bracketed by the graph's CPU timer and `observer` (may be null).
    /// Once per graph: throws RenderGraphError when called again. Rethrows
    /// what a pass throws (the frame stops there; that pass runs again next
    /// frame) and what the allocator throws.
    void execute(PassObserver* observer = nullptr);

    [[nodiscard]] bool compiled() const noexcept;

    /// The graph's blackboard: resource handles by name, for passes to find
    /// each other's outputs (see Blackboard).
    [[nodiscard]] Blackboard& blackboard() noexcept;
    [[nodiscard]] const Blackboard& blackboard() const noexcept;

    /// After execute(): the content of `handle`'s version, for the caller
    /// (e.g. a status a pass computed). `handle` must be the latest version
    /// of a persistent or imported resource; returns nullptr when no pass
    /// that survived culling wrote it (a cached writer counts: its content
    /// is kept). The object stays valid until the cache executes another
    /// graph or is cleared. Throws RenderGraphError before execute(), after
    /// an execute() that threw, for a transient resource (its storage went
    /// back to the pool: make it persistent) or for an older version.
    template <class R>
    [[nodiscard]] const R* result(Handle<R> handle) const {
        return static_cast<const R*>(resultOf(handle.index(), handle.version(), typeid(R)));
    }

    /// Every pass in declaration order / every resource in declaration order.
    /// Throw RenderGraphError before compile().
    [[nodiscard]] std::vector<PassInfo> passes() const;
    [[nodiscard]] std::vector<ResourceInfo> resources() const;

    /// CPU time of every pass that ran in execute(), in execution order;
    /// empty before. Skipped and culled passes have no entry.
    [[nodiscard]] const std::vector<PassTiming>& timings() const noexcept;

    /// The compiled graph as Graphviz dot: passes as boxes (culled ones grey
    /// and dashed, cached ones blue), resource versions as ellipses labelled
    /// "name vN" (transient / persistent / imported, targets double-circled).
    /// Throws RenderGraphError before compile().
    [[nodiscard]] std::string toDot() const;
    /// The compiled graph as text: one block per pass (state, order, reads,
    /// writes, parameters, reason, time), then one line per resource with its
    /// kind, description and lifetime. Throws RenderGraphError before compile().
    [[nodiscard]] std::string toText() const;

  private:
    /// A pass's execute callback with its Data.
    class PassCallback {
      public:
        virtual ~PassCallback() = default;
        PassCallback(const PassCallback&) = delete;
        PassCallback& operator=(const PassCallback&) = delete;
        PassCallback(PassCallback&&) = delete;
        PassCallback& operator=(PassCallback&&) = delete;
        virtual void run(const Resources& resources) = 0;

      protected:
        PassCallback() = default;
    };

    template <class Data, class Execute>
    class TypedPass final : public PassCallback {
      public:
        explicit TypedPass(Execute execute) : execute_(std::move(execute)) {}
        [[nodiscard]] Data& data() noexcept { return data_; }
        void run(const Resources& resources) override {
            std::invoke(execute_, resources, std::as_const(data_));
        }

      private:
        Data data_{};
        Execute execute_;
    };

    struct Impl;

    template <class R>
    [[nodiscard]] static Handle<R> makeHandle(std::uint32_t index, std::uint32_t version) noexcept {
        return Handle<R>(index, version);
    }

    // The untyped core behind the templates (RenderGraph.cpp).
    std::size_t beginPass(std::string_view name, std::unique_ptr<PassCallback> callback);
    void failSetup(std::size_t pass) noexcept;
    std::uint32_t declareCreated(std::string_view name,
                                 std::unique_ptr<detail::ErasedDescriptor> descriptor,
                                 ResourceKind kind);
    std::uint32_t declareImported(std::string_view name,
                                  std::unique_ptr<detail::ErasedResource> resource,
                                  std::type_index type, std::string description,
                                  const ImportOptions& options);
    void declareRead(std::size_t pass, std::uint32_t index, std::uint32_t version,
                     std::type_index type);
    std::uint32_t declareWrite(std::size_t pass, std::uint32_t index, std::uint32_t version,
                               std::type_index type);
    void declareSideEffect(std::size_t pass);
    void declareParameter(std::size_t pass, std::string_view key, std::span<const std::byte> value);
    void declareTarget(std::uint32_t index, std::uint32_t version, std::type_index type);
    std::uint32_t declareRenderTarget(std::size_t pass, std::string_view name,
                                      const RenderTargetAttachments& attachments);
    [[nodiscard]] RenderTarget resolveRenderTarget(std::size_t pass, RenderTargetId id) const;
    [[noreturn]] void throwMissingEntry(std::size_t pass, std::string_view name) const;
    [[nodiscard]] const void* resultOf(std::uint32_t index, std::uint32_t version,
                                       std::type_index type) const;
    [[nodiscard]] void* access(std::size_t pass, std::uint32_t index, std::uint32_t version,
                               std::type_index type, bool forWrite) const;
    [[nodiscard]] std::string_view passName(std::size_t pass) const;

    std::unique_ptr<Impl> impl_;
};

/// Declares one pass's resources during its setup. Valid only inside setup.
class RenderGraph::Builder {
  public:
    Builder(const Builder&) = delete;
    Builder& operator=(const Builder&) = delete;
    Builder(Builder&&) = delete;
    Builder& operator=(Builder&&) = delete;
    ~Builder() = default;

    /// A new transient resource (version 0, no content yet: write it before
    /// anyone reads it). Its storage comes from the pool for the passes
    /// between its first and last use. Throws RenderGraphError for a
    /// duplicate or empty name, and what R::validate throws (Texture:
    /// InvalidArgumentError for a bad size).
    template <AllocatableResource R>
    [[nodiscard]] Handle<R> create(std::string_view name,
                                   const typename R::Descriptor& descriptor) {
        return declare<R>(name, descriptor, ResourceKind::Transient);
    }

    /// As create(), but the storage is kept across frames under `name` (in
    /// the cache), so that the pass writing it can be skipped when nothing
    /// it depends on changed. A changed descriptor gives new storage (and
    /// re-runs the writer).
    template <AllocatableResource R>
    [[nodiscard]] Handle<R> createPersistent(std::string_view name,
                                             const typename R::Descriptor& descriptor) {
        return declare<R>(name, descriptor, ResourceKind::Persistent);
    }

    /// Declares that this pass reads `handle`'s version; returns it. Throws
    /// RenderGraphError for an invalid handle or one of another graph.
    template <class R>
    Handle<R> read(Handle<R> handle) {
        graph_->declareRead(pass_, handle.index(), handle.version(), typeid(R));
        return handle;
    }

    /// Declares that this pass writes the resource, and returns the handle of
    /// the new version; use that one from now on. Writing does not imply
    /// reading the previous content (read() it too for that). Throws
    /// RenderGraphError for an invalid handle, a handle that is not the
    /// latest version, or a second write of the same resource by this pass.
    template <class R>
    [[nodiscard]] Handle<R> write(Handle<R> handle) {
        return makeHandle<R>(handle.index(), graph_->declareWrite(pass_, handle.index(),
                                                                  handle.version(), typeid(R)));
    }

    /// Declares that this pass reads the resource another pass put on the
    /// graph's blackboard under `name` (its handle there, usually the latest
    /// version); returns it. Throws RenderGraphError naming this pass and
    /// `name` when nothing is under that name, and like read(handle).
    template <class R>
    Handle<R> read(std::string_view name) {
        if (!graph_->blackboard().contains(name)) {
            graph_->throwMissingEntry(pass_, name);
        }
        return read(graph_->blackboard().get<R>(name));
    }

    /// Declares a render target of this pass: `attachments` drawn into at
    /// once (the backend binds a framebuffer for it; Resources::renderTarget).
    /// Every attachment must be a version this pass writes (write() it
    /// first), all of one size (checked when it is resolved). Throws
    /// RenderGraphError for an empty or duplicate name, no attachment, or an
    /// attachment this pass does not write.
    [[nodiscard]] RenderTargetId declareRenderTarget(std::string_view name,
                                                     const RenderTargetAttachments& attachments) {
        return RenderTargetId(graph_->declareRenderTarget(pass_, name, attachments));
    }

    /// The pass does something outside the graph (presents, writes a file):
    /// it is never culled and never skipped.
    void sideEffect() { graph_->declareSideEffect(pass_); }

    /// Declares a parameter of the pass: when its value differs from the last
    /// run (byte for byte), the pass runs again. `T` is trivially copyable
    /// and not a pointer (hash what a pointer points to instead); types with
    /// padding bytes must have them zeroed. Throws RenderGraphError for a key
    /// declared twice in this pass.
    template <class T>
    requires std::is_trivially_copyable_v<T> &&
        (!std::is_pointer_v<T>)&&(!std::ranges::range<T>)void dependsOn(std::string_view key,
                                                                        const T& value) {
        graph_->declareParameter(pass_, key, std::as_bytes(std::span<const T>(&value, 1)));
    }

    /// As above for a contiguous range of values (a vector, an array, a span).
    template <std::ranges::contiguous_range Range>
    requires std::ranges::sized_range<const Range> &&
        std::is_trivially_copyable_v<std::ranges::range_value_t<Range>> &&
        (!std::is_pointer_v<std::ranges::range_value_t<Range>>)&&(
            !std::is_same_v<std::ranges::range_value_t<Range>,
                            char>)void dependsOn(std::string_view key, const Range& values) {
        using Value = std::ranges::range_value_t<Range>;
        graph_->declareParameter(pass_, key,
                                 std::as_bytes(std::span<const Value>(std::ranges::data(values),
                                                                      std::ranges::size(values))));
    }

    /// As above for text (a solver name, a file path).
    void dependsOn(std::string_view key, std::string_view text) {
        graph_->declareParameter(pass_, key, std::as_bytes(std::span<const char>(text)));
    }

    [[nodiscard]] std::string_view passName() const { return graph_->passName(pass_); }

  private:
    friend class RenderGraph;

    Builder(RenderGraph& graph, std::size_t pass) noexcept : graph_(&graph), pass_(pass) {}

    template <AllocatableResource R>
    [[nodiscard]] Handle<R> declare(std::string_view name, const typename R::Descriptor& descriptor,
                                    ResourceKind kind) {
        if constexpr (requires { R::validate(descriptor); }) {
            R::validate(descriptor);
        }
        return makeHandle<R>(
            graph_->declareCreated(name, std::make_unique<detail::TypedDescriptor<R>>(descriptor),
                                   kind),
            0);
    }

    RenderGraph* graph_;
    std::size_t pass_;
};

/// What a pass's execute callback may touch: exactly what its setup declared.
class RenderGraph::Resources {
  public:
    Resources(const Resources&) = delete;
    Resources& operator=(const Resources&) = delete;
    Resources(Resources&&) = delete;
    Resources& operator=(Resources&&) = delete;
    ~Resources() = default;

    /// The resource behind a version this pass declared (read or written).
    /// Throws RenderGraphError for any other handle.
    template <class R>
    [[nodiscard]] const R& get(Handle<R> handle) const {
        return *static_cast<const R*>(
            graph_->access(pass_, handle.index(), handle.version(), typeid(R), false));
    }

    /// The resource behind a version this pass writes, for modification.
    /// Throws RenderGraphError for any other handle.
    template <class R>
    [[nodiscard]] R& getForWrite(Handle<R> handle) const {
        return *static_cast<R*>(
            graph_->access(pass_, handle.index(), handle.version(), typeid(R), true));
    }

    /// A render target this pass declared, with the textures behind it.
    /// Throws RenderGraphError for an id of another pass, or when its
    /// attachments differ in size.
    [[nodiscard]] RenderTarget renderTarget(RenderTargetId id) const {
        return graph_->resolveRenderTarget(pass_, id);
    }

    [[nodiscard]] std::string_view passName() const { return graph_->passName(pass_); }

  private:
    friend class RenderGraph;

    Resources(const RenderGraph& graph, std::size_t pass) noexcept : graph_(&graph), pass_(pass) {}

    const RenderGraph* graph_;
    std::size_t pass_;
};

template <class Data, class Setup, class Execute>
    const Data& RenderGraph::addPass(std::string_view name, Setup&& setup,
                                     Execute&& execute) requires std::default_initializable<Data> &&
    std::invocable<Setup&, Builder&, Data&> && std::invocable < std::decay_t<Execute>
&, const Resources&, const Data& > {
    auto callback =
        std::make_unique<TypedPass<Data, std::decay_t<Execute>>>(std::forward<Execute>(execute));
    Data& data = callback->data();
    const std::size_t pass = beginPass(name, std::move(callback));
    Builder builder(*this, pass);
    try {
        std::invoke(setup, builder, data);
    } catch (...) {
        failSetup(pass);
        throw;
    }
    return data;
}

template <ImportableResource R>
Handle<R> RenderGraph::importResource(std::string_view name, R resource, ImportOptions options) {
    std::string description = detail::describeImported(resource);
    return makeHandle<R>(
        declareImported(name, std::make_unique<detail::TypedResource<R>>(std::move(resource)),
                        typeid(R), std::move(description), options),
        0);
}

template <class R>
void RenderGraph::markTarget(Handle<R> handle) {
    declareTarget(handle.index(), handle.version(), typeid(R));
}

}  // namespace vv::render
