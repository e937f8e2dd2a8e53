// SPDX-License-Identifier: MIT
// ssam::gl as engines written elsewhere use it: depth kept in a renderbuffer, vertex arrays at the
// engine's own attribute locations, release() when the context is gone, and a compatibility-profile
// context with fixed-function alpha testing left on. Raw GL targets (not our backend's), as such a
// host has; the host and its helpers are ssam_gl_host.hpp's.
#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

#include "raw_gl_targets.hpp"
#include "ssam_gl_host.hpp"

namespace {

using namespace ssam::testing;
using ssam::gl::Status;

const auto kDraw = [](const HostFoliage& foliage) {
    return [&foliage](const ssam::gl::FoliageProgram&) { foliage.draw(); };
};

// A depth renderbuffer gives what a depth texture gives: the same composite and the same foliage
// depth written into it, with the host's occluder (left half) hiding the foliage there.
TEST(SsamGlEngine, DepthRenderbufferWorksAsADepthTexture) {
    GlHost host;  // the context
    auto ssam = initializedSsam();
    HostFoliage foliage({kQuadA, kQuadB});
    const std::vector<ssam::gl::Box> bounds = boxesOf({kQuadA, kQuadB});
    std::vector<std::vector<std::uint8_t>> colors;
    std::vector<std::vector<float>> depths;
    for (const GLenum format : {GL_DEPTH_COMPONENT32F, GL_DEPTH24_STENCIL8}) {
        for (const bool renderbuffer : {false, true}) {
            SCOPED_TRACE(std::string(renderbuffer ? "renderbuffer " : "texture ") + std::to_string(format));
            RawGlTargets targets(renderbuffer, format);
            ssam::gl::FrameDesc frame = targets.frame();
            frame.foliageBounds = bounds.data();
            frame.foliageBoundsCount = bounds.size();
            ASSERT_EQ(ssam->render(frame, kDraw(foliage)), Status::Ok) << ssam->lastMessage();
            colors.push_back(targets.readColor());
            depths.push_back(targets.readDepth());
        }
    }
    for (std::size_t i = 1; i < colors.size(); ++i) EXPECT_EQ(colors[i], colors[0]) << "run " << i;
    EXPECT_EQ(depths[1], depths[0]);  // GL_DEPTH_COMPONENT32F
    EXPECT_EQ(depths[3], depths[2]);  // GL_DEPTH24_STENCIL8
    // Not a vacuous comparison: on the left quad A (alpha 0.4) is composited and its depth written;
    // on the right the host's occluder hides the foliage.
    const auto red = [&](int x, int y) { return colors[1][std::size_t((y * kGlSize + x) * 4)]; };
    EXPECT_GT(red(2, 8), RawGlTargets::kOpaqueCode[0]);
    EXPECT_EQ(red(12, 8), RawGlTargets::kOpaqueCode[0]);
    EXPECT_LT(depths[1][std::size_t(8 * kGlSize + 2)], 1.0f);
    EXPECT_EQ(depths[1][std::size_t(8 * kGlSize + 12)], RawGlTargets::kOccluderDepth);
}

// A renderbuffer's name handed over as a texture is named as a renderbuffer, whether or not a
// texture of that name exists too; and the other way round. Mixed or missing depth: which fields.
TEST(SsamGlEngine, ARenderbufferGivenAsATextureIsNamedForWhatItIs) {
    GlHost host;
    auto ssam = initializedSsam();
    RawGlTargets targets(true, GL_DEPTH_COMPONENT32F);
    const auto expect = [&](const ssam::gl::FrameDesc& frame, Status status, const std::string& text) {
        EXPECT_EQ(ssam->render(frame, [](const ssam::gl::FoliageProgram&) {}), status) << ssam->lastMessage();
        EXPECT_NE(std::string(ssam->lastMessage()).find(text), std::string::npos)
            << "\"" << ssam->lastMessage() << "\" lacks \"" << text << "\"";
    };
    // A renderbuffer whose name is also a texture's, as engines meet it ("depth texture 1 has format
    // GL_RGBA8": texture 1 was another object). Names are per kind: textures are generated until
    // one has the renderbuffer's name.
    ssam::gl::FrameDesc frame = targets.frame();
    GLuint shared = 0;
    glGenRenderbuffers(1, &shared);
    ASSERT_FALSE(glIsTexture(shared));
    std::vector<GLuint> textures(1, 0);
    for (GLuint i = 0; i < shared + 1000 && textures.back() != shared; ++i)
        textures.push_back(0), glGenTextures(1, &textures.back());
    ASSERT_EQ(textures.back(), shared);
    glBindTexture(GL_TEXTURE_2D, shared);
    glTexStorage2D(GL_TEXTURE_2D, 1, GL_RGBA8, kGlSize, kGlSize);
    glBindRenderbuffer(GL_RENDERBUFFER, shared);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT32F, kGlSize, kGlSize);
    frame.depthTexture = shared;
    frame.depthRenderbuffer = 0;
    const std::string name = std::to_string(shared);
    expect(frame, Status::InvalidTexture,
           "depth texture " + name +
               " has format GL_RGBA8; use a GL_DEPTH_COMPONENT* or depth-stencil format (GL name " + name +
               " is also a renderbuffer: if that is your depth, pass it as FrameDesc::depthRenderbuffer)");
    glDeleteRenderbuffers(1, &shared);
    glDeleteTextures(GLsizei(textures.size()), textures.data());
    GLuint lone = 0;  // a renderbuffer whose name no texture has
    glGenRenderbuffers(1, &lone);
    ASSERT_FALSE(glIsTexture(lone));
    glBindRenderbuffer(GL_RENDERBUFFER, lone);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT32F, kGlSize, kGlSize);
    frame.depthTexture = lone;
    expect(frame, Status::InvalidTexture,
           "depth texture " + std::to_string(lone) +
               " is not a texture but a renderbuffer: pass it as FrameDesc::depthRenderbuffer");
    frame = targets.frame();
    frame.depthTexture = frame.colorTexture;
    expect(frame, Status::InvalidArgument, "give the depth as exactly one of FrameDesc::depthTexture");
    frame = targets.frame();
    frame.depthRenderbuffer = 0;
    expect(frame, Status::InvalidArgument, "exactly one of");
    frame = targets.frame();
    frame.depthRenderbuffer = frame.colorTexture + 1000;
    expect(frame, Status::InvalidTexture, "is not a GL renderbuffer name");
    glBindRenderbuffer(GL_RENDERBUFFER, lone);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, kGlSize, kGlSize);
    frame.depthRenderbuffer = lone;
    expect(frame, Status::InvalidTexture, "depth renderbuffer " + std::to_string(lone) + " has format GL_RGBA8");
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, 8, 8);
    expect(frame, Status::InvalidTexture, "the depth renderbuffer is 8x8 but the frame is 16x16");
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, 4, GL_DEPTH_COMPONENT24, kGlSize, kGlSize);
    expect(frame, Status::InvalidTexture, "is multisampled (4 samples)");
    glDeleteRenderbuffers(1, &lone);
}

// The host's vertex arrays at its own locations (uv at 8, normal at 2, tint at 10, ...): the built-in programs
// read them there and give the image of SSAM's default locations; the generic values SSAM sets at
// the new locations are the host's again afterwards. Bad locations are named.
TEST(SsamGlEngine, BuiltInProgramsReadTheHostsAttributeLocations) {
    auto&& [host, targets, defaults] = HostWithSsam{};
    const std::vector<Quad> quads{kQuadA, kQuadB};
    HostFoliage atDefaults(quads);
    ASSERT_EQ(defaults->render(host.frameOf(*targets), kDraw(atDefaults)), Status::Ok) << defaults->lastMessage();
    const engine::render::Readback expected = host.backend->readback(targets->color());

    ssam::gl::AttributeLocations attributes;
    attributes.position = 5;
    attributes.normal = 2;
    attributes.uv = 8;
    attributes.color = 9;
    attributes.instanceModel = 11;
    attributes.instanceTint = 10;  // off uv's 8, its default
    HostFoliage atHosts(quads, attributes);
    auto moved = initializedSsam({}, attributes);
    auto again = host.opaque();
    glVertexAttrib4f(9, 0.25f, 0.5f, 0.75f, 1.0f);  // the host's own generic value at colour's location
    ASSERT_EQ(moved->render(host.frameOf(*again), kDraw(atHosts)), Status::Ok) << moved->lastMessage();
    EXPECT_EQ(host.backend->readback(again->color()).values, expected.values);
    GLfloat value[4] = {};
    glGetVertexAttribfv(9, GL_CURRENT_VERTEX_ATTRIB, value);
    EXPECT_EQ((std::vector<float>(value, value + 4)), (std::vector<float>{0.25f, 0.5f, 0.75f, 1.0f}));

    // setAttributeLocations() with new locations recompiles: the defaults' object now reads the moved arrays.
    auto third = host.opaque();
    ASSERT_EQ(defaults->setAttributeLocations(attributes), Status::Ok) << defaults->lastMessage();
    ASSERT_EQ(defaults->render(host.frameOf(*third), kDraw(atHosts)), Status::Ok) << defaults->lastMessage();
    EXPECT_EQ(host.backend->readback(third->color()).values, expected.values);

    ssam::gl::AttributeLocations bad;
    bad.uv = 5;  // inside instanceModel's 4..7
    EXPECT_EQ(defaults->setAttributeLocations(bad), Status::InvalidArgument);
    EXPECT_STREQ(defaults->lastMessage(),
                 "ssam::gl settings: attributes.uv (5) and attributes.instanceModel (4) overlap");
    bad = {};
    bad.instanceModel = 13;
    EXPECT_EQ(defaults->setAttributeLocations(bad), Status::InvalidArgument);
    EXPECT_NE(std::string(defaults->lastMessage()).find("attributes.instanceModel = 13 (it takes 4 locations)"),
              std::string::npos)
        << defaults->lastMessage();
    EXPECT_EQ(defaults->attributeLocations().uv, 8u);  // the locations in force stay
}

// Settings::depthMaskThreshold: the host's depth keeps the foliage depth only where the composited
// mask reaches the threshold (a leaf of alpha 1) and has the opaque depth back where it does not (a
// leaf of alpha 0.4: mask 0.16); the colour is the same as without it, and the host's state is back.
TEST(SsamGlEngine, DepthMaskThresholdKeepsFoliageDepthOnlyWhereTheMaskIsHigh) {
    GlHost host;
    const Quad faint{-1.0f, -1.0f, -0.1f, 1.0f, 0.3f, {1.0f, 0.0f, 0.0f, 0.4f}};
    const Quad solid{0.1f, -1.0f, 1.0f, 1.0f, 0.6f, {0.0f, 0.0f, 1.0f, 1.0f}};
    HostFoliage foliage({faint, solid});
    const HostGlState hostState;
    std::vector<engine::render::Readback> colors, depths;
    for (const float threshold : {0.0f, 0.5f}) {
        SCOPED_TRACE("threshold " + std::to_string(threshold));
        ssam::gl::Settings settings;
        settings.depthMaskThreshold = threshold;
        auto ssam = initializedSsam(settings);
        auto targets = host.opaque();
        const ssam::gl::FrameDesc frame = host.frameOf(*targets);
        hostState.set();
        ASSERT_EQ(ssam->render(frame, kDraw(foliage)), Status::Ok) << ssam->lastMessage();
        hostState.expectRestored();
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        glDisable(GL_STENCIL_TEST);
        glDisable(GL_COLOR_LOGIC_OP);
        colors.push_back(host.backend->readback(targets->color()));
        depths.push_back(host.backend->readback(targets->depth()));
    }
    EXPECT_EQ(colors[1].values, colors[0].values);
    EXPECT_FLOAT_EQ(depths[0].at(3, 8, 0), faint.depth);  // the paper's: the faint leaf's depth too
    EXPECT_FLOAT_EQ(depths[0].at(12, 8, 0), solid.depth);
    EXPECT_FLOAT_EQ(depths[1].at(3, 8, 0), 1.0f);  // mask 0.16 < 0.5: the opaque (far) depth back
    EXPECT_FLOAT_EQ(depths[1].at(12, 8, 0), solid.depth);
    ssam::gl::Settings bad;
    bad.depthMaskThreshold = 1.5f;
    auto ssam = initializedSsam();
    EXPECT_EQ(ssam->setSettings(bad), Status::InvalidArgument);
    EXPECT_STREQ(ssam->lastMessage(), "ssam::gl: ssam settings: depthMaskThreshold = 1.500000 is outside [0, 1]");
}

// release() without a current context deletes nothing and says so (a status and the message
// callback); made current again, a second release() has nothing left and initialize() works.
TEST(SsamGlEngine, ReleaseWithoutAContextIsReported) {
    GlHost host;
    auto ssam = initializedSsam();
    std::vector<std::string> errors;
    ssam->setMessageCallback(
        [](void* user, ssam::gl::Severity severity, const char* message) {
            if (severity == ssam::gl::Severity::Error) static_cast<std::vector<std::string>*>(user)->push_back(message);
        },
        &errors);
    const EGLDisplay display = eglGetCurrentDisplay();
    const EGLContext context = eglGetCurrentContext();
    ASSERT_TRUE(eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT));
    const Status status = ssam->release();
    ASSERT_TRUE(eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context));
    EXPECT_EQ(status, Status::NoContext);
    ASSERT_EQ(errors.size(), 1u);
    EXPECT_NE(errors[0].find("release() without a current GL context"), std::string::npos) << errors[0];
    EXPECT_EQ(errors[0], ssam->lastMessage());
    EXPECT_EQ(ssam->release(), Status::Ok);  // released already: nothing to delete
    EXPECT_EQ(ssam->initialize(eglGetProcAddress), Status::Ok) << ssam->lastMessage();
    EXPECT_EQ(ssam->release(), Status::Ok);
    EXPECT_EQ(errors.size(), 1u);
}

// A compatibility-profile host that leaves fixed-function alpha testing on (and stipple, and
// colour clamping): SSAM's frame is the one it gives with them off, and they are on again after.
TEST(SsamGlEngine, CompatibilityContextAlphaTestLeavesTheFrameAlone) {
    OwnEglContext compat(OwnContextKind::Compatibility33);
    if (!compat.why.empty()) GTEST_SKIP() << "no compatibility-profile context: " << compat.why;
    ssam::gl::ScreenSpaceAlphaMaskGl ssam;
    ASSERT_EQ(ssam.initialize(eglGetProcAddress), Status::Ok) << ssam.lastMessage();
    HostFoliage foliage({kQuadA, kQuadB});
    std::vector<std::vector<std::uint8_t>> frames;
    for (const bool fixedFunction : {false, true}) {
        SCOPED_TRACE(fixedFunction ? "alpha test on" : "alpha test off");
        RawGlTargets targets(false, GL_DEPTH_COMPONENT32F);
        compat.setFixedFunction(fixedFunction);
        ASSERT_EQ(ssam.render(targets.frame(), kDraw(foliage)), Status::Ok) << ssam.lastMessage();
        compat.expectFixedFunction(fixedFunction);
        frames.push_back(targets.readColor());
    }
    EXPECT_EQ(frames[1], frames[0]);
    // The host's alpha test (GREATER 0.9) and stipple would have rejected both quads: the frame has
    // quad A (alpha 0.4, red) in it.
    EXPECT_GT(frames[0][std::size_t((8 * kGlSize + 2) * 4)], RawGlTargets::kOpaqueCode[0]);
    EXPECT_EQ(ssam.release(), Status::Ok);
}

}  // namespace
