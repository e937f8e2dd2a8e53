// SPDX-License-Identifier: MIT
#include "gl_texture_limits.hpp"

#include "gl_api.hpp"

#include <algorithm>
#include <cstdint>
#include <vector>

#include "engine/core/error.hpp"

namespace engine::render::gl {

namespace {

// Extension enums, not in every GL header.
constexpr GLenum kGpuMemoryCurrentAvailableNvx = 0x9049;  // GL_NVX_gpu_memory_info, KiB
constexpr GLenum kTextureFreeMemoryAti = 0x87FC;          // GL_ATI_meminfo, KiB (4 values: the first is the total free)

bool rendersOnTheCpu(const std::string& renderer) {
    for (const char* name : {"llvmpipe", "softpipe", "swrast"})
        if (renderer.find(name) != std::string::npos) return true;
    return false;
}

MemoryProbe memoryProbe(const std::string& renderer) {
    if (rendersOnTheCpu(renderer)) return hostMemoryAvailable;
    if (glHasExtension("GL_NVX_gpu_memory_info"))
        return []() -> std::optional<AvailableMemory> {
            GLint kib = 0;
            glGetIntegerv(kGpuMemoryCurrentAvailableNvx, &kib);
            if (kib <= 0) return std::nullopt;
            return AvailableMemory{std::uint64_t(kib) << 10, "GL_NVX_gpu_memory_info's available video memory"};
        };
    if (glHasExtension("GL_ATI_meminfo"))
        return []() -> std::optional<AvailableMemory> {
            GLint kib[4] = {};
            glGetIntegerv(kTextureFreeMemoryAti, kib);
            if (kib[0] <= 0) return std::nullopt;
            return AvailableMemory{std::uint64_t(kib[0]) << 10, "GL_ATI_meminfo's free texture memory"};
        };
    return {};
}

}  // namespace

GlTextureLimits queryGlTextureLimits(const std::string& renderer, bool es) {
    GlTextureLimits limits;
    limits.renderer = renderer;
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &limits.maxTextureSize);
    if (es) {
        glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &limits.maxFramebufferWidth);
        limits.maxFramebufferHeight = limits.maxFramebufferWidth;
    }
#if !defined(__EMSCRIPTEN__)  // desktop GL's limits (the web build's ES headers have none)
    else {
        glGetIntegerv(GL_MAX_FRAMEBUFFER_WIDTH, &limits.maxFramebufferWidth);
        glGetIntegerv(GL_MAX_FRAMEBUFFER_HEIGHT, &limits.maxFramebufferHeight);
    }
#endif
    limits.memory = memoryProbe(renderer);
    return limits;
}

int maxSamplesOf(unsigned int target, unsigned int internal) {
    GLint count = 0;
#if defined(__EMSCRIPTEN__)
    // WebGL2 answers GL_SAMPLES only (the counts themselves, never their number): as many as fit
    // in 16 entries, the rest left 0.
    count = 16;
#else
    glGetInternalformativ(target, internal, GL_NUM_SAMPLE_COUNTS, 1, &count);
#endif
    std::vector<GLint> counts(std::size_t(std::max(count, 0)));
    if (count > 0) glGetInternalformativ(target, internal, GL_SAMPLES, count, counts.data());
    int best = 1;
    for (GLint c : counts) best = std::max(best, int(c));
    return best;
}

void checkGlTextureFits(const TextureDesc& desc, const std::string& what, const GlTextureLimits& limits) {
    const std::string by = " (" + limits.renderer + ")";
    if (desc.width > limits.maxTextureSize || desc.height > limits.maxTextureSize)
        throw Error(what + ": " + describeSize(desc) + " exceeds this GL implementation's GL_MAX_TEXTURE_SIZE of " +
                    std::to_string(limits.maxTextureSize) + by);
    if ((desc.usage & UsageRenderTarget) &&
        (desc.width > limits.maxFramebufferWidth || desc.height > limits.maxFramebufferHeight))
        throw Error(
            what + ": render target " + describeSize(desc) + " exceeds this GL implementation's framebuffer limit of " +
            std::to_string(limits.maxFramebufferWidth) + "x" + std::to_string(limits.maxFramebufferHeight) + by);
}

}  // namespace engine::render::gl
