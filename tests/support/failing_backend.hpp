// SPDX-License-Identifier: MIT
#pragma once
// A backend decorator for exception-safety tests: the create call number `failAt` (0-based,
// counting textures, buffers, programs, pipelines and queries alike) throws engine::Error
// instead of creating, the draw call number `failDrawAt` throws instead of drawing, and
// `live` counts what was created through it and not yet destroyed, so a test can check that
// nothing leaked and no pass was left open after the error.
#include "engine/core/error.hpp"
#include "engine/render/forwarding_backend.hpp"

namespace ssam::testing {

class FailingBackend final : public engine::render::ForwardingBackend {
public:
    using ForwardingBackend::ForwardingBackend;

    int failAt = -1;  // -1: never
    int creates = 0;  // create calls so far, the failed one included
    int live = 0;
    int failDrawAt = -1;  // -1: never
    int draws = 0;        // draw calls so far, the failed one included

    engine::render::TextureHandle createTexture(const engine::render::TextureDesc& desc,
                                                const engine::render::TextureData* data) override {
        return made(next() ? inner_.createTexture(desc, data) : engine::render::TextureHandle{});
    }
    engine::render::BufferHandle createBuffer(const engine::render::BufferDesc& desc,
                                              std::span<const std::byte> data) override {
        return made(next() ? inner_.createBuffer(desc, data) : engine::render::BufferHandle{});
    }
    engine::render::ProgramHandle createProgram(const engine::render::ProgramDesc& desc) override {
        return made(next() ? inner_.createProgram(desc) : engine::render::ProgramHandle{});
    }
    engine::render::PipelineHandle createPipeline(const engine::render::PipelineDesc& desc) override {
        return made(next() ? inner_.createPipeline(desc) : engine::render::PipelineHandle{});
    }
    engine::render::QueryHandle createQuery(const std::string& name) override {
        return made(next() ? inner_.createQuery(name) : engine::render::QueryHandle{});
    }
    void draw(const engine::render::DrawDesc& desc) override {
        if (draws++ == failDrawAt) throw engine::Error("injected failure of draw call " + std::to_string(failDrawAt));
        inner_.draw(desc);
    }
    void destroy(engine::render::TextureHandle h) override { gone(h); }
    void destroy(engine::render::BufferHandle h) override { gone(h); }
    void destroy(engine::render::ProgramHandle h) override { gone(h); }
    void destroy(engine::render::PipelineHandle h) override { gone(h); }
    void destroy(engine::render::QueryHandle h) override { gone(h); }

private:
    bool next() {
        if (creates++ == failAt) throw engine::Error("injected failure of create call " + std::to_string(failAt));
        return true;
    }
    template <typename Handle>
    Handle made(Handle h) {
        ++live;
        return h;
    }
    template <typename Handle>
    void gone(Handle h) {
        inner_.destroy(h);
        --live;
    }
};

}  // namespace ssam::testing
