// SPDX-License-Identifier: MIT
// ssam::gl on OpenGL ES (Api::Gles30): on Mesa's ES context (EGL_OPENGL_ES_API, which Mesa makes
// ES 3.2) it gives the desktop context's frame; a context of the other API is refused; and on an
// ES 3.0 / WebGL2 context without extensions -- Mesa's, seen through a host loader that answers
// version 3.0 and no extensions -- it refuses the float targets ES 3.0 cannot render into, naming
// the extension, and still renders the RGBA8 mask with ES 3.0's global blend and colour-mask state.
#include <epoxy/egl.h>
#include <epoxy/gl.h>
#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

#include "raw_gl_targets.hpp"
#include "ssam_gl_host.hpp"

namespace {

using namespace ssam::testing;
using ssam::gl::Api;
using ssam::gl::Status;

struct DepthCase {
    const char* name;
    bool renderbuffer;
    GLenum format;
};
const DepthCase kDepthCases[] = {{"depth texture D32F", false, GL_DEPTH_COMPONENT32F},
                                 {"depth texture D24S8", false, GL_DEPTH24_STENCIL8},
                                 {"depth renderbuffer D16", true, GL_DEPTH_COMPONENT16}};

// Quads A and B over the host's targets with the current context and `api`; the colour read back.
std::vector<std::uint8_t> frameOf(const DepthCase& depth, Api api, const ssam::gl::Settings& settings = {}) {
    ssam::gl::ScreenSpaceAlphaMaskGl ssam;
    EXPECT_EQ(ssam.initialize(eglGetProcAddress, settings, {}, api), Status::Ok) << ssam.lastMessage();
    HostFoliage foliage({kQuadA, kQuadB});
    RawGlTargets targets(depth.renderbuffer, depth.format);
    EXPECT_EQ(ssam.render(targets.frame(), [&](const ssam::gl::FoliageProgram&) { foliage.draw(); }), Status::Ok)
        << ssam.lastMessage();
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));  // no desktop-only enum or entry point on ES
    return targets.readColor();
}

bool says(const ssam::gl::ScreenSpaceAlphaMaskGl& ssam, const char* text) {
    return std::string(ssam.lastMessage()).find(text) != std::string::npos;
}

TEST(SsamGlEs, AnEsContextGivesTheDesktopFrame) {
    GlHost host;  // the desktop context, current again when `es` goes
    ssam::gl::Settings rg16fThreshold;
    rg16fThreshold.maskPrecision = ssam::MaskPrecision::Rg16f;
    rg16fThreshold.depthMaskThreshold = 0.5f;  // the depth restore's blit and program on ES too
    for (const DepthCase& depth : kDepthCases)
        for (const ssam::gl::Settings& settings : {ssam::gl::Settings{}, rg16fThreshold}) {
            SCOPED_TRACE(std::string(depth.name) + (settings.depthMaskThreshold > 0 ? ", rg16f + threshold" : ""));
            const std::vector<std::uint8_t> desktop = frameOf(depth, Api::Gl33, settings);
            OwnEglContext es(OwnContextKind::Es30);
            if (!es.why.empty()) GTEST_SKIP() << "no OpenGL ES context: " << es.why;
            const std::vector<std::uint8_t> onEs = frameOf(depth, Api::Gles30, settings);
            EXPECT_EQ(onEs, desktop);
            // Quad A (alpha 0.4, red) is in it: the test cannot pass with nothing drawn.
            EXPECT_GT(onEs[std::size_t((8 * kGlSize + 2) * 4)], RawGlTargets::kOpaqueCode[0]);
        }
}

TEST(SsamGlEs, AContextOfTheOtherApiIsRefused) {
    GlHost host;
    ssam::gl::ScreenSpaceAlphaMaskGl ssam;
    EXPECT_EQ(ssam.initialize(eglGetProcAddress, {}, {}, Api::Gles30), Status::InvalidArgument);
    EXPECT_TRUE(says(ssam, "told Api::Gles30 but the current context is 4.")) << ssam.lastMessage();
    EXPECT_TRUE(says(ssam, "pass Api::Gl33")) << ssam.lastMessage();
    OwnEglContext es(OwnContextKind::Es30);
    if (!es.why.empty()) GTEST_SKIP() << "no OpenGL ES context: " << es.why;
    EXPECT_EQ(ssam.initialize(eglGetProcAddress), Status::InvalidArgument);
    EXPECT_TRUE(says(ssam, "told Api::Gl33 but the current context is OpenGL ES 3")) << ssam.lastMessage();
    EXPECT_TRUE(says(ssam, "pass Api::Gles30")) << ssam.lastMessage();
}

// A multisampled depth: refused on ES too, saying why the paper's closest-sample downsample is
// not possible there (ssam/docs/gles.md "What is refused").
TEST(SsamGlEs, AMultisampledDepthIsRefusedSayingWhy) {
    OwnEglContext es(OwnContextKind::Es30);
    if (!es.why.empty()) GTEST_SKIP() << "no OpenGL ES context: " << es.why;
    ssam::gl::ScreenSpaceAlphaMaskGl ssam;
    ASSERT_EQ(ssam.initialize(eglGetProcAddress, {}, {}, Api::Gles30), Status::Ok) << ssam.lastMessage();
    RawGlTargets targets(false, GL_DEPTH_COMPONENT32F);
    GLuint multisampled = 0;
    glGenRenderbuffers(1, &multisampled);
    glBindRenderbuffer(GL_RENDERBUFFER, multisampled);
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, 4, GL_DEPTH_COMPONENT24, kGlSize, kGlSize);
    ssam::gl::FrameDesc frame = targets.frame();
    frame.depthTexture = 0;
    frame.depthRenderbuffer = multisampled;
    EXPECT_EQ(ssam.render(frame, [](const ssam::gl::FoliageProgram&) {}), Status::InvalidTexture);
    EXPECT_TRUE(says(ssam, "is multisampled (4 samples)")) << ssam.lastMessage();
    EXPECT_TRUE(says(ssam, "closest-sample downsample of [Hathaway 2010] 3.5.1 is not possible there"))
        << ssam.lastMessage();
    glDeleteRenderbuffers(1, &multisampled);
}

// Mesa's ES context as an ES 3.0 / WebGL2 context without extensions: GL_VERSION and
// GL_MINOR_VERSION say 3.0, GL_NUM_EXTENSIONS 0 (so no GL_EXT_color_buffer_float, no
// OES_draw_buffers_indexed); every other function is Mesa's.
PFNGLGETSTRINGPROC mesaGetString = nullptr;
PFNGLGETINTEGERVPROC mesaGetIntegerv = nullptr;
const GLubyte* es30GetString(GLenum name) {
    if (name == GL_VERSION) return reinterpret_cast<const GLubyte*>("OpenGL ES 3.0 (Mesa's, without extensions)");
    return mesaGetString(name);
}
void es30GetIntegerv(GLenum name, GLint* value) {
    if (name == GL_MINOR_VERSION || name == GL_NUM_EXTENSIONS) *value = 0;
    else mesaGetIntegerv(name, value);
}
using AnyFunction = void (*)();
AnyFunction es30Loader(const char* name) {
    const std::string function = name;
    if (function == "glGetString") {
        mesaGetString = reinterpret_cast<PFNGLGETSTRINGPROC>(eglGetProcAddress(name));
        return reinterpret_cast<AnyFunction>(&es30GetString);
    }
    if (function == "glGetIntegerv") {
        mesaGetIntegerv = reinterpret_cast<PFNGLGETINTEGERVPROC>(eglGetProcAddress(name));
        return reinterpret_cast<AnyFunction>(&es30GetIntegerv);
    }
    return eglGetProcAddress(name);
}

TEST(SsamGlEs, AnEs30ContextRefusesFloatTargetsAndRendersTheRgba8Mask) {
    GlHost host;
    const DepthCase& depth = kDepthCases[0];
    const std::vector<std::uint8_t> desktop = frameOf(depth, Api::Gl33);
    OwnEglContext es(OwnContextKind::Es30);
    if (!es.why.empty()) GTEST_SKIP() << "no OpenGL ES context: " << es.why;
    ssam::gl::ScreenSpaceAlphaMaskGl ssam;
    for (const ssam::MaskPrecision precision : {ssam::MaskPrecision::Rgba16f, ssam::MaskPrecision::Rg16f}) {
        ssam::gl::Settings settings;
        settings.maskPrecision = precision;
        EXPECT_EQ(ssam.initialize(es30Loader, settings, {}, Api::Gles30), Status::UnsupportedFeature);
        EXPECT_TRUE(says(ssam, "without GL_EXT_color_buffer_float; use Rgba8")) << ssam.lastMessage();
    }
    ASSERT_EQ(ssam.initialize(es30Loader, {}, {}, Api::Gles30), Status::Ok) << ssam.lastMessage();
    ssam::gl::Settings rg16f;
    rg16f.maskPrecision = ssam::MaskPrecision::Rg16f;
    EXPECT_EQ(ssam.setSettings(rg16f), Status::UnsupportedFeature);
    EXPECT_TRUE(says(ssam, "maskPrecision rg16f renders into float targets")) << ssam.lastMessage();

    // The RGBA8 mask with ES 3.0's global colour mask and blend enable: the desktop frame, and the
    // host's (odd) colour mask and blend enable back afterwards.
    HostFoliage foliage({kQuadA, kQuadB});
    RawGlTargets targets(depth.renderbuffer, depth.format);
    glColorMask(GL_TRUE, GL_FALSE, GL_TRUE, GL_TRUE);
    glEnable(GL_BLEND);
    ASSERT_EQ(ssam.render(targets.frame(), [&](const ssam::gl::FoliageProgram&) { foliage.draw(); }), Status::Ok)
        << ssam.lastMessage();
    GLboolean mask[4] = {};
    glGetBooleanv(GL_COLOR_WRITEMASK, mask);
    EXPECT_EQ(std::vector<int>(mask, mask + 4), (std::vector<int>{1, 0, 1, 1}));
    EXPECT_TRUE(glIsEnabled(GL_BLEND));
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDisable(GL_BLEND);
    EXPECT_EQ(targets.readColor(), desktop);

    // A float colour texture: rt_foliage would take its format.
    GLuint floatColor = 0;
    glGenTextures(1, &floatColor);
    glBindTexture(GL_TEXTURE_2D, floatColor);
    glTexStorage2D(GL_TEXTURE_2D, 1, GL_RGBA16F, kGlSize, kGlSize);
    ssam::gl::FrameDesc frame = targets.frame();
    frame.colorTexture = floatColor;
    EXPECT_EQ(ssam.render(frame, [&](const ssam::gl::FoliageProgram&) { foliage.draw(); }), Status::UnsupportedFeature);
    EXPECT_TRUE(says(ssam,
                     "is GL_RGBA16F, which this OpenGL ES context cannot render and blend into without "
                     "GL_EXT_color_buffer_float"))
        << ssam.lastMessage();
    glDeleteTextures(1, &floatColor);
    EXPECT_EQ(ssam.release(), Status::Ok);
}

}  // namespace
