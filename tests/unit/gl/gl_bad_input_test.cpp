// SPDX-License-Identifier: MIT
// Bad input on the GL backend: broken GLSL, incomplete framebuffers and impossible contexts
// give engine::Error with a clear message; misuse of the Backend interface is rejected with
// exactly the soft backend's message (validation parity).
#include <functional>
#include <memory>
#include <optional>
#include <string>

#include <epoxy/gl.h>
#include <gtest/gtest.h>

#include "../../conformance/backend_fixture.hpp"
#include "engine/core/error.hpp"
#include "engine/render/gl/gl_backend.hpp"
#include "engine/render/gl/gl_program.hpp"
#include "engine/render/soft/soft_backend.hpp"
#include "ssam/composite_program.hpp"

namespace ssam::test {
namespace {

namespace gl = engine::render::gl;
using render::Format;

constexpr const char* kVertex = "#version 450 core\nvoid main() { gl_Position = vec4(0.0); }\n";

TEST(GlBadInput, BrokenGlslThrowsWithTheInfoLog) {
    auto backend = gl::createGlBackend();
    try {
        gl::compileProgram("broken_fragment", kVertex,
                           "#version 450 core\nout vec4 o;\nvoid main() { o = undefined_function(1.0); }\n");
        FAIL() << "broken GLSL compiled";
    } catch (const engine::Error& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find("broken_fragment"), std::string::npos) << message;
        EXPECT_NE(message.find("fragment shader does not compile"), std::string::npos) << message;
        EXPECT_NE(message.find("undefined_function"), std::string::npos) << "the info log is missing: " << message;
    }
    expectError(
        [] { gl::compileProgram("broken_vertex", "#version 450 core\nvoid main() { gl_Position = 1; }\n", kVertex); },
        "broken_vertex': vertex shader does not compile");
}

TEST(GlBadInput, LinkErrorThrowsWithTheInfoLog) {
    auto backend = gl::createGlBackend();
    expectError(
        [] {
            gl::compileProgram(
                "unlinked", kVertex,
                "#version 450 core\nin vec4 v_never_written;\nout vec4 o;\nvoid main() { o = v_never_written; }\n");
        },
        "'unlinked' does not link");
}

TEST(GlBadInput, IncompleteFramebufferThrows) {
    auto backend = gl::createGlBackend();
    GLuint fbo = 0;
    glCreateFramebuffers(1, &fbo);
    expectError([&] { gl::checkFramebuffer(fbo, "framebuffer 'empty'"); },
                "framebuffer 'empty': framebuffer incomplete (GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT)");
    glDeleteFramebuffers(1, &fbo);
}

// Through the backend: a host texture whose sample locations are not fixed cannot share a
// framebuffer with the backend's depth texture (fixed locations): the pass fails, named.
TEST(GlBadInput, IncompletePassFramebufferThrows) {
    auto backend = gl::createGlBackend();
    GLuint id = 0;
    glCreateTextures(GL_TEXTURE_2D_MULTISAMPLE, 1, &id);
    glTextureStorage2DMultisample(id, 4, GL_RGBA8, 8, 8, GL_FALSE);
    const auto color = engine::render::gl::importTexture(
        *backend, id, {"host_msaa", 8, 8, Format::RGBA8_UNORM, 4, 1, render::UsageRenderTarget});
    const auto depth = backend->createTexture({"depth", 8, 8, Format::D32F, 4, 1, render::UsageRenderTarget});
    render::PassDesc pass;
    pass.name = "mixed";
    pass.color[0] = {color};
    pass.depth = {depth};
    expectError([&] { backend->beginPass(pass); },
                "pass 'mixed': framebuffer incomplete (GL_FRAMEBUFFER_INCOMPLETE_MULTISAMPLE)");
    // The failed pass left nothing open.
    pass.depth = {};
    backend->beginPass(pass);
    backend->endPass();
    glDeleteTextures(1, &id);
}

TEST(GlBadInput, ImpossibleContextsThrow) {
    expectError([] { gl::HeadlessEglContext::create({.major = 9, .minor = 5}); }, "no OpenGL 9.5 core context");
    expectError([] { gl::HeadlessEglContext::create({.device = 1000}); }, "device 1000");
    EXPECT_FALSE(gl::HeadlessEglContext::unavailableReason({.major = 9}).empty());
    gl::GlOptions both;
    both.context = gl::HeadlessEglContext::create();
    both.useCurrentContext = true;
    expectError([&] { gl::createGlBackend(both); }, "pick one");
}

TEST(GlBadInput, SampleCountsBeyondTheImplementationThrow) {
    auto backend = gl::createGlBackend();
    if (gl::glDriver(*backend).info().maxSamples >= 8) GTEST_SKIP() << "this implementation has 8x MSAA";
    expectError(
        [&] {
            backend->createTexture({"msaa8", 8, 8, Format::RGBA8_UNORM, 8, 1, render::UsageRenderTarget});
        },
        "texture 'msaa8': 8 samples exceed this GL implementation's");
}

// ---- validation parity: every misuse gives the soft backend's message ------------------

struct Rig {
    std::unique_ptr<render::Backend> backend;
    render::TextureHandle color, colorSmall, depth, sampled, msaa;
    render::BufferHandle vertices, indices, instances;
    render::PipelineHandle flat, depthTested, lit;
};

Rig makeRig(std::unique_ptr<render::Backend> backend) {
    Rig r;
    r.backend = std::move(backend);
    render::Backend& b = *r.backend;
    r.color =
        b.createTexture({"color", 8, 8, Format::RGBA8_UNORM, 1, 1, render::UsageRenderTarget | render::UsageSampled});
    r.colorSmall =
        b.createTexture({"small", 4, 4, Format::RGBA8_UNORM, 1, 1, render::UsageRenderTarget | render::UsageSampled});
    r.depth = b.createTexture({"depth", 8, 8, Format::D32F, 1, 1, render::UsageRenderTarget});
    r.sampled = b.createTexture({"sampled", 8, 8, Format::RGBA8_UNORM, 1, 1, render::UsageSampled});
    r.msaa = b.createTexture({"msaa", 8, 8, Format::RGBA8_UNORM, 4, 1, render::UsageRenderTarget});
    const auto quad = pixelRect(8, 8, 0, 0, 8, 8);
    r.vertices =
        b.createBuffer({"quad", render::BufferKind::Vertex, quad.size() * sizeof(render::Vertex)}, bytesOf(quad));
    const std::vector<std::uint32_t> idx = {0, 1, 2, 3, 4, 9};
    r.indices = b.createBuffer({"bad_indices", render::BufferKind::Index, idx.size() * 4}, bytesOf(idx));
    r.instances = b.createBuffer({"instances", render::BufferKind::Instance, 2 * sizeof(render::Instance)}, {});
    render::PipelineDesc flat;
    flat.name = "flat";
    r.flat = b.createPipeline(flat);
    render::PipelineDesc dt;
    dt.name = "depth_tested";
    dt.depth = render::DepthState::testAndWrite();
    r.depthTested = b.createPipeline(dt);
    render::PipelineDesc lit;
    lit.name = "lit";
    lit.program = render::ProgramKind::OpaqueLit;
    r.lit = b.createPipeline(lit);
    return r;
}

// Runs `misuse` on a fresh rig; returns the Error message, or nullopt when nothing was thrown.
std::optional<std::string> messageOf(std::unique_ptr<render::Backend> backend,
                                     const std::function<void(Rig&)>& misuse) {
    Rig rig = makeRig(std::move(backend));
    try {
        misuse(rig);
    } catch (const engine::Error& e) {
        return std::string(e.what());
    }
    return std::nullopt;
}

void beginColorPass(Rig& r, render::TextureHandle color = {}) {
    render::PassDesc p;
    p.name = "p";
    p.color[0] = {color ? color : r.color};
    r.backend->beginPass(p);
}

render::DrawDesc flatDraw(const Rig& r) { return meshDraw(r.flat, render::FlatParams{}, r.vertices, 6); }

struct Misuse {
    const char* name;
    std::function<void(Rig&)> run;
};

// A misuse that draws flatDraw(r) in a colour pass after `edit` has changed it.
std::function<void(Rig&)> badDraw(void (*edit)(Rig&, render::DrawDesc&)) {
    return [edit](Rig& r) {
        beginColorPass(r);
        render::DrawDesc d = flatDraw(r);
        edit(r, d);
        r.backend->draw(d);
    };
}

// The lit program sampling `texture`.
void sampleWithLit(Rig& r, render::DrawDesc& d, render::TextureHandle texture) {
    d.pipeline = r.lit;
    render::SurfaceParams params;
    params.baseColor.texture = texture;
    d.params = params;
}

const Misuse kMisuses[] = {
    {"empty texture",
     [](Rig& r) {
         r.backend->createTexture({"zero", 0, 4});
     }},
    {"huge texture",
     [](Rig& r) {
         r.backend->createTexture({"huge", 20000, 4});
     }},
    {"3 samples",
     [](Rig& r) {
         r.backend->createTexture({"three", 4, 4, Format::RGBA8_UNORM, 3, 1, render::UsageRenderTarget});
     }},
    {"sampled msaa",
     [](Rig& r) {
         r.backend->createTexture({"ms", 4, 4, Format::RGBA8_UNORM, 4});
     }},
    {"sampled depth",
     [](Rig& r) {
         r.backend->createTexture({"d", 4, 4, Format::D32F});
     }},
    {"too many mips",
     [](Rig& r) {
         r.backend->createTexture({"mips", 4, 4, Format::RGBA8_UNORM, 1, 4});
     }},
    {"wrong level size",
     [](Rig& r) {
         std::vector<std::byte> bytes(10);
         render::TextureData data{{bytes}};
         r.backend->createTexture({"data", 4, 4}, &data);
     }},
    {"too many levels",
     [](Rig& r) {
         std::vector<std::byte> bytes(64);
         render::TextureData data{{bytes, bytes}};
         r.backend->createTexture({"levels", 4, 4}, &data);
     }},
    {"buffer size",
     [](Rig& r) {
         r.backend->createBuffer({"odd", render::BufferKind::Vertex, 47}, {});
     }},
    {"buffer data size",
     [](Rig& r) {
         std::vector<std::byte> bytes(8);
         r.backend->createBuffer({"short", render::BufferKind::Index, 16}, bytes);
     }},
    {"buffer overrun",
     [](Rig& r) {
         std::vector<std::byte> bytes(8);
         r.backend->updateBuffer(r.indices, 20, bytes);
     }},
    {"stale texture",
     [](Rig& r) {
         r.backend->destroy(r.sampled);
         r.backend->describe(r.sampled);
     }},
    {"null pipeline", [](Rig& r) { r.backend->pipelineInfo({}); }},
    {"nan alpha reference",
     [](Rig& r) {
         render::PipelineDesc pd;
         pd.name = "nan";
         pd.alphaTest = {true, render::CompareFunc::Less, std::nanf(""), render::AlphaFailMode::Keep, false};
         r.backend->createPipeline(pd);
     }},
    {"depth-tested composite",
     [](Rig& r) {
         render::PipelineDesc pd;
         pd.name = "composite";
         pd.program = r.backend->createProgram(ssam::compositeProgram());
         pd.depth = render::DepthState::testOnly();
         r.backend->createPipeline(pd);
     }},
    {"nested pass",
     [](Rig& r) {
         beginColorPass(r);
         beginColorPass(r);
     }},
    {"pass size mismatch",
     [](Rig& r) {
         render::PassDesc p;
         p.name = "mismatch";
         p.color[0] = {r.color};
         p.color[1] = {r.colorSmall};
         r.backend->beginPass(p);
     }},
    {"not a render target", [](Rig& r) { beginColorPass(r, r.sampled); }},
    {"depth as colour", [](Rig& r) { beginColorPass(r, r.depth); }},
    {"colour as depth",
     [](Rig& r) {
         render::PassDesc p;
         p.name = "depth";
         p.depth = {r.color};
         r.backend->beginPass(p);
     }},
    {"no attachments",
     [](Rig& r) {
         render::PassDesc p;
         p.name = "empty";
         r.backend->beginPass(p);
     }},
    {"draw outside pass", [](Rig& r) { r.backend->draw(flatDraw(r)); }},
    {"end without begin", [](Rig& r) { r.backend->endPass(); }},
    {"params mismatch", badDraw([](Rig&, render::DrawDesc& d) { d.params = render::AlphaOnlyParams{}; })},
    {"depth test without depth", badDraw([](Rig& r, render::DrawDesc& d) { d.pipeline = r.depthTested; })},
    {"count not multiple of 3", badDraw([](Rig&, render::DrawDesc& d) { d.count = 4; })},
    {"vertices out of range", badDraw([](Rig&, render::DrawDesc& d) { d.first = 3; })},
    {"index out of range", badDraw([](Rig& r, render::DrawDesc& d) { d.indices = r.indices; })},
    {"indices past the buffer", badDraw([](Rig& r, render::DrawDesc& d) {
         d.indices = r.indices;
         d.first = 3;
     })},
    {"index buffer as vertices", badDraw([](Rig& r, render::DrawDesc& d) { d.vertices = r.indices; })},
    {"too many instances", badDraw([](Rig& r, render::DrawDesc& d) {
         d.instances = r.instances;
         d.instanceCount = 3;
     })},
    {"instances without buffer", badDraw([](Rig&, render::DrawDesc& d) { d.instanceCount = 2; })},
    {"sampling the target", badDraw([](Rig& r, render::DrawDesc& d) { sampleWithLit(r, d, r.color); })},
    {"sampling msaa", badDraw([](Rig& r, render::DrawDesc& d) { sampleWithLit(r, d, r.msaa); })},
    {"resolve mismatch",
     [](Rig& r) {
         r.backend->resolve({r.msaa, r.colorSmall});
     }},
    {"readback msaa", [](Rig& r) { r.backend->readback(r.msaa); }},
};

TEST(GlBadInput, ValidationMatchesSoftWordForWord) {
    for (const Misuse& m : kMisuses) {
        const auto soft = messageOf(engine::render::soft::createSoftBackend({.threads = 1}), m.run);
        const auto gl = messageOf(gl::createGlBackend(), m.run);
        ASSERT_TRUE(soft.has_value()) << m.name << ": the soft backend accepted it";
        ASSERT_TRUE(gl.has_value()) << m.name << ": the GL backend accepted it (soft: " << *soft << ")";
        EXPECT_EQ(*gl, *soft) << m.name;
    }
}

}  // namespace
}  // namespace ssam::test
