// SPDX-License-Identifier: MIT
// What the GLES driver does differently from GL 4.5 because OpenGL ES 3.0 cannot do otherwise
// (engine/render/docs/gles.md), checked where it shows: the closest-sample depth resolve of
// [Hathaway 2010] §3.5.1 is refused by name (any sample is not), native alpha-to-coverage is reported inexact,
// pass times say they are the CPU's, a colour resolve still averages by blit, and a depth
// texture sampled with a filter (incomplete on ES 3.0: its reads would be 0) is refused by name,
// as a 32-bit float one is without OES_texture_float_linear, and without EXT_clip_control the
// device still starts, says so, and draws with the extension's origin, facing and depth.
#include <epoxy/gl.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdlib>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "engine/core/error.hpp"
#include "expect_error.hpp"  // tests/support
#include "engine/render/gles/gles_backend.hpp"
#include "engine/render/program.hpp"
#include "engine/render/vertex.hpp"

namespace engine::render::gles {
namespace {

using ::testing::HasSubstr;
using ssam::testing::errorOf;

TextureDesc target(const char* name, Format format, int samples) {
    TextureDesc d;
    d.name = name;
    d.width = 8;
    d.height = 4;
    d.format = format;
    d.samples = samples;
    d.usage = UsageRenderTarget | (samples == 1 ? UsageSampled : 0);
    return d;
}

TEST(GlesDifferences, MultisampledDepthResolveIsRefusedNamingWhy) {
    const auto device = createGlesBackend();
    const TextureHandle source = device->createTexture(target("ms depth", Format::D32F, 4));
    const TextureHandle destination = device->createTexture(target("depth", Format::D32F, 1));
    const std::string message = errorOf([&] { device->resolve({source, destination, CompareFunc::Less}); });
    EXPECT_THAT(message, HasSubstr("closest-sample"));
    EXPECT_THAT(message, HasSubstr("[Hathaway 2010] §3.5.1"));
    EXPECT_THAT(message, HasSubstr("DepthResolve::AnySample"));
    // What the message offers runs (the conformance suite's DepthIsOneOfItsSamples checks its values).
    EXPECT_NO_THROW(device->resolve({source, destination, CompareFunc::Less, DepthResolve::AnySample}));
}

TEST(GlesDifferences, MultisampledColourResolvesToTheClearValue) {
    const auto device = createGlesBackend();
    const TextureHandle source = device->createTexture(target("ms colour", Format::RGBA8_UNORM, 4));
    const TextureHandle destination = device->createTexture(target("colour", Format::RGBA8_UNORM, 1));
    PassDesc pass;
    pass.name = "clear";
    pass.color[0] = {source, LoadOp::Clear, glm::vec4(0.0f, 1.0f, 0.0f, 1.0f)};
    device->beginPass(pass);
    device->endPass();
    device->resolve({source, destination});
    const Readback r = device->readback(destination);
    for (int y = 0; y < r.height; ++y)
        for (int x = 0; x < r.width; ++x) {
            EXPECT_EQ(r.at(x, y, 0), 0.0f);
            EXPECT_EQ(r.at(x, y, 1), 1.0f);
        }
}

// Where a ctest entry turns `extension` off with Mesa's MESA_EXTENSION_OVERRIDE, the current
// context must lack it: an ignored override would otherwise pass as the extension's own path.
::testing::AssertionResult overrideHonoured(const std::string& extension) {
    const char* override = std::getenv("MESA_EXTENSION_OVERRIDE");
    const bool turnedOff = override && std::string_view(override).find("-" + extension) != std::string_view::npos;
    if (turnedOff && epoxy_has_gl_extension(extension.c_str()))
        return ::testing::AssertionFailure() << "MESA_EXTENSION_OVERRIDE did not turn " << extension << " off";
    return ::testing::AssertionSuccess();
}

// A triangle over a target sampling `texture` as its base colour through `filter`.
void drawSampling(Device& device, TextureHandle texture, Filter filter) {
    const TextureHandle colour = device.createTexture(target("colour", Format::RGBA8_UNORM, 1));
    const std::vector<Vertex> triangle{{{-1.0f, -1.0f, 0.5f}}, {{3.0f, -1.0f, 0.5f}}, {{-1.0f, 3.0f, 0.5f}}};
    const auto bytes = std::as_bytes(std::span(triangle));
    const BufferHandle vertices = device.createBuffer({"triangle", BufferKind::Vertex, bytes.size()}, bytes);
    PipelineDesc desc;
    desc.name = "samples depth";
    desc.program = ProgramKind::OpaqueLit;
    SurfaceParams params;
    params.baseColor = {texture, {filter, AddressMode::Clamp, AddressMode::Clamp}};
    PassDesc pass;
    pass.name = "sampling depth";
    pass.color[0] = {colour, LoadOp::Clear};
    device.beginPass(pass);
    DrawDesc d;
    d.pipeline = device.createPipeline(desc);
    d.params = params;
    d.vertices = vertices;
    d.count = 3;
    try {
        device.draw(d);
    } catch (...) {
        device.endPass();
        throw;
    }
    device.endPass();
}

TEST(GlesDifferences, DepthSampledWithAFilterIsRefusedNamingTheTexture) {
    const auto device = createGlesBackend();
    const TextureHandle depth = device->createTexture(target("scene depth", Format::D32F, 1));
    for (const Filter filter : {Filter::Bilinear, Filter::Trilinear}) {
        const std::string message = errorOf([&] { drawSampling(*device, depth, filter); });
        EXPECT_THAT(message, HasSubstr("'scene depth' (D32F)"));
        EXPECT_THAT(message, HasSubstr("Filter::Nearest"));
    }
    EXPECT_NO_THROW(drawSampling(*device, depth, Filter::Nearest));
}

// ES 3.0 filters RGBA32F only with OES_texture_float_linear (Table 3.13). Mesa offers it, so the
// refusal runs where ctest's GlesDifferences.Float32FilterRefusedWithoutTheExtension turns the
// extension off (MESA_EXTENSION_OVERRIDE, tests/conformance/gles/CMakeLists.txt); there the test
// first checks that it is off, so a driver that ignored the override fails instead of passing.
TEST(GlesDifferences, Float32SampledWithAFilterNeedsFloatLinear) {
    const auto device = createGlesBackend();
    TextureDesc desc = target("float colour", Format::RGBA32F, 1);
    desc.usage = UsageSampled;
    const TextureHandle texture = device->createTexture(desc);
    ASSERT_TRUE(overrideHonoured("GL_OES_texture_float_linear"));
    const bool floatLinear = epoxy_has_gl_extension("GL_OES_texture_float_linear");
    EXPECT_NO_THROW(drawSampling(*device, texture, Filter::Nearest));
    for (const Filter filter : {Filter::Bilinear, Filter::Trilinear}) {
        if (floatLinear) {
            EXPECT_NO_THROW(drawSampling(*device, texture, filter));
            continue;
        }
        const std::string message = errorOf([&] { drawSampling(*device, texture, filter); });
        EXPECT_THAT(message, HasSubstr("'float colour' (RGBA32F)"));
        EXPECT_THAT(message, HasSubstr("without GL_OES_texture_float_linear"));
    }
}

// Without EXT_clip_control the vertex stages remap origin and depth themselves (gles_shaders.cpp).
// Mesa offers the extension, so the fallback runs where ctest's
// GlesDifferences.ClipControlRemappedWithoutTheExtension turns it off (MESA_EXTENSION_OVERRIDE);
// there the test first checks that it is off. Either way the device starts, says which path it
// took, and a back-culled counter-clockwise triangle over the top half lands in rows 0-1 at its
// depth: origin, facing and depth as the extension gives them.
TEST(GlesDifferences, ClipControlPathIsNamedAndDrawsTheSame) {
    const auto device = createGlesBackend();
    ASSERT_TRUE(overrideHonoured("GL_EXT_clip_control"));
    const bool clipControl = epoxy_has_gl_extension("GL_EXT_clip_control");
    const std::string line = device->driver().describe();
    EXPECT_NE(line.find(clipControl ? "by EXT_clip_control"
                                    : "depth and origin remapped in the vertex stage: no EXT_clip_control"),
              std::string::npos)
        << line;

    const TextureHandle colour = device->createTexture(target("colour", Format::RGBA8_UNORM, 1));
    const TextureHandle depth = device->createTexture(target("depth", Format::D32F, 1));
    // Counter-clockwise as displayed (y up in NDC), covering NDC y > 0: the top two rows.
    const std::vector<Vertex> triangle{{{-1.0f, 0.0f, 0.25f}}, {{3.0f, 0.0f, 0.25f}}, {{-1.0f, 4.0f, 0.25f}}};
    const auto bytes = std::as_bytes(std::span(triangle));
    const BufferHandle vertices = device->createBuffer({"triangle", BufferKind::Vertex, bytes.size()}, bytes);
    PipelineDesc desc;
    desc.name = "top half";
    desc.program = ProgramKind::Flat;
    desc.depth = DepthState::testAndWrite(CompareFunc::Less);
    desc.raster.cull = CullMode::Back;
    PassDesc pass;
    pass.name = "top half";
    pass.color[0] = {colour, LoadOp::Clear};
    pass.depth = {depth, LoadOp::Clear, 1.0f};
    device->beginPass(pass);
    DrawDesc d;
    d.pipeline = device->createPipeline(desc);
    d.params = FlatParams{};
    d.vertices = vertices;
    d.count = 3;
    device->draw(d);
    device->endPass();
    const Readback c = device->readback(colour);
    const Readback z = device->readback(depth);
    for (int y = 0; y < c.height; ++y)
        for (int x = 0; x < c.width; ++x) {
            EXPECT_EQ(c.at(x, y, 0), y < 2 ? 1.0f : 0.0f) << x << ", " << y;
            EXPECT_EQ(z.at(x, y, 0), y < 2 ? 0.25f : 1.0f) << x << ", " << y;
        }
}

TEST(GlesDifferences, AlphaToCoverageIsReportedInexact) {
    const auto device = createGlesBackend();
    PipelineDesc desc;
    desc.name = "a2c";
    desc.alphaTest.alphaToCoverage = true;
    const PipelineInfo info = device->pipelineInfo(device->createPipeline(desc));
    EXPECT_FALSE(info.exact);
    EXPECT_NE(info.note.find("GL_SAMPLE_ALPHA_TO_COVERAGE"), std::string::npos) << info.note;
}

TEST(GlesDifferences, DescribeSaysPassTimesAreTheCpus) {
    const auto device = createGlesBackend();
    const std::string line = device->driver().describe();
    EXPECT_EQ(line.rfind("gles: ", 0), 0u) << line;
    EXPECT_NE(line.find("CPU wall time"), std::string::npos) << line;
}

}  // namespace
}  // namespace engine::render::gles
