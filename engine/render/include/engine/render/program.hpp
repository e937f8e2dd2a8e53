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
    WboitAccumulate,  // FoliageColor's colour, weighted for blended OIT (McGuire & Bavoil 2013)
    WboitResolve,     // full-screen: weighted average over the opaque colour by revealage
    CoverageComposite,  // full-screen SSAM+ combination: coverage estimated from the MAX and ADD masks
    Particle,        // soft billboard into a premultiplied layer (modules/particles, seeds/003)
    LayerComposite,  // full-screen: a premultiplied layer over the colour, depth-aware upsampling
    LightShafts,     // full-screen: radial blur towards the sun of the sky seen in the depth (modules/lightshafts)
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

// WboitAccumulate (McGuire & Bavoil, "Weighted Blended Order-Independent Transparency",
// JCGT 2(2), 2013): the fragment is shaded exactly as FoliageColor shades it, straight
// (C, a), then output premultiplied and weighted, (C * a * w, a * w), for a ONE/ONE additive
// RGBA16F accumulation target. w is the paper's eq. (7):
//   w(z, a) = a * clamp(10 / (1e-5 + (|z|/5)^2 + (|z|/200)^6), 1e-2, 3e3)
// with z the view depth (clip w; 1 under an orthographic or identity projection) times
// depthScale, which maps the scene's units onto the metres eq. (7) was tuned for.
struct WboitAccumulateParams {
    glm::mat4 viewProj{1.0f};
    glm::vec4 baseColorFactor{1.0f};
    TextureBinding baseColor;
    DirectionalLight light;
    float depthScale = 1.0f;
};

// WboitResolve (McGuire & Bavoil 2013, the composite pass), one texel per pixel:
//   out = (accum.rgb / max(accum.a, 1e-5), revealage.r)
// blended ONE_MINUS_SRC_ALPHA / SRC_ALPHA onto the opaque colour:
//   result = average * (1 - revealage) + opaque * revealage.
// Non-finite components come out as 0 (as Composite's).
struct WboitResolveParams {
    TextureHandle accumulation;  // RGBA16F: sum of (C * a * w, a * w)
    TextureHandle revealage;     // r: product of (1 - a), cleared to 1
};

// How CoverageComposite turns the MAX mask m and the ADD mask s (sum of the layers' alphas,
// unclamped: a float mask) into the covered fraction of the pixel, 1 - prod(1 - a_i):
enum class CoverageModel : std::uint8_t {
    // n = s / m layers all of alpha m: 1 - (1 - m)^(s / m). Exact when the layers share one
    // alpha, and exact for one layer (s = m); between the paper's MAX (too low) and ADD (too high).
    EqualLayers,
    // Many thin layers (Poisson): 1 - exp(-s).
    Exponential,
};

// CoverageComposite (SSAM+, modules/transparency): as Composite, one texel per pixel,
//   out = (foliage.rgb, coverage(mask.r, ADD)), ADD = maskAdd.r when given, else mask.a,
// coverage clamped to [0,1] (NaN -> 0), non-finite foliage components as 0; the pipeline
// blends it SRC_ALPHA / INV_SRC_ALPHA onto the opaque colour.
struct CoverageCompositeParams {
    TextureHandle foliage;
    TextureHandle mask;
    TextureHandle maskAdd;
    CoverageModel model = CoverageModel::EqualLayers;
};

// Particle (modules/particles): a camera-facing quad whose vertex carries the particle's
// straight colour and alpha (color), its view distance (normal.x) and how additive it is
// (normal.y: 0 alpha-blended .. 1 additive); uv spans the quad, the shape is a round falloff.
// Output is PREMULTIPLIED so alpha-blended and additive particles share one layer under
// BlendState::premultipliedOver() (seeds/003):
//   a = saturate(color.a) * shape(uv) * fade,  out = (color.rgb * a, a * (1 - additive))
// Soft particles: fade = saturate((sceneDistance - particleDistance) / softness), where the
// scene distance is read from `sceneDepth` (the opaque + foliage depth) at this pixel; with
// depthStride 2 the layer is half resolution and the closest of the 2x2 depth texels is used
// (closest-sample downsample, seeds/000 §3.5.1). distance = depthScale / (depth + depthOffset)
// (for a perspective projection P: depthScale = P[3][2], depthOffset = P[2][2]). Non-finite
// values output 0.
struct ParticleParams {
    glm::mat4 viewProj{1.0f};
    TextureHandle sceneDepth;  // D32F or R32F, full resolution
    int depthStride = 1;       // 1: full-resolution layer, 2: half
    float depthScale = 1.0f;
    float depthOffset = 0.0f;
    float softness = 0.5f;     // metres over which a particle fades into the scene behind it
    bool greaterIsCloser = false;  // reverse-Z (CompareFunc::Greater)
};

// LayerComposite: out = the premultiplied layer texel (alpha saturated, non-finite -> 0),
// blended with BlendState::premultipliedOver(). layerScale 2: the layer is half resolution
// and each pixel takes, of the 2x2 nearest layer texels, the one whose closest-sample depth
// is nearest in distance to this pixel's depth, so a layer texel never bleeds across a
// foliage edge (a halo) — a nearest-depth upsample.
struct LayerCompositeParams {
    TextureHandle layer;
    TextureHandle sceneDepth;  // full resolution (layerScale 2 only)
    int layerScale = 1;
    float depthScale = 1.0f;
    float depthOffset = 0.0f;
    bool greaterIsCloser = false;
};

// LightShafts (modules/lightshafts): screen-space light scattering. The occlusion image is
// the depth itself: a texel is lit sky where it still holds the clear value `farDepth`
// (nothing opaque or foliage drawn there). For each pixel p, `samples` points march from p
// towards the sun's pixel `sunPixel` (a fraction `density` of the way), weighted by decay^i:
//   out = (color * intensity * sum(decay^i * sky(q_i)) / samples, 0)
// to be added over the frame (ONE/ONE on RGB). Non-finite results output 0.
struct LightShaftParams {
    TextureHandle depth;       // D32F or R32F, the target's size
    glm::vec2 sunPixel{0.0f};  // the sun's position in pixels (may be off screen)
    float farDepth = 1.0f;     // the depth clear value (0 for reverse-Z)
    bool greaterIsCloser = false;
    glm::vec3 color{1.0f, 0.95f, 0.8f};
    float intensity = 0.35f;
    float decay = 0.96f;
    float density = 0.8f;
    int samples = 32;          // 1..128
    // The occlusion image is the sun's glow where sky shows (GPU Gems 3 ch. 13 draws the sun
    // as a bright disc): a sky sample at distance d from the sun weighs (1 - d/glowRadius)^2.
    // 0: every sky pixel glows alike.
    float glowRadius = 0.0f;   // pixels
};

using ProgramParams = std::variant<FlatParams, SurfaceParams, AlphaOnlyParams, CompositeParams, WboitAccumulateParams,
                                   WboitResolveParams, CoverageCompositeParams, ParticleParams, LayerCompositeParams,
                                   LightShaftParams>;

// Which ProgramParams alternative a kind takes.
constexpr std::size_t paramsIndexFor(ProgramKind kind) {
    switch (kind) {
        case ProgramKind::Flat: return 0;
        case ProgramKind::OpaqueLit:
        case ProgramKind::FoliageColor: return 1;
        case ProgramKind::FoliageAlpha: return 2;
        case ProgramKind::Composite: return 3;
        case ProgramKind::WboitAccumulate: return 4;
        case ProgramKind::WboitResolve: return 5;
        case ProgramKind::CoverageComposite: return 6;
        case ProgramKind::Particle: return 7;
        case ProgramKind::LayerComposite: return 8;
        case ProgramKind::LightShafts: return 9;
    }
    return 0;
}

// Composite reads its textures itself and needs no vertex input.
constexpr bool isFullscreen(ProgramKind kind) {
    return kind == ProgramKind::Composite || kind == ProgramKind::WboitResolve || kind == ProgramKind::CoverageComposite ||
           kind == ProgramKind::LayerComposite || kind == ProgramKind::LightShafts;
}

}  // namespace engine::render
