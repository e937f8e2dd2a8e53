// SPDX-License-Identifier: MIT
#pragma once
// What the GL backend keeps behind its handles.
#include <cstdint>
#include <string>
#include <vector>

#include <epoxy/gl.h>

#include "engine/render/buffer.hpp"
#include "engine/render/resource_pool.hpp"
#include "engine/render/texture.hpp"

namespace engine::render::gl {

struct GlTexture {
    TextureDesc desc;
    GLuint id = 0;
    int actualSamples = 1;  // what GL allocated (llvmpipe makes 2x into 4x)
    bool imported = false;
};
using GlTexturePool = ResourcePool<TextureTag, GlTexture>;

struct GlBuffer {
    BufferDesc desc;
    GLuint id = 0;
    std::vector<std::byte> shadow;  // index buffers: read only when a draw may index past its vertices
    std::uint32_t maxIndex = 0;     // index buffers: the largest index (validation's fast accept)
};

// An occlusion query handle's GL query object (GL_ANY_SAMPLES_PASSED), made at the first
// pass that counts into it.
struct GlQuery {
    std::string name;
    GLuint id = 0;
    bool counted = false;
};

// A pass's timer query, read by takeTimings.
struct PendingTiming {
    std::string pass;
    GLuint query = 0;
    GLuint condition = 0;  // the pass's drawOnlyIfSamplesIn query object, read for `skipped`
};

}  // namespace engine::render::gl
