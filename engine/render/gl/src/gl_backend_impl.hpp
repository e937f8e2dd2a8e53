// SPDX-License-Identifier: MIT
#pragma once
// The OpenGL 4.5 core backend's class, whose members are defined by concern:
//   gl_backend.cpp    the context check, the vertex layout, tear-down
//   gl_resources.cpp  textures, buffers, programs, pipelines and occlusion queries
//   gl_passes.cpp     passes (framebuffer, clears, queries), resolve, present
//   gl_readback.cpp   readback, in row bands
//   gl_draw.cpp       one draw: its fixed-function state, the fail-mode steps, the GL calls
// Draws execute as they are recorded (GL queues them); every piece of fixed-function state a
// draw depends on is set for that pass or draw, so a host engine sharing the context may
// change state between passes. Validation and error messages are the shared ones
// (validation.hpp), so both backends reject the same input with the same words.
#include <array>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include <epoxy/gl.h>
#include <glm/glm.hpp>

#include "engine/render/gl/gl_backend.hpp"
#include "engine/render/resolved_draw_state.hpp"
#include "engine/render/resource_pool.hpp"
#include "engine/render/standard_programs.hpp"
#include "engine/render/validation.hpp"
#include "gl_caches.hpp"
#include "gl_objects.hpp"
#include "gl_program_slot.hpp"
#include "gl_texture_limits.hpp"

namespace engine::render::gl {

struct GlPipeline {
    PipelineDesc desc;
    PipelineInfo info;
    std::shared_ptr<const ProgramSlot> program;  // alive while the pipeline is
};

class GlBackendImpl final : public GlBackend {
public:
    GlBackendImpl(const GlOptions& options, std::shared_ptr<GlContext> context);
    ~GlBackendImpl() override;

    std::string name() const override { return "gl"; }
    const GlInfo& info() const override { return info_; }
    GlContext* context() const override { return context_.get(); }

    // gl_resources.cpp
    TextureHandle createTexture(const TextureDesc& desc, const TextureData* data) override;
    TextureHandle importTexture(unsigned int id, const TextureDesc& desc) override;
    unsigned int glTexture(TextureHandle h) const override { return textures_.get(h).id; }
    BufferHandle createBuffer(const BufferDesc& desc, std::span<const std::byte> data) override;
    void updateBuffer(BufferHandle handle, std::uint64_t offset, std::span<const std::byte> data) override;
    ProgramHandle createProgram(const ProgramDesc& desc) override;
    PipelineHandle createPipeline(const PipelineDesc& desc) override;
    void destroy(TextureHandle h) override;
    void destroy(BufferHandle h) override;
    void destroy(ProgramHandle h) override;
    void destroy(PipelineHandle h) override { pipelines_.remove(h); }
    QueryHandle createQuery(const std::string& name) override { return queries_.add({name}); }
    void destroy(QueryHandle h) override;
    bool anySamplesPassed(QueryHandle h) override;
    const TextureDesc& describe(TextureHandle h) const override { return textures_.get(h).desc; }
    PipelineInfo pipelineInfo(PipelineHandle h) const override { return pipelines_.get(h).info; }

    // gl_passes.cpp
    void beginPass(const PassDesc& pass) override;
    void endPass() override;
    void abortPass() noexcept override;
    void resolve(const ResolveDesc& r) override;
    Readback readback(TextureHandle h) override;
    std::vector<PassTiming> takeTimings() override;
    bool present(TextureHandle h) override;

    // gl_draw.cpp
    void draw(const DrawDesc& d) override;

private:
    struct Target {
        TextureHandle texture;
        Format format;
        ColorAttachment attachment;
    };

    void makeCurrent() {
        if (context_) context_->makeCurrent();
    }

    // gl_resources.cpp
    int maxSamplesFor(GLenum internal);
    void upload(GlTexture& t, const TextureData& data);  // data that validateTextureData accepted
    void clearTexture(const GlTexture& t, const glm::vec4& value);
    void clearToZero(const GlTexture& t);  // GL leaves new storage undefined; soft starts from zeros
    std::shared_ptr<const ProgramSlot> programFor(const ProgramRef& ref);
    ProgramSlot& internalProgram(std::optional<ProgramSlot>& slot, const char* name, const std::string& fragment);
    GlslTarget glsl() const { return {glMajor_, glMinor_}; }

    // gl_passes.cpp
    void applyBaseState();
    void endPassQueries(bool counted);
    void validateFramebufferState();
    bool conditionPending(GLuint query) const;
    void releaseQueryObject(GLuint query);

    // gl_draw.cpp
    void execute(const DrawDesc& d);
    // GlOptions::failModes in the resolver's terms: GL has only `discard`, so fail modes are
    // always emulated.
    FailModeEmulation failModeEmulation() const {
        return options_.failModes == FailModeStrategy::PerTriangle ? FailModeEmulation::PerTriangle
                                                                   : FailModeEmulation::TwoPass;
    }
    void drawRange(const DrawDesc& d, std::uint32_t first, std::uint32_t count, std::uint32_t baseInstance,
                   std::uint32_t instances);
    template <typename ApplyStep>
    void drawPerTriangle(const DrawDesc& d, const FailModePlan& plan, ApplyStep& applyStep);

    GlOptions options_;
    std::shared_ptr<GlContext> context_;
    GlInfo info_;
    GlTextureLimits textureLimits_;
    int glMajor_ = 4, glMinor_ = 5;
    GlTexturePool textures_;
    ResourcePool<BufferTag, GlBuffer> buffers_;
    ResourcePool<PipelineTag, GlPipeline> pipelines_;
    ResourcePool<QueryTag, GlQuery> queries_;
    ResourcePool<ProgramTag, std::shared_ptr<const ProgramSlot>> programs_;
    ResourceLookup lookup_;  // what the shared validation reads
    std::set<GLuint> ownedTextures_, ownedBuffers_;
    std::map<GLenum, int> maxSamplesByFormat_;
    GlFramebufferCache framebuffers_;
    GlSamplerCache samplers_;
    StandardProgramSlots<ProgramSlot> standardPrograms_;
    std::optional<ProgramSlot> resolveColor_, resolveDepth_, nothing_;
    GLuint vao_ = 0, emptyVao_ = 0, identityInstance_ = 0;

    std::optional<PassDesc> pass_;
    std::vector<Target> targets_;  // the pass's colour attachments, packed (soft: colorTargets)
    int passWidth_ = 0, passHeight_ = 0, passSamples_ = 1, passActualSamples_ = 1;
    GLuint passFbo_ = 0, passQuery_ = 0, passCondition_ = 0;
    std::vector<PendingTiming> pendingTimings_;
    std::set<GLuint> occlusionQueries_;   // every GL query object behind a QueryHandle, live or retired
    std::vector<GLuint> retiredQueries_;  // replaced while a pending timing reads them
};

}  // namespace engine::render::gl
