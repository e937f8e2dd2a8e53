// SPDX-License-Identifier: MIT
#pragma once
// The OpenGL 4.5 core driver's class, whose members are defined by concern:
//   gl_backend.cpp    the context check, the vertex layout, tear-down
//   gl_resources.cpp  textures, buffers, programs, pipelines and occlusion queries
//   gl_passes.cpp     passes (framebuffer, clears, queries), resolve, present
//   gl_readback.cpp   readback, in row bands
//   gl_draw.cpp       one draw: its fixed-function state, the fail-mode steps, the GL calls
// Draws execute as they are recorded (GL queues them); every piece of fixed-function state a
// draw depends on is set for that pass or draw, so a host engine sharing the context may
// change state between passes. The device (device.hpp) has validated and resolved all it is given.
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
#include "engine/render/native_slots.hpp"
#include "engine/render/resolved_draw_state.hpp"
#include "engine/render/validation.hpp"
#include "gl_caches.hpp"
#include "gl_objects.hpp"
#include "gl_program_slot.hpp"
#include "gl_texture_limits.hpp"

namespace engine::render::gl {

class GlDriverImpl final : public GlDriver {
public:
    GlDriverImpl(const GlOptions& options, std::shared_ptr<GlContext> context);
    ~GlDriverImpl() override;

    std::string name() const override { return "gl"; }
    std::string describe() const override { return "gl: " + info_.renderer; }
    void attach(const NativeTextures& textures) override { natives_ = &textures; }
    // GL has only `discard`, so the alpha test's fail modes are always emulated.
    FailModeEmulation failModeEmulation() const override {
        return options_.failModes == FailModeStrategy::PerTriangle ? FailModeEmulation::PerTriangle
                                                                   : FailModeEmulation::TwoPass;
    }
    MemoryProbe memoryProbe() const override;  // gl_resources.cpp
    const GlInfo& info() const override { return info_; }
    GlContext* context() const override { return context_.get(); }
    unsigned int glTexture(NativeId h) const override { return textures_[h].id; }

    // gl_resources.cpp
    void checkTexture(const TextureDesc& desc, const TextureData* data, const std::string& what) override;
    NativeId wrapTexture(unsigned int id, const TextureDesc& desc, const std::string& what) override;
    void notePipeline(const PipelineDesc& desc, ResolvedPipeline& resolved) override;
    NativeId createQuery(const std::string&) override { return queries_.add({}); }
    // gl_passes.cpp
    bool present(NativeId h, const TextureDesc& desc) override;

    // The driver calls: resources and queries in gl_resources.cpp, passes, resolves, readbacks
    // and timings in gl_passes.cpp, draws in gl_draw.cpp.
    ENGINE_DRIVER_CALLS(ENGINE_DRIVER_OVERRIDE)

private:
    void makeCurrent() {
        if (context_) context_->makeCurrent();
    }

    // gl_resources.cpp
    int maxSamplesFor(GLenum internal);
    void upload(GlTexture& t, const TextureData& data);  // data that validateTextureData accepted
    void clearTexture(const GlTexture& t, const glm::vec4& value);
    void clearToZero(const GlTexture& t);  // GL leaves new storage undefined; soft starts from zeros
    ProgramSlot& internalProgram(std::optional<ProgramSlot>& slot, const char* name, const std::string& fragment);
    GlslTarget glsl() const { return {glMajor_, glMinor_}; }

    // gl_passes.cpp
    void applyBaseState();
    void endPassQueries();
    void validateFramebufferState();
    bool conditionPending(GLuint query) const;
    void releaseQueryObject(GLuint query);

    // gl_draw.cpp
    void drawRange(const DriverDraw& d, std::uint32_t first, std::uint32_t count, std::uint32_t baseInstance,
                   std::uint32_t instances);
    template <typename ApplyStep>
    void drawPerTriangle(const DriverDraw& d, const FailModePlan& plan, ApplyStep& applyStep);

    GlOptions options_;
    std::shared_ptr<GlContext> context_;
    GlInfo info_;
    GlTextureLimits textureLimits_;
    int glMajor_ = 4, glMinor_ = 5;
    const NativeTextures* natives_ = nullptr;  // the device's handles, for the textures a draw samples
    GlTexturePool textures_;
    NativeSlots<GlBuffer> buffers_;
    NativeSlots<GlQuery> queries_;
    NativeSlots<std::shared_ptr<const ProgramSlot>> programs_;
    std::set<GLuint> ownedTextures_, ownedBuffers_;
    std::map<GLenum, int> maxSamplesByFormat_;
    GlFramebufferCache framebuffers_;
    GlSamplerCache samplers_;
    std::optional<ProgramSlot> resolveColor_, resolveDepth_, nothing_;
    GLuint vao_ = 0, emptyVao_ = 0, identityInstance_ = 0;

    std::optional<DriverPass> pass_;
    std::vector<NativeId> targets_;  // the pass's colour attachments, packed (soft: colorTargets)
    int passWidth_ = 0, passHeight_ = 0, passSamples_ = 1, passActualSamples_ = 1;
    GLuint passFbo_ = 0, passQuery_ = 0, passCondition_ = 0;
    std::vector<PendingTiming> pendingTimings_;
    std::set<GLuint> occlusionQueries_;   // every GL query object behind a QueryHandle, live or retired
    std::vector<GLuint> retiredQueries_;  // replaced while a pending timing reads them
};

}  // namespace engine::render::gl
