// SPDX-License-Identifier: MIT
#pragma once
// The texture handles a draw's parameters name, read as its program's layout declares them:
// what validation checks and what the device keeps alive for the open pass.
#include <cstddef>
#include <cstring>

#include "engine/render/draw_params.hpp"
#include "engine/render/program_desc.hpp"

namespace engine::render {

// Calls f(field, handle) for each texture field, null handles included (a TextureBinding's
// first member is its handle).
template <typename F>
void forEachTextureParam(const ProgramDesc& program, const DrawParams& params, F&& f) {
    const auto* bytes = static_cast<const std::byte*>(params.data());
    for (const TextureField& field : program.gl.textures) {
        TextureHandle handle;
        std::memcpy(&handle, bytes + field.offset, sizeof handle);
        f(field, handle);
    }
}

}  // namespace engine::render
