// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// Type erasure between RenderGraph's typed templates and its untyped core.
// Not part of the API: names and shapes here may change without notice.

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <typeindex>
#include <typeinfo>
#include <utility>
#include <vector>

#include "vv/render/RenderGraphResources.h"

namespace vv::render::detail {

/// One resource object of any type, owned.
class ErasedResource {
  public:
    virtual ~ErasedResource() = default;
    ErasedResource(const ErasedResource&) = delete;
    ErasedResource& operator=(const ErasedResource&) = delete;
    ErasedResource(ErasedResource&&) = delete;
    ErasedResource& operator=(ErasedResource&&) = delete;

    /// Address of the held object (an R for TypedResource<R>).
    [[nodiscard]] virtual void* get() noexcept = 0;

  protected:
    ErasedResource() = default;
};

template <class R>
class TypedResource final : public ErasedResource {
  public:
    explicit TypedResource(R resource) : resource_(std::move(resource)) {}
    [[nodiscard]] void* get() noexcept override { return std::addressof(resource_); }

  private:
    R resource_;
};

/// The descriptor of a resource the graph creates, with what the pool needs:
/// equality and hashing (pool key), a description (dumps) and creation.
class ErasedDescriptor {
  public:
    virtual ~ErasedDescriptor() = default;
    ErasedDescriptor(const ErasedDescriptor&) = delete;
    ErasedDescriptor& operator=(const ErasedDescriptor&) = delete;
    ErasedDescriptor(ErasedDescriptor&&) = delete;
    ErasedDescriptor& operator=(ErasedDescriptor&&) = delete;

    /// The resource type R (not the descriptor type).
    [[nodiscard]] virtual std::type_index type() const noexcept = 0;
    [[nodiscard]] virtual std::string describe() const = 0;
    [[nodiscard]] virtual std::size_t hash() const = 0;
    /// Same resource type and equal descriptors.
    [[nodiscard]] virtual bool equals(const ErasedDescriptor& other) const = 0;
    [[nodiscard]] virtual std::unique_ptr<ErasedDescriptor> clone() const = 0;
    [[nodiscard]] virtual std::unique_ptr<ErasedResource> create(
        ResourceAllocator& allocator) const = 0;
    /// Prepares `resource` (made by create()) to be handed out again with
    /// other content: R::recycle(R&) when R has it, else nothing.
    virtual void recycle(ErasedResource& resource) const noexcept = 0;

  protected:
    ErasedDescriptor() = default;
};

template <AllocatableResource R>
class TypedDescriptor final : public ErasedDescriptor {
  public:
    using Descriptor = typename R::Descriptor;

    explicit TypedDescriptor(Descriptor descriptor) : descriptor_(std::move(descriptor)) {}

    [[nodiscard]] std::type_index type() const noexcept override { return typeid(R); }
    [[nodiscard]] std::string describe() const override { return R::describe(descriptor_); }
    [[nodiscard]] std::size_t hash() const override { return R::hash(descriptor_); }
    [[nodiscard]] bool equals(const ErasedDescriptor& other) const override {
        const auto* typed = dynamic_cast<const TypedDescriptor*>(&other);
        return typed != nullptr && typed->descriptor_ == descriptor_;
    }
    [[nodiscard]] std::unique_ptr<ErasedDescriptor> clone() const override {
        return std::make_unique<TypedDescriptor>(descriptor_);
    }
    [[nodiscard]] std::unique_ptr<ErasedResource> create(
        ResourceAllocator& allocator) const override {
        return std::make_unique<TypedResource<R>>(R::create(allocator, descriptor_));
    }
    void recycle(ErasedResource& resource) const noexcept override {
        if constexpr (requires(R & r) { R::recycle(r); }) {
            R::recycle(*static_cast<R*>(resource.get()));
        }
    }

  private:
    Descriptor descriptor_;
};

/// "R32F 640x360" for an imported resource with a describable descriptor,
/// "imported" otherwise.
template <class R>
[[nodiscard]] std::string describeImported(const R& resource) {
    if constexpr (requires { R::describe(resource.descriptor()); }) {
        return R::describe(resource.descriptor());
    } else {
        return "imported";
    }
}

/// One `dependsOn(key, value)` of a pass: the value's bytes, compared exactly.
struct PassParameter {
    std::string key;
    std::vector<std::byte> value;
    friend bool operator==(const PassParameter&, const PassParameter&) = default;
};

/// One resource version a pass read, with the stamp of its content.
struct InputStamp {
    std::string resource;
    std::uint32_t version = 0;
    std::uint64_t stamp = 0;
    friend bool operator==(const InputStamp&, const InputStamp&) = default;
};

/// One persistent resource version a pass wrote, with the generation of the
/// storage it wrote into (a new generation = new storage = content lost).
struct OutputStamp {
    std::string resource;
    std::uint32_t version = 0;
    std::uint64_t generation = 0;
    friend bool operator==(const OutputStamp&, const OutputStamp&) = default;
};

/// Everything a cached pass result depends on.
struct PassSignature {
    std::vector<PassParameter> parameters;
    std::vector<InputStamp> inputs;
    std::vector<OutputStamp> outputs;
    friend bool operator==(const PassSignature&, const PassSignature&) = default;
};

}  // namespace vv::render::detail
