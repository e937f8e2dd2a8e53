// SPDX-License-Identifier: MIT
#pragma once
// What the GL backend keeps behind its handles.
#include <cstdint>
#include <string>
#include <vector>

#include "gl_api.hpp"

#include "engine/render/buffer.hpp"
#include "engine/render/native_slots.hpp"
#include "engine/render/texture.hpp"

namespace engine::render::gl {

struct GlTexture {
    TextureDesc desc;
    GLuint id = 0;
    int actualSamples = 1;  // what GL allocated (llvmpipe makes 2x into 4x)
    bool imported = false;
};
using GlTexturePool = NativeSlots<GlTexture>;

struct GlBuffer {
    GLuint id = 0;
    // Where the GLES driver binds it to write: WebGL2 lets an index buffer be bound nowhere but
    // GL_ELEMENT_ARRAY_BUFFER, and any other buffer never there (WebGL 2.0 §5.1).
    GLenum uploadTarget = GL_COPY_WRITE_BUFFER;
};

// An occlusion query handle's GL query object (GL_ANY_SAMPLES_PASSED), made at the first
// pass that counts into it.
struct GlQuery {
    GLuint id = 0;
};

// A pass's timer query, read by takeTimings.
struct PendingTiming {
    std::uint64_t serial = 0;  // the pass's DriverPass::serial
    GLuint query = 0;
    GLuint condition = 0;  // the pass's drawOnlyIfSamplesIn query object, read for `skipped`
};

}  // namespace engine::render::gl
