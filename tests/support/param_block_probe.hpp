// SPDX-License-Identifier: MIT
#pragma once
// A tiny full-screen program whose parameter block is declared once (param_block.hpp), with a
// member of every kind a block can have: each uniform type, a direction, a texelFetch texture and
// an optional sampled one. Its body writes a colour every member changes, in values exact in
// binary (dyadic), so the soft kernel, GL and Vulkan give the same bits, which
// expectedProbe() computes on the CPU: a member missing from the table, at a wrong offset or
// of a wrong type changes them. The GL and Vulkan tests draw it on the real drivers, which
// compile the declarations the block gives (unit_param_block, gl_param_block, vk_param_block).
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "draws.hpp"
#include "engine/render/backend.hpp"
#include "engine/render/kernel/fragment.hpp"
#include "engine/render/kernel/program_kernel.hpp"
#include "engine/render/kernel/sampler.hpp"
#include "engine/render/kernel/texture_lookup.hpp"
#include "engine/render/param_block.hpp"
#include "engine/render/shader_interface.hpp"

namespace ssam::testing {

enum class ProbeMode : std::uint8_t { Off, Half, Full };

#define SSAM_TESTING_PROBE_PARAMS(UNIFORM, DIRECTION, TEXTURE)             \
    UNIFORM(glm::mat4, viewProj, glm::mat4(1.0f))                          \
    UNIFORM(float, scale, 1.0f)                                            \
    UNIFORM(int, steps, 0)                                                 \
    UNIFORM(bool, flipped, false)                                          \
    UNIFORM(ProbeMode, mode, ProbeMode::Off) /* a one-byte enum: Byte */   \
    UNIFORM(glm::vec2, offset, glm::vec2(0.0f))                            \
    UNIFORM(glm::vec3, unused, glm::vec3(0.0f)) /* declared, never read */ \
    UNIFORM(glm::vec4, tint, glm::vec4(1.0f))                              \
    DIRECTION(towardLight, glm::vec3(0.0f, 1.0f, 0.0f))                    \
    TEXTURE(source, Texel, FullSize, Required)                             \
    TEXTURE(detail, Sampled, Sampled, Optional)
ENGINE_PARAM_BLOCK(ProbeParams, SSAM_TESTING_PROBE_PARAMS);

inline constexpr int kProbeWidth = 4, kProbeHeight = 2;

// What the body computes at pixel (x, y) when the source's red is (x + 4y) / 8 and the
// detail, when there is one, has alpha 1.
inline glm::vec4 expectedProbe(const ProbeParams& p, bool withDetail, int x, int y) {
    const float source = float(x + kProbeWidth * y) / 8.0f;
    const glm::vec3 light = glm::normalize(p.towardLight);
    return {p.scale * source + p.viewProj[3][0], float(p.steps) * 0.125f + (p.flipped ? 0.5f : 0.0f),
            float(p.mode) * 0.25f + p.offset.x + light.y * 0.125f, p.tint.a * 0.5f + (withDetail ? 0.25f : 0.0f)};
}

inline constexpr const char* kProbeBody = R"(
void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    float r = u_scale * texelFetch(u_source, p, 0).r + u_viewProj[3][0];
    float g = float(u_steps) * 0.125 + (u_flipped ? 0.5 : 0.0);
    float b = float(u_mode) * 0.25 + u_offset.x + u_towardLight.y * 0.125;
    float a = u_tint.a * 0.5 + (u_detailBound ? 0.25 * texture(u_detail, vec2(0.5)).a : 0.0);
    finish(vec4(r, g, b, a));
}
)";

// The soft backend's kernel: the same arithmetic (the direction normalised here, as the GPU
// drivers do before upload).
struct ProbeKernel {
    static constexpr engine::render::soft::ProgramNeeds kNeeds{};
    static constexpr bool kReadsPixels = true;
    ProbeParams params;
    const engine::render::soft::SoftTexture* source;
    const engine::render::soft::SoftTexture* detail;

    ProbeKernel(const ProbeParams& p, const engine::render::soft::TextureLookup& textures)
        : params(p), source(textures.texture(p.source)), detail(textures.texture(p.detail.texture)) {}
    glm::vec4 shade(const engine::render::soft::Fragment& f) const {
        const glm::vec3 light = glm::normalize(params.towardLight);
        const float detailAlpha = detail ? engine::render::soft::fetchTexel(*detail, 0, 0).a : 0.0f;
        return {params.scale * engine::render::soft::fetchTexel(*source, f.x, f.y).r + params.viewProj[3][0],
                float(params.steps) * 0.125f + (params.flipped ? 0.5f : 0.0f),
                float(params.mode) * 0.25f + params.offset.x + light.y * 0.125f,
                params.tint.a * 0.5f + (detail ? 0.25f * detailAlpha : 0.0f)};
    }
};

inline engine::render::ProgramDesc probeProgram() {
    using namespace engine::render;
    ProgramDesc d = describeProgram<ProbeParams>("Probe", VertexInput::Fullscreen, "ssam::testing::ProbeParams");
    d.gl.fragment = samplerDeclarations(d.gl) + kProbeBody;
    d.soft = soft::makeKernel<ProbeKernel, ProbeParams>();
    return d;
}

// The probe drawn over a 4x2 RGBA32F target with `p` (its textures made here: the source's red
// (x + 4y) / 8, a 1x1 detail of alpha 1 when `withDetail`), read back.
inline engine::render::Readback drawProbe(engine::render::Backend& backend, ProbeParams p, bool withDetail) {
    using namespace engine::render;
    std::vector<float> texels(std::size_t(kProbeWidth) * kProbeHeight * 4, 0.0f);
    for (int i = 0; i < kProbeWidth * kProbeHeight; ++i) texels[std::size_t(i) * 4] = float(i) / 8.0f;
    TextureDesc sourceDesc{"probe source", kProbeWidth, kProbeHeight, Format::RGBA32F};
    const TextureData sourceData{{std::as_bytes(std::span<const float>(texels))}};
    p.source = backend.createTexture(sourceDesc, &sourceData);
    const std::uint8_t white[4] = {255, 255, 255, 255};
    const TextureData detailData{{std::as_bytes(std::span<const std::uint8_t>(white))}};
    p.detail = {};
    if (withDetail) {
        p.detail.texture = backend.createTexture({"probe detail", 1, 1, Format::RGBA8_UNORM}, &detailData);
        p.detail.sampler = {Filter::Nearest, AddressMode::Clamp, AddressMode::Clamp};
    }
    const TextureHandle target =
        backend.createTexture(renderTargetDesc("probe target", kProbeWidth, kProbeHeight, Format::RGBA32F));
    const ProgramHandle program = backend.createProgram(probeProgram());
    drawFullscreenInto(backend, program, p, target, "probe");
    Readback r = backend.readback(target);
    backend.destroy(program);
    backend.destroy(target);
    backend.destroy(p.source);
    if (p.detail.texture) backend.destroy(p.detail.texture);
    return r;
}

// How many channels of a drawn probe differ from expectedProbe() (bit-exact: every value is dyadic).
inline int probeMismatches(const engine::render::Readback& r, const ProbeParams& p, bool withDetail) {
    if (r.width != kProbeWidth || r.height != kProbeHeight || r.channels != 4) return kProbeWidth * kProbeHeight * 4;
    int differ = 0;
    for (int y = 0; y < kProbeHeight; ++y)
        for (int x = 0; x < kProbeWidth; ++x)
            for (int c = 0; c < 4; ++c) differ += r.at(x, y, c) != expectedProbe(p, withDetail, x, y)[c];
    return differ;
}

// Every member set away from its default, in values the body's sums keep exact.
inline ProbeParams probeValues() {
    ProbeParams p;
    p.viewProj[3][0] = 0.0625f;
    p.scale = 2.0f;
    p.steps = 3;
    p.flipped = true;
    p.mode = ProbeMode::Full;
    p.offset = glm::vec2(0.125f, 7.0f);
    p.tint = glm::vec4(0.0f, 0.0f, 0.0f, 0.5f);
    p.towardLight = glm::vec3(0.0f, 3.0f, 0.0f);
    return p;
}

}  // namespace ssam::testing
