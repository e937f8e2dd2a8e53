// SPDX-License-Identifier: MIT
// GL backend unit tests on a headless EGL context: conventions (row order, uv origin,
// winding, scissor), formats, resolves, programs, timings and pipeline info. Where the
// soft backend is the reference, the same calls run on both and the results are compared.
#include <cmath>
#include <cstring>
#include <functional>
#include <memory>
#include <vector>

#include <epoxy/gl.h>
#include <gtest/gtest.h>

#include "../../conformance/backend_fixture.hpp"
#include "engine/core/error.hpp"
#include "engine/render/gl/gl_backend.hpp"
#include "engine/render/soft/soft_backend.hpp"
#include "ssam/composite_program.hpp"

namespace ssam::test {
namespace {

namespace gl = engine::render::gl;
using render::Format;

std::unique_ptr<render::Backend> makeGl(gl::GlOptions options = {}) { return gl::createGlBackend(options); }
std::unique_ptr<render::Backend> makeSoft() { return engine::render::soft::createSoftBackend({.threads = 1}); }

render::TextureHandle target(render::Backend& b, int w, int h, Format f, int samples = 1,
                             const std::string& name = "t") {
    return b.createTexture(render::renderTargetDesc(name, w, h, f, samples));
}

render::BufferHandle vertices(render::Backend& b, const std::vector<render::Vertex>& v) {
    return b.createBuffer({"vertices", render::BufferKind::Vertex, v.size() * sizeof(render::Vertex)}, bytesOf(v));
}

render::PipelineHandle flat(render::Backend& b, render::PipelineDesc desc = {}) {
    if (desc.name.empty()) desc.name = "flat";
    return b.createPipeline(desc);
}

void drawFlatOn(render::Backend& b, render::PipelineHandle p, render::BufferHandle vb, std::uint32_t count,
                glm::vec4 color = glm::vec4(1.0f), std::optional<render::Rect> scissor = std::nullopt) {
    auto d = meshDraw(p, render::FlatParams{glm::mat4(1.0f), color}, vb, count);
    d.scissor = scissor;
    b.draw(d);
}

void onePass(render::Backend& b, render::TextureHandle color, glm::vec4 clear, const std::function<void()>& draws,
             render::TextureHandle depth = {}, float depthClear = 1.0f) {
    render::PassDesc p;
    p.name = "pass";
    p.color[0] = {color, render::LoadOp::Clear, clear};
    if (depth) p.depth = {depth, render::LoadOp::Clear, depthClear};
    b.beginPass(p);
    draws();
    b.endPass();
}

// Expects two readbacks to be equal value for value (bit-exact paths).
void expectSame(const render::Readback& a, const render::Readback& b, const std::string& what) {
    ASSERT_EQ(a.width, b.width) << what;
    ASSERT_EQ(a.height, b.height) << what;
    ASSERT_EQ(a.channels, b.channels) << what;
    int reported = 0;
    for (std::size_t i = 0; i < a.values.size(); ++i) {
        const bool same = a.values[i] == b.values[i] || (std::isnan(a.values[i]) && std::isnan(b.values[i]));
        if (!same && ++reported <= 5) {
            const std::size_t pixel = i / a.channels;
            ADD_FAILURE() << what << ": pixel (" << pixel % a.width << "," << pixel / a.width << ") channel "
                          << i % a.channels << ": " << a.values[i] << " vs " << b.values[i];
        }
    }
    EXPECT_EQ(reported, 0) << what << ": values differ";
}

// Expects two readbacks to agree within what GL leaves to the implementation for stores:
// UNORM/sRGB one code (tie rounding, sRGB curve precision), 16F one half ULP (rounding mode
// of the float-to-half conversion), 32F 1e-6 relative.
void expectClose(const render::Readback& a, const render::Readback& b, const std::string& what) {
    ASSERT_EQ(a.values.size(), b.values.size()) << what;
    const render::FormatInfo& info = render::formatInfo(a.format);
    const bool half = a.format == Format::RGBA16F || a.format == Format::RG16F || a.format == Format::R16F;
    int reported = 0;
    for (std::size_t i = 0; i < a.values.size(); ++i) {
        const double x = a.values[i], y = b.values[i];
        double tolerance = std::max(1e-6, 1e-6 * std::fabs(y));
        if (info.isNormalized()) tolerance = 1.0 / 255.0 + 1e-6;
        else if (half) tolerance = std::max(std::ldexp(1.0, -24), std::ldexp(std::fabs(y), -10));
        if (!(std::fabs(x - y) <= tolerance) && ++reported <= 5) {
            const std::size_t pixel = i / a.channels;
            ADD_FAILURE() << what << ": pixel (" << pixel % a.width << "," << pixel / a.width << ") channel "
                          << i % a.channels << ": " << x << " vs " << y;
        }
    }
    EXPECT_EQ(reported, 0) << what;
}

class GlBackendTest : public ::testing::Test {
protected:
    void SetUp() override { gfx_ = makeGl(); }
    render::Backend& gfx() { return *gfx_; }
    gl::GlDriver& glb() { return gl::glDriver(static_cast<render::Device&>(*gfx_)); }
    std::unique_ptr<render::Backend> gfx_;
};

TEST_F(GlBackendTest, ReportsItsContext) {
    EXPECT_EQ(gfx().name(), "gl");
    EXPECT_FALSE(glb().info().renderer.empty());
    EXPECT_EQ(glb().info().version.rfind("4.", 0), 0u) << glb().info().version;
    EXPECT_NE(glb().context(), nullptr);
    EXPECT_GE(glb().info().maxSamples, 4);
    std::cout << "[ gl       ] " << glb().info().renderer << " | " << glb().info().version << " | "
              << glb().info().context << "\n";
}

// Clears of every colour format store what the soft backend stores (clamping, sRGB
// encoding, half rounding), read back with the same layout.
TEST_F(GlBackendTest, ClearsMatchSoftForEveryFormat) {
    auto soft = makeSoft();
    const glm::vec4 clears[] = {
        {0.2f, 0.55f, 0.9f, 0.6f}, {1.5f, -0.25f, 0.0031f, 0.5f}, {0.1234567f, 0.7f, 1e-5f, 65504.0f}};
    for (Format f : {Format::RGBA8_UNORM, Format::RGBA8_SRGB, Format::R8_UNORM, Format::RG8_UNORM, Format::RGBA16F,
                     Format::RG16F, Format::R16F, Format::RGBA32F, Format::R32F}) {
        for (const glm::vec4& c : clears) {
            const auto a = target(gfx(), 3, 2, f), b = target(*soft, 3, 2, f);
            onePass(gfx(), a, c, [] {});
            onePass(*soft, b, c, [] {});
            expectSame(gfx().readback(a), soft->readback(b), std::string(render::formatName(f)) + " clear");
        }
    }
    // Depth: cleared values read back as floats.
    const auto color = target(gfx(), 2, 2, Format::RGBA8_UNORM);
    const auto depth = target(gfx(), 2, 2, Format::D32F);
    onePass(
        gfx(), color, glm::vec4(0.0f), [] {}, depth, 0.375f);
    const render::Readback r = gfx().readback(depth);
    EXPECT_EQ(r.channels, 1);
    EXPECT_EQ(r.at(1, 1, 0), 0.375f);
}

// A readback is read in bands of whole rows (GlOptions::readbackBandBytes: a 16384x16384 float
// readback would wrap the GLsizei byte count of one call). Bands of 3 rows over 11 rows, the
// last one short, read exactly what one call reads, for 8-bit (through one band-sized byte
// buffer, sRGB through its view) and float formats.
TEST(GlReadbackTest, BandsOfRowsReadWhatOneCallReads) {
    constexpr int w = 7, h = 11;
    for (Format f : {Format::RGBA8_UNORM, Format::RGBA8_SRGB, Format::R8_UNORM, Format::RGBA32F, Format::R32F}) {
        const render::FormatInfo& info = render::formatInfo(f);
        const std::size_t texelBytes = info.isNormalized() ? info.channels : info.channels * sizeof(float);
        std::vector<std::byte> texels(w * h * texelBytes);
        if (info.isNormalized()) {
            for (std::size_t i = 0; i < texels.size(); ++i) texels[i] = std::byte(i * 37 % 251);
        } else {
            for (std::size_t i = 0; i < texels.size(); i += sizeof(float)) {
                const float v = float(i) * 0.25f - 7.0f;
                std::memcpy(&texels[i], &v, sizeof v);
            }
        }
        gl::GlOptions banded;
        banded.readbackBandBytes = 3 * w * texelBytes;
        auto whole = makeGl(), bands = makeGl(banded);
        const render::TextureDesc desc{"bands", w, h, f};
        const render::TextureData data{{std::span<const std::byte>(texels)}};
        const render::Readback expected = whole->readback(whole->createTexture(desc, &data));
        const render::Readback got = bands->readback(bands->createTexture(desc, &data));
        expectSame(got, expected, std::string(render::formatName(f)) + " in bands of 3 rows");
        if (info.isNormalized()) {
            EXPECT_EQ(got.at(w - 1, h - 1, info.channels - 1), float(texels.back()) / 255.0f) << render::formatName(f);
        }
    }
}

// NDC +y is row 0, which is the top of a Readback; a rect of the top-left quadrant lands there.
TEST_F(GlBackendTest, RowZeroIsTheTop) {
    const auto t = target(gfx(), 8, 8, Format::RGBA8_UNORM);
    const auto vb = vertices(gfx(), pixelRect(8, 8, 0, 0, 4, 2));
    const auto p = flat(gfx());
    onePass(gfx(), t, glm::vec4(0.0f), [&] { drawFlatOn(gfx(), p, vb, 6, {1, 0, 0, 1}); });
    const render::Readback r = gfx().readback(t);
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 8; ++x) EXPECT_EQ(r.at(x, y, 0), (x < 4 && y < 2) ? 1.0f : 0.0f) << x << "," << y;
}

// Texture uv (0,0) is the first stored row; sampled with Nearest it appears at the top.
TEST_F(GlBackendTest, UvOriginIsTheFirstStoredRow) {
    render::TextureDesc desc{"rows", 2, 2, Format::RGBA8_UNORM};
    const std::uint8_t texels[] = {255, 0, 0, 255, 255, 0, 0, 255, 0, 255, 0, 255, 0, 255, 0, 255};
    render::TextureData data{{std::as_bytes(std::span(texels))}};
    const auto tex = gfx().createTexture(desc, &data);
    const auto t = target(gfx(), 4, 4, Format::RGBA8_UNORM);
    const auto vb = vertices(gfx(), pixelRect(4, 4, 0, 0, 4, 4));
    render::PipelineDesc pd;
    pd.name = "lit";
    pd.program = render::ProgramKind::OpaqueLit;
    const auto p = gfx().createPipeline(pd);
    onePass(gfx(), t, glm::vec4(0.0f), [&] {
        render::SurfaceParams params;
        params.baseColor = {tex, {render::Filter::Nearest}};
        params.light = {{0, 0, 1}, glm::vec3(0.0f), glm::vec3(1.0f)};  // ambient only: the texel itself
        gfx().draw(meshDraw(p, params, vb, 6));
    });
    const render::Readback r = gfx().readback(t);
    EXPECT_EQ(r.at(1, 0, 0), 1.0f);
    EXPECT_EQ(r.at(1, 3, 1), 1.0f);
    EXPECT_EQ(r.at(1, 3, 0), 0.0f);
}

// Counter-clockwise as displayed is the front face by default, on both backends; culling
// and FrontFace = Clockwise flip it.
TEST_F(GlBackendTest, WindingAndCullingMatchSoft) {
    auto soft = makeSoft();
    // Top-left triangle counter-clockwise as displayed, bottom-right one clockwise.
    std::vector<render::Vertex> v = {pixelVertex(8, 8, 0, 0), pixelVertex(8, 8, 0, 8), pixelVertex(8, 8, 8, 0),
                                     pixelVertex(8, 8, 8, 8), pixelVertex(8, 8, 0, 8), pixelVertex(8, 8, 8, 0)};
    for (render::CullMode cull : {render::CullMode::None, render::CullMode::Back, render::CullMode::Front}) {
        for (render::Winding front : {render::Winding::CounterClockwise, render::Winding::Clockwise}) {
            std::vector<render::Readback> results;
            for (render::Backend* b : {&gfx(), soft.get()}) {
                const auto t = target(*b, 8, 8, Format::RGBA8_UNORM);
                const auto vb = vertices(*b, v);
                render::PipelineDesc pd;
                pd.name = "winding";
                pd.program = render::ProgramKind::MaskedLit;  // double-sided lighting shows facing
                pd.raster = {cull, front};
                const auto p = b->createPipeline(pd);
                onePass(*b, t, glm::vec4(0.0f), [&] {
                    render::SurfaceParams params;
                    params.light = {{0, 0, 1}, glm::vec3(1.0f), glm::vec3(0.0f)};
                    b->draw(meshDraw(p, params, vb, 6));
                });
                results.push_back(b->readback(t));
            }
            expectSame(results[0], results[1],
                       "cull " + std::to_string(int(cull)) + " front " + std::to_string(int(front)));
            if (cull == render::CullMode::Back && front == render::Winding::CounterClockwise) {
                EXPECT_EQ(results[0].at(1, 1, 0), 1.0f);  // front face, lit
                EXPECT_EQ(results[0].at(6, 6, 0), 0.0f);  // back face, culled
            }
        }
    }
}

TEST_F(GlBackendTest, ScissorIsFromTheTop) {
    const auto t = target(gfx(), 8, 8, Format::RGBA8_UNORM);
    const auto vb = vertices(gfx(), pixelRect(8, 8, 0, 0, 8, 8));
    const auto p = flat(gfx());
    onePass(gfx(), t, glm::vec4(0.0f), [&] { drawFlatOn(gfx(), p, vb, 6, glm::vec4(1.0f), render::Rect{1, 2, 3, 4}); });
    const render::Readback r = gfx().readback(t);
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 8; ++x)
            EXPECT_EQ(r.at(x, y, 0), (x >= 1 && x < 4 && y >= 2 && y < 6) ? 1.0f : 0.0f) << x << "," << y;
}

// Several colour targets: the program's colour goes to each (packed in attachment order,
// as in the soft backend), each with its own blend state and mask.
TEST_F(GlBackendTest, MultipleTargetsMatchSoft) {
    auto soft = makeSoft();
    std::vector<render::Readback> results[2];
    int k = 0;
    for (render::Backend* b : {&gfx(), soft.get()}) {
        const auto t0 = target(*b, 4, 4, Format::RGBA8_SRGB, 1, "t0");
        const auto t1 = target(*b, 4, 4, Format::RGBA16F, 1, "t1");
        const auto t2 = target(*b, 4, 4, Format::R8_UNORM, 1, "t2");
        const auto vb = vertices(*b, pixelRect(4, 4, 1, 1, 4, 4));
        render::PipelineDesc pd;
        pd.name = "mrt";
        pd.blend[0] = render::BlendState::alphaOver();
        pd.blend[1] = render::BlendState::maxRgbAddAlpha();
        pd.blend[2] = render::BlendState::premultipliedOver();
        pd.blend[2].writeMask = render::WriteR;
        const auto p = b->createPipeline(pd);
        render::PassDesc pass;
        pass.name = "mrt";
        pass.color[0] = {t0, render::LoadOp::Clear, {0.2f, 0.4f, 0.6f, 0.5f}};
        pass.color[2] = {t1, render::LoadOp::Clear, {0.5f, 0.25f, 2.0f, 1.5f}};  // slot 1 left empty
        pass.color[3] = {t2, render::LoadOp::Clear, {0.3f, 0.0f, 0.0f, 0.0f}};
        b->beginPass(pass);
        drawFlatOn(*b, p, vb, 6, {0.9f, 0.3f, 0.1f, 0.7f});
        b->endPass();
        results[k++] = {b->readback(t0), b->readback(t1), b->readback(t2)};
    }
    for (int i = 0; i < 3; ++i) expectClose(results[0][i], results[1][i], "target " + std::to_string(i));
}

TEST_F(GlBackendTest, ResolvesMatchSoft) {
    auto soft = makeSoft();
    for (Format f : {Format::RGBA8_UNORM, Format::RGBA8_SRGB, Format::RGBA16F, Format::RGBA32F}) {
        for (render::CompareFunc func : {render::CompareFunc::Less, render::CompareFunc::Greater}) {
            std::vector<render::Readback> results;
            for (render::Backend* b : {&gfx(), soft.get()}) {
                const auto color = target(*b, 8, 8, f, 4, "msaa");
                const auto depth = target(*b, 8, 8, Format::D32F, 4, "msaa_depth");
                // A triangle whose edges cut pixels, at a depth that varies across it.
                // Vertices on the 1/256-pixel grid: both backends then interpolate from the same
                // positions (llvmpipe's planes use unsnapped positions, the soft backend's snapped ones).
                std::vector<render::Vertex> v = {pixelVertex(8, 8, 0.3125, 0.1875, 0.2f),
                                                 pixelVertex(8, 8, 1.09375, 7.625, 0.8f),
                                                 pixelVertex(8, 8, 7.6875, 3.3125, 0.5f)};
                v[0].color = {1.0f, 0.5f, 0.25f, 1.0f};
                const auto vb = vertices(*b, v);
                render::PipelineDesc pd;
                pd.name = "resolve";
                pd.depth = render::DepthState::testAndWrite(func);
                const auto p = b->createPipeline(pd);
                const float clearDepth = func == render::CompareFunc::Less ? 1.0f : 0.0f;
                onePass(
                    *b, color, {0.1f, 0.2f, 0.3f, 1.0f},
                    [&] {
                        drawFlatOn(*b, p, vb, 3, {0.9f, 0.8f, 0.7f, 1.0f});
                    },
                    depth, clearDepth);
                const auto resolvedColor = target(*b, 8, 8, f, 1, "resolved");
                const auto resolvedDepth = target(*b, 8, 8, Format::D32F, 1, "resolved_depth");
                b->resolve({color, resolvedColor});
                b->resolve({depth, resolvedDepth, func});
                results.push_back(b->readback(resolvedColor));
                results.push_back(b->readback(resolvedDepth));
            }
            const std::string what = std::string(render::formatName(f)) + " " + render::compareFuncName(func);
            // Colour averages: UNORM within 1 code (sRGB precision, rounding of ties), 16F within
            // one half ULP (llvmpipe stores halves rounded toward zero), 32F exact.
            expectClose(results[0], results[2], what + " colour");
            // Closest depth sample: the same float, never an average.
            const render::Readback &glDepth = results[1], &softDepth = results[3];
            for (std::size_t i = 0; i < glDepth.values.size(); ++i)
                EXPECT_NEAR(glDepth.values[i], softDepth.values[i], 1e-6) << what << " depth value " << i;
        }
    }
}

// Composite reads one texel per pixel and blends with the pipeline's SRC_ALPHA/INV_SRC_ALPHA.
TEST_F(GlBackendTest, CompositeMatchesSoft) {
    auto soft = makeSoft();
    std::vector<render::Readback> results;
    for (render::Backend* b : {&gfx(), soft.get()}) {
        const int w = 6, h = 5;
        auto filled = [&](Format f, const std::string& name, auto value) {
            render::TextureDesc desc{name, w, h, f, 1, 1, render::UsageSampled | render::UsageRenderTarget};
            std::vector<float> texels;
            for (int y = 0; y < h; ++y)
                for (int x = 0; x < w; ++x) {
                    const glm::vec4 v = value(x, y);
                    for (int c = 0; c < render::formatInfo(f).channels; ++c) texels.push_back(v[c]);
                }
            render::TextureData data{{std::as_bytes(std::span(texels))}};
            return b->createTexture(desc, &data);
        };
        const auto foliage =
            filled(Format::RGBA16F, "foliage", [](int x, int y) { return glm::vec4(0.1f * x, 0.2f * y, 0.5f, 1.0f); });
        const auto mask =
            filled(Format::RGBA16F, "mask", [](int x, int y) { return glm::vec4(0.15f * x, 0.0f, 0.0f, 0.3f * y); });
        const auto maskAdd = filled(Format::R16F, "mask_add", [](int x, int y) { return glm::vec4(0.05f * (x + y)); });
        const auto out = target(*b, w, h, Format::RGBA8_SRGB, 1, "out");
        render::PipelineDesc pd;
        pd.name = "composite";
        pd.program = b->createProgram(ssam::compositeProgram());
        pd.blend[0] = render::BlendState::alphaOver();
        const auto p = b->createPipeline(pd);
        render::PassDesc pass;
        pass.name = "composite";
        pass.color[0] = {out, render::LoadOp::Clear, {0.3f, 0.6f, 0.2f, 1.0f}};
        b->beginPass(pass);
        auto d = fullscreenDraw(p, ssam::CompositeParams{foliage, mask, {}, 0.85f, true});
        d.scissor = render::Rect{0, 0, 6, 3};
        b->draw(d);
        d.params = ssam::CompositeParams{foliage, mask, maskAdd, 0.5f, false};
        d.scissor = render::Rect{0, 3, 6, 2};
        b->draw(d);
        b->endPass();
        results.push_back(b->readback(out));
    }
    for (std::size_t i = 0; i < results[0].values.size(); ++i)
        EXPECT_NEAR(results[0].values[i], results[1].values[i], 1.0 / 255.0 + 1e-6) << "value " << i;
}

TEST_F(GlBackendTest, TimingsPerPassInOrder) {
    const auto t = target(gfx(), 16, 16, Format::RGBA8_UNORM);
    const auto vb = vertices(gfx(), pixelRect(16, 16, 0, 0, 16, 16));
    const auto p = flat(gfx());
    for (const char* name : {"first", "second", "third"}) {
        render::PassDesc pass;
        pass.name = name;
        pass.color[0] = {t};
        gfx().beginPass(pass);
        drawFlatOn(gfx(), p, vb, 6);
        gfx().endPass();
    }
    const auto timings = gfx().takeTimings();
    ASSERT_EQ(timings.size(), 3u);
    EXPECT_EQ(timings[0].pass, "first");
    EXPECT_EQ(timings[2].pass, "third");
    for (const auto& timing : timings) {
        std::cout << "[ timing   ] " << timing.pass << ": " << timing.milliseconds << " ms\n";
        EXPECT_GE(timing.milliseconds, 0.0);
        EXPECT_LT(timing.milliseconds, 10000.0);
    }
    EXPECT_TRUE(gfx().takeTimings().empty());
}

// PipelineInfo says which fail-mode emulations are exact, and the same simplifications as soft.
TEST_F(GlBackendTest, PipelineInfoReportsEmulation) {
    auto soft = makeSoft();
    auto info = [&](render::Backend& b, render::AlphaFailMode mode, render::DepthState depth,
                    render::BlendState blend = render::BlendState::alphaOver()) {
        render::PipelineDesc pd;
        pd.name = "fail_mode";
        pd.blend.fill(blend);
        pd.depth = depth;
        pd.alphaTest = {true, render::CompareFunc::GreaterEqual, 0.5f, mode, false};
        return b.pipelineInfo(b.createPipeline(pd));
    };
    using render::AlphaFailMode;
    using render::CompareFunc;
    using render::DepthState;
    // Depth tested and written with LESS: the two-pass split is inexact, and says why.
    const auto fb = info(gfx(), AlphaFailMode::FbOnly, DepthState::testAndWrite(CompareFunc::Less));
    EXPECT_FALSE(fb.exact);
    EXPECT_NE(fb.note.find(render::alphaFailModeName(AlphaFailMode::FbOnly)), std::string::npos) << fb.note;
    // ALWAYS: the seed's depth-always rewrite is exact.
    EXPECT_TRUE(info(gfx(), AlphaFailMode::FbOnly, DepthState::testAndWrite(CompareFunc::Always)).exact);
    EXPECT_TRUE(info(gfx(), AlphaFailMode::ZbOnly, DepthState::testAndWrite(CompareFunc::Always)).exact);
    // No depth writes: RGB_ONLY splits RGB and alpha; inexact only when RGB blending reads dst alpha.
    EXPECT_TRUE(info(gfx(), AlphaFailMode::RgbOnly, DepthState::testOnly()).exact);
    render::BlendState readsDstAlpha = render::BlendState::alphaOver();
    readsDstAlpha.dstRgb = render::BlendFactor::InvDstAlpha;
    EXPECT_FALSE(info(gfx(), AlphaFailMode::RgbOnly, DepthState::testOnly(), readsDstAlpha).exact);
    // Dropped tests agree with soft.
    for (AlphaFailMode mode : render::kAllAlphaFailModes) {
        for (DepthState depth : {DepthState::off(), DepthState::testOnly(), DepthState::testAndWrite()}) {
            const auto g = info(gfx(), mode, depth), s = info(*soft, mode, depth);
            EXPECT_EQ(g.alphaTestDropped, s.alphaTestDropped) << render::alphaFailModeName(mode);
            EXPECT_EQ(g.blendIsPlainWrite, s.blendIsPlainWrite);
        }
    }
    // Per-triangle steps make every fail mode exact.
    gl::GlOptions perTriangle;
    perTriangle.failModes = gl::FailModeStrategy::PerTriangle;
    auto exact = makeGl(perTriangle);
    EXPECT_TRUE(info(*exact, AlphaFailMode::FbOnly, DepthState::testAndWrite(CompareFunc::Less)).exact);
}

// A host's context (here: an EGL one we make current ourselves) is adopted as it is.
TEST(GlContextTest, AdoptsTheCurrentContext) {
    auto context = gl::HeadlessEglContext::create();
    context->makeCurrent();
    gl::GlOptions adopt;
    adopt.useCurrentContext = true;
    auto backend = gl::createGlBackend(adopt);
    EXPECT_EQ(gl::glDriver(*backend).context(), nullptr);
    EXPECT_EQ(gl::glDriver(*backend).info().context, "current context");
    const auto t = target(*backend, 4, 4, Format::RGBA8_UNORM);
    onePass(*backend, t, {0.0f, 1.0f, 0.0f, 1.0f}, [] {});
    EXPECT_EQ(backend->readback(t).at(3, 3, 1), 1.0f);
    EXPECT_FALSE(backend->present(t));  // no window
}

// Textures made by the host in the same context can be wrapped; mismatches are errors.
TEST(GlContextTest, ImportsHostTextures) {
    auto backend = gl::createGlBackend();
    GLuint id = 0;
    glCreateTextures(GL_TEXTURE_2D, 1, &id);
    glTextureStorage2D(id, 1, GL_RGBA16F, 8, 4);
    render::TextureDesc desc{"host", 8, 4, Format::RGBA16F, 1, 1, render::UsageRenderTarget | render::UsageSampled};
    const auto t = engine::render::gl::importTexture(*backend, id, desc);
    EXPECT_EQ(engine::render::gl::glTexture(*backend, t), id);
    onePass(*backend, t, {0.5f, 2.0f, -1.0f, 1.0f}, [] {});
    EXPECT_EQ(backend->readback(t).at(7, 3, 1), 2.0f);
    backend->destroy(t);
    EXPECT_TRUE(glIsTexture(id)) << "imported textures are not deleted";
    desc.format = Format::RGBA8_UNORM;
    expectError([&] { engine::render::gl::importTexture(*backend, id, desc); }, "internal format");
    desc.format = Format::RGBA16F;
    desc.width = 9;
    expectError([&] { engine::render::gl::importTexture(*backend, id, desc); }, "is 8x4");
    glDeleteTextures(1, &id);
}

}  // namespace
}  // namespace ssam::test
