// SPDX-License-Identifier: MIT
// ssam::gl (the raw-OpenGL entry point, ssam/include/ssam/gl/ssam_gl.hpp) in a headless EGL
// context. Its render targets come from our GL backend, which is the "host engine" here: the
// backend draws the opaque pass, hands its GL texture names to ssam::gl, and reads the results
// back (its own SSAM is verified exactly by ssam_cases.hpp). The host's foliage is drawn by the
// callback with plain GL (its own VAO and buffer at ssam::gl::AttributeLocations).
#include <gtest/gtest.h>

#include <epoxy/egl.h>
#include <epoxy/gl.h>

#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "engine/core/error.hpp"
#include "engine/render/frame_targets.hpp"
#include "engine/render/gl/gl_backend.hpp"
#include "expect_error.hpp"
#include "quad_scene.hpp"
#include "ssam/gl/ssam_gl.hpp"
#include "ssam/ssam.hpp"

namespace {

using namespace engine::render;
using ssam::testing::Quad;
using ssam::testing::QuadBatches;

constexpr int kSize = 16;
const glm::vec4 kOpaqueColor{0.2f, 0.4f, 0.6f, 1.0f};
const DirectionalLight kUnlit{{0.0f, 0.0f, 1.0f}, glm::vec3(0.0f), glm::vec3(1.0f)};
// The crossing pair of ssam_cases.hpp: A (alpha 0.4, nearer) on the left, B (alpha 0.2) on the right.
const Quad kQuadA{-1.0f, -1.0f, 0.25f, 1.0f, 0.3f, {1.0f, 0.0f, 0.0f, 0.4f}};
const Quad kQuadB{-0.25f, -1.0f, 1.0f, 1.0f, 0.6f, {0.0f, 1.0f, 0.0f, 0.2f}};

// The host's foliage: one VAO and buffer of position + colour quads, drawn one quad per draw.
struct HostFoliage {
    GLuint vao = 0, buffer = 0;
    int quads = 0;
    explicit HostFoliage(const std::vector<Quad>& qs) : quads(static_cast<int>(qs.size())) {
        std::vector<float> data;
        for (const Quad& q : qs)
            for (const Vertex& v : ssam::testing::quadVertices(q))
                data.insert(data.end(), {v.position.x, v.position.y, v.position.z, v.color.r, v.color.g, v.color.b, v.color.a});
        glGenVertexArrays(1, &vao);
        glGenBuffers(1, &buffer);
        glBindVertexArray(vao);
        glBindBuffer(GL_ARRAY_BUFFER, buffer);
        glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(data.size() * sizeof(float)), data.data(), GL_STATIC_DRAW);
        using Loc = ssam::gl::AttributeLocations;
        glEnableVertexAttribArray(Loc::position);
        glVertexAttribPointer(Loc::position, 3, GL_FLOAT, GL_FALSE, 7 * sizeof(float), nullptr);
        glEnableVertexAttribArray(Loc::color);
        glVertexAttribPointer(Loc::color, 4, GL_FLOAT, GL_FALSE, 7 * sizeof(float),
                              reinterpret_cast<const void*>(3 * sizeof(float)));
        glBindVertexArray(0);
    }
    ~HostFoliage() {
        glDeleteBuffers(1, &buffer);
        glDeleteVertexArrays(1, &vao);
    }
    void draw(const ssam::gl::FoliageProgram&) const {
        glBindVertexArray(vao);
        for (int i = 0; i < quads; ++i) glDrawArrays(GL_TRIANGLES, i * 6, 6);
    }
};

std::vector<engine::render::BoundingBox> boundsOf(const std::vector<Quad>& qs) {
    std::vector<engine::render::BoundingBox> out;
    for (const Quad& q : qs) out.push_back({{q.x0, q.y0, q.depth}, {q.x1, q.y1, q.depth}});
    return out;
}

struct Host {
    std::unique_ptr<gl::GlBackend> backend = gl::createGlBackend({});

    // Opaque targets cleared to kOpaqueColor and the far depth (plus an optional opaque quad).
    std::unique_ptr<engine::render::FrameTargets> opaque(CompareFunc depthFunc = CompareFunc::Less,
                                                 Format format = Format::RGBA8_UNORM,
                                                 const std::vector<Quad>& quads = {}) {
        auto targets = std::make_unique<engine::render::FrameTargets>(*backend,
                                                              engine::render::FrameTargetsDesc{kSize, kSize, 1, format, depthFunc});
        PipelineDesc p;
        p.name = "opaque flat";
        p.depth = DepthState::testAndWrite(depthFunc);
        const PipelineHandle pipeline = backend->createPipeline(p);
        QuadBatches geometry(*backend, quads);
        backend->beginPass(targets->passDesc(kOpaqueColor));
        geometry.drawFlat(pipeline);
        backend->endPass();
        backend->destroy(pipeline);
        return targets;
    }

    ssam::gl::FrameDesc frameOf(const engine::render::FrameTargets& t) const {
        ssam::gl::FrameDesc f;
        f.colorTexture = backend->glTexture(t.color());
        f.depthTexture = backend->glTexture(t.depth());
        f.width = f.height = kSize;
        f.light = kUnlit;
        return f;
    }

    Readback readGl(unsigned int name, Format format) {
        TextureDesc desc;
        desc.name = "ssam_gl target";
        desc.width = desc.height = kSize;
        desc.format = format;
        desc.usage = UsageRenderTarget | UsageSampled;
        const TextureHandle h = backend->importTexture(name, desc);
        Readback r = backend->readback(h);
        backend->destroy(h);
        return r;
    }
};

void expectNear(const Readback& a, const Readback& b, float tolerance, const std::string& what) {
    ASSERT_EQ(a.values.size(), b.values.size()) << what;
    int bad = 0;
    for (std::size_t i = 0; i < a.values.size(); ++i)
        if (!(std::fabs(a.values[i] - b.values[i]) <= tolerance) && bad++ < 5)
            ADD_FAILURE() << what << ": value " << i << " is " << a.values[i] << ", the GL backend's " << b.values[i];
}

// Every knob of ssam::Config: ssam::gl gives the image, depth and masks that ssam::ScreenSpaceAlphaMask
// gives on the GL backend for the same scene. Same GPU, same blending: masks and depth exact; the
// composite within 1 code (the two composite shaders round their arithmetic differently).
TEST(SsamGl, MatchesSsamOnTheGlBackendForEveryKnob) {
    struct Case {
        const char* name;
        ssam::Config config;
        Format colorFormat = Format::RGBA8_UNORM;
    };
    std::vector<Case> cases;
    cases.push_back({"defaults", {}});
    ssam::Config c;
    c.squareMask = false;
    cases.push_back({"squareMask off", c});
    c = {};
    c.maskLerp = 0.0f;
    cases.push_back({"maskLerp 0 (max only)", c});
    c = {};
    c.maskLerp = 1.0f;
    cases.push_back({"maskLerp 1 (add only)", c});
    c = {};
    c.maskPrecision = ssam::MaskPrecision::RGBA16F;
    cases.push_back({"rgba16f mask", c});
    c = {};
    c.maskPrecision = ssam::MaskPrecision::RG16F;
    cases.push_back({"rg16f mask (two r16f targets)", c});
    c = {};
    c.colorAlphaReference = 0.5f;  // both quads fail the colour pass: the clear colour shows
    c.foliageClearColor = {0.9f, 0.1f, 0.5f, 0.0f};
    cases.push_back({"colour reference 0.5 + clear colour", c});
    c = {};
    c.depthFunc = CompareFunc::Greater;
    cases.push_back({"reverse-Z (Greater)", c});
    cases.push_back({"sRGB colour", {}, Format::RGBA8_SRGB});
    cases.push_back({"rgba16f colour", {}, Format::RGBA16F});

    Host host;
    for (const Case& k : cases) {
        SCOPED_TRACE(k.name);
        const bool reversed = k.config.depthFunc == CompareFunc::Greater;
        std::vector<Quad> quads{kQuadA, kQuadB};
        if (reversed)
            for (Quad& q : quads) q.depth = 1.0f - q.depth;  // the nearer stays nearer
        // The GL backend's SSAM.
        auto reference = host.opaque(k.config.depthFunc, k.colorFormat);
        ssam::ScreenSpaceAlphaMask backendSsam(*host.backend, k.config);
        QuadBatches batches(*host.backend, quads);
        ASSERT_EQ(backendSsam.render({reference->color(), reference->depth()}, {glm::mat4(1.0f), kUnlit, batches.batches})
                      .passesRun,
                  3);
        // ssam::gl on identical targets.
        auto targets = host.opaque(k.config.depthFunc, k.colorFormat);
        ssam::gl::ScreenSpaceAlphaMaskGl glSsam(k.config);
        HostFoliage foliage(quads);
        const std::vector<engine::render::BoundingBox> bounds = boundsOf(quads);
        ssam::gl::FrameDesc frame = host.frameOf(*targets);
        frame.foliageBounds = std::span<const engine::render::BoundingBox>(bounds);
        int calls = 0;
        const ssam::gl::FrameReport report =
            glSsam.render(frame, [&](const ssam::gl::FoliageProgram& p) { ++calls, foliage.draw(p); });
        EXPECT_EQ(report.passesRun, 3);
        EXPECT_EQ(calls, 2);

        const float colorTolerance = k.colorFormat == Format::RGBA16F ? 2e-3f : 1.0f / 255.0f + 1e-6f;
        expectNear(host.backend->readback(targets->color()), host.backend->readback(reference->color()), colorTolerance,
                   "composited colour");
        expectNear(host.backend->readback(targets->depth()), host.backend->readback(reference->depth()), 1e-6f,
                   "opaque + foliage depth");
        const ssam::Intermediates ref = backendSsam.intermediates();
        const ssam::gl::GlIntermediates ours = glSsam.intermediates();
        const Format maskFormat = host.backend->describe(ref.mask).format;
        expectNear(host.readGl(ours.mask, maskFormat), host.backend->readback(ref.mask), 1e-6f, "mask");
        if (ref.maskAdd) expectNear(host.readGl(ours.maskAdd, maskFormat), host.backend->readback(ref.maskAdd), 1e-6f, "add mask");
        expectNear(host.readGl(ours.foliage, k.colorFormat), host.backend->readback(ref.foliage),
                   k.colorFormat == Format::RGBA16F ? 1e-3f : 1e-6f, "rt_foliage");
    }
}

TEST(SsamGl, CallbackSeesTheMaskPassThenTheColourPass) {
    Host host;
    auto targets = host.opaque();
    ssam::gl::ScreenSpaceAlphaMaskGl ssam;
    HostFoliage foliage({kQuadA});
    std::vector<ssam::gl::FoliageProgram> seen;
    ssam.render(host.frameOf(*targets), [&](const ssam::gl::FoliageProgram& p) {
        GLint bound = 0;
        glGetIntegerv(GL_CURRENT_PROGRAM, &bound);
        EXPECT_EQ(GLuint(bound), p.program);
        EXPECT_GE(p.modelUniform, 0);
        EXPECT_GE(p.baseColorFactorUniform, 0);
        seen.push_back(p);
        foliage.draw(p);
    });
    ASSERT_EQ(seen.size(), 2u);
    EXPECT_EQ(seen[0].pass, ssam::gl::FoliagePass::Mask);
    EXPECT_EQ(seen[0].alphaReference, 0.0f);  // §3.5.2: nothing rejected
    EXPECT_EQ(seen[1].pass, ssam::gl::FoliagePass::Color);
    EXPECT_EQ(seen[1].alphaReference, ssam::Config{}.colorAlphaReference);
    EXPECT_NE(seen[0].program, seen[1].program);
}

TEST(SsamGl, ModelMatrixAndBaseColourFactorApply) {
    // A quad drawn at x in [-1, 0] moved right by the model matrix; its alpha halved by the factor.
    Host host;
    auto targets = host.opaque();
    ssam::gl::ScreenSpaceAlphaMaskGl ssam;
    HostFoliage foliage({{-1.0f, -1.0f, 0.0f, 1.0f, 0.5f, {1, 1, 1, 0.8f}}});
    ssam.render(host.frameOf(*targets), [&](const ssam::gl::FoliageProgram& p) {
        p.setModel(glm::translate(glm::mat4(1.0f), glm::vec3(1.0f, 0.0f, 0.0f)));
        p.setBaseColorFactor({1, 1, 1, 0.5f});
        foliage.draw(p);
    });
    const Readback mask = host.readGl(ssam.intermediates().mask, Format::RGBA8_UNORM);
    EXPECT_FLOAT_EQ(mask.at(3, 8, 3), 0.0f);                             // left half: moved away
    EXPECT_FLOAT_EQ(mask.at(12, 8, 3), std::round(0.4f * 255) / 255.0f);  // right half: 0.8 * 0.5
}

TEST(SsamGl, NothingInViewRunsNoPassAndNeverCallsBack) {
    Host host;
    auto targets = host.opaque();
    const Readback before = host.backend->readback(targets->color());
    ssam::gl::ScreenSpaceAlphaMaskGl ssam;
    const std::vector<engine::render::BoundingBox> bounds{{{-1, -1, -0.5f}, {1, 1, -0.5f}}, {{3, 3, 0.5f}, {4, 4, 0.5f}}};
    ssam::gl::FrameDesc frame = host.frameOf(*targets);
    frame.foliageBounds = std::span<const engine::render::BoundingBox>(bounds);
    int calls = 0;
    EXPECT_EQ(ssam.render(frame, [&](const ssam::gl::FoliageProgram&) { ++calls; }).passesRun, 0);
    EXPECT_EQ(calls, 0);
    EXPECT_EQ(ssam.intermediates().mask, 0u);  // no target was even allocated
    EXPECT_EQ(host.backend->readback(targets->color()).values, before.values);
}

TEST(SsamGl, CompositeIsScissoredToTheFoliage) {
    // The foliage quad covers only the top-left quarter, but its bounds say the top-left
    // 4x4 pixels: outside the scissor the composite must not touch the colour.
    Host host;
    auto targets = host.opaque();
    ssam::gl::ScreenSpaceAlphaMaskGl ssam;
    HostFoliage foliage({{-1.0f, 0.0f, 0.0f, 1.0f, 0.5f, {1, 1, 1, 1.0f}}});
    const std::vector<engine::render::BoundingBox> bounds{{{-1.0f, 0.5f, 0.5f}, {-0.5f, 1.0f, 0.5f}}};
    ssam::gl::FrameDesc frame = host.frameOf(*targets);
    frame.foliageBounds = std::span<const engine::render::BoundingBox>(bounds);
    const ssam::gl::FrameReport report = ssam.render(frame, [&](const ssam::gl::FoliageProgram& p) { foliage.draw(p); });
    // The backend's clip origin is GL_UPPER_LEFT: window row 0 is the top, as in screenBounds().
    EXPECT_EQ(report.compositeRegion.x, 0);
    EXPECT_EQ(report.compositeRegion.y, 0);
    EXPECT_LE(report.compositeRegion.width, 6);
    const Readback color = host.backend->readback(targets->color());
    EXPECT_FLOAT_EQ(color.at(1, 1, 0), 1.0f);                              // inside: the white leaf
    EXPECT_NEAR(color.at(7, 6, 0), kOpaqueColor.r, 0.5f / 255.0f);         // leaf, outside the scissor
}

// Every piece of state ssam::gl changes is back afterwards, also when the callback throws.
TEST(SsamGl, RestoresTheHostsGlState) {
    Host host;
    auto targets = host.opaque();
    ssam::gl::ScreenSpaceAlphaMaskGl ssam;
    HostFoliage foliage({kQuadA, kQuadB});
    GLuint hostFbo = 0, hostVao = 0, hostTexture = 0;
    glGenFramebuffers(1, &hostFbo);
    glGenVertexArrays(1, &hostVao);
    glGenTextures(1, &hostTexture);
    glBindTexture(GL_TEXTURE_2D, hostTexture);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
    for (const bool throwing : {false, true}) {
        SCOPED_TRACE(throwing ? "callback throws" : "normal frame");
        glBindFramebuffer(GL_FRAMEBUFFER, hostFbo);
        glViewport(1, 2, 3, 4);
        glScissor(5, 6, 7, 8);
        glEnable(GL_SCISSOR_TEST);
        glEnable(GL_CULL_FACE);
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_GEQUAL);
        glDepthMask(GL_FALSE);
        glEnablei(GL_BLEND, 0);
        glDisablei(GL_BLEND, 1);
        glBlendEquationSeparate(GL_FUNC_SUBTRACT, GL_MIN);
        glBlendFuncSeparate(GL_DST_COLOR, GL_ZERO, GL_ONE_MINUS_DST_ALPHA, GL_SRC_ALPHA);
        glColorMask(GL_TRUE, GL_FALSE, GL_TRUE, GL_FALSE);
        glEnable(GL_STENCIL_TEST);
        glDisable(GL_FRAMEBUFFER_SRGB);
        glEnable(GL_COLOR_LOGIC_OP);
        glBindVertexArray(hostVao);
        glActiveTexture(GL_TEXTURE2);
        glBindTexture(GL_TEXTURE_2D, hostTexture);
        glActiveTexture(GL_TEXTURE1);
        glVertexAttrib4f(3, 0.25f, 0.5f, 0.75f, 1.0f);
        glUseProgram(0);

        auto frame = host.frameOf(*targets);
        auto draw = [&](const ssam::gl::FoliageProgram& p) {
            foliage.draw(p);
            if (throwing) throw std::runtime_error("host failure");
        };
        if (throwing) EXPECT_THROW(ssam.render(frame, draw), std::runtime_error);
        else ssam.render(frame, draw);

        GLint i = 0, v[4] = {};
        glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &i);
        EXPECT_EQ(GLuint(i), hostFbo);
        glGetIntegerv(GL_VIEWPORT, v);
        EXPECT_EQ((std::vector<GLint>(v, v + 4)), (std::vector<GLint>{1, 2, 3, 4}));
        glGetIntegerv(GL_SCISSOR_BOX, v);
        EXPECT_EQ((std::vector<GLint>(v, v + 4)), (std::vector<GLint>{5, 6, 7, 8}));
        EXPECT_TRUE(glIsEnabled(GL_SCISSOR_TEST));
        EXPECT_TRUE(glIsEnabled(GL_CULL_FACE));
        EXPECT_TRUE(glIsEnabled(GL_DEPTH_TEST));
        EXPECT_TRUE(glIsEnabled(GL_STENCIL_TEST));
        EXPECT_FALSE(glIsEnabled(GL_FRAMEBUFFER_SRGB));
        EXPECT_TRUE(glIsEnabled(GL_COLOR_LOGIC_OP));
        glGetIntegerv(GL_DEPTH_FUNC, &i);
        EXPECT_EQ(i, GL_GEQUAL);
        GLboolean b[4] = {};
        glGetBooleanv(GL_DEPTH_WRITEMASK, b);
        EXPECT_FALSE(b[0]);
        EXPECT_TRUE(glIsEnabledi(GL_BLEND, 0));
        EXPECT_FALSE(glIsEnabledi(GL_BLEND, 1));
        glGetIntegerv(GL_BLEND_EQUATION_RGB, &i);
        EXPECT_EQ(i, GL_FUNC_SUBTRACT);
        glGetIntegerv(GL_BLEND_EQUATION_ALPHA, &i);
        EXPECT_EQ(i, GL_MIN);
        glGetIntegerv(GL_BLEND_SRC_RGB, &i);
        EXPECT_EQ(i, GL_DST_COLOR);
        glGetIntegerv(GL_BLEND_DST_ALPHA, &i);
        EXPECT_EQ(i, GL_SRC_ALPHA);
        glGetIntegeri_v(GL_BLEND_EQUATION_RGB, 1, &i);
        EXPECT_EQ(i, GL_FUNC_SUBTRACT);
        glGetBooleanv(GL_COLOR_WRITEMASK, b);
        EXPECT_TRUE(b[0] && !b[1] && b[2] && !b[3]);
        glGetIntegerv(GL_VERTEX_ARRAY_BINDING, &i);
        EXPECT_EQ(GLuint(i), hostVao);
        glGetIntegerv(GL_CURRENT_PROGRAM, &i);
        EXPECT_EQ(i, 0);
        glGetIntegerv(GL_ACTIVE_TEXTURE, &i);
        EXPECT_EQ(i, GL_TEXTURE1);
        glActiveTexture(GL_TEXTURE2);
        glGetIntegerv(GL_TEXTURE_BINDING_2D, &i);
        EXPECT_EQ(GLuint(i), hostTexture);
        GLfloat attribute[4] = {};
        glGetVertexAttribfv(3, GL_CURRENT_VERTEX_ATTRIB, attribute);
        EXPECT_EQ((std::vector<float>(attribute, attribute + 4)), (std::vector<float>{0.25f, 0.5f, 0.75f, 1.0f}));
        EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
    }
    glDisable(GL_COLOR_LOGIC_OP);
    glDisable(GL_STENCIL_TEST);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glDeleteFramebuffers(1, &hostFbo);
    glDeleteVertexArrays(1, &hostVao);
    glDeleteTextures(1, &hostTexture);
}

using ssam::testing::expectError;

TEST(SsamGl, BadInputIsRejectedWithClearErrors) {
    Host host;
    auto targets = host.opaque();
    auto small = std::make_unique<engine::render::FrameTargets>(*host.backend, engine::render::FrameTargetsDesc{8, 8, 1, Format::RGBA8_UNORM});
    ssam::gl::ScreenSpaceAlphaMaskGl ssam;
    const auto draw = [](const ssam::gl::FoliageProgram&) {};
    const ssam::gl::FrameDesc good = host.frameOf(*targets);
    auto with = [&](auto change) {
        ssam::gl::FrameDesc f = good;
        change(f);
        return f;
    };
    expectError([&] { ssam.render(with([](auto& f) { f.width = 0; }), draw); }, "is not positive");
    expectError([&] { ssam.render(with([](auto& f) { f.colorTexture = 0; }), draw); }, "colour texture 0 is not a GL texture");
    expectError([&] { ssam.render(with([](auto& f) { f.depthTexture = 987654; }), draw); }, "depth texture 987654");
    expectError([&] { ssam.render(with([&](auto& f) { f.colorTexture = good.depthTexture; }), draw); },
                "has format GL_DEPTH_COMPONENT32F");
    expectError([&] { ssam.render(with([&](auto& f) { f.depthTexture = good.colorTexture; }), draw); }, "GL_RGBA8");
    expectError([&] { ssam.render(with([&](auto& f) { f.colorTexture = host.backend->glTexture(small->color()); }), draw); },
                "colour texture is 8x8 but the frame is 16x16");
    expectError([&] { ssam.render(with([&](auto& f) { f.depthTexture = host.backend->glTexture(small->depth()); }), draw); },
                "depth texture is 8x8");
    expectError([&] { ssam.render(good, ssam::gl::DrawFoliage{}); }, "no foliage callback");
    // A multisampled texture is not a GL_TEXTURE_2D.
    TextureDesc ms;
    ms.name = "msaa";
    ms.width = ms.height = kSize;
    ms.samples = 4;
    ms.usage = UsageRenderTarget;
    const TextureHandle msaa = host.backend->createTexture(ms);
    expectError([&] { ssam.render(with([&](auto& f) { f.colorTexture = host.backend->glTexture(msaa); }), draw); },
                "is not a GL_TEXTURE_2D");
    host.backend->destroy(msaa);
    // An unsupported colour format (R8).
    TextureDesc r8 = ms;
    r8.samples = 1;
    r8.format = Format::R8_UNORM;
    const TextureHandle red = host.backend->createTexture(r8);
    expectError([&] { ssam.render(with([&](auto& f) { f.colorTexture = host.backend->glTexture(red); }), draw); },
                "use GL_RGBA8, GL_SRGB8_ALPHA8");
    host.backend->destroy(red);
    // A bad knob, named.
    ssam::Config bad;
    bad.maskLerp = 2.0f;
    expectError([&] { ssam.setConfig(bad); }, "maskLerp");
    // After all that, a good frame still works.
    HostFoliage foliage({kQuadA});
    EXPECT_EQ(ssam.render(good, [&](const ssam::gl::FoliageProgram& p) { foliage.draw(p); }).passesRun, 3);
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST(SsamGl, NoCurrentContextIsAnError) {
    Host host;  // makes its EGL context current
    const EGLDisplay display = eglGetCurrentDisplay();
    const EGLContext context = eglGetCurrentContext();
    ASSERT_NE(context, EGL_NO_CONTEXT);
    ASSERT_TRUE(eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT));
    expectError([] { ssam::gl::ScreenSpaceAlphaMaskGl ssam; }, "no OpenGL context is current");
    ASSERT_TRUE(eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context));
}

}  // namespace
