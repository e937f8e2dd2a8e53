#pragma once
// Programs are a small set of named kinds, each with a parameter struct (DESIGN.md
// "Backend interface"). Every backend implements every kind: the soft backend as
// specialised C++, GL as GLSL. Fragment outputs are straight-alpha RGBA unless stated.
#include <cstdint>
#include <variant>

#include <glm/glm.hpp>

#include "engine/render/texture.hpp"

namespace engine::render {

enum class ProgramKind : std::uint8_t {
    Flat,          // out = params.color * vertex.color * instance.tint
    OpaqueLit,     // Lambert + ambient on the base colour texture; alpha forced to 1
    FoliageColor,  // double-sided Lambert; alpha = texture alpha (alpha-tested by the pipeline)
    FoliageAlpha,  // alpha only, replicated to rgba (seeds/000 Listing 3.1): no lighting, no colour fetch
    Composite,     // full-screen SSAM combination (seeds/000 Listing 3.2)
};

const char* programKindName(ProgramKind kind);

struct DirectionalLight {
    glm::vec3 towardLight{0.3f, 0.8f, 0.5f};  // normalised by the program
    glm::vec3 color{1.0f};
    glm::vec3 ambient{0.25f};
};

struct FlatParams {
    glm::mat4 viewProj{1.0f};
    glm::vec4 color{1.0f};
};

// OpaqueLit and FoliageColor.
struct SurfaceParams {
    glm::mat4 viewProj{1.0f};
    glm::vec4 baseColorFactor{1.0f};
    TextureBinding baseColor;  // null texture: white
    DirectionalLight light;
};

// FoliageAlpha: out = (a, a, a, a) with a = saturate(texture alpha * factor * vertex alpha).
// Saturated because an alpha outside [0,1] (HDR sources) has no meaning as coverage and
// would make float masks negative or unbounded (seeds/003 saturates particle alpha alike);
// NaN saturates to 0.
struct AlphaOnlyParams {
    glm::mat4 viewProj{1.0f};
    float alphaFactor = 1.0f;
    TextureBinding baseColor;
};

// Composite (seeds/000 §3.5.4, §3.6.2, Listing 3.2), one texel per pixel:
//   mask = lerp(mask.r (MAX), mask.a (ADD), maskLerp), squared when squareMask
//   out  = (foliage.rgb, mask), non-finite foliage components output as 0
// The pipeline blends it onto the opaque colour with SRC_ALPHA / INV_SRC_ALPHA, which is
// Listing 3.2's lerp(opaque, foliage, mask) done by the blend unit, as §3.5 describes the
// post-process ("resembles frame-buffer blending ... SRCALPHA and INVSRCALPHA"). Composing
// in place lets a scissor limit the work to the foliage's screen bounds.
struct CompositeParams {
    TextureHandle foliage;
    TextureHandle mask;     // r = MAX mask, a = ADD mask (one RGBA target)
    TextureHandle maskAdd;  // optional: ADD mask in its own R target (then `mask` holds MAX in r)
    float maskLerp = 0.85f;
    bool squareMask = true;
};

using ProgramParams = std::variant<FlatParams, SurfaceParams, AlphaOnlyParams, CompositeParams>;

// Which ProgramParams alternative a kind takes.
constexpr std::size_t paramsIndexFor(ProgramKind kind) {
    switch (kind) {
        case ProgramKind::Flat: return 0;
        case ProgramKind::OpaqueLit:
        case ProgramKind::FoliageColor: return 1;
        case ProgramKind::FoliageAlpha: return 2;
        case ProgramKind::Composite: return 3;
    }
    return 0;
}

// Composite reads its textures itself and needs no vertex input.
constexpr bool isFullscreen(ProgramKind kind) { return kind == ProgramKind::Composite; }

}  // namespace engine::render
