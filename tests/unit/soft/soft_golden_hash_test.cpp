// SPDX-License-Identifier: MIT
// Bit-exactness guard for the soft backend's fast paths: a set of scenes that together
// exercise every rasterizer path (depth-only, plain stores, every blend factor/op, sRGB,
// 8/16/32-bit targets, alpha test fail modes, MSAA with alpha-to-coverage, scissor,
// near-plane clipping, textures with mips, the composite program) rendered and hashed.
//   * every scene must hash the same for 1 and 2 threads and for tile sizes 8, 24 and 64
//     (the backend promises bit-identical images for any thread count), and
//   * the hashes are pinned: an optimisation that changes a single stored bit fails here.
// When a change is meant to alter the images, rerun with SSAM_PRINT_GOLDEN_HASHES=1 and
// update the hashes in scenes(). Scenes use a fixed LCG, never <random> distributions
// (implementation-defined).
#include <array>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <initializer_list>
#include <optional>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "draws.hpp"  // tests/support
#include "lcg.hpp"    // tests/support
#include "engine/core/error.hpp"
#include "engine/render/soft/soft_backend.hpp"
#include "ssam/composite_program.hpp"
#include "engine/render/vertex.hpp"

namespace {

namespace render = engine::render;
namespace soft = engine::render::soft;
using render::Format;

using ssam::testing::Lcg;
using ssam::testing::fullscreenDraw;
using ssam::testing::meshDraw;

struct Hasher {
    std::uint64_t h = 1469598103934665603ull;
    void bytes(const void* p, std::size_t n) {
        const auto* b = static_cast<const unsigned char*>(p);
        for (std::size_t i = 0; i < n; ++i) h = (h ^ b[i]) * 1099511628211ull;
    }
    void readback(const render::Readback& r) {
        bytes(&r.width, sizeof r.width);
        bytes(&r.height, sizeof r.height);
        bytes(r.values.data(), r.values.size() * sizeof(float));
    }
    // Each target read back from `b` and hashed, in this order.
    template <class Handles>
    void targets(render::Backend& b, const Handles& handles) {
        for (render::TextureHandle t : handles) readback(b.readback(t));
    }
    void targets(render::Backend& b, std::initializer_list<render::TextureHandle> handles) {
        targets<std::initializer_list<render::TextureHandle>>(b, handles);
    }
};

template <typename T>
std::span<const std::byte> bytesOf(const std::vector<T>& v) {
    return std::as_bytes(std::span<const T>(v));
}

constexpr int kW = 203, kH = 141;  // not multiples of any tile size

render::TextureHandle target(render::Backend& b, Format f, int samples = 1, int w = kW, int h = kH) {
    return b.createTexture(render::renderTargetDesc("target", w, h, f, samples));
}

// A 64x64 RGBA8 texture with a full mip chain, colour noise and alpha from 0 to 1.
render::TextureHandle noiseTexture(render::Backend& b, Format f, render::AlphaMode alpha) {
    Lcg rng{77};
    std::vector<std::uint8_t> texels(64 * 64 * 4);
    for (std::size_t i = 0; i < texels.size(); ++i) texels[i] = std::uint8_t(rng.next() >> 7);
    render::TextureDesc d;
    d.name = "noise";
    d.width = d.height = 64;
    d.format = f;
    d.mipLevels = 7;
    d.alpha = alpha;
    render::TextureData data;
    data.levels.push_back(std::as_bytes(std::span<const std::uint8_t>(texels)));
    return b.createTexture(d, &data);
}

// Random triangles: sizes from sub-pixel to larger than the target, some reaching behind
// the near plane (w small or negative) or outside the guard band of the view.
std::vector<render::Vertex> randomTriangles(Lcg& rng, int count, float maxSize, bool perspective) {
    std::vector<render::Vertex> v;
    for (int t = 0; t < count; ++t) {
        const float cx = rng.range(-1.3f, 1.3f), cy = rng.range(-1.3f, 1.3f), size = maxSize * rng.unit() * rng.unit();
        for (int k = 0; k < 3; ++k) {
            render::Vertex vx;
            const float z = rng.range(0.05f, 0.95f);
            vx.position = {cx + rng.range(-size, size), cy + rng.range(-size, size),
                           perspective ? -1.0f - 4.0f * z : z};
            vx.normal = glm::normalize(glm::vec3(rng.range(-1, 1), rng.range(-1, 1), 0.5f));
            vx.uv = {rng.range(-1.0f, 2.0f), rng.range(-1.0f, 2.0f)};
            vx.color = {rng.unit(), rng.unit(), rng.unit(), rng.range(-0.1f, 1.1f)};
            v.push_back(vx);
        }
    }
    return v;
}

// One colour target of each format, for a pass of four colour attachments (MRT).
std::array<render::TextureHandle, 4> targetsOf(render::Backend& b, const std::array<Format, 4>& formats) {
    std::array<render::TextureHandle, 4> targets;
    for (int i = 0; i < 4; ++i) targets[i] = target(b, formats[i]);
    return targets;
}

render::BufferHandle vertexBuffer(render::Backend& b, const std::vector<render::Vertex>& v) {
    return b.createBuffer({"vb", render::BufferKind::Vertex, v.size() * sizeof(render::Vertex)}, bytesOf(v));
}

glm::mat4 perspectiveViewProj() {
    // Clip z in [0, w]: GLM's zero-to-one projection.
    return glm::perspectiveRH_ZO(glm::radians(70.0f), float(kW) / kH, 0.5f, 20.0f);
}

void drawTriangles(render::Backend& b, render::PipelineHandle p, render::BufferHandle vb, std::uint32_t count,
                   render::DrawParams params, std::optional<render::Rect> scissor = std::nullopt) {
    auto d = meshDraw(p, params, vb, count);
    d.scissor = scissor;
    b.draw(d);
}

using Scene = std::function<void(render::Backend&, Hasher&)>;

// Flat triangles into RGBA8 + depth (Less), then LessEqual test-only on top.
void sceneFlatDepth(render::Backend& b, Hasher& h) {
    Lcg rng{1};
    const auto color = target(b, Format::RGBA8_UNORM), depth = target(b, Format::D32F);
    const auto tris = randomTriangles(rng, 300, 0.6f, false);
    const auto vb = vertexBuffer(b, tris);
    render::PipelineDesc pd;
    pd.depth = render::DepthState::testAndWrite(render::CompareFunc::Less);
    const auto p = b.createPipeline(pd);
    pd.depth = render::DepthState::testOnly(render::CompareFunc::LessEqual);
    pd.raster.cull = render::CullMode::Back;
    const auto p2 = b.createPipeline(pd);
    render::PassDesc pass;
    pass.name = "flat";
    pass.color[0] = {color, render::LoadOp::Clear, glm::vec4(0.1f, 0.2f, 0.3f, 1.0f)};
    pass.depth = {depth, render::LoadOp::Clear, 1.0f};
    b.beginPass(pass);
    drawTriangles(b, p, vb, 600, render::FlatParams{glm::mat4(1.0f), glm::vec4(0.9f, 0.8f, 0.7f, 1.0f)});
    drawTriangles(b, p2, vb, 300, render::FlatParams{glm::mat4(1.0f), glm::vec4(0.2f, 0.9f, 0.4f, 0.5f)},
                  render::Rect{17, 9, 150, 100});
    b.endPass();
    h.targets(b, {color, depth});
}

// A depth-only pre-pass (no colour target, reverse-Z), then Equal-tested colour.
void sceneDepthPrepass(render::Backend& b, Hasher& h) {
    Lcg rng{2};
    const auto color = target(b, Format::RGBA8_SRGB), depth = target(b, Format::D32F);
    const auto vb = vertexBuffer(b, randomTriangles(rng, 400, 0.5f, true));
    render::PipelineDesc pd;
    pd.depth = render::DepthState::testAndWrite(render::CompareFunc::Greater);
    const auto pre = b.createPipeline(pd);
    pd.depth = render::DepthState::testOnly(render::CompareFunc::Equal);
    pd.program = render::ProgramKind::OpaqueLit;
    const auto shade = b.createPipeline(pd);
    render::PassDesc prepass;
    prepass.name = "prepass";
    prepass.depth = {depth, render::LoadOp::Clear, 0.0f};
    const glm::mat4 vp = perspectiveViewProj();
    b.beginPass(prepass);
    drawTriangles(b, pre, vb, 1200, render::FlatParams{vp, glm::vec4(1.0f)});
    b.endPass();
    render::PassDesc main;
    main.name = "main";
    main.color[0] = {color, render::LoadOp::Clear, glm::vec4(0.5f, 0.25f, 0.125f, 1.0f)};
    main.depth = {depth, render::LoadOp::Load, 0.0f};
    b.beginPass(main);
    render::SurfaceParams sp;
    sp.viewProj = vp;
    drawTriangles(b, shade, vb, 1200, sp);
    b.endPass();
    h.targets(b, {color, depth});
}

// Textured foliage: alpha test with each fail mode, mipmapped trilinear/bilinear/nearest.
void sceneFoliage(render::Backend& b, Hasher& h) {
    Lcg rng{3};
    const auto color = target(b, Format::RGBA8_UNORM), depth = target(b, Format::D32F);
    const auto tex = noiseTexture(b, Format::RGBA8_SRGB, render::AlphaMode::Straight);
    const auto texPre = noiseTexture(b, Format::RGBA8_UNORM, render::AlphaMode::Premultiplied);
    const auto vb = vertexBuffer(b, randomTriangles(rng, 200, 0.7f, true));
    render::PassDesc pass;
    pass.name = "foliage";
    pass.color[0] = {color, render::LoadOp::Clear, glm::vec4(0.0f, 0.0f, 0.0f, 0.0f)};
    pass.depth = {depth, render::LoadOp::Clear, 1.0f};
    b.beginPass(pass);
    const render::AlphaFailMode modes[] = {render::AlphaFailMode::Keep, render::AlphaFailMode::FbOnly,
                                           render::AlphaFailMode::ZbOnly, render::AlphaFailMode::RgbOnly};
    const render::Filter filters[] = {render::Filter::Trilinear, render::Filter::Bilinear, render::Filter::Nearest,
                                      render::Filter::Trilinear};
    const render::AddressMode addr[] = {render::AddressMode::Wrap, render::AddressMode::Clamp,
                                        render::AddressMode::Mirror, render::AddressMode::Wrap};
    for (int i = 0; i < 4; ++i) {
        render::PipelineDesc pd;
        pd.program = render::ProgramKind::MaskedLit;
        pd.depth = render::DepthState::testAndWrite(render::CompareFunc::LessEqual);
        pd.alphaTest = {true, i == 3 ? render::CompareFunc::Less : render::CompareFunc::GreaterEqual, 0.4f + 0.05f * i,
                        modes[i], false};
        pd.blend[0].writeMask = i == 2 ? std::uint8_t(render::WriteRGB) : std::uint8_t(render::WriteAll);
        render::SurfaceParams sp;
        sp.viewProj = perspectiveViewProj() * glm::translate(glm::mat4(1.0f), glm::vec3(0.1f * i, 0.0f, 0.0f));
        sp.baseColor = {i == 3 ? texPre : tex, {filters[i], addr[i], addr[(i + 1) % 4]}};
        sp.baseColorFactor = {1.0f, 0.9f, 0.8f, 1.0f};
        drawTriangles(b, b.createPipeline(pd), vb, 600, sp);
    }
    b.endPass();
    h.targets(b, {color, depth});
}

// Every blend factor and op, on RGBA8, sRGB, RGBA16F and RGBA32F targets at once (MRT).
void sceneBlendMatrix(render::Backend& b, Hasher& h) {
    Lcg rng{4};
    const std::array<render::TextureHandle, 4> targets =
        targetsOf(b, {Format::RGBA8_UNORM, Format::RGBA8_SRGB, Format::RGBA16F, Format::RGBA32F});
    const auto vb = vertexBuffer(b, randomTriangles(rng, 60, 0.9f, false));
    render::PassDesc pass;
    pass.name = "blend";
    for (int i = 0; i < 4; ++i)
        pass.color[i] = {targets[i], render::LoadOp::Clear, glm::vec4(0.3f + 0.1f * i, 0.6f, 0.9f - 0.2f * i, 0.7f)};
    b.beginPass(pass);
    int drawn = 0;
    for (render::BlendFactor s : render::kAllBlendFactors) {
        for (render::BlendFactor d : render::kAllBlendFactors) {
            const render::BlendOp op = render::kAllBlendOps[(int(s) + int(d)) % 5];
            render::PipelineDesc pd;
            pd.blendConstant = {0.25f, 0.5f, 0.75f, 0.6f};
            for (int i = 0; i < 4; ++i) {
                pd.blend[i] = {true,
                               s,
                               d,
                               op,
                               render::kAllBlendFactors[(int(s) + i) % 15],
                               render::kAllBlendFactors[(int(d) + 2 * i) % 15],
                               render::kAllBlendOps[(int(op) + i) % 5],
                               std::uint8_t(15 - ((int(s) * 3 + i) % 4 == 0 ? 1 << (int(d) % 4) : 0))};
            }
            const auto p = b.createPipeline(pd);
            const std::uint32_t first = std::uint32_t((drawn * 7) % 60) * 3;
            render::DrawDesc dd;
            dd.pipeline = p;
            dd.params = render::FlatParams{glm::mat4(1.0f), glm::vec4(1.2f, 0.7f, -0.1f, 0.55f)};
            dd.vertices = vb;
            dd.first = first;
            dd.count = 3;
            b.draw(dd);
            ++drawn;
        }
    }
    b.endPass();
    h.targets(b, targets);
}

// The common presets and plain stores into R8 / RG8 / RG16F / R32F, with write masks.
void scenePresetsSmallFormats(render::Backend& b, Hasher& h) {
    Lcg rng{5};
    const std::array<render::TextureHandle, 4> targets =
        targetsOf(b, {Format::R8_UNORM, Format::RG8_UNORM, Format::RG16F, Format::R32F});
    const auto vb = vertexBuffer(b, randomTriangles(rng, 500, 0.4f, false));
    const render::BlendState presets[] = {render::BlendState::opaque(), render::BlendState::alphaOver(),
                                          render::BlendState::premultipliedOver(),
                                          render::BlendState::maxRgbAddAlpha()};
    render::PassDesc pass;
    pass.name = "small";
    for (int i = 0; i < 4; ++i) pass.color[i] = {targets[i], render::LoadOp::Clear, glm::vec4(0.25f)};
    b.beginPass(pass);
    for (int k = 0; k < 4; ++k) {
        render::PipelineDesc pd;
        for (int i = 0; i < 4; ++i) {
            pd.blend[i] = presets[(k + i) % 4];
            if (k == 3) pd.blend[i].writeMask = render::WriteR | render::WriteA;
        }
        render::DrawDesc dd;
        dd.pipeline = b.createPipeline(pd);
        dd.params = render::FlatParams{glm::mat4(1.0f), glm::vec4(1.0f, 0.5f, 0.25f, 0.6f)};
        dd.vertices = vb;
        dd.first = std::uint32_t(k * 375);
        dd.count = 375;
        b.draw(dd);
    }
    b.endPass();
    h.targets(b, targets);
}

// MSAA with alpha-to-coverage and an SSAM mask into a float target, resolved.
template <int Samples>
void sceneMsaa(render::Backend& b, Hasher& h) {
    Lcg rng{6};
    const auto msColor = target(b, Format::RGBA8_SRGB, Samples), msMask = target(b, Format::RGBA16F, Samples);
    const auto msDepth = target(b, Format::D32F, Samples);
    const auto color = target(b, Format::RGBA8_SRGB), mask = target(b, Format::RGBA16F);
    const auto depth = target(b, Format::D32F);
    const auto tex = noiseTexture(b, Format::RGBA8_UNORM, render::AlphaMode::Straight);
    const auto vb = vertexBuffer(b, randomTriangles(rng, 250, 0.5f, true));
    render::PassDesc pass;
    pass.name = "msaa";
    pass.color[0] = {msColor, render::LoadOp::Clear, glm::vec4(0.2f, 0.4f, 0.6f, 1.0f)};
    pass.color[1] = {msMask, render::LoadOp::Clear, glm::vec4(0.0f)};
    pass.depth = {msDepth, render::LoadOp::Clear, 1.0f};
    b.beginPass(pass);
    render::PipelineDesc pd;
    pd.program = render::ProgramKind::MaskedLit;
    pd.depth = render::DepthState::testAndWrite();
    pd.alphaTest = {true, render::CompareFunc::Greater, 0.3f, render::AlphaFailMode::Keep, true};
    pd.blend[1] = render::BlendState::maxRgbAddAlpha();
    render::SurfaceParams sp;
    sp.viewProj = perspectiveViewProj();
    sp.baseColor = {tex, {}};
    drawTriangles(b, b.createPipeline(pd), vb, 750, sp);
    b.endPass();
    b.resolve({msColor, color});
    b.resolve({msMask, mask});
    b.resolve({msDepth, depth, render::CompareFunc::Less});
    h.targets(b, {color, mask, depth});
}

// Full-screen composite under a scissor, onto an sRGB target.
void sceneComposite(render::Backend& b, Hasher& h) {
    Lcg rng{7};
    const auto foliage = target(b, Format::RGBA8_UNORM), mask = target(b, Format::RGBA16F);
    const auto maskAdd = target(b, Format::R16F), out = target(b, Format::RGBA8_SRGB);
    const auto vb = vertexBuffer(b, randomTriangles(rng, 200, 0.5f, false));
    render::PassDesc pre;
    pre.name = "inputs";
    pre.color[0] = {foliage, render::LoadOp::Clear, glm::vec4(0.0f)};
    pre.color[1] = {mask, render::LoadOp::Clear, glm::vec4(0.0f)};
    pre.color[2] = {maskAdd, render::LoadOp::Clear, glm::vec4(0.0f)};
    render::PipelineDesc pd;
    pd.blend[1] = render::BlendState::maxRgbAddAlpha();
    pd.blend[2] = render::BlendState::maxRgbAddAlpha();
    b.beginPass(pre);
    drawTriangles(b, b.createPipeline(pd), vb, 600,
                  render::FlatParams{glm::mat4(1.0f), glm::vec4(0.9f, 0.6f, 0.3f, 0.4f)});
    b.endPass();
    render::PassDesc comp;
    comp.name = "composite";
    comp.color[0] = {out, render::LoadOp::Clear, glm::vec4(0.05f, 0.1f, 0.2f, 1.0f)};
    render::PipelineDesc cd;
    cd.program = b.createProgram(ssam::compositeProgram());
    cd.blend[0] = render::BlendState::alphaOver();
    const auto cp = b.createPipeline(cd);
    b.beginPass(comp);
    for (int i = 0; i < 2; ++i) {
        auto d = fullscreenDraw(
            cp, ssam::CompositeParams{foliage, mask, i == 1 ? maskAdd : render::TextureHandle{}, 0.85f, i == 0});
        d.scissor = render::Rect{10 + 40 * i, 5, 120, 130};
        b.draw(d);
    }
    b.endPass();
    h.readback(b.readback(out));
}

// Many tiny triangles (the small-triangle benchmark's case), instanced, culled both ways.
void sceneTinyInstanced(render::Backend& b, Hasher& h) {
    Lcg rng{8};
    const auto color = target(b, Format::RGBA8_UNORM), depth = target(b, Format::D32F);
    const auto vb = vertexBuffer(b, randomTriangles(rng, 3000, 0.08f, false));
    std::vector<render::Instance> inst(3);
    for (int i = 0; i < 3; ++i) {
        inst[i].model = glm::translate(glm::mat4(1.0f), glm::vec3(0.05f * i, -0.03f * i, 0.0f));
        inst[i].tint = {1.0f - 0.2f * i, 0.5f, 0.2f * i, 1.0f};
    }
    const auto ib =
        b.createBuffer({"inst", render::BufferKind::Instance, inst.size() * sizeof(render::Instance)}, bytesOf(inst));
    render::PipelineDesc pd;
    pd.depth = render::DepthState::testAndWrite(render::CompareFunc::LessEqual);
    pd.raster = {render::CullMode::Back, render::Winding::Clockwise};
    render::PassDesc pass;
    pass.name = "tiny";
    pass.color[0] = {color, render::LoadOp::Clear, glm::vec4(0.0f, 0.0f, 0.0f, 1.0f)};
    pass.depth = {depth, render::LoadOp::Clear, 1.0f};
    b.beginPass(pass);
    auto d = meshDraw(b.createPipeline(pd), render::FlatParams{glm::mat4(1.0f), glm::vec4(1.0f)}, vb, 9000);
    d.instances = ib;
    d.instanceCount = 3;
    b.draw(d);
    pd.raster = {render::CullMode::Front, render::Winding::Clockwise};
    pd.blend[0] = render::BlendState::premultipliedOver();
    d.pipeline = b.createPipeline(pd);
    d.instanceCount = 2;
    b.draw(d);
    b.endPass();
    h.targets(b, {color, depth});
}

// Quads larger than several tiles: depth-only, opaque, alpha-over and alpha-tested
// textured, the bench_soft workloads at a smaller size (whole tiles and blocks covered).
void sceneBigQuads(render::Backend& b, Hasher& h) {
    const auto color = target(b, Format::RGBA8_UNORM), srgb = target(b, Format::RGBA8_SRGB);
    const auto depth = target(b, Format::D32F);
    const auto tex = noiseTexture(b, Format::RGBA8_UNORM, render::AlphaMode::Straight);
    std::vector<render::Vertex> quads;
    const float rects[][5] = {{-1.0f, -1.0f, 1.0f, 1.0f, 0.9f},
                              {-0.93f, -0.71f, 0.77f, 0.97f, 0.6f},
                              {-0.3f, -1.0f, 1.0f, 0.4f, 0.7f},
                              {-1.0f, -0.5f, 0.51f, 0.87f, 0.3f}};
    for (const auto& r : rects) {
        render::Vertex v[4];
        const float xy[4][2] = {{r[0], r[1]}, {r[2], r[1]}, {r[2], r[3]}, {r[0], r[3]}};
        for (int k = 0; k < 4; ++k) {
            v[k].position = {xy[k][0], xy[k][1], r[4]};
            v[k].uv = {xy[k][0] * 1.7f, xy[k][1] * 2.3f};
            v[k].color = {0.5f + 0.5f * xy[k][0], 0.7f, 0.5f - 0.4f * xy[k][1], 0.4f + 0.3f * r[4]};
        }
        quads.insert(quads.end(), {v[0], v[1], v[2], v[0], v[2], v[3]});
    }
    const auto vb = vertexBuffer(b, quads);
    render::PipelineDesc pd;
    pd.depth = render::DepthState::testAndWrite(render::CompareFunc::Less);
    const auto depthOnly = b.createPipeline(pd);
    render::PassDesc pre;
    pre.name = "depth";
    pre.depth = {depth, render::LoadOp::Clear, 1.0f};
    b.beginPass(pre);
    drawTriangles(b, depthOnly, vb, 24, render::FlatParams{});
    b.endPass();
    h.readback(b.readback(depth));

    render::PassDesc pass;
    pass.name = "colour";
    pass.color[0] = {color, render::LoadOp::Clear, glm::vec4(0.1f, 0.2f, 0.3f, 0.4f)};
    pass.color[1] = {srgb, render::LoadOp::Clear, glm::vec4(0.4f, 0.3f, 0.2f, 0.1f)};
    pass.depth = {depth, render::LoadOp::Clear, 1.0f};
    b.beginPass(pass);
    pd.depth = render::DepthState::off();
    drawTriangles(b, b.createPipeline(pd), vb, 6,
                  render::FlatParams{glm::mat4(1.0f), glm::vec4(0.8f, 0.6f, 0.4f, 1.0f)});
    pd.blend[0] = pd.blend[1] = render::BlendState::alphaOver();
    render::DrawDesc d;
    d.pipeline = b.createPipeline(pd);
    d.params = render::FlatParams{glm::mat4(1.0f), glm::vec4(0.3f, 0.9f, 0.6f, 0.5f)};
    d.vertices = vb;
    d.first = 6;
    d.count = 6;
    b.draw(d);
    pd = {};
    pd.program = render::ProgramKind::MaskedLit;
    pd.depth = render::DepthState::testAndWrite(render::CompareFunc::LessEqual);
    pd.alphaTest = render::AlphaTest::discardBelow(0.5f);
    render::SurfaceParams sp;
    sp.baseColor = {tex, {}};
    d.pipeline = b.createPipeline(pd);
    d.params = sp;
    d.first = 12;
    d.count = 12;
    b.draw(d);
    b.endPass();
    h.targets(b, {color, srgb, depth});
}

// Clipping: perspective triangles crossing the near plane and far outside the guard band.
void sceneClipping(render::Backend& b, Hasher& h) {
    Lcg rng{9};
    const auto color = target(b, Format::RGBA8_UNORM), depth = target(b, Format::D32F);
    std::vector<render::Vertex> tris;
    for (int t = 0; t < 120; ++t) {
        for (int k = 0; k < 3; ++k) {
            render::Vertex v;
            const float spread = t % 3 == 0 ? 4000.0f : 6.0f;  // some far beyond the guard band
            v.position = {rng.range(-spread, spread), rng.range(-spread, spread) * 0.5f, rng.range(-8.0f, 1.5f)};
            v.uv = {rng.unit(), rng.unit()};
            v.color = {rng.unit(), rng.unit(), rng.unit(), 1.0f};
            tris.push_back(v);
        }
    }
    const auto vb = vertexBuffer(b, tris);
    render::PipelineDesc pd;
    pd.depth = render::DepthState::testAndWrite(render::CompareFunc::LessEqual);
    render::PassDesc pass;
    pass.name = "clip";
    pass.color[0] = {color, render::LoadOp::Clear, glm::vec4(0.0f)};
    pass.depth = {depth, render::LoadOp::Clear, 1.0f};
    b.beginPass(pass);
    drawTriangles(b, b.createPipeline(pd), vb, std::uint32_t(tris.size()),
                  render::FlatParams{perspectiveViewProj(), glm::vec4(1.0f)});
    b.endPass();
    h.targets(b, {color, depth});
}

// Constant-colour triangles (w = 1, one vertex colour): the fragment is the same at every
// pixel. Large and small ones, blends of every kind (including the destination-alpha ones
// a per-channel table cannot do), alpha test fail modes, a -0.0 colour channel.
void sceneConstantColour(render::Backend& b, Hasher& h) {
    Lcg rng{10};
    const auto c0 = target(b, Format::RGBA8_UNORM), c1 = target(b, Format::RGBA8_SRGB);
    const auto c2 = target(b, Format::RGBA16F), depth = target(b, Format::D32F);
    std::vector<render::Vertex> tris;
    for (int t = 0; t < 90; ++t) {
        const float size = t % 3 == 0 ? 2.5f : (t % 3 == 1 ? 0.6f : 0.08f);
        const float cx = rng.range(-1.0f, 1.0f), cy = rng.range(-1.0f, 1.0f), z = rng.range(0.1f, 0.9f);
        for (int k = 0; k < 3; ++k) {
            render::Vertex v;
            v.position = {cx + rng.range(-size, size), cy + rng.range(-size, size), z};
            tris.push_back(v);
        }
    }
    const auto vb = vertexBuffer(b, tris);
    render::PassDesc pass;
    pass.name = "constant";
    pass.color[0] = {c0, render::LoadOp::Clear, glm::vec4(0.2f, 0.4f, 0.6f, 0.8f)};
    pass.color[1] = {c1, render::LoadOp::Clear, glm::vec4(0.7f, 0.5f, 0.3f, 0.1f)};
    pass.color[2] = {c2, render::LoadOp::Clear, glm::vec4(0.5f, -0.25f, 2.0f, 0.5f)};
    pass.depth = {depth, render::LoadOp::Clear, 1.0f};
    b.beginPass(pass);
    const render::BlendState blends[] = {
        render::BlendState::opaque(),
        render::BlendState::alphaOver(),
        render::BlendState::premultipliedOver(),
        render::BlendState::maxRgbAddAlpha(),
        {true, render::BlendFactor::DstColor, render::BlendFactor::InvSrcColor, render::BlendOp::RevSubtract,
         render::BlendFactor::DstAlpha, render::BlendFactor::One, render::BlendOp::Subtract, render::WriteAll},
        {true, render::BlendFactor::DstAlpha, render::BlendFactor::InvDstAlpha, render::BlendOp::Add,
         render::BlendFactor::One, render::BlendFactor::One, render::BlendOp::Add, render::WriteRGB},
        {true, render::BlendFactor::SrcAlphaSat, render::BlendFactor::ConstantColor, render::BlendOp::Add,
         render::BlendFactor::InvConstantAlpha, render::BlendFactor::SrcAlpha, render::BlendOp::Min,
         render::WriteR | render::WriteA},
    };
    const glm::vec4 colors[] = {
        {0.9f, 0.5f, 0.1f, 0.7f}, {1.3f, -0.2f, 0.5f, 0.35f}, {-0.0f, 0.25f, 0.75f, 1.0f}, {0.3f, 0.3f, 0.3f, 0.2f}};
    int drawn = 0;
    for (int k = 0; k < 7; ++k) {
        for (int a = 0; a < 3; ++a) {
            render::PipelineDesc pd;
            pd.blendConstant = {0.1f, 0.6f, 0.3f, 0.45f};
            for (int i = 0; i < 3; ++i) pd.blend[i] = blends[(k + i) % 7];
            pd.depth =
                a == 1 ? render::DepthState::testAndWrite(render::CompareFunc::LessEqual) : render::DepthState::off();
            if (a == 2) {
                const render::AlphaFailMode modes[] = {render::AlphaFailMode::Keep, render::AlphaFailMode::FbOnly,
                                                       render::AlphaFailMode::ZbOnly, render::AlphaFailMode::RgbOnly};
                pd.depth = render::DepthState::testAndWrite(render::CompareFunc::Less);
                pd.alphaTest = {true, render::CompareFunc::Greater, 0.5f, modes[k % 4], false};
            }
            render::DrawDesc d;
            d.pipeline = b.createPipeline(pd);
            d.params = render::FlatParams{glm::mat4(1.0f), colors[drawn % 4]};
            d.vertices = vb;
            d.first = std::uint32_t((drawn * 12) % 270);
            d.count = 12;
            b.draw(d);
            ++drawn;
        }
    }
    b.endPass();
    h.targets(b, {c0, c1, c2, depth});
}

struct GoldenScene {
    const char* name;
    Scene render;
    std::uint64_t hash;
};

// Pinned hashes (see the header comment).
const std::vector<GoldenScene>& scenes() {
    static const std::vector<GoldenScene> k = {
        {"FlatDepth", sceneFlatDepth, 0x7f95133d1b283deeull},
        {"DepthPrepass", sceneDepthPrepass, 0x1a973ed03272d9c4ull},
        {"Foliage", sceneFoliage, 0xc70f89b45435bcdeull},
        {"BlendMatrix", sceneBlendMatrix, 0xbd246e88ca1686a2ull},
        {"PresetsSmallFormats", scenePresetsSmallFormats, 0x70bdec5801eb2125ull},
        {"Msaa2", sceneMsaa<2>, 0x876dbfd1cfa4c044ull},
        {"Msaa4", sceneMsaa<4>, 0x7cb30c5449fe23b0ull},
        {"Msaa8", sceneMsaa<8>, 0xef141b6fbe9406ddull},
        {"Composite", sceneComposite, 0x6a55db376195669dull},
        {"TinyInstanced", sceneTinyInstanced, 0xc4364c58889f3278ull},
        {"Clipping", sceneClipping, 0xe43177e54e8842daull},
        {"ConstantColour", sceneConstantColour, 0x459c36071107bd57ull},
        {"BigQuads", sceneBigQuads, 0x4100c30440bcd5f4ull},
    };
    return k;
}

std::uint64_t renderScene(const Scene& scene, int threads, int tileSize, bool print = false,
                          std::optional<soft::SimdIsa> isa = std::nullopt) {
    auto backend = soft::createSoftBackend({.threads = threads, .tileSize = tileSize, .simd = isa});
    Hasher h;
    scene(*backend, h);
    if (print) {
        const soft::SoftStats s = soft::softDriver(*backend).stats();
        std::printf("  // triangles in %llu, rasterized %llu, dropped %llu; pixels shaded %llu, touched %llu\n",
                    (unsigned long long)s.trianglesIn, (unsigned long long)s.trianglesRasterized,
                    (unsigned long long)s.trianglesDropped, (unsigned long long)s.pixelsShaded,
                    (unsigned long long)s.pixelsTouched);
    }
    return h.h;
}

TEST(SoftGoldenHash, ScenesAreBitExactAndIndependentOfThreadsAndTiles) {
    const bool print = std::getenv("SSAM_PRINT_GOLDEN_HASHES") != nullptr;
    for (const GoldenScene& s : scenes()) {
        const std::uint64_t reference = renderScene(s.render, 1, 64, print);
        if (print) std::printf("        {\"%s\", ..., 0x%016llxull},\n", s.name, (unsigned long long)reference);
        EXPECT_EQ(renderScene(s.render, 2, 64), reference) << s.name << ": 2 threads differ from 1";
        EXPECT_EQ(renderScene(s.render, 2, 8), reference) << s.name << ": tile size 8 differs from 64";
        EXPECT_EQ(renderScene(s.render, 1, 24), reference) << s.name << ": tile size 24 differs from 64";
        if (!print) {
            EXPECT_EQ(reference, s.hash) << s.name << std::hex << ": hash 0x" << reference
                                         << " differs from the pinned 0x" << s.hash;
        }
    }
}

// The wide kernels run in the instruction set the backend picks at run time
// (engine/render/kernel/simd_isa.hpp): each one this CPU runs must draw the pinned bits.
TEST(SoftGoldenHash, EveryInstructionSetDrawsTheSameBits) {
    for (soft::SimdIsa isa : soft::supportedSimdIsas()) {
        for (const GoldenScene& s : scenes()) {
            const std::uint64_t hash = renderScene(s.render, 2, 64, false, isa);
            EXPECT_EQ(hash, s.hash) << s.name << " with " << soft::simdIsaName(isa) << std::hex << ": hash 0x" << hash
                                    << " differs from the pinned 0x" << s.hash;
        }
    }
}

TEST(SoftGoldenHash, InstructionSetNamesParseAndOneTheCpuLacksIsRefused) {
    for (soft::SimdIsa isa : {soft::SimdIsa::Sse2, soft::SimdIsa::Avx2}) {
        if (soft::simdIsaSupported(isa)) continue;
        try {
            soft::createSoftBackend({.simd = isa});
            ADD_FAILURE() << soft::simdIsaName(isa) << " was accepted on a CPU that does not run it";
        } catch (const engine::Error& e) {
            EXPECT_NE(std::string(e.what()).find("does not run"), std::string::npos) << e.what();
        }
    }
    EXPECT_TRUE(soft::simdIsaSupported(soft::SimdIsa::Sse2)) << "x86-64's baseline";
    EXPECT_EQ(soft::parseSimdIsa("avx2"), soft::SimdIsa::Avx2);
    EXPECT_EQ(soft::parseSimdIsa("sse2"), soft::SimdIsa::Sse2);
    EXPECT_FALSE(soft::parseSimdIsa("avx512"));
}

}  // namespace
