// SPDX-License-Identifier: MIT
#pragma once
// How a soft program resolves the texture handles its parameters name (program_kernel.hpp).
#include "engine/render/handles.hpp"
#include "engine/render/kernel/sampler.hpp"
#include "engine/render/kernel/soft_texture.hpp"

namespace engine::render::soft {

class TextureLookup {
public:
    virtual ~TextureLookup() = default;
    virtual const SoftTexture* texture(TextureHandle handle) const = 0;  // null for a null handle

    // The backend's sampleTexture<All>, for a program compiled where the soft backend is not linked
    // (a module whose host may draw only on GL): its kernel samples through this pointer instead of
    // instantiating the sampler itself. Null where no backend provides it (a test's lookup).
    using SampleFunction = glm::vec4 (*)(const SoftTexture&, const SamplerState&, glm::vec2, const UvDerivatives&);
    virtual SampleFunction sampleFunction() const { return nullptr; }
};

}  // namespace engine::render::soft
