// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/render/RenderGraphResources.h"

#include <functional>
#include <string>
#include <utility>

#include "vv/core/Error.h"

namespace vv::render {

namespace {

constexpr int kMaxTextureSize = 32768;
constexpr int kMaxSamples = 64;

/// Mixes `value` into `seed` (the usual golden-ratio combine).
void combineHash(std::size_t& seed, std::size_t value) noexcept {
    seed ^= value + 0x9e3779b97f4a7c15ULL + (seed << 6U) + (seed >> 2U);
}

}  // namespace

std::string_view toString(TextureFormat format) noexcept {
    switch (format) {
        case TextureFormat::R8:
            return "R8";
        case TextureFormat::RGBA8:
            return "RGBA8";
        case TextureFormat::R16F:
            return "R16F";
        case TextureFormat::RGBA16F:
            return "RGBA16F";
        case TextureFormat::R32F:
            return "R32F";
        case TextureFormat::RG32F:
            return "RG32F";
        case TextureFormat::RGBA32F:
            return "RGBA32F";
        case TextureFormat::R32UI:
            return "R32UI";
        case TextureFormat::Depth32F:
            return "Depth32F";
    }
    return "unknown";
}

int channelCount(TextureFormat format) noexcept {
    switch (format) {
        case TextureFormat::RG32F:
            return 2;
        case TextureFormat::RGBA8:
        case TextureFormat::RGBA16F:
        case TextureFormat::RGBA32F:
            return 4;
        case TextureFormat::R8:
        case TextureFormat::R16F:
        case TextureFormat::R32F:
        case TextureFormat::R32UI:
        case TextureFormat::Depth32F:
            return 1;
    }
    return 1;
}

Texture::Texture(const TextureDescriptor& descriptor, std::shared_ptr<TextureObject> object)
    : descriptor_(descriptor), object_(std::move(object)) {
    validate(descriptor_);
    if (object_ == nullptr) {
        throw InvalidArgumentError("texture: no backend object");
    }
}

Texture Texture::create(ResourceAllocator& allocator, const Descriptor& descriptor) {
    validate(descriptor);
    std::shared_ptr<TextureObject> object = allocator.createTexture(descriptor);
    if (object == nullptr) {
        throw RenderError("texture " + describe(descriptor) + ": the allocator returned nothing");
    }
    return {descriptor, std::move(object)};
}

void Texture::validate(const Descriptor& descriptor) {
    if (descriptor.width < 1 || descriptor.width > kMaxTextureSize || descriptor.height < 1 ||
        descriptor.height > kMaxTextureSize) {
        throw InvalidArgumentError("texture size " + std::to_string(descriptor.width) + "x" +
                                   std::to_string(descriptor.height) + " is outside 1.." +
                                   std::to_string(kMaxTextureSize));
    }
    if (descriptor.samples < 1 || descriptor.samples > kMaxSamples) {
        throw InvalidArgumentError("texture sample count " + std::to_string(descriptor.samples) +
                                   " is outside 1.." + std::to_string(kMaxSamples));
    }
}

std::string Texture::describe(const Descriptor& descriptor) {
    std::string text = std::string(toString(descriptor.format)) + " " +
                       std::to_string(descriptor.width) + "x" + std::to_string(descriptor.height);
    if (descriptor.samples > 1) {
        text += " x" + std::to_string(descriptor.samples) + " MSAA";
    }
    return text;
}

std::size_t Texture::hash(const Descriptor& descriptor) noexcept {
    std::size_t seed = std::hash<int>{}(descriptor.width);
    combineHash(seed, std::hash<int>{}(descriptor.height));
    combineHash(seed, std::hash<int>{}(static_cast<int>(descriptor.format)));
    combineHash(seed, std::hash<int>{}(descriptor.samples));
    return seed;
}

void Texture::throwWrongObjectType() {
    throw RenderGraphError("texture: its backend object is not of the requested type");
}

CpuTexture::CpuTexture(const TextureDescriptor& descriptor) : descriptor_(descriptor) {
    Texture::validate(descriptor_);
    texels_.assign(static_cast<std::size_t>(descriptor_.width) *
                       static_cast<std::size_t>(descriptor_.height) *
                       static_cast<std::size_t>(channelCount(descriptor_.format)) *
                       static_cast<std::size_t>(descriptor_.samples),
                   0.0F);
}

CpuTexture::~CpuTexture() {
    setLifetimeCounter(nullptr);
}

void CpuTexture::setLifetimeCounter(std::shared_ptr<long> counter) noexcept {
    if (liveCounter_ != nullptr) {
        --*liveCounter_;
    }
    liveCounter_ = std::move(counter);
    if (liveCounter_ != nullptr) {
        ++*liveCounter_;
    }
}

CpuResourceAllocator::CpuResourceAllocator() : alive_(std::make_shared<long>(0)) {}

std::unique_ptr<TextureObject> CpuResourceAllocator::createTexture(
    const TextureDescriptor& descriptor) {
    auto texture = std::make_unique<CpuTexture>(descriptor);
    texture->setLifetimeCounter(alive_);
    ++created_;
    return texture;
}

}  // namespace vv::render
