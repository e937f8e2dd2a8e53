// SPDX-License-Identifier: MIT
// TemporalResolve's GLSL (transparency/temporal.hpp; soft: temporal_kernel.hpp), the jitter
// sequence and the reprojection matrix.
#include <cmath>
#include <cstddef>
#include <string>

#include "engine/render/kernel/program_kernel.hpp"
#include "temporal_kernel.hpp"
#include "transparency/temporal.hpp"

namespace transparency {
namespace {

using namespace engine::render;

constexpr const char* kTemporalResolveFragment = R"(
layout(binding = 0) uniform sampler2D u_current;
layout(binding = 1) uniform sampler2D u_depth;
layout(binding = 2) uniform sampler2D u_history;
vec4 finiteOf(vec4 c) {
    for (int i = 0; i < 4; ++i)
        if (isnan(c[i]) || isinf(c[i])) c[i] = 0.0;
    return c;
}
vec4 at(sampler2D t, ivec2 p) {
    ivec2 size = textureSize(t, 0);
    return finiteOf(texelFetch(t, clamp(p, ivec2(0), size - 1), 0));
}
void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    vec4 c = at(u_current, p);
    if (u_copyOnly || !u_hasHistory || !u_hasDepth || !u_hasHistoryTexture) {
        finish(c);
        return;
    }
    float d = texelFetch(u_depth, p, 0).r;
    precise float px = float(p.x) + 0.5, py = float(p.y) + 0.5;
    precise vec4 q = ((u_reprojection[0] * px + u_reprojection[1] * py) + u_reprojection[2] * d) + u_reprojection[3];
    precise float hx = q.x / q.w, hy = q.y / q.w;
    vec2 size = vec2(textureSize(u_history, 0));
    if (!(hx >= 0.0 && hx <= size.x && hy >= 0.0 && hy <= size.y)) {
        finish(c);
        return;
    }
    precise float sx = hx - 0.5, sy = hy - 0.5;
    float x0 = floor(sx), y0 = floor(sy);
    precise float fx = sx - x0, fy = sy - y0;
    ivec2 i0 = ivec2(int(x0), int(y0));
    precise vec4 top = at(u_history, i0) * (1.0 - fx) + at(u_history, i0 + ivec2(1, 0)) * fx;
    precise vec4 bottom = at(u_history, i0 + ivec2(0, 1)) * (1.0 - fx) + at(u_history, i0 + ivec2(1, 1)) * fx;
    precise vec4 hist = top * (1.0 - fy) + bottom * fy;
    vec4 lo = c, hi = c;
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
            vec4 n = at(u_current, p + ivec2(dx, dy));
            lo = min(lo, n);
            hi = max(hi, n);
        }
    vec4 clamped = min(max(hist, lo), hi);
    precise vec4 result = clamped + (c - clamped) * u_blend;
    finish(result);
}
)";

float halton(std::uint64_t index, std::uint64_t base) {
    float f = 1.0f, r = 0.0f;
    while (index > 0) {
        f /= float(base);
        r += f * float(index % base);
        index /= base;
    }
    return r;
}

}  // namespace

glm::vec2 haltonJitter(std::uint64_t frameIndex, int phases) {
    const std::uint64_t i = 1 + frameIndex % std::uint64_t(phases < 1 ? 1 : phases);
    // Rounded to 1/256 pixel (finer than the rasterizers' sub-pixel grids): a binary fraction,
    // so that a jittered and unjittered matrix differ by exactly the jitter.
    auto snap = [](float v) { return std::round(v * 256.0f) / 256.0f; };
    return {snap(halton(i, 2) - 0.5f), snap(halton(i, 3) - 0.5f)};
}

glm::mat4 jitteredViewProj(const glm::mat4& viewProj, glm::vec2 jitterPixels, int width, int height) {
    if (jitterPixels == glm::vec2(0.0f)) return viewProj;  // the same bits, not a product with the identity
    glm::mat4 j(1.0f);
    j[3][0] = 2.0f * jitterPixels.x / float(width);
    j[3][1] = -2.0f * jitterPixels.y / float(height);  // rows grow downwards
    return j * viewProj;
}

bool reprojectionMatrix(const glm::mat4& current, const glm::mat4& previous, int width, int height, glm::mat4& out) {
    const glm::dmat4 c(current), p(previous);
    if (!(std::abs(glm::determinant(c)) > 0.0)) return false;
    const double w = width, h = height;
    // Pixel (centre coordinates) and depth to NDC: x = 2 px / w - 1, y = 1 - 2 py / h.
    glm::dmat4 toNdc(1.0);
    toNdc[0][0] = 2.0 / w;
    toNdc[1][1] = -2.0 / h;
    toNdc[3][0] = -1.0;
    toNdc[3][1] = 1.0;
    // Previous clip to pixel coordinates times w: px w = (x + w) * width / 2, py w = (w - y) * height / 2.
    glm::dmat4 toPixels(1.0);
    toPixels[0][0] = w / 2.0;
    toPixels[1][1] = -h / 2.0;
    toPixels[3][0] = w / 2.0;
    toPixels[3][1] = h / 2.0;
    const glm::dmat4 m = toPixels * p * glm::inverse(c) * toNdc;
    out = glm::mat4(m);
    for (int i = 0; i < 4; ++i)
        for (int k = 0; k < 4; ++k)
            if (!std::isfinite(out[i][k])) return false;
    return true;
}

ProgramDesc temporalResolveProgram() {
    ProgramDesc d = describeProgram<TemporalResolveParams>("TemporalResolve", VertexInput::Fullscreen,
                                                           "transparency::TemporalResolveParams");
    d.gl.fragment = kTemporalResolveFragment;
    d.gl.uniforms = {
        {"u_reprojection", UniformType::Mat4, offsetof(TemporalResolveParams, reprojection)},
        {"u_blend", UniformType::Float, offsetof(TemporalResolveParams, blend)},
        {"u_hasHistory", UniformType::Bool, offsetof(TemporalResolveParams, hasHistory)},
        {"u_copyOnly", UniformType::Bool, offsetof(TemporalResolveParams, copyOnly)},
    };
    d.gl.textures = {
        {"u_current", offsetof(TemporalResolveParams, current), 0, TextureRead::Texel, TextureUse::FullSize},
        {"u_depth", offsetof(TemporalResolveParams, depth), 1, TextureRead::Texel, TextureUse::FullSize, true,
         "u_hasDepth"},
        {"u_history", offsetof(TemporalResolveParams, history), 2, TextureRead::Texel, TextureUse::FullSize, true,
         "u_hasHistoryTexture"},
    };
    d.check = [](const void* params, const DrawCheck& check) {
        const float blend = static_cast<const TemporalResolveParams*>(params)->blend;
        if (!(blend > 0.0f && blend <= 1.0f)) check.fail("blend " + std::to_string(blend) + " must be in (0, 1]");
    };
    d.soft = soft::makeKernel<TemporalResolveKernel, TemporalResolveParams>();
    return d;
}

}  // namespace transparency
