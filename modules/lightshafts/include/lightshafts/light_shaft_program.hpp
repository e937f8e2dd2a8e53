// SPDX-License-Identifier: MIT
#pragma once
// The light-shaft program: screen-space light scattering (GPU Gems 3 ch. 13) over a frame
// whose occlusion image is its depth; [Hathaway 2010] §3.7 lists light shafts among the
// passes that follow the foliage and depth-test against its depth. Described once for every
// backend (engine/render/program_desc.hpp): its parameter block declared once below
// (engine/render/param_block.hpp), the GLSL body in glsl/, the CPU kernel in light_shaft_kernel.hpp.
//
// Full screen, one output per pixel p: `samples` points q_i march from p towards the sun's
// pixel `sunPixel` (a fraction `density` of the way), weighted by decay^i:
//   out = (color * intensity * sum(decay^i * sky(q_i) * glow(q_i)) / samples, 0)
// to be added over the frame (ONE/ONE on RGB). A texel is sky where the depth still holds the
// clear value `farDepth`. Non-finite results output 0.
#include <glm/glm.hpp>

#include "engine/render/param_block.hpp"
#include "engine/render/program_desc.hpp"
#include "engine/render/texture.hpp"

namespace lightshafts {

// glowRadius: the occlusion image is the sun's glow where sky shows (GPU Gems 3 ch. 13 draws
// the sun as a bright disc): a sky sample at distance d from the sun weighs (1 - d/glowRadius)^2;
// 0: every sky pixel glows alike.
#define LIGHTSHAFTS_PARAMS(UNIFORM, DIRECTION, TEXTURE)                                                  \
    TEXTURE(depth, Texel, FullSize, Required)     /* D32F or R32F, the target's size */                  \
    UNIFORM(glm::vec2, sunPixel, glm::vec2(0.0f)) /* the sun's position in pixels (may be off screen) */ \
    UNIFORM(float, farDepth, 1.0f)                /* the depth clear value (0 for reverse-Z) */          \
    UNIFORM(bool, greaterIsCloser, false)                                                                \
    UNIFORM(glm::vec3, color, glm::vec3(1.0f, 0.95f, 0.8f))                                              \
    UNIFORM(float, intensity, 0.35f)                                                                     \
    UNIFORM(float, decay, 0.96f)                                                                         \
    UNIFORM(float, density, 0.8f)                                                                        \
    UNIFORM(int, samples, 32)        /* 1..128 */                                                        \
    UNIFORM(float, glowRadius, 0.0f) /* pixels */
ENGINE_PARAM_BLOCK(LightShaftParams, LIGHTSHAFTS_PARAMS);

// For Backend::createProgram. Draws are checked for: a D32F or R32F depth of at least the
// target's size, samples in 1..128, finite parameters.
engine::render::ProgramDesc lightShaftProgram();

}  // namespace lightshafts
