// SPDX-License-Identifier: MIT
// ssam::gl with the host's own shaders (way b: beginFrame, begin/endMaskPass, begin/endColorPass,
// composite), in a headless EGL context: the state each pass sets, the host's state between and
// after the passes, calls out of order, and -- the contract's proof -- host shaders that follow
// the documented contract and compute what the built-in programs compute give the same image,
// masks and depth, bit for bit.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "engine/render/gl/gl_program.hpp"
#include "ssam_gl_host.hpp"

namespace {

using namespace engine::render;
using namespace ssam::testing;
using engine::render::gl::compileProgram;
using engine::render::gl::GlProgram;
using ssam::gl::Status;

// The host's foliage shaders, written to the contract: the vertex colour's alpha is the coverage.
constexpr const char* kHostVertex = R"(#version 330 core
layout(location = 0) in vec3 position;
layout(location = 3) in vec4 color;
uniform mat4 viewProj;
out vec4 v_color;
void main() {
    gl_Position = viewProj * vec4(position, 1.0);
    v_color = color;
}
)";
// Mask pass: vec4(saturated alpha) to every draw buffer SSAM has (PassInfo::drawBuffers).
constexpr const char* kHostMask = R"(#version 330 core
in vec4 v_color;
layout(location = 0) out vec4 mask;
layout(location = 1) out vec4 maskAdd;
void main() {
    float a = clamp(v_color.a, 0.0, 1.0);
    mask = vec4(a);
    maskAdd = vec4(a);
}
)";
// Colour pass: straight colour and alpha, alpha-tested at PassInfo::alphaReference.
constexpr const char* kHostColor = R"(#version 330 core
in vec4 v_color;
uniform float alphaReference;
layout(location = 0) out vec4 color;
void main() {
    if (!(v_color.a >= alphaReference)) discard;
    color = v_color;
}
)";

// Compiled as any GL program of ours is (a compile or link error throws with the log).
struct HostPrograms {
    GlProgram mask = compileProgram("host mask", kHostVertex, kHostMask);
    GlProgram color = compileProgram("host colour", kHostVertex, kHostColor);
    void use(const GlProgram& program, const ssam::gl::FrameDesc& frame) const {
        glUseProgram(program.id());
        glUniformMatrix4fv(program.uniform("viewProj"), 1, GL_FALSE, frame.viewProj);
    }
};

// The whole frame with the host's shaders; returns the first status that is not Ok.
Status renderWithHostShaders(ssam::gl::ScreenSpaceAlphaMaskGl& ssam, const ssam::gl::FrameDesc& frame,
                             const HostPrograms& programs, const HostFoliage& foliage) {
    ssam::gl::FrameReport report;
    if (Status s = ssam.beginFrame(frame, &report); s != Status::Ok || !report.foliageInView) return s;
    ssam::gl::PassInfo pass;
    if (Status s = ssam.beginMaskPass(&pass); s != Status::Ok) return s;
    programs.use(programs.mask, frame);
    foliage.draw();
    if (Status s = ssam.endMaskPass(); s != Status::Ok) return s;
    if (Status s = ssam.beginColorPass(&pass); s != Status::Ok) return s;
    programs.use(programs.color, frame);
    glUniform1f(programs.color.uniform("alphaReference"), pass.alphaReference);
    foliage.draw();
    if (Status s = ssam.endColorPass(); s != Status::Ok) return s;
    return ssam.composite();
}

TEST(SsamGlHostShaders, MimickingTheBuiltInProgramsGivesTheSameImage) {
    std::vector<ConfigCase> cases;
    cases.push_back({"defaults", {}});
    ssam::Settings c;
    c.maskPrecision = ssam::MaskPrecision::Rg16f;  // two draw buffers in the mask pass
    cases.push_back({"rg16f mask", c});
    c = {};
    c.maskPrecision = ssam::MaskPrecision::Rgba16f;
    c.squareMask = false;
    cases.push_back({"rgba16f mask, not squared", c});
    c = {};
    c.depthTest = ssam::DepthTest::Greater;
    cases.push_back({"reverse-Z (Greater)", c});
    c = {};
    c.colorAlphaReference = 0.3f;  // B (alpha 0.2) fails the colour pass, A passes
    cases.push_back({"colour reference 0.3", c});
    cases.push_back({"sRGB colour", {}, Format::RGBA8_SRGB});

    GlHost host;
    const HostPrograms programs;
    for (const ConfigCase& k : cases) {
        SCOPED_TRACE(k.name);
        std::vector<Quad> quads{kQuadA, kQuadB};
        if (k.config.depthTest == ssam::DepthTest::Greater)
            for (Quad& q : quads) q.depth = 1.0f - q.depth;  // the nearer stays nearer
        HostFoliage foliage(quads);
        const std::vector<ssam::gl::Box> bounds = boxesOf(quads);

        auto builtIn = initializedSsam(k.config);
        auto builtInTargets = host.opaque(ssam::compareFuncOf(k.config.depthTest), k.colorFormat);
        ssam::gl::FrameDesc frame = host.frameOf(*builtInTargets);
        frame.foliageBounds = bounds.data();
        frame.foliageBoundsCount = bounds.size();
        ASSERT_EQ(builtIn->render(frame, [&](const ssam::gl::FoliageProgram&) { foliage.draw(); }), Status::Ok)
            << builtIn->lastMessage();

        auto hosted = initializedSsam(k.config);
        auto hostTargets = host.opaque(ssam::compareFuncOf(k.config.depthTest), k.colorFormat);
        ssam::gl::FrameDesc hostFrame = host.frameOf(*hostTargets);
        hostFrame.foliageBounds = bounds.data();
        hostFrame.foliageBoundsCount = bounds.size();
        ASSERT_EQ(renderWithHostShaders(*hosted, hostFrame, programs, foliage), Status::Ok) << hosted->lastMessage();

        expectNear(host.backend->readback(hostTargets->color()), host.backend->readback(builtInTargets->color()), 0.0f,
                   "composited colour");
        expectNear(host.backend->readback(hostTargets->depth()), host.backend->readback(builtInTargets->depth()), 0.0f,
                   "opaque + foliage depth");
        const ssam::gl::Intermediates a = builtIn->intermediates(), b = hosted->intermediates();
        const Format maskFormat = k.config.maskPrecision == ssam::MaskPrecision::Rgba8     ? Format::RGBA8_UNORM
                                  : k.config.maskPrecision == ssam::MaskPrecision::Rgba16f ? Format::RGBA16F
                                                                                           : Format::R16F;
        const Readback mask = host.readGl(b.mask, maskFormat);
        expectNear(mask, host.readGl(a.mask, maskFormat), 0.0f, "mask");
        if (a.maskAdd)
            expectNear(host.readGl(b.maskAdd, maskFormat), host.readGl(a.maskAdd, maskFormat), 0.0f, "add mask");
        expectNear(host.readGl(b.foliage, k.colorFormat), host.readGl(a.foliage, k.colorFormat), 0.0f, "rt_foliage");
        // Not vacuous: A's alpha is in the mask where A is, nothing where no quad is drawn.
        EXPECT_NEAR(mask.at(2, 8, 0), 0.4f, 1.0f / 255.0f);
    }
}

// What a host shader can rely on: each pass's framebuffer, blend, depth and cull state.
TEST(SsamGlHostShaders, EachPassSetsItsStateAndGivesTheHostsBack) {
    auto&& [host, targets, ssam] = HostWithSsam{};
    const HostGlState hostState;
    hostState.set();
    ssam::gl::FrameReport report;
    ASSERT_EQ(ssam->beginFrame(host.frameOf(*targets), &report), Status::Ok) << ssam->lastMessage();
    EXPECT_TRUE(report.foliageInView);
    hostState.expectRestored();
    auto integer = [](GLenum what) {
        GLint v = 0;
        glGetIntegerv(what, &v);
        return v;
    };
    auto boolean = [](GLenum what) {
        GLboolean v = GL_FALSE;
        glGetBooleanv(what, &v);
        return v == GL_TRUE;
    };

    auto attachment = [](GLenum point) {
        GLint name = 0;
        glGetFramebufferAttachmentParameteriv(GL_DRAW_FRAMEBUFFER, point, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME, &name);
        return GLuint(name);
    };
    const ssam::gl::FrameDesc frame = host.frameOf(*targets);
    auto expectFoliagePassState = [&] {
        GLint viewport[4] = {};
        glGetIntegerv(GL_VIEWPORT, viewport);
        EXPECT_EQ((std::vector<GLint>(viewport, viewport + 4)), (std::vector<GLint>{0, 0, kGlSize, kGlSize}));
        EXPECT_FALSE(glIsEnabled(GL_SCISSOR_TEST));
        EXPECT_FALSE(glIsEnabled(GL_CULL_FACE));  // both faces of a card
        EXPECT_FALSE(glIsEnabled(GL_STENCIL_TEST));
        EXPECT_FALSE(glIsEnabled(GL_COLOR_LOGIC_OP));
        EXPECT_TRUE(glIsEnabled(GL_DEPTH_TEST));
        EXPECT_EQ(integer(GL_DEPTH_FUNC), GL_LESS);
        EXPECT_EQ(attachment(GL_DEPTH_ATTACHMENT), frame.depthTexture);  // the host's depth
        GLboolean mask[4] = {};
        glGetBooleanv(GL_COLOR_WRITEMASK, mask);
        EXPECT_TRUE(mask[0] && mask[1] && mask[2] && mask[3]);
    };

    ssam::gl::PassInfo pass;
    ASSERT_EQ(ssam->beginMaskPass(&pass), Status::Ok) << ssam->lastMessage();
    EXPECT_EQ(pass.pass, ssam::gl::FoliagePass::Mask);
    EXPECT_EQ(pass.drawBuffers, 1);
    EXPECT_EQ(pass.alphaReference, 0.0f);
    expectFoliagePassState();
    EXPECT_EQ(attachment(GL_COLOR_ATTACHMENT0), ssam->intermediates().mask);
    EXPECT_FALSE(boolean(GL_DEPTH_WRITEMASK));  // tested, not written (Table 3.1)
    EXPECT_TRUE(glIsEnabledi(GL_BLEND, 0));
    EXPECT_EQ(integer(GL_BLEND_EQUATION_RGB), GL_MAX);
    EXPECT_EQ(integer(GL_BLEND_EQUATION_ALPHA), GL_FUNC_ADD);
    for (GLenum factor : {GL_BLEND_SRC_RGB, GL_BLEND_DST_RGB, GL_BLEND_SRC_ALPHA, GL_BLEND_DST_ALPHA})
        EXPECT_EQ(integer(factor), GL_ONE);
    ASSERT_EQ(ssam->endMaskPass(), Status::Ok);
    hostState.expectRestored();

    ASSERT_EQ(ssam->beginColorPass(&pass), Status::Ok) << ssam->lastMessage();
    EXPECT_EQ(pass.pass, ssam::gl::FoliagePass::Color);
    EXPECT_EQ(pass.alphaReference, ssam::gl::Settings{}.colorAlphaReference);
    expectFoliagePassState();
    EXPECT_EQ(attachment(GL_COLOR_ATTACHMENT0), ssam->intermediates().foliage);
    EXPECT_TRUE(boolean(GL_DEPTH_WRITEMASK));  // the foliage depth reaches the host's (§3.7)
    EXPECT_FALSE(glIsEnabledi(GL_BLEND, 0));
    ASSERT_EQ(ssam->endColorPass(), Status::Ok);
    hostState.expectRestored();

    ASSERT_EQ(ssam->composite(), Status::Ok) << ssam->lastMessage();
    hostState.expectRestored();
}

// Calls out of order are InvalidCall naming what comes next; the open frame is abandoned with the
// host's state restored, and the next frame starts cleanly.
TEST(SsamGlHostShaders, CallsOutOfOrderAreInvalidAndLeaveNothingOpen) {
    auto&& [host, targets, ssam] = HostWithSsam{};
    const HostGlState hostState;
    hostState.set();
    const ssam::gl::FrameDesc frame = host.frameOf(*targets);

    EXPECT_EQ(ssam->beginMaskPass(), Status::InvalidCall);
    EXPECT_NE(std::string(ssam->lastMessage()).find("beginMaskPass called when no frame is open"), std::string::npos)
        << ssam->lastMessage();
    EXPECT_EQ(ssam->composite(), Status::InvalidCall);

    ASSERT_EQ(ssam->beginFrame(frame), Status::Ok);
    EXPECT_EQ(ssam->beginColorPass(), Status::InvalidCall);
    EXPECT_NE(std::string(ssam->lastMessage()).find("beginMaskPass comes next"), std::string::npos)
        << ssam->lastMessage();
    EXPECT_EQ(ssam->beginMaskPass(), Status::InvalidCall);  // the frame was abandoned

    ASSERT_EQ(ssam->beginFrame(frame), Status::Ok);
    ASSERT_EQ(ssam->beginMaskPass(), Status::Ok);
    EXPECT_EQ(ssam->beginFrame(frame), Status::InvalidCall);  // inside the mask pass
    EXPECT_NE(std::string(ssam->lastMessage()).find("endMaskPass comes next"), std::string::npos)
        << ssam->lastMessage();
    hostState.expectRestored();  // the open pass's state was given back
    EXPECT_EQ(ssam->setSettings({}), Status::Ok);

    // Then a whole frame in order.
    const HostPrograms programs;
    HostFoliage foliage({kQuadA});
    EXPECT_EQ(renderWithHostShaders(*ssam, frame, programs, foliage), Status::Ok) << ssam->lastMessage();
    EXPECT_NEAR(host.backend->readback(targets->color()).at(2, 8, 0), 1.0f * 0.16f + kOpaqueColor.r * 0.84f,
                1.5f / 255.0f);  // A's red at the squared mask 0.4^2 (§3.6.2)
}

TEST(SsamGlHostShaders, NothingInViewEndsTheFrameAtBeginFrame) {
    auto&& [host, targets, ssam] = HostWithSsam{};
    const ssam::gl::Box behind{{-1, -1, -0.5f}, {1, 1, -0.5f}};
    ssam::gl::FrameDesc frame = host.frameOf(*targets);
    frame.foliageBounds = &behind;
    frame.foliageBoundsCount = 1;
    ssam::gl::FrameReport report;
    report.foliageInView = true;
    ASSERT_EQ(ssam->beginFrame(frame, &report), Status::Ok);
    EXPECT_FALSE(report.foliageInView);
    EXPECT_EQ(report.passesRun, 0);
    EXPECT_EQ(ssam->beginMaskPass(), Status::InvalidCall);
    EXPECT_EQ(ssam->intermediates().mask, 0u);
}

}  // namespace
