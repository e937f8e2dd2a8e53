#include "counting_backend.hpp"

#include <algorithm>

#include "engine/render/soft/soft_backend.hpp"

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

// Every Backend call forwarded; creation and destruction counted.
template <typename Interface>
class Counting : public Interface {
public:
    Counting(Interface& inner, ResourceCount& count) : inner_(inner), count_(count) {}

    std::string name() const override { return inner_.name(); }
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
    void updateBuffer(BufferHandle buffer, std::uint64_t offset, std::span<const std::byte> data) override {
        inner_.updateBuffer(buffer, offset, data);
    }
    PipelineHandle createPipeline(const PipelineDesc& desc) override { return inner_.createPipeline(desc); }
    void destroy(TextureHandle texture) override {
        inner_.destroy(texture);
        count_.destroyed(key(texture), true);
    }
    void destroy(BufferHandle buffer) override {
        inner_.destroy(buffer);
        count_.destroyed(key(buffer), false);
    }
    void destroy(PipelineHandle pipeline) override { inner_.destroy(pipeline); }
    QueryHandle createQuery(const std::string& name) override { return inner_.createQuery(name); }
    void destroy(QueryHandle query) override { inner_.destroy(query); }
    bool anySamplesPassed(QueryHandle query) override { return inner_.anySamplesPassed(query); }
    const TextureDesc& describe(TextureHandle texture) const override { return inner_.describe(texture); }
    PipelineInfo pipelineInfo(PipelineHandle pipeline) const override { return inner_.pipelineInfo(pipeline); }
    void beginPass(const PassDesc& pass) override { inner_.beginPass(pass); }
    void draw(const DrawDesc& draw) override { inner_.draw(draw); }
    void endPass() override { inner_.endPass(); }
    void resolve(const ResolveDesc& resolve) override { inner_.resolve(resolve); }
    Readback readback(TextureHandle texture) override { return inner_.readback(texture); }
    std::vector<PassTiming> takeTimings() override { return inner_.takeTimings(); }

protected:
    Interface& inner_;
    ResourceCount& count_;
};

class CountingSoft final : public Counting<soft::SoftBackend> {
public:
    using Counting::Counting;
    soft::SoftStats stats() const override { return inner_.stats(); }
    const soft::SoftOptions& options() const override { return inner_.options(); }
    void setFragmentSink(soft::FragmentSink* sink) override { inner_.setFragmentSink(sink); }
};

}  // namespace

std::unique_ptr<Backend> makeCountingBackend(Backend& inner, ResourceCount& count) {
    if (auto* soft = dynamic_cast<soft::SoftBackend*>(&inner)) return std::make_unique<CountingSoft>(*soft, count);
    return std::make_unique<Counting<Backend>>(inner, count);
}

}  // namespace bench
