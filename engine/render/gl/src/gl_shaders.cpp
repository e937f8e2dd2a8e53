#include "gl_shaders.hpp"

namespace engine::render::gl {
namespace {

// Vertex stage of every mesh program. Positions are computed with the soft backend's float
// operations in its order (glm: mvp = viewProj * model column by column, then
// (c0*x + c1*y) + (c2*z + c3*w)); `precise` forbids FMA contraction and reassociation, so
// the clip positions, and with them the snapped vertices, agree bit for bit.
constexpr const char* kMeshVertex = R"(#version 450 core
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec2 a_uv;
layout(location = 3) in vec4 a_color;
layout(location = 4) in vec4 a_model0;
layout(location = 5) in vec4 a_model1;
layout(location = 6) in vec4 a_model2;
layout(location = 7) in vec4 a_model3;
layout(location = 8) in vec4 a_tint;

uniform mat4 u_viewProj;

out vec2 v_uv;
out vec3 v_normal;
out vec4 v_color;
flat out int v_instance;  // see kMeshFragmentGuard

vec4 mulColumn(mat4 a, vec4 b) {
    precise vec4 r = a[0] * b.x + a[1] * b.y + a[2] * b.z + a[3] * b.w;
    return r;
}

void main() {
    mat4 model = mat4(a_model0, a_model1, a_model2, a_model3);
    mat4 mvp = mat4(mulColumn(u_viewProj, model[0]), mulColumn(u_viewProj, model[1]),
                    mulColumn(u_viewProj, model[2]), mulColumn(u_viewProj, model[3]));
    precise vec4 xy = mvp[0] * a_position.x + mvp[1] * a_position.y;
    precise vec4 zw = mvp[2] * a_position.z + mvp[3];
    precise vec4 clip = xy + zw;
    gl_Position = clip;
    v_uv = a_uv;
    v_normal = mat3(model) * a_normal;
    v_color = a_color * a_tint;
    v_instance = gl_InstanceID;
}
)";

// Full-screen programs: one triangle covering the viewport, no vertex input.
constexpr const char* kFullscreenVertex = R"(#version 450 core
void main() {
    vec2 p = vec2(float((gl_VertexID & 1) << 2) - 1.0, float((gl_VertexID & 2) << 1) - 1.0);
    gl_Position = vec4(p, 0.0, 1.0);
}
)";

// Shared tail of every program kind: alpha-to-coverage with the soft backend's rule, the
// GS alpha test as a fragment selection, and the colour broadcast to every bound target.
constexpr const char* kFragmentCommon = R"(#version 450 core
layout(location = 0) out vec4 o_color0;
layout(location = 1) out vec4 o_color1;
layout(location = 2) out vec4 o_color2;
layout(location = 3) out vec4 o_color3;

uniform int u_alphaSelect;   // 0 all fragments, 1 those passing the alpha test, 2 those failing it
uniform int u_alphaFunc;     // CompareFunc
uniform float u_alphaRef;
uniform int u_a2cSamples;    // samples of the target as created (0: alpha-to-coverage off)
uniform int u_a2cActual;     // samples GL really allocated (llvmpipe turns 2 into 4)
uniform ivec4 u_scissor;     // x0, y0, x1, y1 of the draw's scissor; x1 = 0: not checked here

float clamp01(float v) { return v > 0.0 ? (v < 1.0 ? v : 1.0) : 0.0; }

bool alphaPasses(float a) {
    switch (u_alphaFunc) {
        case 0: return false;
        case 1: return a < u_alphaRef;
        case 2: return a == u_alphaRef;
        case 3: return a <= u_alphaRef;
        case 4: return a > u_alphaRef;
        case 5: return a != u_alphaRef;
        case 6: return a >= u_alphaRef;
        default: return true;
    }
}

void finish(vec4 color) {
    // Multisampled targets: the scissor again, per pixel. llvmpipe (Mesa 22.x) tests the
    // scissor rectangle at sample positions half a pixel off and lets the column left of it
    // and the row above it through; glScissor still bounds the work.
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    if (u_scissor.z > 0 && (any(lessThan(pixel, u_scissor.xy)) || any(greaterThanEqual(pixel, u_scissor.zw)))) discard;
    int mask = -1;
    if (u_a2cSamples > 1) {
        // round(alpha * samples) samples, the first ones (tile_rasterizer.cpp); a 2x target that
        // GL made 4x covers the same fraction of its samples.
        precise float scaled = clamp01(color.a) * float(u_a2cSamples) + 0.5;
        int covered = int(scaled) * u_a2cActual / u_a2cSamples;
        mask = (1 << covered) - 1;
    }
    gl_SampleMask[0] = mask;
    if (u_alphaSelect != 0 && alphaPasses(color.a) != (u_alphaSelect == 1)) discard;
    o_color0 = color;
    o_color1 = color;
    o_color2 = color;
    o_color3 = color;
}
)";

// Mesh programs read one flat input. llvmpipe (Mesa 22.x) has a fast path for non-indexed
// draws of exactly three triangles whose last one has zero area (lp_setup_analyse_triangles,
// meant for one Windows compositor's rectangles) that draws nothing at all unless the pattern
// is that rectangle; it is skipped when the fragment shader has a flat ("constant") input.
constexpr const char* kMeshFragmentGuard = R"(
flat in int v_instance;
bool llvmpipeGuard() { return v_instance < 0; }  // never true; keeps the input alive
)";

constexpr const char* kFlatFragment = R"(
in vec4 v_color;
uniform vec4 u_color;
void main() {
    if (llvmpipeGuard()) discard;
    finish(u_color * v_color);
}
)";

constexpr const char* kSampling = R"(
// Base colour sampling. Nearest and bilinear are the sampler's (GL_NEAREST / GL_LINEAR: the
// base level only). Trilinear computes its LOD here, as the soft backend does: rho is the
// longer analytic UV derivative in texels, lambda = log2 rho, and the two nearest levels are
// lerped. GL's own LOD takes finite differences of uv and leaves precision to the
// implementation (llvmpipe quantizes the fraction); here the derivatives are analytic:
// uv/w and 1/w (gl_FragCoord.w) are linear in screen space, so their differences are exact and
// d(uv)/dx = (d(uv/w)/dx - uv * d(1/w)/dx) * w (soft: tile_rasterizer.cpp interpolate()).
uniform int u_filter;  // 0 nearest, 1 bilinear, 2 trilinear
layout(binding = 0) uniform sampler2D u_baseColor;
vec4 sampleBase(vec2 uv) {
    float inverseW = gl_FragCoord.w;
    vec2 uvOverW = uv * inverseW;
    // Linear functions: fine and coarse differences agree, so plain dFdx (GLSL 4.30) will do.
    vec2 dqdx = dFdx(uvOverW), dqdy = dFdy(uvOverW);
    float dwdx = dFdx(inverseW), dwdy = dFdy(inverseW);
    if (u_filter != 2) return texture(u_baseColor, uv);
    float w = 1.0 / inverseW;
    vec2 size = vec2(textureSize(u_baseColor, 0));
    vec2 dx = (dqdx - uv * dwdx) * w * size;
    vec2 dy = (dqdy - uv * dwdy) * w * size;
    float rho = max(length(dx), length(dy));
    float lambda = log2(rho);
    int last = textureQueryLevels(u_baseColor) - 1;
    if (!(lambda > 0.0) || last == 0) return textureLod(u_baseColor, uv, 0.0);
    if (lambda >= float(last)) return textureLod(u_baseColor, uv, float(last));
    int lo = int(lambda);
    return mix(textureLod(u_baseColor, uv, float(lo)), textureLod(u_baseColor, uv, float(lo + 1)), lambda - float(lo));
}
)";

// OpaqueLit / FoliageColor (soft: SurfaceProgram<Foliage>).
constexpr const char* kSurfaceFragment = R"(
in vec2 v_uv;
in vec3 v_normal;
in vec4 v_color;
uniform vec4 u_color;
uniform bool u_hasTexture;
uniform bool u_premultiplied;
uniform vec3 u_towardLight;  // normalised on the CPU, as glm::normalize does in the soft backend
uniform vec3 u_lightColor;
uniform vec3 u_ambient;

vec4 toStraight(vec4 t) {
    if (!u_premultiplied || !(t.a > 0.0)) return t;
    return vec4(t.rgb / t.a, t.a);
}

float lambert(vec3 n) {
    float len = length(n);
    if (!(len > 0.0)) return 0.0;
    return max(dot(n / len, u_towardLight), 0.0);
}

void main() {
    if (llvmpipeGuard()) discard;
    vec4 base = u_color * v_color;
    if (u_hasTexture) base *= toStraight(sampleBase(v_uv));
    vec3 n = v_normal;
#if FOLIAGE
    if (!gl_FrontFacing) n = -n;  // double-sided: back faces lit with the flipped normal
#endif
    vec3 lit = base.rgb * (u_ambient + u_lightColor * lambert(n));
#if FOLIAGE
#ifdef WBOIT
    finish(wboitWeighted(vec4(lit, base.a)));
#else
    finish(vec4(lit, base.a));
#endif
#else
    finish(vec4(lit, 1.0));
#endif
}
)";

// WboitAccumulate: defines wboitWeighted() for the surface program (soft: programs.hpp
// wboitWeight, the same operations in the same order). McGuire & Bavoil 2013, eq. (7), with
// the view depth |z| = clip w = 1 / gl_FragCoord.w.
constexpr const char* kWboitWeight = R"(
#define WBOIT 1
uniform float u_depthScale;
vec4 wboitWeighted(vec4 c) {
    precise float z = abs((1.0 / gl_FragCoord.w) * u_depthScale);
    precise float near = z / 5.0, far = z / 200.0;
    precise float far2 = far * far;
    precise float g = 10.0 / (1e-5 + near * near + far2 * far2 * far2);
    precise float w = c.a * (g > 1e-2 ? (g < 3e3 ? g : 3e3) : 1e-2);
    precise float aw = c.a * w;
    return vec4(c.rgb * aw, aw);
}
)";

// The WBOIT composite (McGuire & Bavoil 2013): average colour and revealage; the blend
// (INV_SRC_ALPHA / SRC_ALPHA) puts it over the opaque colour.
constexpr const char* kWboitResolveFragment = R"(
layout(binding = 0) uniform sampler2D u_accumulation;
layout(binding = 1) uniform sampler2D u_revealage;
void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    vec4 sum = texelFetch(u_accumulation, p, 0);
    float reveal = clamp01(texelFetch(u_revealage, p, 0).r);
    float weight = sum.a > 1e-5 ? sum.a : 1e-5;
    vec3 average = sum.rgb / weight;
    for (int c = 0; c < 3; ++c)
        if (isnan(average[c]) || isinf(average[c])) average[c] = 0.0;
    finish(vec4(average, reveal));
}
)";

// SSAM+'s composite (soft: programs.hpp CoverageCompositeProgram, layerCoverage).
constexpr const char* kCoverageCompositeFragment = R"(
layout(binding = 0) uniform sampler2D u_foliage;
layout(binding = 1) uniform sampler2D u_mask;
layout(binding = 2) uniform sampler2D u_maskAdd;
uniform bool u_hasMaskAdd;
uniform int u_coverageModel;  // CoverageModel: 0 equal layers, 1 exponential
void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    vec4 m = texelFetch(u_mask, p, 0);
    float addMask = u_hasMaskAdd ? texelFetch(u_maskAdd, p, 0).r : m.a;
    float coverage = 0.0;
    if (u_coverageModel == 1) coverage = 1.0 - exp(-addMask);
    else if (m.r >= 1.0) coverage = 1.0;
    else if (m.r > 0.0) coverage = 1.0 - pow(1.0 - m.r, addMask / m.r);
    coverage = clamp01(coverage);
    vec3 color = texelFetch(u_foliage, p, 0).rgb;
    for (int c = 0; c < 3; ++c)
        if (isnan(color[c]) || isinf(color[c])) color[c] = 0.0;
    finish(vec4(color, coverage));
}
)";

// seeds/000 Listing 3.1: alpha only, replicated; no lighting, no colour fetch.
constexpr const char* kFoliageAlphaFragment = R"(
in vec2 v_uv;
in vec4 v_color;
uniform float u_alphaFactor;
uniform bool u_hasTexture;
void main() {
    if (llvmpipeGuard()) discard;
    float a = u_alphaFactor * v_color.a;
    if (u_hasTexture) a *= sampleBase(v_uv).a;
    finish(vec4(a));
}
)";

// seeds/000 Listing 3.2, one texel per pixel; the lerp with the opaque colour is the blend.
constexpr const char* kCompositeFragment = R"(
layout(binding = 0) uniform sampler2D u_foliage;
layout(binding = 1) uniform sampler2D u_mask;
layout(binding = 2) uniform sampler2D u_maskAdd;
uniform bool u_hasMaskAdd;
uniform float u_maskLerp;
uniform bool u_squareMask;
void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    vec4 m = texelFetch(u_mask, p, 0);
    float addMask = u_hasMaskAdd ? texelFetch(u_maskAdd, p, 0).r : m.a;
    precise float blend = m.r + (addMask - m.r) * u_maskLerp;
    blend = blend > 0.0 ? (blend < 1.0 ? blend : 1.0) : 0.0;
    if (u_squareMask) blend *= blend;  // the squared alpha trick (seeds/000 §3.6.2)
    finish(vec4(texelFetch(u_foliage, p, 0).rgb, blend));
}
)";

// Colour resolve: the average of the samples in the linear domain (the fetch decodes sRGB,
// GL_FRAMEBUFFER_SRGB encodes the result), summed in sample order as the soft backend does.
constexpr const char* kResolveColorFragment = R"(#version 450 core
layout(binding = 0) uniform sampler2DMS u_source;
uniform int u_samples;
layout(location = 0) out vec4 o_color;
void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    precise vec4 sum = vec4(0.0);
    for (int s = 0; s < u_samples; ++s) sum += texelFetch(u_source, p, s);
    precise vec4 average = sum / float(u_samples);
    o_color = average;
}
)";

// Depth resolve: the sample closest to the observer under the depth function (seeds/000
// §3.5.1), never an average.
constexpr const char* kResolveDepthFragment = R"(#version 450 core
layout(binding = 0) uniform sampler2DMS u_source;
uniform int u_samples;
uniform bool u_greater;  // GREATER / GEQUAL: larger is closer (reverse-Z)
void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    float best = texelFetch(u_source, p, 0).r;
    for (int s = 1; s < u_samples; ++s) {
        float z = texelFetch(u_source, p, s).r;
        if (u_greater ? z > best : z < best) best = z;
    }
    gl_FragDepth = best;
}
)";

// Particle (soft: particle_programs.hpp): premultiplied soft billboard (program.hpp
// ParticleParams, seeds/003), closest-sample scene depth for half-resolution layers.
constexpr const char* kParticleDepth = R"(
layout(binding = 0) uniform sampler2D u_sceneDepth;
uniform bool u_greaterIsCloser;
float saturateOrZero(float v) { return v > 0.0 ? (v < 1.0 ? v : 1.0) : 0.0; }
float closestDepth(ivec2 p, int stride) {
    stride = clamp(stride, 1, 4);
    ivec2 last = textureSize(u_sceneDepth, 0) - 1;
    float best = texelFetch(u_sceneDepth, min(p * stride, last), 0).r;
    for (int sy = 0; sy < stride; ++sy)
        for (int sx = 0; sx < stride; ++sx) {
            float z = texelFetch(u_sceneDepth, min(p * stride + ivec2(sx, sy), last), 0).r;
            if (u_greaterIsCloser ? z > best : z < best) best = z;
        }
    return best;
}
)";

constexpr const char* kParticleFragment = R"(
in vec2 v_uv;
in vec3 v_normal;
in vec4 v_color;
uniform bool u_hasDepth;
uniform int u_depthStride;
uniform float u_distanceScale;
uniform float u_distanceOffset;
uniform float u_softness;
void main() {
    if (llvmpipeGuard()) discard;
    vec2 q = v_uv * 2.0 - 1.0;
    float shape = saturateOrZero(1.0 - (q.x * q.x + q.y * q.y));
    float fade = 1.0;
    if (u_hasDepth) {
        float z = closestDepth(ivec2(gl_FragCoord.xy), u_depthStride);
        float sceneDistance = u_distanceScale / (z + u_distanceOffset);
        fade = saturateOrZero((sceneDistance - v_normal.x) / u_softness);
    }
    float a = saturateOrZero(v_color.a) * shape * fade;
    float additive = saturateOrZero(v_normal.y);
    vec4 o = vec4(v_color.rgb * a, a * (1.0 - additive));
    for (int c = 0; c < 4; ++c)
        if (isnan(o[c]) || isinf(o[c])) o[c] = 0.0;
    finish(o);
}
)";

// LayerComposite (soft: particle_programs.hpp): the layer texel, nearest-depth upsampled.
constexpr const char* kLayerCompositeFragment = R"(
layout(binding = 1) uniform sampler2D u_layer;
uniform int u_layerScale;
uniform bool u_hasDepth;
uniform float u_distanceScale;
uniform float u_distanceOffset;
float distanceOf(float z) { return u_distanceScale / (z + u_distanceOffset); }
void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    int scale = clamp(u_layerScale, 1, 4);
    ivec2 last = textureSize(u_layer, 0) - 1;
    ivec2 l = min(p / scale, last);
    if (scale > 1 && u_hasDepth) {
        float here = distanceOf(texelFetch(u_sceneDepth, p, 0).r);
        ivec2 c0 = clamp((p - 1) / 2, ivec2(0), last), c1 = min(c0 + 1, last);
        ivec2 n = clamp(p / 2, ivec2(0), last);
        vec4 c00 = texelFetch(u_layer, c0, 0);
        bool same = c00 == texelFetch(u_layer, ivec2(c1.x, c0.y), 0) && c00 == texelFetch(u_layer, ivec2(c0.x, c1.y), 0) &&
                    c00 == texelFetch(u_layer, c1, 0);
        if (same) l = c0; else {
        float best = abs(distanceOf(closestDepth(n, scale)) - here);
        l = n;
        for (int j = 0; j < 2; ++j)
            for (int i = 0; i < 2; ++i) {
                ivec2 c = ivec2(i == 0 ? c0.x : c1.x, j == 0 ? c0.y : c1.y);
                float diff = abs(distanceOf(closestDepth(c, scale)) - here);
                if (diff < best) { best = diff; l = c; }
            }
        }
    }
    vec4 c = texelFetch(u_layer, l, 0);
    for (int i = 0; i < 4; ++i)
        if (isnan(c[i]) || isinf(c[i])) c[i] = 0.0;
    c.a = saturateOrZero(c.a);
    finish(c);
}
)";

// LightShafts (soft: particle_programs.hpp LightShaftsProgram), the same march.
constexpr const char* kLightShaftsFragment = R"(
layout(binding = 0) uniform sampler2D u_shaftDepth;
uniform vec2 u_sunPixel;
uniform float u_farDepth;
uniform bool u_shaftGreater;
uniform vec3 u_shaftColor;
uniform float u_intensity;
uniform float u_decay;
uniform float u_density;
uniform int u_samples;
uniform float u_glowRadius;
float sunGlow(vec2 q) {
    if (!(u_glowRadius > 0.0)) return 1.0;
    float t = max(0.0, 1.0 - length(q - u_sunPixel) / u_glowRadius);
    return t * t;
}
void main() {
    ivec2 size = textureSize(u_shaftDepth, 0);
    int samples = clamp(u_samples, 1, 128);
    precise vec2 p = floor(gl_FragCoord.xy) + 0.5;
    precise vec2 step = (u_sunPixel - p) * (u_density / float(samples));
    float sum = 0.0, weight = 1.0;
    for (int i = 0; i < samples; ++i) {
        precise vec2 q = p + step * float(i);
        if (!(q.x >= 0.0 && q.y >= 0.0 && q.x < float(size.x) && q.y < float(size.y))) break;
        float z = texelFetch(u_shaftDepth, ivec2(q), 0).r;
        bool sky = u_shaftGreater ? !(z > u_farDepth) : !(z < u_farDepth);
        if (sky) sum += weight * sunGlow(q);
        weight *= u_decay;
    }
    vec3 c = u_shaftColor * (u_intensity * sum / float(samples));
    for (int i = 0; i < 3; ++i)
        if (isnan(c[i]) || isinf(c[i])) c[i] = 0.0;
    finish(vec4(c, 0.0));
}
)";

}  // namespace

std::string vertexSource(ProgramKind kind) { return isFullscreen(kind) ? kFullscreenVertex : kMeshVertex; }

std::string fragmentSource(ProgramKind kind) {
    std::string s = kFragmentCommon;
    switch (kind) {
        case ProgramKind::Flat: return s + kMeshFragmentGuard + kFlatFragment;
        case ProgramKind::OpaqueLit: return s + kMeshFragmentGuard + kSampling + "#define FOLIAGE 0\n" + kSurfaceFragment;
        case ProgramKind::FoliageColor: return s + kMeshFragmentGuard + kSampling + "#define FOLIAGE 1\n" + kSurfaceFragment;
        case ProgramKind::FoliageAlpha: return s + kMeshFragmentGuard + kSampling + kFoliageAlphaFragment;
        case ProgramKind::Composite: return s + kCompositeFragment;
        case ProgramKind::WboitAccumulate:
            return s + kMeshFragmentGuard + kSampling + "#define FOLIAGE 1\n" + kWboitWeight + kSurfaceFragment;
        case ProgramKind::WboitResolve: return s + kWboitResolveFragment;
        case ProgramKind::CoverageComposite: return s + kCoverageCompositeFragment;
        case ProgramKind::Particle: return s + kMeshFragmentGuard + kParticleDepth + kParticleFragment;
        case ProgramKind::LayerComposite: return s + kParticleDepth + kLayerCompositeFragment;
        case ProgramKind::LightShafts: return s + kLightShaftsFragment;
    }
    return s;
}

std::string withGlslVersion(std::string source, int major, int minor) {
    if (major > 4 || (major == 4 && minor >= 5)) return source;
    const std::string from = "#version 450 core", to = "#version 430 core";  // 4.3/4.4 contexts
    if (source.compare(0, from.size(), from) == 0) source.replace(0, from.size(), to);
    return source;
}

std::string fullscreenVertexSource() { return kFullscreenVertex; }
std::string resolveColorFragmentSource() { return kResolveColorFragment; }
std::string resolveDepthFragmentSource() { return kResolveDepthFragment; }

}  // namespace engine::render::gl
