// SPDX-License-Identifier: MIT
#pragma once
// A backend decorator for leak tests: counts, per kind, what was created through it and not
// yet destroyed (creates minus destroys), so a long run can check that the frame's resources
// stay flat. Everything else is forwarded unchanged (capabilities included), so the renderer
// draws exactly as on the wrapped backend.
#include <ostream>

#include "engine/render/forwarding_backend.hpp"

namespace ssam::testing {

struct LiveResources {
    long textures = 0;
    long buffers = 0;
    long programs = 0;
    long pipelines = 0;
    long queries = 0;

    friend bool operator==(const LiveResources&, const LiveResources&) = default;
    friend std::ostream& operator<<(std::ostream& out, const LiveResources& r) {
        return out << r.textures << " textures, " << r.buffers << " buffers, " << r.programs << " programs, "
                   << r.pipelines << " pipelines, " << r.queries << " queries";
    }
};

class CountingBackend final : public engine::render::ForwardingBackend {
public:
    using ForwardingBackend::ForwardingBackend;

    const LiveResources& live() const { return live_; }
    long creates() const { return creates_; }  // every create call so far, of any kind

    engine::render::TextureHandle createTexture(const engine::render::TextureDesc& desc,
                                                const engine::render::TextureData* data) override {
        return made(inner_.createTexture(desc, data), live_.textures);
    }
    engine::render::BufferHandle createBuffer(const engine::render::BufferDesc& desc,
                                              std::span<const std::byte> data) override {
        return made(inner_.createBuffer(desc, data), live_.buffers);
    }
    engine::render::ProgramHandle createProgram(const engine::render::ProgramDesc& desc) override {
        return made(inner_.createProgram(desc), live_.programs);
    }
    engine::render::PipelineHandle createPipeline(const engine::render::PipelineDesc& desc) override {
        return made(inner_.createPipeline(desc), live_.pipelines);
    }
    engine::render::QueryHandle createQuery(const std::string& name) override {
        return made(inner_.createQuery(name), live_.queries);
    }
    void destroy(engine::render::TextureHandle h) override { gone(h, live_.textures); }
    void destroy(engine::render::BufferHandle h) override { gone(h, live_.buffers); }
    void destroy(engine::render::ProgramHandle h) override { gone(h, live_.programs); }
    void destroy(engine::render::PipelineHandle h) override { gone(h, live_.pipelines); }
    void destroy(engine::render::QueryHandle h) override { gone(h, live_.queries); }

private:
    template <typename Handle>
    Handle made(Handle h, long& count) {
        ++creates_;
        if (h) ++count;
        return h;
    }
    // Destroying a null handle is allowed and frees nothing, so it is not counted.
    template <typename Handle>
    void gone(Handle h, long& count) {
        inner_.destroy(h);
        if (h) --count;
    }

    LiveResources live_;
    long creates_ = 0;
};

}  // namespace ssam::testing
