// SPDX-License-Identifier: MIT
#pragma once
// What this GL implementation can allocate, asked once when the backend starts: its texture and
// framebuffer size limits (below the engine's 16384 on some hardware) and where its memory
// figure comes from. createTexture checks a texture against them before glTextureStorage2D,
// so a size the driver cannot hold is refused by name rather than by a GL error or an
// out-of-memory kill (memory_budget.hpp).
#include <string>

#include "engine/render/memory_budget.hpp"
#include "engine/render/texture.hpp"

namespace engine::render::gl {

struct GlTextureLimits {
    std::string renderer;                                   // GL_RENDERER, for messages
    int maxTextureSize = 0;                                 // GL_MAX_TEXTURE_SIZE
    int maxFramebufferWidth = 0, maxFramebufferHeight = 0;  // GL_MAX_FRAMEBUFFER_WIDTH / _HEIGHT
    // A software rasterizer (llvmpipe, softpipe) keeps textures in host memory; a GPU says how
    // much video memory it has left through GL_NVX_gpu_memory_info or GL_ATI_meminfo, or
    // nothing (then GL_OUT_OF_MEMORY is the only answer, which checkGl turns into an error).
    MemoryProbe memory;
};

// Needs the backend's context current. `es`: an OpenGL ES 3.0 context, which has no
// GL_MAX_FRAMEBUFFER_WIDTH (ES 3.1): its render targets are bounded by GL_MAX_RENDERBUFFER_SIZE.
GlTextureLimits queryGlTextureLimits(const std::string& renderer, bool es = false);

// The most samples `internal` offers for `target` (GL_TEXTURE_2D_MULTISAMPLE on GL 4.5,
// GL_RENDERBUFFER on ES 3.0), 1 when none; needs the context current.
int maxSamplesOf(unsigned int target, unsigned int internal);

// Throws engine::Error naming `what`, the size and the limit when `desc` exceeds one of them.
void checkGlTextureFits(const TextureDesc& desc, const std::string& what, const GlTextureLimits& limits);

}  // namespace engine::render::gl
