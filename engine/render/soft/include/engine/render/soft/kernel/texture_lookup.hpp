// SPDX-License-Identifier: MIT
#pragma once
// How a soft program resolves the texture handles its parameters name (program_kernel.hpp).
#include "engine/render/handles.hpp"
#include "engine/render/soft/kernel/soft_texture.hpp"

namespace engine::render::soft {

class TextureLookup {
public:
    virtual ~TextureLookup() = default;
    virtual const SoftTexture* texture(TextureHandle handle) const = 0;  // null for a null handle
};

}  // namespace engine::render::soft
