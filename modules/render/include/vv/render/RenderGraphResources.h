// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <concepts>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "vv/render/RenderGraphHandle.h"

namespace vv::render {

/// Texel formats of graph textures. The GL allocator maps them to internal
/// formats; the CPU allocator stores every format as floats, one per channel.
enum class TextureFormat {
    R8,
    RGBA8,
    R16F,
    RGBA16F,
    R32F,
    RG32F,
    RGBA32F,
    R32UI,
    Depth32F,
};

/// "R8", "RGBA8", ..., "Depth32F".
[[nodiscard]] std::string_view toString(TextureFormat format) noexcept;
/// Channels per texel: 1, 2 or 4.
[[nodiscard]] int channelCount(TextureFormat format) noexcept;

/// What a graph texture is: size, format and MSAA samples. Two textures with
/// equal descriptors are interchangeable, which is what lets the allocator
/// pool reuse one for the other.
struct TextureDescriptor {
    int width = 1;
    int height = 1;
    TextureFormat format = TextureFormat::RGBA8;
    int samples = 1;  ///< 1 = not multisampled

    friend bool operator==(const TextureDescriptor&, const TextureDescriptor&) = default;
};

/// The backend object behind a Texture: a GL texture (+ FBO) in the GL
/// renderer, a CpuTexture in tests and headless tools. Passes reach the
/// concrete type through Texture::objectAs<T>().
class TextureObject {
  public:
    virtual ~TextureObject() = default;
    TextureObject(const TextureObject&) = delete;
    TextureObject& operator=(const TextureObject&) = delete;
    TextureObject(TextureObject&&) = delete;
    TextureObject& operator=(TextureObject&&) = delete;

  protected:
    TextureObject() = default;
};

/// Makes the backend objects behind transient and persistent graph resources.
/// It only creates: reuse is the graph's job (RenderGraphCache pools objects
/// by descriptor and asks the allocator only when no free one fits), and an
/// object is destroyed by destroying it (its destructor frees the backend
/// storage; for GL, with the context current).
class ResourceAllocator {
  public:
    virtual ~ResourceAllocator() = default;

    /// A new texture object for `descriptor` (already validated). Never null;
    /// throws RenderError (GL) when the backend cannot make it.
    [[nodiscard]] virtual std::unique_ptr<TextureObject> createTexture(
        const TextureDescriptor& descriptor) = 0;

  protected:
    ResourceAllocator() = default;
    ResourceAllocator(const ResourceAllocator&) = default;
    ResourceAllocator& operator=(const ResourceAllocator&) = default;
    ResourceAllocator(ResourceAllocator&&) = default;
    ResourceAllocator& operator=(ResourceAllocator&&) = default;
};

/// A 2D texture resource of the graph: a descriptor and a shared reference to
/// its backend object. Copying a Texture copies the reference, not the texels.
class Texture {
  public:
    using Descriptor = TextureDescriptor;

    /// Wraps an existing backend object, e.g. to import the default
    /// framebuffer. Throws InvalidArgumentError if `object` is null or the
    /// descriptor is invalid (see validate()).
    Texture(const TextureDescriptor& descriptor, std::shared_ptr<TextureObject> object);

    /// Asks `allocator` for a new object. Throws InvalidArgumentError for an
    /// invalid descriptor, RenderError if the allocator returns null, and
    /// whatever the allocator throws.
    [[nodiscard]] static Texture create(ResourceAllocator& allocator, const Descriptor& descriptor);

    /// Throws InvalidArgumentError unless 1 <= width, height <= 32768 and
    /// 1 <= samples <= 64.
    static void validate(const Descriptor& descriptor);
    /// "R32F 640x360" (+ " x4 MSAA" when multisampled); for graph dumps.
    [[nodiscard]] static std::string describe(const Descriptor& descriptor);
    /// A hash consistent with operator== (equal descriptors, equal hashes).
    [[nodiscard]] static std::size_t hash(const Descriptor& descriptor) noexcept;

    [[nodiscard]] const Descriptor& descriptor() const noexcept { return descriptor_; }
    [[nodiscard]] TextureObject& object() const noexcept { return *object_; }

    /// The backend object as `T`. Throws RenderGraphError when it is another
    /// type (e.g. a CpuTexture handed to a GL pass).
    template <class T>
    [[nodiscard]] T& objectAs() const {
        auto* typed = dynamic_cast<T*>(object_.get());
        if (typed == nullptr) {
            throwWrongObjectType();
        }
        return *typed;
    }

  private:
    [[noreturn]] static void throwWrongObjectType();

    Descriptor descriptor_;
    std::shared_ptr<TextureObject> object_;
};

/// A resource type the graph can create and pool: it has a `Descriptor`
/// (copyable, equality comparable), makes itself through the allocator and
/// can describe and hash its descriptor. R::validate(descriptor) is called at
/// declaration when R has it.
template <class R>
concept AllocatableResource = std::move_constructible<R> && std::destructible<R> &&
    std::copy_constructible<typename R::Descriptor> &&
    std::equality_comparable<typename R::Descriptor> &&
    requires(ResourceAllocator& allocator, const typename R::Descriptor& descriptor) {
    { R::create(allocator, descriptor) } -> std::same_as<R>;
    { R::describe(descriptor) } -> std::convertible_to<std::string>;
    { R::hash(descriptor) } -> std::convertible_to<std::size_t>;
};

/// A value in main memory as a graph resource: what one pass hands another on
/// the CPU (a depth range read back, a solved VSS, the cue a pass shaded with).
/// Declare it like a texture, with `CpuValue<T>::Descriptor{}`:
///
///     d.range = b.write(b.createPersistent<CpuValue<Range>>("range", {}));
///     ... execute: r.getForWrite(d.range).set(range);
///     ... a reader's execute: const Range& range = r.get(d.range).value();
///
/// A persistent value keeps its content across frames, like a persistent
/// texture: when its writer is skipped (cached), readers see what it wrote
/// last, and the content stamps make a reader re-run exactly when the writer
/// ran. Fresh storage (a persistent value's first frame, new storage after
/// expiry, a transient value taken from the pool) starts empty, so a read
/// before the writer set it throws instead of showing another frame's value.
/// After RenderGraph::execute(), RenderGraph::result() hands a persistent
/// value to the caller (renderer-level outputs such as a frame's status).
template <class T>
class CpuValue {
  public:
    /// Values of one type are interchangeable storage: nothing to describe.
    struct Descriptor {
        friend bool operator==(const Descriptor&, const Descriptor&) = default;
    };

    [[nodiscard]] static CpuValue create(ResourceAllocator& /*allocator*/,
                                         const Descriptor& /*descriptor*/) {
        return CpuValue();
    }
    [[nodiscard]] static std::string describe(const Descriptor& /*descriptor*/) {
        return "CPU value";
    }
    [[nodiscard]] static std::size_t hash(const Descriptor& /*descriptor*/) noexcept {
        return 0x43505556U;  // one bucket; the graph tells the value types apart
    }
    /// Called by the graph whenever it hands out storage that held another
    /// content before (pooled or expired): empties it.
    static void recycle(CpuValue& value) noexcept { value.value_.reset(); }

    /// True once set() gave it a content.
    [[nodiscard]] bool hasValue() const noexcept { return value_.has_value(); }
    /// The content. Throws RenderGraphError while there is none (its writer
    /// has not set it in this storage).
    [[nodiscard]] const T& value() const {
        if (!value_.has_value()) {
            throwEmpty();
        }
        return *value_;
    }
    void set(T value) { value_ = std::move(value); }

  private:
    [[noreturn]] static void throwEmpty() {
        throw RenderGraphError("render graph: a CPU value is read before its writer set it");
    }

    std::optional<T> value_;
};

/// A resource type the graph can import: any object type it can move in and
/// hand to passes (a Texture, a file sink, a pointer to a CPU image cache).
template <class R>
concept ImportableResource =
    std::is_object_v<R> && std::move_constructible<R> && std::destructible<R>;

/// A texture in main memory: width × height × channelCount(format) × samples
/// floats, row 0 first, channels interleaved, all zero when made.
class CpuTexture final : public TextureObject {
  public:
    /// Throws InvalidArgumentError for an invalid descriptor.
    explicit CpuTexture(const TextureDescriptor& descriptor);
    ~CpuTexture() override;
    CpuTexture(const CpuTexture&) = delete;
    CpuTexture& operator=(const CpuTexture&) = delete;
    CpuTexture(CpuTexture&&) = delete;
    CpuTexture& operator=(CpuTexture&&) = delete;

    [[nodiscard]] const TextureDescriptor& descriptor() const noexcept { return descriptor_; }
    [[nodiscard]] std::span<float> texels() noexcept { return texels_; }
    [[nodiscard]] std::span<const float> texels() const noexcept { return texels_; }

    /// Counts this object in `*counter`: +1 now, -1 when it is destroyed
    /// (CpuResourceAllocator counts live objects this way). Replaces (and
    /// decrements) a counter set before; null means none.
    void setLifetimeCounter(std::shared_ptr<long> counter) noexcept;

  private:
    TextureDescriptor descriptor_;
    std::vector<float> texels_;
    std::shared_ptr<long> liveCounter_;
};

/// The GL-free allocator: makes CpuTexture objects and counts its work, so
/// tests can check how often the graph asked for storage.
class CpuResourceAllocator final : public ResourceAllocator {
  public:
    CpuResourceAllocator();

    [[nodiscard]] std::unique_ptr<TextureObject> createTexture(
        const TextureDescriptor& descriptor) override;

    /// How many textures this allocator has made so far.
    [[nodiscard]] long texturesCreated() const noexcept { return created_; }
    /// How many of them still exist.
    [[nodiscard]] long texturesAlive() const noexcept { return *alive_; }

  private:
    long created_ = 0;
    std::shared_ptr<long> alive_;
};

}  // namespace vv::render
