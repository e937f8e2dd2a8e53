// SPDX-License-Identifier: MIT
#pragma once
// A Backend that forwards every call to another: the base of decorators that observe or
// alter some calls (ssam-bench counts the bytes a technique allocates; tests make a create
// fail on cue). Capabilities are forwarded too, so a decorated backend offers what the
// wrapped one offers without anybody downcasting either.
#include "engine/render/backend.hpp"

namespace engine::render {

class ForwardingBackend : public Backend {
public:
    explicit ForwardingBackend(Backend& inner) : inner_(inner) {}

    std::string name() const override { return inner_.name(); }
    TextureHandle createTexture(const TextureDesc& desc, const TextureData* data) override {
        return inner_.createTexture(desc, data);
    }
    BufferHandle createBuffer(const BufferDesc& desc, std::span<const std::byte> data) override {
        return inner_.createBuffer(desc, data);
    }
    void updateBuffer(BufferHandle buffer, std::uint64_t offset, std::span<const std::byte> data) override {
        inner_.updateBuffer(buffer, offset, data);
    }
    ProgramHandle createProgram(const ProgramDesc& desc) override { return inner_.createProgram(desc); }
    PipelineHandle createPipeline(const PipelineDesc& desc) override { return inner_.createPipeline(desc); }
    void destroy(TextureHandle texture) override { inner_.destroy(texture); }
    void destroy(BufferHandle buffer) override { inner_.destroy(buffer); }
    void destroy(PipelineHandle pipeline) override { inner_.destroy(pipeline); }
    void destroy(ProgramHandle program) override { inner_.destroy(program); }
    QueryHandle createQuery(const std::string& name) override { return inner_.createQuery(name); }
    void destroy(QueryHandle query) override { inner_.destroy(query); }
    bool anySamplesPassed(QueryHandle query) override { return inner_.anySamplesPassed(query); }
    const TextureDesc& describe(TextureHandle texture) const override { return inner_.describe(texture); }
    PipelineInfo pipelineInfo(PipelineHandle pipeline) const override { return inner_.pipelineInfo(pipeline); }
    void beginPass(const PassDesc& pass) override { inner_.beginPass(pass); }
    void draw(const DrawDesc& draw) override { inner_.draw(draw); }
    void endPass() override { inner_.endPass(); }
    void abortPass() noexcept override { inner_.abortPass(); }
    void resolve(const ResolveDesc& resolve) override { inner_.resolve(resolve); }
    Readback readback(TextureHandle texture) override { return inner_.readback(texture); }
    std::vector<PassTiming> takeTimings() override { return inner_.takeTimings(); }
    void endFrame() override { inner_.endFrame(); }
    FragmentCapture* fragmentCapture() override { return inner_.fragmentCapture(); }

protected:
    Backend& inner_;
};

}  // namespace engine::render
