// SPDX-License-Identifier: MIT
// Soft backend throughput at 1280x720, each case at 1 and 2 threads (SoftOptions::threads;
// the argument) so the 2-thread speed-up can be read off directly. Wall-clock time
// (UseRealTime) throughout: the work runs on TBB workers, not only the timing thread.
//   DepthOnly     8 full-screen quads at decreasing depth, no colour target, Less + write,
//                 depth cleared each pass (the clear is part of the measured pass)
//   FlatFill      8 full-screen opaque Flat quads into RGBA8 (load, no depth)
//   TexturedAlpha 4 full-screen MaskedLit quads, 256^2 RGBA8 mipmapped texture
//                 (trilinear), alpha test discarding below 0.5 (about half the texels)
//   BlendFill     8 full-screen alpha-over quads (alpha 0.5) into RGBA8
//   SsamMask      SSAM's mask pass ([Hathaway 2010] §3.5.2): 8 receding foliage layers under a
//                 perspective camera, AlphaOnly with the 256^2 texture (trilinear,
//                 repeated 4x), MAX/ADD ONE/ONE blend into RGBA8, depth test without write
//                 (every layer is shaded: the pass's cost scales with depth complexity)
//   SsamColor     the same layers through SSAM's colour pass (§3.5.3): MaskedLit, alpha
//                 test at 64/255, depth test and write, into RGBA8
//   SsamMaskFar, SsamColorFar
//                 the same two passes with the texture repeated 16x instead of 4x: minified
//                 2 to 5 times, so trilinear filtering mixes two mip levels with a log2f per
//                 fragment, as on the distant foliage of the ssam-bench forest
//   SsamMaskHalf  SsamMask onto SSAM+'s float mask (ssam maskPrecision RG16F): two R16F
//                 targets, ONE/ONE MAX into one and ADD into the other (no saturation, so
//                 no layer is skipped where the 8-bit mask would be full)
//   SsamMaskRgba16f  SsamMask onto one RGBA16F target (maskPrecision RGBA16F)
//   SsamComposite SSAM's composite (§3.5.4): a full-screen RGBA8 mask (no foliage over 40%
//                 of it) and sRGB foliage colour blended onto an sRGB target
//   SsamCompositeBlur  SsamComposite as the measured preset draws it: maskLerp 0.9, the
//                 foliage colour blurred over its covered neighbours (colorBlur)
//   SsamPlusComposite  SSAM+'s composite (CoverageComposite, equal layers: a pow() per
//                 partly covered pixel) from the same masks as two R16F targets, the ADD
//                 one unsaturated (up to 4)
//   SmallTris     100k triangles of ~10 px each, Flat into RGBA8 + depth (LessEqual)
//   SetupCulled   1M triangles outside the viewport (inside the guard band): vertex
//                 stage, clipping and setup only, every triangle dropped
//   SetupTiny     1M sub-pixel triangles on screen: setup, binning and block rejection
//   Memcpy        256 MiB memcpy split over the threads: the bandwidth bound
// "Mpix/s" counts pixels that passed coverage (and depth) per second; "Mtri/s" triangles
// submitted per second; "pix/pass" the pixels of one pass. Memory-bandwidth bound for
// depth-only fill: a depth test + write moves 4 bytes read + 4 bytes written per pixel, as
// memcpy reads and writes each byte once, so bound Mpix/s = memcpy bytes/s / 8: Memcpy
// reports that bound as its "Mpix/s" (every run has the same counters, as the CSV and
// JSON reporters require).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <memory>
#include <span>
#include <string>
#include <thread>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "engine/render/soft/soft_backend.hpp"
#include "ssam/composite_program.hpp"
#include "transparency/programs.hpp"
#include "engine/render/vertex.hpp"

namespace {

namespace render = engine::render;
namespace soft = engine::render::soft;

constexpr int kWidth = 1280, kHeight = 720;

template <typename T>
std::span<const std::byte> bytesOf(const std::vector<T>& v) {
    return std::as_bytes(std::span<const T>(v));
}

// A full-screen quad (two counter-clockwise triangles) at clip depth z, uv 0..1.
void appendQuad(std::vector<render::Vertex>& out, float z) {
    auto at = [&](float x, float y) {
        render::Vertex v;
        v.position = {x, y, z};
        v.uv = {0.5f * (x + 1.0f), 0.5f * (1.0f - y)};
        return v;
    };
    const render::Vertex bl = at(-1, -1), br = at(1, -1), tr = at(1, 1), tl = at(-1, 1);
    out.insert(out.end(), {bl, br, tr, bl, tr, tl});
}

render::TextureHandle renderTarget(render::Backend& b, render::Format format) {
    render::TextureDesc d;
    d.name = render::formatName(format);
    d.width = kWidth;
    d.height = kHeight;
    d.format = format;
    d.usage = render::UsageRenderTarget;
    return b.createTexture(d);
}

render::BufferHandle vertexBuffer(render::Backend& b, const std::vector<render::Vertex>& v) {
    return b.createBuffer({"vertices", render::BufferKind::Vertex, v.size() * sizeof(render::Vertex)}, bytesOf(v));
}

// 256x256 RGBA8 with a full mip chain: colour gradients, alpha in soft-edged leaf blobs
// covering about half the texture.
render::TextureHandle foliageTexture(render::Backend& b) {
    constexpr int kSize = 256;
    std::vector<std::uint8_t> texels(kSize * kSize * 4);
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            std::uint8_t* t = &texels[(std::size_t(y) * kSize + x) * 4];
            const float leaf = std::sin(x * 0.19f) * std::sin(y * 0.23f) + 0.3f * std::sin((x + y) * 0.05f);
            t[0] = std::uint8_t(40 + x / 4);
            t[1] = std::uint8_t(120 + y / 3);
            t[2] = std::uint8_t(30 + (x ^ y) / 8);
            t[3] = std::uint8_t(std::clamp(128.0f + 400.0f * leaf, 0.0f, 255.0f));
        }
    render::TextureDesc d;
    d.name = "foliage";
    d.width = d.height = kSize;
    d.mipLevels = 9;
    render::TextureData data;
    data.levels.push_back(std::as_bytes(std::span<const std::uint8_t>(texels)));
    return b.createTexture(d, &data);
}

struct Counts {
    std::uint64_t pixels = 0;
    std::uint64_t triangles = 0;
};

// Runs `pass` once untimed (warm-up, and to measure the work per pass from the backend's
// counters), then once per iteration; reports Mpix/s and Mtri/s.
template <typename Pass>
void runPasses(benchmark::State& state, render::Device& backend, Pass&& pass) {
    const soft::SoftStats before = soft::softDriver(backend).stats();
    pass();
    const soft::SoftStats after = soft::softDriver(backend).stats();
    const Counts perPass{after.pixelsTouched - before.pixelsTouched, after.trianglesIn - before.trianglesIn};
    for (auto _ : state) pass();
    const double n = double(state.iterations());
    state.SetItemsProcessed(std::int64_t(n * double(perPass.pixels ? perPass.pixels : perPass.triangles)));
    state.counters["Mpix/s"] = benchmark::Counter(n * double(perPass.pixels) / 1e6, benchmark::Counter::kIsRate);
    state.counters["Mtri/s"] = benchmark::Counter(n * double(perPass.triangles) / 1e6, benchmark::Counter::kIsRate);
    state.counters["pix/pass"] = double(perPass.pixels);
}

std::unique_ptr<render::Device> makeBackend(const benchmark::State& state) {
    return soft::createSoftBackend({int(state.range(0)), 64, false});
}

void draw(render::Backend& b, render::PipelineHandle p, render::BufferHandle vb, std::uint32_t count,
          const render::DrawParams& params) {
    render::DrawDesc d;
    d.pipeline = p;
    d.params = params;
    d.vertices = vb;
    d.count = count;
    b.draw(d);
}

void BM_DepthOnly(benchmark::State& state) {
    auto backend = makeBackend(state);
    render::Backend& b = *backend;
    const auto depth = renderTarget(b, render::Format::D32F);
    std::vector<render::Vertex> quads;
    for (int i = 0; i < 8; ++i) appendQuad(quads, 0.9f - 0.1f * float(i));
    const auto vb = vertexBuffer(b, quads);
    render::PipelineDesc pd;
    pd.name = "depth-only";
    pd.depth = render::DepthState::testAndWrite(render::CompareFunc::Less);
    const auto pipeline = b.createPipeline(pd);
    render::PassDesc pass;
    pass.name = "depth";
    pass.depth = {depth, render::LoadOp::Clear, 1.0f};
    runPasses(state, *backend, [&] {
        b.beginPass(pass);
        draw(b, pipeline, vb, std::uint32_t(quads.size()), render::FlatParams{});
        b.endPass();
    });
}

// Full-screen quads into an RGBA8 target (loaded, no depth) with the given blend.
void fillColor(benchmark::State& state, const render::BlendState& blend, glm::vec4 color) {
    auto backend = makeBackend(state);
    render::Backend& b = *backend;
    const auto target = renderTarget(b, render::Format::RGBA8_UNORM);
    std::vector<render::Vertex> quads;
    for (int i = 0; i < 8; ++i) appendQuad(quads, 0.5f);
    const auto vb = vertexBuffer(b, quads);
    render::PipelineDesc pd;
    pd.blend[0] = blend;
    const auto pipeline = b.createPipeline(pd);
    render::PassDesc pass;
    pass.name = "fill";
    pass.color[0] = {target, render::LoadOp::Load, glm::vec4(0.0f)};
    runPasses(state, *backend, [&] {
        b.beginPass(pass);
        draw(b, pipeline, vb, std::uint32_t(quads.size()), render::FlatParams{glm::mat4(1.0f), color});
        b.endPass();
    });
}

void BM_FlatFill(benchmark::State& state) { fillColor(state, render::BlendState::opaque(), {0.8f, 0.4f, 0.2f, 1.0f}); }
void BM_BlendFill(benchmark::State& state) {
    fillColor(state, render::BlendState::alphaOver(), {0.8f, 0.4f, 0.2f, 0.5f});
}

void BM_TexturedAlpha(benchmark::State& state) {
    auto backend = makeBackend(state);
    render::Backend& b = *backend;
    const auto target = renderTarget(b, render::Format::RGBA8_UNORM);
    const auto texture = foliageTexture(b);
    std::vector<render::Vertex> quads;
    for (int i = 0; i < 4; ++i) appendQuad(quads, 0.5f);
    const auto vb = vertexBuffer(b, quads);
    render::PipelineDesc pd;
    pd.program = render::ProgramKind::MaskedLit;
    pd.alphaTest = render::AlphaTest::discardBelow(0.5f);
    const auto pipeline = b.createPipeline(pd);
    render::SurfaceParams params;
    params.baseColor = {texture, {}};
    render::PassDesc pass;
    pass.name = "foliage";
    pass.color[0] = {target, render::LoadOp::Load, glm::vec4(0.0f)};
    runPasses(state, *backend, [&] {
        b.beginPass(pass);
        draw(b, pipeline, vb, std::uint32_t(quads.size()), params);
        b.endPass();
    });
}

// 8 vertical 24 x 14 m foliage layers 1 m apart, 6 to 13 m in front of a 60° camera
// looking slightly down the row, so w and the texture LOD vary over every layer; uv 0..repeats.
struct FoliageLayers {
    std::vector<render::Vertex> vertices;
    glm::mat4 viewProj{1.0f};
    explicit FoliageLayers(float repeats) {
        for (int i = 0; i < 8; ++i) {
            const float z = -6.0f - float(i), x0 = -12.0f + 0.7f * float(i), y0 = -7.0f;
            auto at = [&](float u, float v) {
                render::Vertex vertex;
                vertex.position = {x0 + 24.0f * u, y0 + 14.0f * v, z - 2.0f * u};
                vertex.uv = {repeats * u, repeats * (1.0f - v)};
                return vertex;
            };
            const render::Vertex bl = at(0, 0), br = at(1, 0), tr = at(1, 1), tl = at(0, 1);
            vertices.insert(vertices.end(), {bl, br, tr, bl, tr, tl});
        }
        viewProj = glm::perspective(1.04719755f, float(kWidth) / float(kHeight), 0.1f, 100.0f) *
                   glm::lookAt(glm::vec3(0.0f, 0.5f, 0.0f), glm::vec3(0.5f, 0.0f, -8.0f), glm::vec3(0.0f, 1.0f, 0.0f));
    }
};

// How the mask pass stores its mask (ssam::Settings::maskPrecision).
enum class MaskTargets { Rgba8, TwoR16f, Rgba16f };

// One SSAM foliage pass over FoliageLayers(repeats): `mask` the mask pass (into `targets`),
// else the colour pass.
void ssamPass(benchmark::State& state, bool mask, float repeats, MaskTargets targets = MaskTargets::Rgba8) {
    auto backend = makeBackend(state);
    render::Backend& b = *backend;
    const auto target = renderTarget(b, !mask || targets == MaskTargets::Rgba8 ? render::Format::RGBA8_UNORM
                                        : targets == MaskTargets::Rgba16f      ? render::Format::RGBA16F
                                                                               : render::Format::R16F);
    const auto maskAdd =
        targets == MaskTargets::TwoR16f ? renderTarget(b, render::Format::R16F) : render::TextureHandle{};
    const auto depth = renderTarget(b, render::Format::D32F);
    const auto texture = foliageTexture(b);
    const FoliageLayers layers(repeats);
    const auto vb = vertexBuffer(b, layers.vertices);
    render::PipelineDesc pd;
    pd.raster.cull = render::CullMode::None;
    render::DrawParams params;
    if (mask) {
        pd.program = render::ProgramKind::AlphaOnly;
        pd.depth = render::DepthState::testOnly(render::CompareFunc::Less);
        pd.blend[0] = render::BlendState::maxRgbAddAlpha();
        if (maskAdd) {  // as ssam::ScreenSpaceAlphaMask splits it: MAX into one, ADD into the other
            pd.blend[0] = render::BlendState::oneOne(render::BlendOp::Max, render::BlendOp::Max);
            pd.blend[1] = render::BlendState::oneOne(render::BlendOp::Add, render::BlendOp::Add);
        }
        render::AlphaOnlyParams p;
        p.viewProj = layers.viewProj;
        p.baseColor = {texture, {}};
        params = p;
    } else {
        pd.program = render::ProgramKind::MaskedLit;
        pd.depth = render::DepthState::testAndWrite(render::CompareFunc::Less);
        pd.alphaTest = render::AlphaTest::discardBelow(64.0f / 255.0f);
        render::SurfaceParams p;
        p.viewProj = layers.viewProj;
        p.baseColor = {texture, {}};
        params = p;
    }
    const auto pipeline = b.createPipeline(pd);
    render::PassDesc pass;
    pass.name = mask ? "ssam mask" : "ssam colour";
    pass.color[0] = {target, render::LoadOp::Clear, glm::vec4(0.0f)};
    if (maskAdd) pass.color[1] = {maskAdd, render::LoadOp::Clear, glm::vec4(0.0f)};
    pass.depth = {depth, render::LoadOp::Clear, 1.0f};
    runPasses(state, *backend, [&] {
        b.beginPass(pass);
        draw(b, pipeline, vb, std::uint32_t(layers.vertices.size()), params);
        b.endPass();
    });
}
void BM_SsamMask(benchmark::State& state) { ssamPass(state, true, 4.0f); }
void BM_SsamColor(benchmark::State& state) { ssamPass(state, false, 4.0f); }
void BM_SsamMaskFar(benchmark::State& state) { ssamPass(state, true, 16.0f); }
void BM_SsamColorFar(benchmark::State& state) { ssamPass(state, false, 16.0f); }
void BM_SsamMaskHalf(benchmark::State& state) { ssamPass(state, true, 4.0f, MaskTargets::TwoR16f); }
void BM_SsamMaskRgba16f(benchmark::State& state) { ssamPass(state, true, 4.0f, MaskTargets::Rgba16f); }

// A screen-sized RGBA8 texture made by texel(x, y, out) (4 bytes into out).
template <typename Texel>
render::TextureHandle screenTexture(render::Backend& b, const char* name, render::Format format, Texel&& texel) {
    std::vector<std::uint8_t> texels(std::size_t(kWidth) * kHeight * 4);
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) texel(x, y, &texels[(std::size_t(y) * kWidth + x) * 4]);
    render::TextureDesc d;
    d.name = name;
    d.width = kWidth;
    d.height = kHeight;
    d.format = format;
    render::TextureData data;
    data.levels.push_back(std::as_bytes(std::span<const std::uint8_t>(texels)));
    return b.createTexture(d, &data);
}

// The foliage colour the composite benchmarks blend over the frame: an opaque sRGB pattern.
render::TextureHandle compositeFoliage(render::Backend& b) {
    return screenTexture(b, "foliage", render::Format::RGBA8_SRGB, [](int x, int y, std::uint8_t* t) {
        t[0] = std::uint8_t(40 + x % 64);
        t[1] = std::uint8_t(120 + y % 96);
        t[2] = std::uint8_t(30 + (x ^ y) % 32);
        t[3] = 255;
    });
}

// A full-screen composite of `program` with `params` over `target`, blended as SSAM's
// composite is drawn: SRC_ALPHA / INV_SRC_ALPHA on RGB, the target's alpha kept.
void runComposite(benchmark::State& state, render::Device& b, render::TextureHandle target,
                  const render::ProgramDesc& program, const render::DrawParams& params, const char* name) {
    render::PipelineDesc pd;
    pd.program = b.createProgram(program);
    pd.blend[0] = render::BlendState::alphaOverKeepAlpha();
    const auto pipeline = b.createPipeline(pd);
    render::PassDesc pass;
    pass.name = name;
    pass.color[0] = {target, render::LoadOp::Clear, glm::vec4(0.3f, 0.5f, 0.8f, 1.0f)};
    runPasses(state, b, [&] {
        b.beginPass(pass);
        render::DrawDesc d;
        d.pipeline = pipeline;
        d.params = params;
        b.draw(d);
        b.endPass();
    });
}

// The composite benchmarks' foliage coverage at (x, y): zero left of 40% of the width (no
// foliage there), then soft leaf-like blobs.
float compositeLeaf(int x, int y) {
    const float leaf = std::sin(float(x) * 0.11f) * std::sin(float(y) * 0.13f);
    return x < kWidth * 2 / 5 ? 0.0f : std::clamp(0.5f + leaf, 0.0f, 1.0f);
}

// SSAM's 8-bit mask of compositeLeaf: MAX in r, ADD in a, saturating where the blobs overlap.
render::TextureHandle compositeMask(render::Backend& b) {
    return screenTexture(b, "mask", render::Format::RGBA8_UNORM, [](int x, int y, std::uint8_t* t) {
        const float m = compositeLeaf(x, y);
        t[0] = t[1] = t[2] = std::uint8_t(255.0f * m);
        t[3] = std::uint8_t(std::min(255.0f, 400.0f * m));
    });
}

void BM_SsamComposite(benchmark::State& state) {
    auto backend = makeBackend(state);
    render::Backend& b = *backend;
    const auto target = renderTarget(b, render::Format::RGBA8_SRGB);
    ssam::CompositeParams params;
    params.foliage = compositeFoliage(b);
    params.mask = compositeMask(b);
    runComposite(state, *backend, target, ssam::compositeProgram(), params, "ssam composite");
}

// SsamComposite as the measured preset draws it (ssam/docs/knobs.md): maskLerp 0.9 and the
// foliage colour blurred over its covered neighbours, the foliage's alpha that of the leaves
// (0 where the mask is, soft at their edges).
void BM_SsamCompositeBlur(benchmark::State& state) {
    auto backend = makeBackend(state);
    render::Backend& b = *backend;
    const auto target = renderTarget(b, render::Format::RGBA8_SRGB);
    const auto mask = compositeMask(b);
    const auto foliage = screenTexture(b, "foliage", render::Format::RGBA8_SRGB, [](int x, int y, std::uint8_t* t) {
        t[0] = std::uint8_t(40 + x % 64);
        t[1] = std::uint8_t(120 + y % 96);
        t[2] = std::uint8_t(30 + (x ^ y) % 32);
        t[3] = std::uint8_t(std::min(255.0f, 510.0f * compositeLeaf(x, y)));
    });
    ssam::CompositeParams params;
    params.foliage = foliage;
    params.mask = mask;
    params.maskLerp = 0.9f;
    params.colorBlur = true;
    runComposite(state, *backend, target, ssam::compositeProgram(), params, "ssam composite (blur)");
}

// A screen-sized R16F texture holding value(x, y).
template <typename Value>
render::TextureHandle screenHalfTexture(render::Backend& b, const char* name, Value&& value) {
    std::vector<float> values(std::size_t(kWidth) * kHeight);
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) values[std::size_t(y) * kWidth + x] = value(x, y);
    render::TextureDesc d;
    d.name = name;
    d.width = kWidth;
    d.height = kHeight;
    d.format = render::Format::R16F;
    render::TextureData data;
    data.levels.push_back(std::as_bytes(std::span<const float>(values)));
    return b.createTexture(d, &data);
}

void BM_SsamPlusComposite(benchmark::State& state) {
    auto backend = makeBackend(state);
    render::Backend& b = *backend;
    const auto target = renderTarget(b, render::Format::RGBA8_SRGB);
    // SsamComposite's masks in floats: MAX in [0, 1], ADD up to 4 (depth complexity).
    const auto mask = screenHalfTexture(b, "mask max", compositeLeaf);
    const auto maskAdd = screenHalfTexture(
        b, "mask add", [&](int x, int y) { return compositeLeaf(x, y) * (1.0f + float(x % 7) * 0.5f); });
    const auto foliage = compositeFoliage(b);
    runComposite(
        state, *backend, target, transparency::coverageCompositeProgram(),
        transparency::CoverageCompositeParams{foliage, mask, maskAdd, transparency::CoverageModel::EqualLayers},
        "ssam+ composite");
}

// 100k right triangles with 4.5 px legs (~10 px each) on a 400 x 250 grid over the screen.
void BM_SmallTris(benchmark::State& state) {
    auto backend = makeBackend(state);
    render::Backend& b = *backend;
    const auto target = renderTarget(b, render::Format::RGBA8_UNORM);
    const auto depth = renderTarget(b, render::Format::D32F);
    std::vector<render::Vertex> tris;
    constexpr int kCols = 400, kRows = 250;
    tris.reserve(std::size_t(kCols) * kRows * 3);
    auto vertex = [](float px, float py, float z) {
        render::Vertex v;
        v.position = {2.0f * px / kWidth - 1.0f, 1.0f - 2.0f * py / kHeight, z};
        return v;
    };
    for (int r = 0; r < kRows; ++r)
        for (int c = 0; c < kCols; ++c) {
            const float x = (c + 0.37f) * (float(kWidth) / kCols), y = (r + 0.21f) * (float(kHeight) / kRows);
            const float z = 0.2f + 0.6f * float((r * 7 + c * 13) % 64) / 64.0f;
            tris.push_back(vertex(x, y + 4.5f, z));
            tris.push_back(vertex(x + 4.5f, y + 4.5f, z));
            tris.push_back(vertex(x, y, z));
        }
    const auto vb = vertexBuffer(b, tris);
    render::PipelineDesc pd;
    pd.depth = render::DepthState::testAndWrite(render::CompareFunc::LessEqual);
    const auto pipeline = b.createPipeline(pd);
    render::PassDesc pass;
    pass.name = "small";
    pass.color[0] = {target, render::LoadOp::Load, glm::vec4(0.0f)};
    pass.depth = {depth, render::LoadOp::Clear, 1.0f};
    runPasses(state, *backend, [&] {
        b.beginPass(pass);
        draw(b, pipeline, vb, std::uint32_t(tris.size()), render::FlatParams{});
        b.endPass();
    });
}

// 1M triangles through the geometry stage; `onScreen`: sub-pixel ones spread over the
// screen (binned, rejected by the block test), else all left of the viewport (culled).
void setupThroughput(benchmark::State& state, bool onScreen) {
    auto backend = makeBackend(state);
    render::Backend& b = *backend;
    const auto target = renderTarget(b, render::Format::RGBA8_UNORM);
    constexpr int kTriangles = 1'000'000;
    std::vector<render::Vertex> tris;
    tris.reserve(kTriangles * 3);
    std::uint32_t seed = 12345;
    auto rnd = [&] {
        seed = seed * 1664525u + 1013904223u;
        return float(seed >> 8) / float(1 << 24);
    };
    for (int t = 0; t < kTriangles; ++t) {
        const float cx = onScreen ? rnd() * 2.0f - 1.0f : -1.5f - rnd(), cy = rnd() * 2.0f - 1.0f;
        const float s = 0.5f / kWidth;  // half a pixel
        render::Vertex v;
        v.position = {cx, cy, 0.5f};
        tris.push_back(v);
        v.position = {cx + 2 * s, cy, 0.5f};
        tris.push_back(v);
        v.position = {cx, cy + 2 * s, 0.5f};
        tris.push_back(v);
    }
    const auto vb = vertexBuffer(b, tris);
    const auto pipeline = b.createPipeline({});
    render::PassDesc pass;
    pass.name = "setup";
    pass.color[0] = {target, render::LoadOp::Load, glm::vec4(0.0f)};
    runPasses(state, *backend, [&] {
        b.beginPass(pass);
        draw(b, pipeline, vb, std::uint32_t(tris.size()), render::FlatParams{});
        b.endPass();
    });
}
void BM_SetupCulled(benchmark::State& state) { setupThroughput(state, false); }
void BM_SetupTiny(benchmark::State& state) { setupThroughput(state, true); }

void BM_Memcpy(benchmark::State& state) {
    constexpr std::size_t kBytes = std::size_t(256) << 20;
    const int threads = int(state.range(0));
    std::vector<char> src(kBytes, 1), dst(kBytes, 2);
    auto copy = [&] {
        if (threads == 1) {
            std::memcpy(dst.data(), src.data(), kBytes);
            return;
        }
        std::vector<std::thread> workers;
        const std::size_t part = kBytes / std::size_t(threads);
        for (int i = 0; i < threads; ++i)
            workers.emplace_back([&, i] { std::memcpy(dst.data() + i * part, src.data() + i * part, part); });
        for (std::thread& w : workers) w.join();
    };
    copy();
    for (auto _ : state) {
        copy();
        benchmark::ClobberMemory();
    }
    state.SetBytesProcessed(std::int64_t(state.iterations()) * std::int64_t(kBytes));
    // The depth-only bound (see the header): 8 bytes of traffic per pixel.
    state.counters["Mpix/s"] =
        benchmark::Counter(double(state.iterations()) * double(kBytes) / 8.0 / 1e6, benchmark::Counter::kIsRate);
    state.counters["Mtri/s"] = 0.0;
    state.counters["pix/pass"] = 0.0;
}

#define SOFT_BENCH(fn) BENCHMARK(fn)->Arg(1)->Arg(2)->ArgName("threads")->UseRealTime()->Unit(benchmark::kMillisecond)
SOFT_BENCH(BM_DepthOnly);
SOFT_BENCH(BM_FlatFill);
SOFT_BENCH(BM_TexturedAlpha);
SOFT_BENCH(BM_BlendFill);
SOFT_BENCH(BM_SsamMask);
SOFT_BENCH(BM_SsamColor);
SOFT_BENCH(BM_SsamMaskFar);
SOFT_BENCH(BM_SsamColorFar);
SOFT_BENCH(BM_SsamMaskHalf);
SOFT_BENCH(BM_SsamMaskRgba16f);
SOFT_BENCH(BM_SsamComposite);
SOFT_BENCH(BM_SsamCompositeBlur);
SOFT_BENCH(BM_SsamPlusComposite);
SOFT_BENCH(BM_SmallTris);
SOFT_BENCH(BM_SetupCulled);
SOFT_BENCH(BM_SetupTiny);
SOFT_BENCH(BM_Memcpy);

}  // namespace

BENCHMARK_MAIN();
