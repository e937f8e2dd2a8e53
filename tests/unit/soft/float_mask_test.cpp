// SPDX-License-Identifier: MIT
// The soft backend's float-mask fast paths against the general path, bit for bit, on whole
// random scenes: SSAM's mask pass (AlphaOnly, ONE/ONE MAX and ADD, [Hathaway 2010] §3.5.2)
// onto half-float targets as maskPrecision RG16F (two R16F targets; SSAM+) and RGBA16F
// store it, and the SSAM / SSAM+ composites onto RGBA8 targets from float and 8-bit masks.
// The targets start with arbitrary halves (NaN, infinities, -0, denormals, values past 1
// and 2048) so that every case of the float blend rules is reached, not only what a
// cleared mask holds. Two references:
//   * the fragments of the same draws captured (SoftBackend::setFragmentSink: the program
//     run per pixel through the scalar path) and blended here with blend() + storeTexel
//     in submission order;
//   * the same draws through the rasterizer's general path, selected by a state that
//     changes nothing else: for the mask, a depth write under CompareFunc::Always (no test
//     depends on it); for the composites, a write mask without alpha (their blend keeps the
//     target's alpha: ZERO / ONE).
// Both with the fast paths' edge cases: targets whose width is no multiple of the 8-pixel
// block, a nearest-filtered texture (no SIMD sampling: the per-lane path), an untextured
// draw, partial write masks, 1 and 2 threads.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <memory>
#include <vector>

#include "draws.hpp"  // tests/support
#include "lcg.hpp"    // tests/support
#include "engine/render/pixel_codec.hpp"
#include "engine/render/soft/soft_backend.hpp"
#include "engine/render/vertex.hpp"

// The general blend (program-authoring header).
#include "engine/render/kernel/detail/blend.hpp"
#include "ssam/composite_program.hpp"
#include "transparency/programs.hpp"

namespace {

namespace render = engine::render;
namespace soft = engine::render::soft;
using render::Format;

constexpr int kW = 83, kH = 61;  // no multiple of 8

using ssam::testing::Lcg;
using ssam::testing::meshDraw;

template <typename T>
std::span<const std::byte> bytesOf(const std::vector<T>& v) {
    return std::as_bytes(std::span<const T>(v));
}

bool sameBits(const render::Readback& a, const render::Readback& b) {
    return a.values.size() == b.values.size() &&
           std::memcmp(a.values.data(), b.values.data(), a.values.size() * sizeof(float)) == 0;
}
int channelsOf(Format f) { return render::formatInfo(f).channels; }

// A half that a mask could hold, or anything else a float target can hold.
std::uint16_t storedHalf(Lcg& rng) {
    static const std::uint16_t kSpecial[] = {0x0000, 0x8000, 0x0001, 0x83FF, 0x03FF, 0x3C00, 0x3BFF,
                                             0x3C01, 0x6800, 0x6801, 0x7BFF, 0xFBFF, 0x7C00, 0xFC00,
                                             0x7C01, 0x7E00, 0xFE00, 0x7FFF, 0xFFFF, 0xBC00, 0x4000};
    switch (rng.next() % 4) {
        case 0: return kSpecial[rng.next() % (sizeof kSpecial / sizeof kSpecial[0])];
        case 1: return std::uint16_t(rng.next());
        default: return render::encodeHalf(rng.range(0.0f, 3.0f));
    }
}

// The floats to upload (upload stores encodeHalf of each) and the halves that makes.
struct HalfImage {
    std::vector<float> values;
    std::vector<std::uint16_t> halves;
};
HalfImage randomHalfImage(Lcg& rng, Format format, int w, int h) {
    HalfImage image;
    const std::size_t n = std::size_t(w) * h * channelsOf(format);
    for (std::size_t i = 0; i < n; ++i) {
        const float v = render::decodeHalf(storedHalf(rng));
        image.values.push_back(v);
        image.halves.push_back(render::encodeHalf(v));
    }
    return image;
}

render::TextureHandle texture(render::Backend& b, const char* name, Format format, bool target,
                              std::span<const std::byte> data, int mipLevels = 1, int w = kW, int h = kH) {
    const auto usage = std::uint8_t(render::UsageSampled | (target ? render::UsageRenderTarget : 0));
    const render::TextureDesc d{name, w, h, format, 1, mipLevels, usage};
    if (data.empty()) return b.createTexture(d);
    render::TextureData td;
    td.levels.push_back(data);
    return b.createTexture(d, &td);
}

// 32x32 RGBA8 foliage texture, full mip chain: alpha 0 over about a third, else noise.
std::vector<std::uint8_t> foliageTexels() {
    Lcg rng{77};
    std::vector<std::uint8_t> t(32 * 32 * 4);
    for (std::size_t i = 0; i < t.size(); ++i) t[i] = std::uint8_t(i % 4 == 3 && rng.next() % 3 == 0 ? 0 : rng.next());
    return t;
}

// Triangles in perspective (w varies, so uv and the mip level do), all sizes, vertex alpha
// a little beyond [0, 1] (the program saturates).
std::vector<render::Vertex> randomTriangles(Lcg& rng, int count) {
    std::vector<render::Vertex> v;
    for (int t = 0; t < count; ++t) {
        const float cx = rng.range(-1.2f, 1.2f), cy = rng.range(-1.2f, 1.2f), size = 1.5f * rng.unit() * rng.unit();
        for (int k = 0; k < 3; ++k) {
            render::Vertex vx;
            const float z = rng.range(0.05f, 0.95f);
            vx.position = {cx + rng.range(-size, size), cy + rng.range(-size, size), -1.0f - 4.0f * z};
            vx.uv = {rng.range(-2.0f, 3.0f), rng.range(-2.0f, 3.0f)};
            vx.color = {1.0f, 1.0f, 1.0f, rng.range(-0.1f, 1.1f)};
            v.push_back(vx);
        }
    }
    return v;
}

glm::mat4 viewProj() { return glm::perspectiveRH_ZO(glm::radians(70.0f), float(kW) / kH, 0.5f, 20.0f); }

// One mask configuration: its targets and their blends (ssam::ScreenSpaceAlphaMask's).
struct MaskSetup {
    const char* name;
    std::vector<Format> formats;
    std::vector<render::BlendState> blends;
};
render::BlendState oneOne(render::BlendOp rgb, render::BlendOp alpha, std::uint8_t mask = render::WriteAll) {
    render::BlendState b = render::BlendState::oneOne(rgb, alpha);
    b.writeMask = mask;
    return b;
}
std::vector<MaskSetup> maskSetups() {
    using render::BlendOp;
    return {
        {"RG16F (two R16F, SSAM+)",
         {Format::R16F, Format::R16F},
         {oneOne(BlendOp::Max, BlendOp::Max), oneOne(BlendOp::Add, BlendOp::Add)}},
        {"RGBA16F", {Format::RGBA16F}, {render::BlendState::maxRgbAddAlpha()}},
        {"RGBA16F + RG16F, partial write masks",
         {Format::RGBA16F, Format::RG16F},
         {oneOne(BlendOp::Max, BlendOp::Add, render::WriteA | 1u), oneOne(BlendOp::Add, BlendOp::Max, 2u)}},
    };
}

// What one run of the mask scene gives.
struct MaskRun {
    std::vector<render::Readback> targets;
};

// Captures every fragment per pixel, in order.
class Collector final : public soft::FragmentSink {
public:
    explicit Collector(int w, int h) : w_(w), pixels_(std::size_t(w) * h) {}
    void add(int x, int y, const soft::CapturedFragment& f) override {
        pixels_[std::size_t(y) * w_ + x].push_back(f.color);
    }
    const std::vector<glm::vec4>& at(int x, int y) const { return pixels_[std::size_t(y) * w_ + x]; }

private:
    int w_;
    std::vector<std::vector<glm::vec4>> pixels_;
};

enum class MaskMode {
    Fast,         // depth Less, test only: the fast path
    Capture,      // depth Less, fragments to a sink
    AlwaysFast,   // depth Always, test only: the fast path
    AlwaysWrite,  // depth Always with write: the general path
};

// A depth pre-pass of opaque triangles, then the mask draws (textured trilinear, textured
// nearest, untextured) onto targets holding `initial`.
MaskRun runMaskScene(const MaskSetup& setup, const std::vector<HalfImage>& initial, MaskMode mode, int threads,
                     std::uint64_t seed, Collector* sink = nullptr) {
    auto backend = soft::createSoftBackend({threads, 24, false});
    render::Backend& b = *backend;
    Lcg rng{seed};
    std::vector<render::TextureHandle> targets;
    for (std::size_t i = 0; i < setup.formats.size(); ++i)
        targets.push_back(texture(b, "mask", setup.formats[i], true, bytesOf(initial[i].values)));
    const auto depth = texture(b, "depth", Format::D32F, true, {});
    const std::vector<std::uint8_t> texels = foliageTexels();
    const auto foliage = texture(b, "foliage", Format::RGBA8_UNORM, false,
                                 std::as_bytes(std::span<const std::uint8_t>(texels)), 6, 32, 32);
    const std::vector<render::Vertex> opaque = randomTriangles(rng, 12), layers = randomTriangles(rng, 400);
    auto buffer = [&](const std::vector<render::Vertex>& v) {
        return b.createBuffer({"vb", render::BufferKind::Vertex, v.size() * sizeof(render::Vertex)}, bytesOf(v));
    };
    const auto opaqueVb = buffer(opaque), layersVb = buffer(layers);

    render::PassDesc pre;
    pre.name = "depth";
    pre.depth = {depth, render::LoadOp::Clear, 1.0f};
    b.beginPass(pre);
    render::PipelineDesc dp;
    dp.depth = render::DepthState::testAndWrite();
    auto d = meshDraw(b.createPipeline(dp), render::FlatParams{viewProj(), glm::vec4(1.0f)}, opaqueVb,
                      std::uint32_t(opaque.size()));
    b.draw(d);
    b.endPass();

    render::PipelineDesc mp;
    mp.program = render::ProgramKind::AlphaOnly;
    mp.raster.cull = render::CullMode::None;
    const bool always = mode == MaskMode::AlwaysFast || mode == MaskMode::AlwaysWrite;
    mp.depth = {true, mode == MaskMode::AlwaysWrite, always ? render::CompareFunc::Always : render::CompareFunc::Less};
    for (std::size_t i = 0; i < setup.blends.size(); ++i) mp.blend[i] = setup.blends[i];
    const auto maskPipeline = b.createPipeline(mp);

    render::PassDesc pass;
    pass.name = "mask";
    for (std::size_t i = 0; i < targets.size(); ++i) pass.color[i] = {targets[i], render::LoadOp::Load};
    pass.depth = {depth, render::LoadOp::Load};
    if (sink) backend->fragmentCapture()->setFragmentSink(sink);
    b.beginPass(pass);
    const std::uint32_t third = std::uint32_t(layers.size() / 9) * 3;
    for (int k = 0; k < 3; ++k) {
        render::AlphaOnlyParams params;
        params.viewProj = viewProj();
        params.alphaFactor = k == 2 ? 0.7f : 1.0f;
        if (k < 2) params.baseColor = {foliage, {k == 0 ? render::Filter::Trilinear : render::Filter::Nearest}};
        d.pipeline = maskPipeline;
        d.params = params;
        d.vertices = layersVb;
        d.first = third * std::uint32_t(k);
        d.count = k < 2 ? third : std::uint32_t(layers.size()) - 2 * third;
        b.draw(d);
    }
    b.endPass();
    backend->fragmentCapture()->setFragmentSink(nullptr);
    MaskRun run;
    for (auto t : targets) run.targets.push_back(b.readback(t));
    return run;
}

std::vector<HalfImage> initialMasks(const MaskSetup& setup, std::uint64_t seed) {
    Lcg rng{seed};
    std::vector<HalfImage> images;
    for (Format f : setup.formats) images.push_back(randomHalfImage(rng, f, kW, kH));
    return images;
}

TEST(SoftFloatMask, MaskPassMatchesCapturedFragmentsBlendedByTheGeneralBlend) {
    for (const MaskSetup& setup : maskSetups()) {
        for (std::uint64_t seed : {1u, 2u, 3u}) {
            const std::vector<HalfImage> initial = initialMasks(setup, 100 + seed);
            Collector fragments(kW, kH);
            runMaskScene(setup, initial, MaskMode::Capture, 1, seed, &fragments);
            const MaskRun fast = runMaskScene(setup, initial, MaskMode::Fast, 1, seed);
            std::size_t fragmentCount = 0;
            for (int y = 0; y < kH; ++y)
                for (int x = 0; x < kW; ++x) fragmentCount += fragments.at(x, y).size();
            for (std::size_t t = 0; t < setup.formats.size(); ++t) {
                const Format format = setup.formats[t];
                const int channels = channelsOf(format);
                int mismatches = 0;
                for (int y = 0; y < kH; ++y)
                    for (int x = 0; x < kW; ++x) {
                        std::byte texel[8];
                        std::memcpy(texel, &initial[t].halves[(std::size_t(y) * kW + x) * channels], 2 * channels);
                        for (const glm::vec4& color : fragments.at(x, y)) {
                            const glm::vec4 out = soft::blend(setup.blends[t], color, render::loadTexel(texel, format),
                                                              glm::vec4(0.0f), false);
                            render::storeTexel(texel, format, out, setup.blends[t].writeMask);
                        }
                        const glm::vec4 expected = render::loadTexel(texel, format);
                        for (int c = 0; c < channels; ++c) {
                            const float got = fast.targets[t].at(x, y, c);
                            if (std::memcmp(&got, &expected[c], sizeof got) != 0 && mismatches++ < 5)
                                ADD_FAILURE() << setup.name << " seed " << seed << " target " << t << " pixel (" << x
                                              << ", " << y << ") channel " << c << ": " << got << " vs " << expected[c];
                        }
                    }
                EXPECT_EQ(mismatches, 0) << setup.name << " seed " << seed << " target " << t;
            }
            EXPECT_GT(fragmentCount, std::size_t(kW * kH)) << setup.name << ": too few fragments to test";
        }
    }
}

TEST(SoftFloatMask, MaskPassMatchesTheGeneralPathForAnyThreadCount) {
    for (const MaskSetup& setup : maskSetups()) {
        for (std::uint64_t seed : {4u, 5u}) {
            const std::vector<HalfImage> initial = initialMasks(setup, 200 + seed);
            const MaskRun general = runMaskScene(setup, initial, MaskMode::AlwaysWrite, 1, seed);
            for (int threads : {1, 2}) {
                const MaskRun fast = runMaskScene(setup, initial, MaskMode::AlwaysFast, threads, seed);
                for (std::size_t t = 0; t < general.targets.size(); ++t)
                    EXPECT_TRUE(sameBits(fast.targets[t], general.targets[t]))
                        << setup.name << " seed " << seed << " threads " << threads << " target " << t;
            }
            // The scene changes the masks (or the comparison would prove nothing).
            bool changed = false;
            for (std::size_t t = 0; t < general.targets.size(); ++t)
                for (std::size_t i = 0; i < general.targets[t].values.size() && !changed; ++i) {
                    const float v = render::decodeHalf(initial[t].halves[i]);
                    changed = std::memcmp(&v, &general.targets[t].values[i], sizeof v) != 0;
                }
            EXPECT_TRUE(changed) << setup.name;
        }
    }
}

// The composites (Composite: SSAM, CoverageComposite: SSAM+) from masks of every format
// SSAM makes onto 8-bit targets, fast path (write mask RGBA) against the general path
// (write mask RGB), full screen and under a scissor.
enum class CompositeKind { Ssam, SsamPlus };

struct CompositeSetup {
    CompositeKind program;
    Format mask;
    bool maskAdd;  // a second, R16F ADD mask (RG16F precision)
    Format target;
    Format foliage;
    transparency::CoverageModel model = transparency::CoverageModel::EqualLayers;
};

render::Readback runComposite(const CompositeSetup& s, bool general, std::uint64_t seed) {
    auto backend = soft::createSoftBackend({1, 24, false});
    render::Backend& b = *backend;
    Lcg rng{seed};
    auto bytes = [&](int count) {
        std::vector<std::uint8_t> v(static_cast<std::size_t>(count));
        for (auto& x : v) x = std::uint8_t(rng.next() % 5 == 0 ? 0 : rng.next());  // some zero masks
        return v;
    };
    const std::vector<std::uint8_t> targetBytes = bytes(kW * kH * 4), foliageBytes = bytes(kW * kH * 4);
    const auto target = texture(b, "out", s.target, true, std::as_bytes(std::span<const std::uint8_t>(targetBytes)));
    const auto foliage =
        texture(b, "foliage", s.foliage, true, std::as_bytes(std::span<const std::uint8_t>(foliageBytes)));
    std::vector<std::uint8_t> maskBytes;
    HalfImage maskHalves, addHalves;
    render::TextureHandle mask, maskAdd;
    if (s.mask == Format::RGBA8_UNORM) {
        maskBytes = bytes(kW * kH * 4);
        mask = texture(b, "mask", s.mask, true, std::as_bytes(std::span<const std::uint8_t>(maskBytes)));
    } else {
        maskHalves = randomHalfImage(rng, s.mask, kW, kH);
        mask = texture(b, "mask", s.mask, true, bytesOf(maskHalves.values));
    }
    if (s.maskAdd) {
        addHalves = randomHalfImage(rng, Format::R16F, kW, kH);
        maskAdd = texture(b, "maskAdd", Format::R16F, true, bytesOf(addHalves.values));
    }
    render::PipelineDesc pd;
    pd.program = s.program == CompositeKind::Ssam
                     ? render::ProgramRef(b.createProgram(ssam::compositeProgram()))
                     : render::ProgramRef(b.createProgram(transparency::coverageCompositeProgram()));
    pd.blend[0] = render::BlendState::alphaOverKeepAlpha();
    pd.blend[0].writeMask = general ? render::WriteRGB : render::WriteAll;
    const auto pipeline = b.createPipeline(pd);
    render::PassDesc pass;
    pass.name = "composite";
    pass.color[0] = {target, render::LoadOp::Load};
    b.beginPass(pass);
    for (int k = 0; k < 2; ++k) {
        render::DrawDesc d;
        d.pipeline = pipeline;
        if (s.program == CompositeKind::Ssam)
            d.params = ssam::CompositeParams{foliage, mask, maskAdd, k == 0 ? 0.85f : 0.3f, k == 0};
        else d.params = transparency::CoverageCompositeParams{foliage, mask, maskAdd, s.model};
        if (k == 1) d.scissor = render::Rect{5, 7, 41, 30};
        b.draw(d);
    }
    b.endPass();
    return b.readback(target);
}

TEST(SoftFloatMask, CompositesMatchTheGeneralPath) {
    using render::ProgramKind;
    std::vector<CompositeSetup> setups;
    for (CompositeKind program : {CompositeKind::Ssam, CompositeKind::SsamPlus})
        for (Format target : {Format::RGBA8_UNORM, Format::RGBA8_SRGB})
            for (Format foliage : {Format::RGBA8_UNORM, Format::RGBA8_SRGB}) {
                setups.push_back({program, Format::R16F, true, target, foliage});
                setups.push_back({program, Format::RGBA16F, false, target, foliage});
                setups.push_back({program, Format::RGBA8_UNORM, false, target, foliage});
                setups.push_back({program, Format::RGBA16F, true, target, foliage});
            }
    setups.push_back({CompositeKind::SsamPlus, Format::R16F, true, Format::RGBA8_SRGB, Format::RGBA8_SRGB,
                      transparency::CoverageModel::Exponential});
    setups.push_back({CompositeKind::SsamPlus, Format::RGBA16F, false, Format::RGBA8_UNORM, Format::RGBA8_UNORM,
                      transparency::CoverageModel::Exponential});
    std::uint64_t seed = 50;
    for (const CompositeSetup& s : setups) {
        ++seed;
        const render::Readback fast = runComposite(s, false, seed), general = runComposite(s, true, seed);
        EXPECT_TRUE(sameBits(fast, general))
            << (s.program == CompositeKind::Ssam ? "SSAM" : "SSAM+") << " mask " << render::formatName(s.mask)
            << (s.maskAdd ? " + R16F" : "") << " onto " << render::formatName(s.target) << " foliage "
            << render::formatName(s.foliage) << " model " << int(s.model);
    }
}

}  // namespace
