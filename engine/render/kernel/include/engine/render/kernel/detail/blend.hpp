// SPDX-License-Identifier: MIT
#pragma once
// The blend equation (GL 4.5 §17.3.6, Vulkan "Blend Factors"/"Blend Operations").
// Normalized targets clamp source, destination and constant to [0,1] first, so factors
// and products stay in [0,1]; float targets clamp nothing and let NaN/Inf propagate.
#include <algorithm>
#include <cstddef>
#include <cstdint>

#include <glm/glm.hpp>

#include "engine/render/blend_state.hpp"
#include "engine/render/kernel/clamp01.hpp"
#include "engine/render/pixel_codec.hpp"

namespace engine::render::soft {

// Factor for the RGB half; `c` is the constant colour.
inline glm::vec3 rgbFactor(BlendFactor f, const glm::vec4& s, const glm::vec4& d, const glm::vec4& c) {
    switch (f) {
        case BlendFactor::Zero: return glm::vec3(0.0f);
        case BlendFactor::One: return glm::vec3(1.0f);
        case BlendFactor::SrcColor: return glm::vec3(s);
        case BlendFactor::InvSrcColor: return glm::vec3(1.0f) - glm::vec3(s);
        case BlendFactor::SrcAlpha: return glm::vec3(s.a);
        case BlendFactor::InvSrcAlpha: return glm::vec3(1.0f - s.a);
        case BlendFactor::DstColor: return glm::vec3(d);
        case BlendFactor::InvDstColor: return glm::vec3(1.0f) - glm::vec3(d);
        case BlendFactor::DstAlpha: return glm::vec3(d.a);
        case BlendFactor::InvDstAlpha: return glm::vec3(1.0f - d.a);
        case BlendFactor::SrcAlphaSat: return glm::vec3(std::min(s.a, 1.0f - d.a));
        case BlendFactor::ConstantColor: return glm::vec3(c);
        case BlendFactor::InvConstantColor: return glm::vec3(1.0f) - glm::vec3(c);
        case BlendFactor::ConstantAlpha: return glm::vec3(c.a);
        case BlendFactor::InvConstantAlpha: return glm::vec3(1.0f - c.a);
    }
    return glm::vec3(0.0f);
}

// Factor for the alpha half: colour factors use their alpha component; SRC_ALPHA_SAT is 1.
inline float alphaFactor(BlendFactor f, const glm::vec4& s, const glm::vec4& d, const glm::vec4& c) {
    switch (f) {
        case BlendFactor::Zero: return 0.0f;
        case BlendFactor::One:
        case BlendFactor::SrcAlphaSat: return 1.0f;
        case BlendFactor::SrcColor:
        case BlendFactor::SrcAlpha: return s.a;
        case BlendFactor::InvSrcColor:
        case BlendFactor::InvSrcAlpha: return 1.0f - s.a;
        case BlendFactor::DstColor:
        case BlendFactor::DstAlpha: return d.a;
        case BlendFactor::InvDstColor:
        case BlendFactor::InvDstAlpha: return 1.0f - d.a;
        case BlendFactor::ConstantColor:
        case BlendFactor::ConstantAlpha: return c.a;
        case BlendFactor::InvConstantColor:
        case BlendFactor::InvConstantAlpha: return 1.0f - c.a;
    }
    return 0.0f;
}

template <typename T>
inline T applyOp(BlendOp op, const T& s, const T& sf, const T& d, const T& df) {
    switch (op) {
        case BlendOp::Add: return s * sf + d * df;
        case BlendOp::Subtract: return s * sf - d * df;
        case BlendOp::RevSubtract: return d * df - s * sf;
        case BlendOp::Min: return glm::min(s, d);  // factors ignored (GL 4.5 Table 17.1)
        case BlendOp::Max: return glm::max(s, d);
    }
    return s;
}

// Blends src onto dst (both in the linear domain). `normalized`: UNORM/sRGB target rules.
inline glm::vec4 blend(const BlendState& b, glm::vec4 src, glm::vec4 dst, glm::vec4 constant, bool normalized) {
    if (normalized) {
        src = clamp01(src);
        dst = clamp01(dst);
        constant = clamp01(constant);
    }
    const glm::vec3 sf = rgbFactor(b.srcRgb, src, dst, constant);
    const glm::vec3 df = rgbFactor(b.dstRgb, src, dst, constant);
    const float saf = alphaFactor(b.srcAlpha, src, dst, constant);
    const float daf = alphaFactor(b.dstAlpha, src, dst, constant);
    const glm::vec3 rgb = applyOp(b.opRgb, glm::vec3(src), sf, glm::vec3(dst), df);
    const float a = applyOp(b.opAlpha, src.a, saf, dst.a, daf);
    return {rgb, a};
}

// Blends whose factors are all ONE and whose operations are ADD or MAX: sums and maxima of
// coverage (e.g. [Hathaway 2010] Table 3.1's mask).
inline bool isOneOneAddMax(const BlendState& b) {
    auto addOrMax = [](BlendOp op) { return op == BlendOp::Add || op == BlendOp::Max; };
    return b.srcRgb == BlendFactor::One && b.dstRgb == BlendFactor::One && b.srcAlpha == BlendFactor::One &&
           b.dstAlpha == BlendFactor::One && addOrMax(b.opRgb) && addOrMax(b.opAlpha);
}

// blend() + storeTexel() of the colour (a, a, a, a), a in [0, 1], onto the RGBA8_UNORM pixel
// p under such a blend, with the same bits. The UNORM clamps leave a and d / 255 as they
// are. ADD: a * 1 + d * 1 = a + d / 255 exactly, then the UNORM encode. MAX:
// encode(max(a, d / 255)) = max(encode(a), d), as encodeUnorm8 is non-decreasing and
// encodeUnorm8(d / 255) = d (both checked for every float in [0, 1] and every byte).
inline void blendOneOneRgba8(const BlendState& b, std::byte* p, float a, std::uint8_t writeMask) {
    const float* unorm = byteTables().unorm;
    const std::uint8_t encoded = encodeUnorm8(a);
    for (int c = 0; c < 4; ++c) {
        if (!(writeMask & (1u << c))) continue;
        const std::uint8_t d = std::to_integer<std::uint8_t>(p[c]);
        const BlendOp op = c < 3 ? b.opRgb : b.opAlpha;
        p[c] = std::byte{op == BlendOp::Max ? std::max(encoded, d) : encodeUnorm8(a + unorm[d])};
    }
}

}  // namespace engine::render::soft
