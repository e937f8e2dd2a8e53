// SPDX-License-Identifier: MIT
#pragma once
// What an engine written elsewhere hands ssam::gl: its own GL colour texture and depth (a texture
// or a renderbuffer) made with raw GL calls (on desktop GL or OpenGL ES), and, for the
// compatibility-profile and OpenGL ES tests, its own context. Used by ssam_gl_engine_test.cpp and
// ssam_gl_es_test.cpp.
#include <gtest/gtest.h>

#include <epoxy/egl.h>
#include <epoxy/gl.h>

#include <array>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "ssam/gl/ssam_gl.hpp"
#include "ssam_gl_host.hpp"

namespace ssam::testing {

// glClearDepth on desktop GL; OpenGL ES has only the float form.
inline void clearDepthTo(float depth) { epoxy_is_desktop_gl() ? glClearDepth(depth) : glClearDepthf(depth); }

// A kGlSize² colour texture of `format` (immutable storage) as colour 0 of a new framebuffer
// (`*fbo`), which is left bound.
inline GLuint newColorTarget(GLenum format, GLuint* fbo) {
    GLuint texture = 0;
    glGenTextures(1, &texture);
    glBindTexture(GL_TEXTURE_2D, texture);
    glTexStorage2D(GL_TEXTURE_2D, 1, format, kGlSize, kGlSize);
    glGenFramebuffers(1, fbo);
    glBindFramebuffer(GL_FRAMEBUFFER, *fbo);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, texture, 0);
    return texture;
}

// A kGlSize² RGBA8 colour texture cleared to kOpaqueCode, and a depth of `depthFormat` cleared to
// the far plane on the left half and to kOccluderDepth (the host's occluder) on the right half.
struct RawGlTargets {
    static constexpr std::array<std::uint8_t, 4> kOpaqueCode{51, 102, 153, 255};
    static constexpr float kOccluderDepth = 0.125f;  // exact in every depth format
    GLuint color = 0, depth = 0, fbo = 0;
    bool renderbuffer;

    RawGlTargets(bool depthInRenderbuffer, GLenum depthFormat) : renderbuffer(depthInRenderbuffer) {
        color = newColorTarget(GL_RGBA8, &fbo);
        const GLenum attachment = (depthFormat == GL_DEPTH24_STENCIL8 || depthFormat == GL_DEPTH32F_STENCIL8)
                                      ? GL_DEPTH_STENCIL_ATTACHMENT
                                      : GL_DEPTH_ATTACHMENT;
        if (renderbuffer) {
            glGenRenderbuffers(1, &depth);
            glBindRenderbuffer(GL_RENDERBUFFER, depth);
            glRenderbufferStorage(GL_RENDERBUFFER, depthFormat, kGlSize, kGlSize);
            glFramebufferRenderbuffer(GL_FRAMEBUFFER, attachment, GL_RENDERBUFFER, depth);
        } else {
            glGenTextures(1, &depth);
            glBindTexture(GL_TEXTURE_2D, depth);
            glTexStorage2D(GL_TEXTURE_2D, 1, depthFormat, kGlSize, kGlSize);
            glFramebufferTexture2D(GL_FRAMEBUFFER, attachment, GL_TEXTURE_2D, depth, 0);
        }
        EXPECT_EQ(glCheckFramebufferStatus(GL_FRAMEBUFFER), GLenum(GL_FRAMEBUFFER_COMPLETE));
        glDisable(GL_SCISSOR_TEST);
        glDepthMask(GL_TRUE);
        glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
        glClearColor(kOpaqueCode[0] / 255.0f, kOpaqueCode[1] / 255.0f, kOpaqueCode[2] / 255.0f, 1.0f);
        clearDepthTo(1.0f);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        glEnable(GL_SCISSOR_TEST);
        glScissor(kGlSize / 2, 0, kGlSize / 2, kGlSize);
        clearDepthTo(kOccluderDepth);
        glClear(GL_DEPTH_BUFFER_BIT);
        glDisable(GL_SCISSOR_TEST);
        clearDepthTo(1.0f);
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
    }
    ~RawGlTargets() {
        glDeleteFramebuffers(1, &fbo);
        glDeleteTextures(1, &color);
        if (renderbuffer) glDeleteRenderbuffers(1, &depth);
        else glDeleteTextures(1, &depth);
    }
    RawGlTargets(const RawGlTargets&) = delete;
    RawGlTargets& operator=(const RawGlTargets&) = delete;

    ssam::gl::FrameDesc frame() const {
        ssam::gl::FrameDesc f;
        f.colorTexture = color;
        (renderbuffer ? f.depthRenderbuffer : f.depthTexture) = depth;
        f.width = f.height = kGlSize;
        return f;  // identity viewProj, unlit
    }
    std::vector<std::uint8_t> readColor() const {
        std::vector<std::uint8_t> out(std::size_t(kGlSize) * kGlSize * 4);
        glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo);
        glPixelStorei(GL_PACK_ALIGNMENT, 1);
        glReadPixels(0, 0, kGlSize, kGlSize, GL_RGBA, GL_UNSIGNED_BYTE, out.data());
        glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
        return out;
    }
    std::vector<float> readDepth() const {
        std::vector<float> out(std::size_t(kGlSize) * kGlSize);
        glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo);
        glReadPixels(0, 0, kGlSize, kGlSize, GL_DEPTH_COMPONENT, GL_FLOAT, out.data());
        glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
        return out;
    }
};

// An OpenGL 3.3 compatibility-profile context, or an OpenGL ES 3.0 one (Mesa makes it ES 3.2), on
// Mesa's EGL (the device platform, else the surfaceless one), current while this lives; the
// caller's context is current again afterwards. `why` says what failed ("" when current).
enum class OwnContextKind { Compatibility33, Es30 };
struct OwnEglContext {
    EGLDisplay previousDisplay = eglGetCurrentDisplay();
    EGLContext previousContext = eglGetCurrentContext();
    EGLSurface previousDraw = eglGetCurrentSurface(EGL_DRAW), previousRead = eglGetCurrentSurface(EGL_READ);
    EGLDisplay display = EGL_NO_DISPLAY;
    EGLContext context = EGL_NO_CONTEXT;
    std::string why;

    explicit OwnEglContext(OwnContextKind kind) {
        const bool es = kind == OwnContextKind::Es30;
        const char* client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
        if (client && std::strstr(client, "EGL_EXT_platform_device")) {
            EGLDeviceEXT device = nullptr;
            EGLint count = 0;
            if (eglQueryDevicesEXT(1, &device, &count) && count > 0)
                display = eglGetPlatformDisplayEXT(EGL_PLATFORM_DEVICE_EXT, device, nullptr);
        }
        if (display == EGL_NO_DISPLAY && client && std::strstr(client, "EGL_MESA_platform_surfaceless"))
            display = eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
        if (display == EGL_NO_DISPLAY || !eglInitialize(display, nullptr, nullptr) ||
            !eglBindAPI(es ? EGL_OPENGL_ES_API : EGL_OPENGL_API)) {
            why = "no EGL device or surfaceless display";
            return;
        }
        const EGLint attributes[] = {EGL_CONTEXT_MAJOR_VERSION,
                                     3,
                                     EGL_CONTEXT_MINOR_VERSION,
                                     3,
                                     EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                     EGL_CONTEXT_OPENGL_COMPATIBILITY_PROFILE_BIT,
                                     EGL_NONE};
        const EGLint esAttributes[] = {EGL_CONTEXT_MAJOR_VERSION, 3, EGL_CONTEXT_MINOR_VERSION, 0, EGL_NONE};
        context = eglCreateContext(display, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, es ? esAttributes : attributes);
        if (context == EGL_NO_CONTEXT || !eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context)) {
            why = es ? "eglCreateContext / eglMakeCurrent refused an OpenGL ES 3.0 context"
                     : "eglCreateContext / eglMakeCurrent refused an OpenGL 3.3 compatibility context";
            return;
        }
        if (es) return;
        GLint profile = 0;
        glGetIntegerv(GL_CONTEXT_PROFILE_MASK, &profile);
        if (!(profile & GL_CONTEXT_COMPATIBILITY_PROFILE_BIT)) why = "the context is not a compatibility profile";
    }
    ~OwnEglContext() {
        if (context != EGL_NO_CONTEXT) {
            eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
            eglDestroyContext(display, context);
        }
        if (previousContext != EGL_NO_CONTEXT)
            eglMakeCurrent(previousDisplay, previousDraw, previousRead, previousContext);
    }
    OwnEglContext(const OwnEglContext&) = delete;
    OwnEglContext& operator=(const OwnEglContext&) = delete;

    // The fixed-function state a compatibility host may leave on: alpha test GREATER 0.9, an
    // all-zero polygon stipple (every fragment dropped), clamped fragment colours.
    static void setFixedFunction(bool on) {
        GLubyte none[128] = {};
        glPolygonStipple(none);
        glAlphaFunc(GL_GREATER, 0.9f);
        on ? glEnable(GL_ALPHA_TEST) : glDisable(GL_ALPHA_TEST);
        on ? glEnable(GL_POLYGON_STIPPLE) : glDisable(GL_POLYGON_STIPPLE);
        glClampColor(GL_CLAMP_FRAGMENT_COLOR, on ? GL_TRUE : GL_FIXED_ONLY);
    }
    static void expectFixedFunction(bool on) {
        EXPECT_EQ(bool(glIsEnabled(GL_ALPHA_TEST)), on);
        EXPECT_EQ(bool(glIsEnabled(GL_POLYGON_STIPPLE)), on);
        GLint clamp = 0, function = 0;
        GLfloat reference = 0.0f;
        glGetIntegerv(GL_CLAMP_FRAGMENT_COLOR, &clamp);
        EXPECT_EQ(clamp, on ? GL_TRUE : GL_FIXED_ONLY);
        glGetIntegerv(GL_ALPHA_TEST_FUNC, &function);
        glGetFloatv(GL_ALPHA_TEST_REF, &reference);
        EXPECT_EQ(function, GL_GREATER);
        EXPECT_FLOAT_EQ(reference, 0.9f);
        EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
    }
};

}  // namespace ssam::testing
