// SPDX-License-Identifier: MIT
#include "counting_backend.hpp"

#include <algorithm>

#include "engine/render/forwarding_backend.hpp"

namespace bench {

using namespace engine::render;

std::uint64_t textureBytes(const TextureDesc& desc) {
    std::uint64_t bytes = 0;
    std::uint64_t w = std::uint64_t(std::max(desc.width, 1)), h = std::uint64_t(std::max(desc.height, 1));
    for (int level = 0; level < std::max(desc.mipLevels, 1); ++level) {
        bytes += w * h;
        w = std::max<std::uint64_t>(w / 2, 1);
        h = std::max<std::uint64_t>(h / 2, 1);
    }
    return bytes * std::uint64_t(std::max(desc.samples, 1)) * formatInfo(desc.format).bytesPerPixel;
}

void ResourceCount::created(std::uint64_t key, std::uint64_t bytes, bool texture) {
    (texture ? textures_ : buffers_)[key] = bytes;
    live_ += bytes;
    peak_ = std::max(peak_, live_);
}

void ResourceCount::destroyed(std::uint64_t key, bool texture) {
    auto& map = texture ? textures_ : buffers_;
    if (auto it = map.find(key); it != map.end()) {
        live_ -= it->second;
        map.erase(it);
    }
}

namespace {

template <typename H>
std::uint64_t key(H h) {
    return (std::uint64_t(h.index) << 32) | h.generation;
}

// Every Backend call forwarded; creation and destruction of textures and buffers counted.
class Counting final : public ForwardingBackend {
public:
    Counting(Backend& inner, ResourceCount& count) : ForwardingBackend(inner), count_(count) {}

    TextureHandle createTexture(const TextureDesc& desc, const TextureData* data) override {
        const TextureHandle t = inner_.createTexture(desc, data);
        count_.created(key(t), textureBytes(desc), true);
        return t;
    }
    BufferHandle createBuffer(const BufferDesc& desc, std::span<const std::byte> data) override {
        const BufferHandle b = inner_.createBuffer(desc, data);
        count_.created(key(b), desc.size, false);
        return b;
    }
    void destroy(TextureHandle texture) override {
        inner_.destroy(texture);
        count_.destroyed(key(texture), true);
    }
    void destroy(BufferHandle buffer) override {
        inner_.destroy(buffer);
        count_.destroyed(key(buffer), false);
    }
    using ForwardingBackend::destroy;

private:
    ResourceCount& count_;
};

}  // namespace

std::unique_ptr<Backend> makeCountingBackend(Backend& inner, ResourceCount& count) {
    return std::make_unique<Counting>(inner, count);
}

}  // namespace bench
