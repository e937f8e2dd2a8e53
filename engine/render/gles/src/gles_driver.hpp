// SPDX-License-Identifier: MIT
#pragma once
// The OpenGL ES 3.0 driver's class (gles_backend.hpp says what differs from GL 4.5), whose
// members are defined by concern:
//   gles_driver.cpp     the context and its extensions, the vertex array, tear-down
//   gles_resources.cpp  textures and renderbuffers, buffers, programs, pipelines, queries
//   gles_passes.cpp     passes (framebuffer, clears, queries), resolves, timings
//   gles_readback.cpp   readback through glReadPixels
//   gles_draw.cpp       one draw: its fixed-function state, the fail-mode steps, the GL calls
//   gles_present.cpp    the finished frame shown in the context's window (the web page's canvas)
// The shared pieces (formats and enums, error checks, program building and parameters, sampler
// and framebuffer caches) are the GL 4.5 driver's.
#include <chrono>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "gl_api.hpp"

#include "engine/render/driver.hpp"
#include "engine/render/gles/gles_backend.hpp"
#include "engine/render/native_slots.hpp"
#include "gl_caches.hpp"
#include "gl_objects.hpp"
#include "gl_program_slot.hpp"
#include "gl_texture_limits.hpp"

namespace engine::render::gles {

using gl::GlBuffer;
using gl::GlQuery;
using gl::GlTexture;
using gl::ProgramSlot;

// What the context offers beyond ES 3.0 that the driver uses (each refused by name when a
// resource or draw needs it and it is missing).
struct GlesExtensions {
    bool clipControl = false;         // EXT_clip_control: else remapped in the vertex stage (glslEs)
    bool colorBufferFloat = false;    // EXT_color_buffer_float: render to 16F/32F
    bool floatBlend = false;          // EXT_float_blend: blend into 32F
    bool drawBuffersIndexed = false;  // OES_draw_buffers_indexed: blend state per target
    bool gpuShader5 = false;          // EXT_gpu_shader5: `precise`
    bool floatLinear = false;         // OES_texture_float_linear: filter 32F
};

// Framebuffer attachments are named by their GL names; a renderbuffer's (multisampled targets:
// ES 3.0 has no multisampled textures) carries this bit, the two namespaces being separate.
inline constexpr GLuint kRenderbufferBit = 0x80000000u;
// The framebuffer cache's maker (gl_caches.hpp) for ES: bound, attached, checked.
GLuint makeBoundFramebuffer(const std::vector<GLuint>& colors, GLuint depth, const std::string& what);

// A compiled program and the locations of its textures' level counts (glslEs), one per
// GlslProgram::textures entry (-1: not read).
struct GlesProgram {
    std::shared_ptr<const ProgramSlot> slot;
    std::vector<GLint> levels;
};

class GlesDriver final : public Driver {
public:
    GlesDriver(const GlesOptions& options, std::shared_ptr<gl::GlContext> context);
    ~GlesDriver() override;

    std::string name() const override { return "gles"; }
    std::string describe() const override;
    void attach(const NativeTextures& textures) override { natives_ = &textures; }
    FailModeEmulation failModeEmulation() const override {
        return options_.failModes == gl::FailModeStrategy::PerTriangle ? FailModeEmulation::PerTriangle
                                                                       : FailModeEmulation::TwoPass;
    }

    // gles_resources.cpp
    void checkTexture(const TextureDesc& desc, const TextureData* data, const std::string& what) override;
    void notePipeline(const PipelineDesc& desc, ResolvedPipeline& resolved) override;
    NativeId createQuery(const std::string&) override { return queries_.add({}); }

    // The driver calls: resources and queries in gles_resources.cpp, passes, resolves and
    // timings in gles_passes.cpp, readbacks in gles_readback.cpp, draws in gles_draw.cpp.
    ENGINE_DRIVER_CALLS(ENGINE_DRIVER_OVERRIDE)
    std::string whyNoClosestDepthResolve() const override;  // gles_passes.cpp

    // gles_present.cpp
    bool present(NativeId h, const TextureDesc& desc) override;

private:
    void makeCurrent() {
        if (context_) context_->makeCurrent();
    }

    // gles_resources.cpp
    int maxSamplesFor(GLenum internal);
    // Whether occlusion query `id` counted any sample (gles_resources.cpp says when it waits).
    bool samplesPassed(GLuint id);
    GlesProgram compile(std::shared_ptr<const ProgramDesc> desc);
    void upload(const GlTexture& t, const TextureData& data);
    void fill(const GlTexture& t, const glm::vec4& value);  // every texel of level 0 (or all levels: zero)
    void fillLevels(const GlTexture& t, int levels, const std::vector<std::byte>& texel);
    // A framebuffer name for an attachment: renderbuffers are marked (kRenderbufferBit).
    GLuint attachment(const GlTexture& t) const;
    static void deleteStorage(const GlTexture& t);  // its texture or renderbuffer

    // gles_passes.cpp
    void applyBaseState();
    void releaseQueryObject(GLuint query);

    // gles_present.cpp: an sRGB frame's stored codes in a linear RGBA8 texture (why: there)
    GLuint linearCopy(const GlTexture& t, const std::string& what);

    // gles_draw.cpp
    void bindVertices(const DriverDraw& d, std::uint32_t firstInstance);
    void drawRange(const DriverDraw& d, std::uint32_t first, std::uint32_t count, std::uint32_t instances);
    void applyBlend(const DriverDraw& draw);
    void refuseUnfilterable(const GlesProgram& program, const DriverDraw& draw);
    void setLevels(const GlesProgram& program, const DrawParams& params);

    GlesOptions options_;
    std::shared_ptr<gl::GlContext> context_;
    std::string renderer_, version_;
    GlesExtensions extensions_;
    gl::GlTextureLimits textureLimits_;
    const NativeTextures* natives_ = nullptr;
    gl::GlTexturePool textures_;
    NativeSlots<GlBuffer> buffers_;
    NativeSlots<GlQuery> queries_;
    NativeSlots<GlesProgram> programs_;
    std::map<GLenum, int> maxSamplesByFormat_;
    gl::GlFramebufferCache framebuffers_;
    gl::GlSamplerCache samplers_;
    std::optional<ProgramSlot> depthToColor_;  // readback of depth: ES 3.0 cannot glReadPixels it
    GLuint vao_ = 0, emptyVao_ = 0, identityInstance_ = 0;
    struct PresentCopy {  // gles_present.cpp
        GLuint pixels = 0, texture = 0;
        int width = 0, height = 0;
    } presentCopy_;

    std::optional<DriverPass> pass_;
    std::vector<NativeId> targets_;  // the pass's colour attachments, packed
    int passWidth_ = 0, passHeight_ = 0, passActualSamples_ = 1;
    GLuint passFbo_ = 0;
    bool passSkipped_ = false;  // its drawOnlyIfSamplesIn query counted no sample
    std::chrono::steady_clock::time_point passStart_;
    std::vector<DriverTiming> timings_;
};

}  // namespace engine::render::gles
