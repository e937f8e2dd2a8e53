// SPDX-License-Identifier: MIT
// Soft vs GL for the living-scene program kinds (program.hpp): Particle and
// LayerComposite (modules/particles) and LightShafts (modules/lightshafts) — the same depth
// and draws on both backends, compared texel by texel.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "engine/render/gl/gl_backend.hpp"
#include "engine/render/projection.hpp"
#include "engine/render/soft/soft_backend.hpp"
#include "engine/render/vertex.hpp"
#include "lightshafts/light_shaft_program.hpp"
#include "particles/particle_programs.hpp"

#include <tuple>

namespace {

using namespace engine::render;

constexpr int kW = 48, kH = 32;

struct Result {
    Readback layer, color;
};

std::vector<Vertex> quad(float x0, float y0, float x1, float y1, float z, glm::vec4 color, glm::vec3 normal) {
    auto v = [&](float x, float y, float u, float w) {
        Vertex vertex;
        vertex.position = {x, y, z};
        vertex.normal = normal;
        vertex.uv = {u, w};
        vertex.color = color;
        return vertex;
    };
    return {v(x0, y0, 0, 0), v(x1, y0, 1, 0), v(x1, y1, 1, 1), v(x0, y0, 0, 0), v(x1, y1, 1, 1), v(x0, y1, 0, 1)};
}

// The kW x kH colour and reverse-Z depth targets with `wall` (an opaque flat quad: the "tree"
// particles and shafts must respect) drawn over `sky`.
struct WallFrame {
    TextureHandle color, depth;
};

WallFrame wallFrame(Backend& b, const glm::mat4& viewProj, const std::vector<Vertex>& wall, const glm::vec4& sky) {
    TextureDesc t;
    t.width = kW, t.height = kH, t.usage = UsageRenderTarget | UsageSampled, t.name = "colour";
    const TextureHandle color = b.createTexture(t);
    t.name = "depth", t.format = Format::D32F;
    const TextureHandle depth = b.createTexture(t);
    const BufferHandle wallBuffer =
        b.createBuffer({"wall", BufferKind::Vertex, wall.size() * sizeof(Vertex)}, std::as_bytes(std::span(wall)));
    PipelineDesc p;
    p.name = "wall";
    p.depth = DepthState::testAndWrite(CompareFunc::Greater);
    const PipelineHandle wallPipeline = b.createPipeline(p);
    PassDesc pass;
    pass.name = "scene";
    pass.color[0] = {color, LoadOp::Clear, sky};
    pass.depth = {depth, LoadOp::Clear, 0.0f};
    b.beginPass(pass);
    DrawDesc d;
    d.pipeline = wallPipeline;
    d.params = FlatParams{viewProj, glm::vec4(1.0f)};
    d.vertices = wallBuffer;
    d.count = 6;
    b.draw(d);
    b.endPass();
    return {color, depth};
}

Result run(Backend& b, int stride) {
    const glm::mat4 proj = perspectiveReverseZ(1.0f, float(kW) / kH, 0.1f, 30000.0f);
    const glm::mat4 view = glm::lookAt(glm::vec3(0.0f), glm::vec3(0, 0, 1), glm::vec3(0, 1, 0));
    const glm::mat4 viewProj = proj * view;
    // A "tree": a wall at 5 m over the left of the view, its edge at an odd pixel.
    const auto [color, depth] =
        wallFrame(b, viewProj, quad(-9.0f, -9.0f, 0.37f, 9.0f, 5.0f, {0.2f, 0.5f, 0.1f, 1.0f}, {0, 0, -1}),
                  {0.5f, 0.6f, 0.8f, 1.0f});
    TextureDesc t;
    t.usage = UsageRenderTarget | UsageSampled;
    t.name = "layer", t.format = Format::RGBA16F, t.width = (kW + stride - 1) / stride,
    t.height = (kH + stride - 1) / stride;
    const TextureHandle layer = b.createTexture(t);
    // Particles: one straddling the wall's edge behind it, one in front, one additive.
    std::vector<Vertex> parts;
    for (auto [x, y, z, add, c] : {std::tuple{0.6f, 0.3f, 8.0f, 0.0f, glm::vec4(0.9f, 0.4f, 0.2f, 0.8f)},
                                   std::tuple{-0.4f, -0.4f, 4.2f, 0.0f, glm::vec4(0.5f, 0.5f, 0.9f, 0.6f)},
                                   std::tuple{0.2f, 0.0f, 4.8f, 1.0f, glm::vec4(0.3f, 1.0f, 0.3f, 0.7f)}}) {
        const auto q = quad(x - 1.2f, y - 1.2f, x + 1.2f, y + 1.2f, z, c, {z, add, 0.0f});
        parts.insert(parts.end(), q.begin(), q.end());
    }
    const BufferHandle partBuffer = b.createBuffer({"particles", BufferKind::Vertex, parts.size() * sizeof(Vertex)},
                                                   std::as_bytes(std::span(parts)));
    PipelineDesc p;
    p.name = "particles";
    p.program = b.createProgram(particles::particleProgram());
    p.blend[0] = BlendState::premultipliedOver();
    const PipelineHandle particlePipeline = b.createPipeline(p);
    p.name = "composite";
    p.program = b.createProgram(particles::layerCompositeProgram());
    const PipelineHandle compositePipeline = b.createPipeline(p);

    PassDesc layerPass;
    layerPass.name = "particles";
    layerPass.color[0] = {layer, LoadOp::Clear, glm::vec4(0.0f)};
    b.beginPass(layerPass);
    DrawDesc d;
    d.pipeline = particlePipeline;
    d.params = particles::ParticleParams{viewProj, depth, stride, proj[3][2], proj[2][2], 0.5f, true};
    d.vertices = partBuffer;
    d.count = std::uint32_t(parts.size());
    b.draw(d);
    b.endPass();

    PassDesc composite;
    composite.name = "composite";
    composite.color[0] = {color, LoadOp::Load};
    b.beginPass(composite);
    DrawDesc c;
    c.pipeline = compositePipeline;
    c.params = particles::LayerCompositeParams{layer, depth, stride, proj[3][2], proj[2][2], true};
    b.draw(c);
    b.endPass();
    return {b.readback(layer), b.readback(color)};
}

float maxDifference(const Readback& a, const Readback& b) {
    EXPECT_EQ(a.values.size(), b.values.size());
    float worst = 0.0f;
    for (std::size_t i = 0; i < std::min(a.values.size(), b.values.size()); ++i)
        worst = std::max(worst, std::abs(a.values[i] - b.values[i]));
    return worst;
}

TEST(ParticlesGl, SoftAndGlAgree) {
    for (int stride : {1, 2}) {
        auto soft = soft::createSoftBackend({1, 64, false});
        auto gl = gl::createGlBackend();
        const Result s = run(*soft, stride), g = run(*gl, stride);
        // README "Differential tolerances": RGBA16F a few half ULPs (llvmpipe rounds toward
        // zero), RGBA8 2 codes (llvmpipe blends 8-bit targets in 8-bit fixed point).
        EXPECT_LE(maxDifference(s.layer, g.layer), 2e-3f) << "stride " << stride;
        EXPECT_LE(maxDifference(s.color, g.color), 2.0f / 255.0f + 1e-6f) << "stride " << stride;
        float layerSum = 0.0f;
        for (float v : s.layer.values) layerSum += v;
        EXPECT_GT(layerSum, 10.0f);  // the particles are really there
    }
}

Readback shafts(Backend& b) {
    const glm::mat4 proj = perspectiveReverseZ(1.0f, float(kW) / kH, 0.1f, 30000.0f);
    const glm::mat4 viewProj = proj * glm::lookAt(glm::vec3(0.0f), glm::vec3(0, 0, 1), glm::vec3(0, 1, 0));
    const auto [color, depth] =
        wallFrame(b, viewProj, quad(-0.8f, -0.6f, 0.37f, 0.9f, 5.0f, glm::vec4(0.2f, 0.5f, 0.1f, 1.0f), {0, 0, -1}),
                  {0.3f, 0.4f, 0.6f, 1.0f});
    const ProgramHandle program = b.createProgram(lightshafts::lightShaftProgram());
    PipelineDesc p;
    p.name = "shafts";
    p.program = program;
    p.blend[0] = {true,         BlendFactor::One, BlendFactor::One, BlendOp::Add, BlendFactor::Zero, BlendFactor::One,
                  BlendOp::Add, WriteRGB};
    const PipelineHandle shaftPipeline = b.createPipeline(p);
    PassDesc shaftPass;
    shaftPass.name = "light shafts";
    shaftPass.color[0] = {color, LoadOp::Load};
    b.beginPass(shaftPass);
    lightshafts::LightShaftParams params;
    params.depth = depth;
    params.sunPixel = {27.3f, 11.6f};  // behind the wall
    params.farDepth = 0.0f;
    params.greaterIsCloser = true;
    params.intensity = 0.8f;
    DrawDesc s;
    s.pipeline = shaftPipeline;
    s.params = params;
    b.draw(s);
    b.endPass();
    return b.readback(color);
}

TEST(LightShaftsGl, SoftAndGlAgree) {
    auto soft = soft::createSoftBackend({1, 64, false});
    auto gl = gl::createGlBackend();
    const Readback s = shafts(*soft), g = shafts(*gl);
    EXPECT_LE(maxDifference(s, g), 2.0f / 255.0f + 1e-6f);  // RGBA8: 2 codes (README)
    float lit = 0.0f;
    for (int y = 0; y < kH; ++y) lit += s.at(2, y, 0) - 0.3f;  // the shafts really add light
    EXPECT_GT(lit, 0.5f);
}

}  // namespace
