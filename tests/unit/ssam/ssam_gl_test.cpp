// SPDX-License-Identifier: MIT
// ssam::gl (the raw-OpenGL entry point, ssam/include/ssam/gl/ssam_gl.hpp) with its built-in
// foliage programs (way a), in a headless EGL context: results against SSAM on our GL backend,
// the host's GL state, and errors as a Status + message. The host is ssam_gl_host.hpp.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "ssam/core/settings.hpp"
#include "ssam/ssam.hpp"
#include "ssam_gl_host.hpp"
#include "run_ssam.hpp"

namespace {

using namespace engine::render;
using namespace ssam::testing;
using ssam::gl::Status;

// Every knob of ssam::Settings: ssam::gl gives the image, depth and masks that ssam::ScreenSpaceAlphaMask
// gives on the GL backend for the same scene. Same GPU, same blending: masks and depth exact; the
// composite within 1 code (the two composite shaders round their arithmetic differently).
TEST(SsamGl, MatchesSsamOnTheGlBackendForEveryKnob) {
    std::vector<ConfigCase> cases;
    cases.push_back({"defaults", {}});
    ssam::Settings c;
    c.squareMask = false;
    cases.push_back({"squareMask off", c});
    c = {};
    c.maskLerp = 0.0f;
    cases.push_back({"maskLerp 0 (max only)", c});
    c = {};
    c.maskLerp = 1.0f;
    cases.push_back({"maskLerp 1 (add only)", c});
    c = {};
    c.maskPrecision = ssam::MaskPrecision::Rgba16f;
    cases.push_back({"rgba16f mask", c});
    c = {};
    c.maskPrecision = ssam::MaskPrecision::Rg16f;
    cases.push_back({"rg16f mask (two r16f targets)", c});
    c = {};
    c.colorAlphaReference = 0.5f;  // both quads fail the colour pass: the clear colour shows
    c.foliageClearColor[0] = 0.9f, c.foliageClearColor[1] = 0.1f, c.foliageClearColor[2] = 0.5f;
    cases.push_back({"colour reference 0.5 + clear colour", c});
    c = {};
    c.colorFade = 0.5f;
    c.foliageClearColor[0] = 0.9f, c.foliageClearColor[1] = 0.1f, c.foliageClearColor[2] = 0.5f;
    cases.push_back({"colour fade 0.5 + clear colour", c});
    c = {};
    c.colorBlur = true;
    cases.push_back({"colour blur", c});
    c = {};
    c.depthTest = ssam::DepthTest::Greater;
    cases.push_back({"reverse-Z (Greater)", c});
    cases.push_back({"sRGB colour", {}, Format::RGBA8_SRGB});
    cases.push_back({"rgba16f colour", {}, Format::RGBA16F});

    GlHost host;
    for (const ConfigCase& k : cases) {
        SCOPED_TRACE(k.name);
        const bool reversed = k.config.depthTest == ssam::DepthTest::Greater;
        std::vector<Quad> quads{kQuadA, kQuadB};
        if (reversed)
            for (Quad& q : quads) q.depth = 1.0f - q.depth;  // the nearer stays nearer
        // The GL backend's SSAM.
        auto reference = host.opaque(ssam::compareFuncOf(k.config.depthTest), k.colorFormat);
        ssam::ScreenSpaceAlphaMask backendSsam(*host.backend, k.config);
        QuadBatches batches(*host.backend, quads);
        const test_support::SsamRun ref = test_support::runSsam(backendSsam, {reference->color(), reference->depth()},
                                                                {glm::mat4(1.0f), kUnlit, batches.batches}, true);
        ASSERT_EQ(ref.report.passesRun, 3);
        // ssam::gl on identical targets.
        auto targets = host.opaque(ssam::compareFuncOf(k.config.depthTest), k.colorFormat);
        auto glSsam = initializedSsam(k.config);
        HostFoliage foliage(quads);
        const std::vector<ssam::gl::Box> bounds = boxesOf(quads);
        ssam::gl::FrameDesc frame = host.frameOf(*targets);
        frame.foliageBounds = bounds.data();
        frame.foliageBoundsCount = bounds.size();
        int calls = 0;
        ssam::gl::FrameReport report;
        ASSERT_EQ(glSsam->render(
                      frame, [&](const ssam::gl::FoliageProgram&) { ++calls, foliage.draw(); }, &report),
                  Status::Ok)
            << glSsam->lastMessage();
        EXPECT_TRUE(report.foliageInView);
        EXPECT_EQ(report.passesRun, 3);
        EXPECT_EQ(calls, 2);

        const float colorTolerance = k.colorFormat == Format::RGBA16F ? 2e-3f : 1.0f / 255.0f + 1e-6f;
        expectNear(host.backend->readback(targets->color()), host.backend->readback(reference->color()), colorTolerance,
                   "composited colour");
        expectNear(host.backend->readback(targets->depth()), host.backend->readback(reference->depth()), 1e-6f,
                   "opaque + foliage depth");
        const ssam::gl::Intermediates ours = glSsam->intermediates();
        const TextureDesc& size = host.backend->describe(reference->color());
        const Format maskFormat = backendSsam.intermediateDescs(size.width, size.height, k.colorFormat).mask.format;
        expectNear(host.readGl(ours.mask, maskFormat), ref.mask, 1e-6f, "mask");
        if (!ref.maskAdd.values.empty())
            expectNear(host.readGl(ours.maskAdd, maskFormat), ref.maskAdd, 1e-6f, "add mask");
        expectNear(host.readGl(ours.foliage, k.colorFormat), ref.foliage,
                   k.colorFormat == Format::RGBA16F ? 1e-3f : 1e-6f, "rt_foliage");
    }
}

// ssam::gl::measuredSettings() is the core's measured preset (the struct is the core's).
TEST(SsamGl, MeasuredSettingsAreTheMeasuredPreset) {
    const ssam::gl::Settings measured = ssam::gl::measuredSettings();
    EXPECT_EQ(ssam::settingsError(measured), "");
    EXPECT_EQ(measured.maskLerp, ssam::presetSettings(ssam::Preset::Measured).maskLerp);
    EXPECT_NE(measured.squareMask, ssam::gl::Settings{}.squareMask);
}

TEST(SsamGl, CallbackSeesTheMaskPassThenTheColourPass) {
    auto&& [host, targets, ssam] = HostWithSsam{};
    HostFoliage foliage({kQuadA});
    std::vector<ssam::gl::FoliageProgram> seen;
    EXPECT_EQ(ssam->render(host.frameOf(*targets),
                           [&](const ssam::gl::FoliageProgram& p) {
                               GLint bound = 0;
                               glGetIntegerv(GL_CURRENT_PROGRAM, &bound);
                               EXPECT_EQ(GLuint(bound), p.program);
                               EXPECT_GE(p.modelUniform, 0);
                               EXPECT_GE(p.baseColorFactorUniform, 0);
                               seen.push_back(p);
                               foliage.draw();
                           }),
              Status::Ok);
    ASSERT_EQ(seen.size(), 2u);
    EXPECT_EQ(seen[0].pass, ssam::gl::FoliagePass::Mask);
    EXPECT_EQ(seen[0].alphaReference, 0.0f);  // §3.5.2: nothing rejected
    EXPECT_EQ(seen[1].pass, ssam::gl::FoliagePass::Color);
    EXPECT_EQ(seen[1].alphaReference, ssam::Settings{}.colorAlphaReference);
    EXPECT_NE(seen[0].program, seen[1].program);
}

// A plain function + user pointer works as the lambda does (the C-like form of the callback).
void drawHostFoliage(void* user, const ssam::gl::FoliageProgram&) { static_cast<const HostFoliage*>(user)->draw(); }

TEST(SsamGl, ModelMatrixAndBaseColourFactorApply) {
    // A quad drawn at x in [-1, 0] moved right by the model matrix; its alpha halved by the factor.
    auto&& [host, targets, ssam] = HostWithSsam{};
    HostFoliage foliage({{-1.0f, -1.0f, 0.0f, 1.0f, 0.5f, {1, 1, 1, 0.8f}}});
    const glm::mat4 model = glm::translate(glm::mat4(1.0f), glm::vec3(1.0f, 0.0f, 0.0f));
    EXPECT_EQ(ssam->render(host.frameOf(*targets),
                           [&](const ssam::gl::FoliageProgram& p) {
                               p.setModel(glm::value_ptr(model));
                               p.setBaseColorFactor(1, 1, 1, 0.5f);
                               foliage.draw();
                           }),
              Status::Ok);
    const Readback mask = host.readGl(ssam->intermediates().mask, Format::RGBA8_UNORM);
    EXPECT_FLOAT_EQ(mask.at(3, 8, 3), 0.0f);                              // left half: moved away
    EXPECT_FLOAT_EQ(mask.at(12, 8, 3), std::round(0.4f * 255) / 255.0f);  // right half: 0.8 * 0.5

    // The same frame through the function-pointer form: the factor back to 1, alpha 0.8.
    auto again = host.opaque();
    EXPECT_EQ(ssam->render(host.frameOf(*again), drawHostFoliage, &foliage), Status::Ok) << ssam->lastMessage();
    const Readback unscaled = host.readGl(ssam->intermediates().mask, Format::RGBA8_UNORM);
    EXPECT_FLOAT_EQ(unscaled.at(3, 8, 3), std::round(0.8f * 255) / 255.0f);
}

TEST(SsamGl, NothingInViewRunsNoPassAndNeverCallsBack) {
    GlHost host;
    auto targets = host.opaque();
    const Readback before = host.backend->readback(targets->color());
    auto ssam = initializedSsam();
    const std::vector<ssam::gl::Box> bounds{{{-1, -1, -0.5f}, {1, 1, -0.5f}}, {{3, 3, 0.5f}, {4, 4, 0.5f}}};
    ssam::gl::FrameDesc frame = host.frameOf(*targets);
    frame.foliageBounds = bounds.data();
    frame.foliageBoundsCount = bounds.size();
    int calls = 0;
    ssam::gl::FrameReport report;
    report.passesRun = -1;
    EXPECT_EQ(ssam->render(
                  frame, [&](const ssam::gl::FoliageProgram&) { ++calls; }, &report),
              Status::Ok);
    EXPECT_FALSE(report.foliageInView);
    EXPECT_EQ(report.passesRun, 0);
    EXPECT_EQ(calls, 0);
    EXPECT_EQ(ssam->intermediates().mask, 0u);  // no target was even allocated
    EXPECT_EQ(host.backend->readback(targets->color()).values, before.values);
}

TEST(SsamGl, CompositeIsScissoredToTheFoliage) {
    // The foliage quad covers the top half, but its bounds say the top-left 4x4 pixels:
    // outside the scissor the composite must not touch the colour.
    auto&& [host, targets, ssam] = HostWithSsam{};
    HostFoliage foliage({{-1.0f, 0.0f, 0.0f, 1.0f, 0.5f, {1, 1, 1, 1.0f}}});
    const ssam::gl::Box bounds{{-1.0f, 0.5f, 0.5f}, {-0.5f, 1.0f, 0.5f}};
    ssam::gl::FrameDesc frame = host.frameOf(*targets);
    frame.foliageBounds = &bounds;
    frame.foliageBoundsCount = 1;
    ssam::gl::FrameReport report;
    EXPECT_EQ(ssam->render(
                  frame, [&](const ssam::gl::FoliageProgram&) { foliage.draw(); }, &report),
              Status::Ok);
    // The backend's clip origin is GL_UPPER_LEFT: window row 0 is the top, as in screenBounds().
    EXPECT_EQ(report.compositeRegion.x, 0);
    EXPECT_EQ(report.compositeRegion.y, 0);
    EXPECT_LE(report.compositeRegion.width, 6);
    const Readback color = host.backend->readback(targets->color());
    EXPECT_FLOAT_EQ(color.at(1, 1, 0), 1.0f);                       // inside: the white leaf
    EXPECT_NEAR(color.at(7, 6, 0), kOpaqueColor.r, 0.5f / 255.0f);  // leaf, outside the scissor
}

// Every piece of state ssam::gl changes is back afterwards, also when the callback throws (which
// becomes Status::CallbackFailed with the exception's message: nothing unwinds into the host).
TEST(SsamGl, RestoresTheHostsGlState) {
    auto&& [host, targets, ssam] = HostWithSsam{};
    HostFoliage foliage({kQuadA, kQuadB});
    const HostGlState hostState;
    for (const bool throwing : {false, true}) {
        SCOPED_TRACE(throwing ? "callback throws" : "normal frame");
        hostState.set();
        const auto draw = [&](const ssam::gl::FoliageProgram&) {
            foliage.draw();
            if (throwing) throw std::runtime_error("host failure");
        };
        const Status status = ssam->render(host.frameOf(*targets), draw);
        if (throwing) {
            EXPECT_EQ(status, Status::CallbackFailed);
            EXPECT_NE(std::string(ssam->lastMessage()).find("threw in the mask pass: host failure"), std::string::npos)
                << ssam->lastMessage();
        } else {
            EXPECT_EQ(status, Status::Ok) << ssam->lastMessage();
        }
        hostState.expectRestored();
    }
}

// Bad input: a Status naming the problem, through the message callback too; a later good frame works.
TEST(SsamGl, BadInputIsRejectedWithAStatusAndAMessage) {
    GlHost host;
    auto targets = host.opaque();
    auto small = std::make_unique<FrameTargets>(*host.backend, FrameTargetsDesc{8, 8, 1, Format::RGBA8_UNORM});
    auto ssam = initializedSsam();
    struct Messages {
        std::vector<std::pair<ssam::gl::Severity, std::string>> seen;
    } messages;
    ssam->setMessageCallback(
        [](void* user, ssam::gl::Severity severity, const char* message) {
            static_cast<Messages*>(user)->seen.emplace_back(severity, message);
        },
        &messages);
    const auto draw = [](const ssam::gl::FoliageProgram&) {};
    const ssam::gl::FrameDesc good = host.frameOf(*targets);
    auto with = [&](auto change) {
        ssam::gl::FrameDesc f = good;
        change(f);
        return f;
    };
    auto expectStatus = [&](Status status, Status expected, const std::string& substring) {
        EXPECT_EQ(status, expected) << ssam::gl::statusName(status) << ": " << ssam->lastMessage();
        EXPECT_NE(std::string(ssam->lastMessage()).find(substring), std::string::npos)
            << "message \"" << ssam->lastMessage() << "\" lacks \"" << substring << "\"";
        ASSERT_FALSE(messages.seen.empty());
        EXPECT_EQ(messages.seen.back().first, ssam::gl::Severity::Error);
        EXPECT_EQ(messages.seen.back().second, ssam->lastMessage());
        messages.seen.clear();
    };
    const Status invalidArgument = Status::InvalidArgument, invalidTexture = Status::InvalidTexture;
    expectStatus(ssam->render(with([](auto& f) { f.width = 0; }), draw), invalidArgument, "is not positive");
    expectStatus(ssam->render(with([](auto& f) { f.foliageBoundsCount = 2; }), draw), invalidArgument,
                 "foliageBoundsCount is 2 but foliageBounds is null");
    expectStatus(ssam->render(with([](auto& f) { f.colorTexture = 0; }), draw), invalidTexture,
                 "colour texture 0 is not a GL texture");
    expectStatus(ssam->render(with([](auto& f) { f.depthTexture = 987654; }), draw), invalidTexture,
                 "depth texture 987654");
    expectStatus(ssam->render(with([&](auto& f) { f.colorTexture = good.depthTexture; }), draw), invalidTexture,
                 "has format GL_DEPTH_COMPONENT32F");
    expectStatus(ssam->render(with([&](auto& f) { f.depthTexture = good.colorTexture; }), draw), invalidTexture,
                 "GL_RGBA8");
    expectStatus(ssam->render(with([&](auto& f) {
                                  f.colorTexture = engine::render::gl::glTexture(*host.backend, small->color());
                              }),
                              draw),
                 invalidTexture, "colour texture is 8x8 but the frame is 16x16");
    expectStatus(ssam->render(with([&](auto& f) {
                                  f.depthTexture = engine::render::gl::glTexture(*host.backend, small->depth());
                              }),
                              draw),
                 invalidTexture, "depth texture is 8x8");
    expectStatus(ssam->render(good, ssam::gl::ScreenSpaceAlphaMaskGl::DrawFoliage{}, nullptr), invalidArgument,
                 "without a draw callback");
    // A multisampled texture is not a GL_TEXTURE_2D.
    TextureDesc ms;
    ms.name = "msaa";
    ms.width = ms.height = kGlSize;
    ms.samples = 4;
    ms.usage = UsageRenderTarget;
    const TextureHandle msaa = host.backend->createTexture(ms);
    expectStatus(
        ssam->render(with([&](auto& f) { f.colorTexture = engine::render::gl::glTexture(*host.backend, msaa); }), draw),
        invalidTexture, "is not a GL_TEXTURE_2D");
    host.backend->destroy(msaa);
    // An unsupported colour format (R8).
    TextureDesc r8 = ms;
    r8.samples = 1;
    r8.format = Format::R8_UNORM;
    const TextureHandle red = host.backend->createTexture(r8);
    expectStatus(
        ssam->render(with([&](auto& f) { f.colorTexture = engine::render::gl::glTexture(*host.backend, red); }), draw),
        invalidTexture, "use GL_RGBA8, GL_SRGB8_ALPHA8");
    host.backend->destroy(red);
    // Bad knobs, named; the settings in force stay.
    ssam::gl::Settings bad;
    bad.maskLerp = 2.0f;
    expectStatus(ssam->setSettings(bad), invalidArgument, "maskLerp");
    bad = {};
    bad.depthTest = static_cast<ssam::gl::DepthTest>(42);
    expectStatus(ssam->setSettings(bad), invalidArgument, "depthTest = 42 is not a DepthTest");
    bad = {};
    bad.foliageClearColor[2] = NAN;
    expectStatus(ssam->setSettings(bad), invalidArgument, "foliageClearColor");
    EXPECT_EQ(ssam->settings().maskLerp, ssam::gl::Settings{}.maskLerp);
    // A GL error the host left pending is a warning, not SSAM's error; after all that a good frame works.
    glBindTexture(GL_TEXTURE_2D, 0xdeadbeef);  // GL_INVALID_OPERATION
    HostFoliage foliage({kQuadA});
    ssam::gl::FrameReport report;
    EXPECT_EQ(ssam->render(
                  good, [&](const ssam::gl::FoliageProgram&) { foliage.draw(); }, &report),
              Status::Ok);
    EXPECT_EQ(report.passesRun, 3);
    ASSERT_EQ(messages.seen.size(), 1u);
    EXPECT_EQ(messages.seen[0].first, ssam::gl::Severity::Warning);
    EXPECT_NE(messages.seen[0].second.find("a GL error (0x0502) was pending"), std::string::npos)
        << messages.seen[0].second;
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

// Every call before initialize(), and initialize() with a loader that lacks a function: a Status
// naming what is wrong, never a crash.
TEST(SsamGl, UninitialisedAndMissingEntryPointsAreStatuses) {
    GlHost host;
    auto targets = host.opaque();
    ssam::gl::ScreenSpaceAlphaMaskGl ssam;
    EXPECT_EQ(ssam.render(host.frameOf(*targets), [](const ssam::gl::FoliageProgram&) {}), Status::InvalidCall);
    EXPECT_NE(std::string(ssam.lastMessage()).find("before initialize()"), std::string::npos) << ssam.lastMessage();
    EXPECT_EQ(ssam.beginMaskPass(), Status::InvalidCall);
    EXPECT_EQ(ssam.initialize(static_cast<ssam::gl::GetProcAddress>(nullptr)), Status::InvalidArgument);

    // A loader that has everything but glBlendFuncSeparate.
    const ssam::gl::GetProcAddress withoutBlendFuncSeparate = [](const char* name) -> void* {
        if (std::string(name) == "glBlendFuncSeparate") return nullptr;
        return reinterpret_cast<void*>(eglGetProcAddress(name));
    };
    EXPECT_EQ(ssam.initialize(withoutBlendFuncSeparate), Status::MissingEntryPoint);
    EXPECT_NE(std::string(ssam.lastMessage()).find("no address for glBlendFuncSeparate"), std::string::npos)
        << ssam.lastMessage();
    EXPECT_EQ(ssam.render(host.frameOf(*targets), [](const ssam::gl::FoliageProgram&) {}), Status::InvalidCall);

    // The void*-returning loader shape works as eglGetProcAddress's does.
    const ssam::gl::GetProcAddress everything = [](const char* name) -> void* {
        return reinterpret_cast<void*>(eglGetProcAddress(name));
    };
    EXPECT_EQ(ssam.initialize(everything), Status::Ok) << ssam.lastMessage();
    HostFoliage foliage({kQuadA});
    EXPECT_EQ(ssam.render(host.frameOf(*targets), [&](const ssam::gl::FoliageProgram&) { foliage.draw(); }),
              Status::Ok);
    ssam.release();
    EXPECT_EQ(ssam.render(host.frameOf(*targets), [](const ssam::gl::FoliageProgram&) {}), Status::InvalidCall);
}

TEST(SsamGl, NoCurrentContextIsAStatus) {
    GlHost host;  // makes its EGL context current
    const EGLDisplay display = eglGetCurrentDisplay();
    const EGLContext context = eglGetCurrentContext();
    ASSERT_NE(context, EGL_NO_CONTEXT);
    ASSERT_TRUE(eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT));
    ssam::gl::ScreenSpaceAlphaMaskGl ssam;
    const Status status = ssam.initialize(eglGetProcAddress);
    ASSERT_TRUE(eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context));
    EXPECT_EQ(status, Status::NoContext);
    EXPECT_NE(std::string(ssam.lastMessage()).find("no OpenGL context is current"), std::string::npos)
        << ssam.lastMessage();
}

}  // namespace
