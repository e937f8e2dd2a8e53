// SPDX-License-Identifier: MIT
#pragma once
// The particle module's two programs, described once for every backend
// (engine/render/program_desc.hpp): each parameter block declared once below (the struct, the
// uniform and texture table and the GLSL samplers come from it: engine/render/param_block.hpp),
// the GLSL bodies in glsl/, the CPU kernels in particle_kernels.hpp.
#include <glm/glm.hpp>

#include "engine/render/param_block.hpp"
#include "engine/render/program_desc.hpp"
#include "engine/render/texture.hpp"

namespace particles {

// Particle: a camera-facing quad whose vertex carries the particle's straight colour and
// alpha (color), its view distance (normal.x) and how additive it is (normal.y: 0
// alpha-blended .. 1 additive); uv spans the quad, the shape is a round falloff. Output is
// PREMULTIPLIED so alpha-blended and additive particles share one layer under
// BlendState::premultipliedOver() ([Turánszki 2017]):
//   a = saturate(color.a) * shape(uv) * fade,  out = (color.rgb * a, a * (1 - additive))
// Soft particles: fade = saturate((sceneDistance - particleDistance) / softness), where the
// scene distance is read from `sceneDepth` (the opaque + foliage depth) at this pixel; with
// depthStride 2 the layer is half resolution and the closest of the 2x2 depth texels is used
// (closest-sample downsample, [Hathaway 2010] §3.5.1). distance = depthScale / (depth +
// depthOffset) (for a perspective projection P: depthScale = P[3][2], depthOffset = P[2][2]).
// Non-finite values output 0.
#define PARTICLES_PARTICLE_PARAMS(UNIFORM, DIRECTION, TEXTURE)                                              \
    UNIFORM(glm::mat4, viewProj, glm::mat4(1.0f))                                                           \
    TEXTURE(sceneDepth, Texel, Sampled, Optional) /* D32F or R32F, full resolution */                       \
    UNIFORM(int, depthStride, 1)                  /* 1: full-resolution layer, 2: half */                   \
    UNIFORM(float, depthScale, 1.0f)                                                                        \
    UNIFORM(float, depthOffset, 0.0f)                                                                       \
    UNIFORM(float, softness, 0.5f)        /* metres over which a particle fades into the scene behind it */ \
    UNIFORM(bool, greaterIsCloser, false) /* reverse-Z (CompareFunc::Greater) */
ENGINE_PARAM_BLOCK(ParticleParams, PARTICLES_PARTICLE_PARAMS);

// LayerComposite: out = the premultiplied layer texel (alpha saturated, non-finite -> 0),
// blended with BlendState::premultipliedOver(). layerScale 2: the layer is half resolution
// and each pixel takes, of the 2x2 nearest layer texels, the one whose closest-sample depth
// is nearest in distance to this pixel's depth, so a layer texel never bleeds across a
// foliage edge (a halo) — a nearest-depth upsample.
#define PARTICLES_LAYER_COMPOSITE_PARAMS(UNIFORM, DIRECTION, TEXTURE)                        \
    TEXTURE(layer, Texel, Sampled, Required)                                                 \
    TEXTURE(sceneDepth, Texel, FullSize, Optional) /* full resolution (layerScale 2 only) */ \
    UNIFORM(int, layerScale, 1)                                                              \
    UNIFORM(float, depthScale, 1.0f)                                                         \
    UNIFORM(float, depthOffset, 0.0f)                                                        \
    UNIFORM(bool, greaterIsCloser, false)
ENGINE_PARAM_BLOCK(LayerCompositeParams, PARTICLES_LAYER_COMPOSITE_PARAMS);

// For Backend::createProgram. Particle draws are checked for depthStride 1 or 2, a finite
// softness > 0 and finite depth factors; layer composites for layerScale 1 or 2, a layer of at
// least the target's size / layerScale, a scene depth of the target's size when given.
engine::render::ProgramDesc particleProgram();
engine::render::ProgramDesc layerCompositeProgram();

}  // namespace particles
