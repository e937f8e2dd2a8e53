// SPDX-License-Identifier: MIT
// What the GLES driver does differently from GL 4.5 because OpenGL ES 3.0 cannot do otherwise
// (engine/render/docs/gles.md), checked where it shows: the closest-sample depth resolve of
// [Hathaway 2010] §3.5.1 is refused by name, native alpha-to-coverage is reported inexact,
// pass times say they are the CPU's, and a colour resolve still averages by blit.
#include <gtest/gtest.h>

#include <string>

#include "engine/core/error.hpp"
#include "engine/render/gles/gles_backend.hpp"

namespace engine::render::gles {
namespace {

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
    try {
        device->resolve({source, destination, CompareFunc::Less});
        FAIL() << "a multisampled depth resolve ran on OpenGL ES 3.0";
    } catch (const Error& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find("closest-sample"), std::string::npos) << message;
        EXPECT_NE(message.find("[Hathaway 2010] §3.5.1"), std::string::npos) << message;
    }
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
