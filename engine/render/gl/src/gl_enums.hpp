// SPDX-License-Identifier: MIT
#pragma once
// The backend's formats and fixed-function state as GL enums.
#include "gl_api.hpp"

#include "engine/render/blend_state.hpp"
#include "engine/render/compare_func.hpp"
#include "engine/render/format.hpp"
#include "engine/render/texture.hpp"

namespace engine::render::gl {

struct GlFormat {
    GLenum internal;
    GLenum pixelFormat;  // of client data
    GLenum storedType;   // type of the stored layout we upload (16F: half floats)
    GLenum readType;     // type we read back (normalized: bytes, float formats: floats)
};

GlFormat glFormat(Format format);
GLenum glBlendFactor(BlendFactor factor);
GLenum glBlendOp(BlendOp op);
GLenum glCompare(CompareFunc func);
GLenum glWrap(AddressMode mode);

}  // namespace engine::render::gl
