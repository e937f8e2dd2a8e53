// SPDX-License-Identifier: MIT
#pragma once
// Everything the tile loop needs about one recorded draw, resolved once per pass:
// targets, effective fixed-function state (after creation-time simplification) and the
// program instance.
#include <array>
#include <memory>

#include "engine/render/fragment_capture.hpp"
#include "engine/render/kernel/simd_isa.hpp"
#include "engine/render/kernel/soft_texture.hpp"
#include "engine/render/pipeline.hpp"

namespace engine::render::soft {

class BoundProgram;      // program_kernel.hpp
class DepthBlockBounds;  // depth_block_bounds.hpp

// Standard sample positions (D3D11 / Vulkan standard locations), in 1/16 pixel from the
// pixel centre. GL leaves them to the implementation; README "Differential tolerances".
struct SamplePattern {
    int count = 1;
    std::array<int, 8> dx{}, dy{};
};

struct DrawState {
    std::shared_ptr<const BoundProgram> program;  // the draw's program, bound to its parameters
    std::array<SoftTexture*, kMaxColorTargets> colorTargets{};
    int colorTargetCount = 0;
    SoftTexture* depthTarget = nullptr;
    int samples = 1;
    const SamplePattern* pattern = nullptr;

    bool depthTest = false;
    bool depthWrite = false;
    CompareFunc depthFunc = CompareFunc::Less;
    AlphaTest alphaTest;  // enabled only when it can change the result
    bool alphaToCoverage = false;
    std::array<BlendState, kMaxColorTargets> blend{};
    std::array<bool, kMaxColorTargets> blendNeeded{};  // false: plain store
    glm::vec4 blendConstant{0.0f};
    bool shade = true;                // false: depth-only, the program is never run
    FragmentSink* capture = nullptr;  // set: fragments go here, nothing is written (FragmentCapture::setFragmentSink)
    SimdIsa isa = SimdIsa::Sse2;      // the wide kernels' instruction set (SoftOptions::simd)
    // Set where no draw of the pass writes the depth it tests (SoftOptions::depthBlockBounds).
    const DepthBlockBounds* depthBounds = nullptr;
};

}  // namespace engine::render::soft
