// SPDX-License-Identifier: MIT
#pragma once
// The standard programs: what an engine needs for itself, brought by every backend (the soft
// backend as C++ kernels, GL as GLSL). Effects bring their own programs as data
// (program_desc.hpp, Backend::createProgram). Fragment outputs are straight-alpha RGBA.
#include <cstdint>

#include <glm/glm.hpp>

#include "engine/render/handles.hpp"
#include "engine/render/param_block.hpp"
#include "engine/render/texture.hpp"

namespace engine::render {

enum class ProgramKind : std::uint8_t {
    Flat,       // out = params.color * vertex.color * instance.tint
    OpaqueLit,  // Lambert + ambient on the base colour texture; alpha forced to 1
    MaskedLit,  // an alpha-masked surface: double-sided Lambert, alpha = texture alpha (for the
                // pipeline's alpha test or blend)
    AlphaOnly,  // the masked surface's alpha alone, replicated to rgba: no lighting, no colour
                // fetch (coverage masks: [Hathaway 2010] Listing 3.1, WBOIT's revealage)
};

const char* programKindName(ProgramKind kind);

struct DirectionalLight {
    glm::vec3 towardLight{0.3f, 0.8f, 0.5f};  // normalised by the program
    glm::vec3 color{1.0f};
    glm::vec3 ambient{0.25f};
};

// KHR_materials_unlit: no direct light and an ambient of 1, so the lit programs output the
// base colour as it is.
inline DirectionalLight unlitLight() { return {glm::vec3(0.0f, 1.0f, 0.0f), glm::vec3(0.0f), glm::vec3(1.0f)}; }

// Flat's parameter block, declared once (param_block.hpp): the struct and its uniform table.
#define ENGINE_FLAT_PARAMS(UNIFORM, DIRECTION, TEXTURE) \
    UNIFORM(glm::mat4, viewProj, glm::mat4(1.0f))       \
    UNIFORM(glm::vec4, color, glm::vec4(1.0f))
ENGINE_PARAM_BLOCK(FlatParams, ENGINE_FLAT_PARAMS);

// OpaqueLit and MaskedLit: the lit surface alone (param_block.hpp).
ENGINE_PARAM_BLOCK_ON_LIT_SURFACE(SurfaceParams, ENGINE_NO_PARAMS);

// AlphaOnly: out = (a, a, a, a) with a = saturate(texture alpha * factor * vertex alpha).
// Saturated because an alpha outside [0,1] (HDR sources) has no meaning as coverage and
// would make float masks negative or unbounded ([Turánszki 2017] saturates particle alpha alike);
// NaN saturates to 0. Its base colour is sampled as the lit surface's (glsl/base_color_sampling.glsl),
// so standardProgramDesc names that texture's uniforms as the surface names them.
#define ENGINE_ALPHA_ONLY_PARAMS(UNIFORM, DIRECTION, TEXTURE) \
    UNIFORM(glm::mat4, viewProj, glm::mat4(1.0f))             \
    UNIFORM(float, alphaFactor, 1.0f)                         \
    TEXTURE(baseColor, Sampled, Sampled, Optional) /* null: alpha from the factor and vertex alone */
ENGINE_PARAM_BLOCK(AlphaOnlyParams, ENGINE_ALPHA_ONLY_PARAMS);

// Which program a pipeline runs: one of the standard programs every backend brings
// (standard_programs.hpp), or one a module created with Backend::createProgram.
struct ProgramRef {
    ProgramKind standard = ProgramKind::Flat;
    ProgramHandle created;  // valid: this program, else `standard`

    ProgramRef() = default;
    ProgramRef(ProgramKind kind) : standard(kind) {}       // NOLINT: implicit by design
    ProgramRef(ProgramHandle handle) : created(handle) {}  // NOLINT: implicit by design
    friend bool operator==(const ProgramRef&, const ProgramRef&) = default;
};

}  // namespace engine::render
