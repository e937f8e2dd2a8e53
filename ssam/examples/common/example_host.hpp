// SPDX-License-Identifier: MIT
#pragma once
// The host program both examples share: a plain OpenGL 3.3 program (OpenGL ES 3.0 with --api gles,
// its GLSL 3.30 compiled as ES 3.00) that is not built on our engine (its own context, shaders,
// buffers and render targets). It draws its opaque scene into
// its own colour + depth textures, then hands them to SSAM; what differs between the examples
// is how its foliage reaches SSAM (a FoliageRenderer):
//   gl_embedding     SSAM's built-in foliage programs draw the host's VAO (way a)
//   gl_host_shaders  the host's own foliage shaders, with a wind bend, in SSAM's passes (way b)
// The host's own GL calls go through libepoxy (its loader); SSAM gets the platform's loader
// (eglGetProcAddress headless, glfwGetProcAddress in a window), as an engine would pass its own.
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <epoxy/gl.h>

#include <ssam/gl/ssam_gl.hpp>

#include "arguments.hpp"

namespace gl_example {

// The host's scene in GL: opaque quads, the foliage cards (position at attribute 0, uv at 2:
// ssam::gl::AttributeLocations, which the host-shader example keeps too), the leaf texture and
// the render targets SSAM composites into. The view-projection maps world x, y in [-1, 1] to the
// screen and z in [0, 1] to OpenGL's default depth range (scene.hpp).
class HostScene {
public:
    // `wind`: how far (world units, in x) the host's foliage shaders bend the cards' tops; 0 for none.
    explicit HostScene(float wind = 0.0f);
    ~HostScene();
    HostScene(const HostScene&) = delete;
    HostScene& operator=(const HostScene&) = delete;

    void drawOpaque() const;  // into colorTexture + depthTexture, cleared to the sky
    // The host's transparent pass (kMist): blended onto the colour, depth-tested against the depth
    // (after SSAM: the opaque + foliage depth it leaves), as a host's particles or fog are.
    void drawMist() const;
    // Binds the cards' VAO and draws each card, calling setTint(card's tint rgb, alpha factor)
    // first; the same cards in the same order every time (§3.8).
    void drawCards(const std::function<void(const float tint[4])>& setTint) const;
    // The frame SSAM gets: the host's textures, its view-projection, the cards' bounds (wind included).
    ssam::gl::FrameDesc frame() const;

    GLuint leafTexture() const { return leafTexture_; }
    GLuint framebuffer() const { return framebuffer_; }

private:
    GLuint opaqueProgram_ = 0, opaqueVao_ = 0, cardsVao_ = 0, buffers_[2] = {0, 0}, leafTexture_ = 0;
    GLuint colorTexture_ = 0, depthTexture_ = 0, framebuffer_ = 0;
    GLint viewProjUniform_ = -1, colorUniform_ = -1;
    std::vector<ssam::gl::Box> cardBounds_;
};

// How the host's foliage reaches SSAM: created once the context is current, destroyed before it goes.
class FoliageRenderer {
public:
    virtual ~FoliageRenderer() = default;
    // After the host's opaque pass: SSAM's three passes over the cards, composited into the host's
    // colour texture. Throws std::runtime_error with SSAM's message when a call does not return Ok.
    virtual void render(ssam::gl::ScreenSpaceAlphaMaskGl& ssam, const ssam::gl::FrameDesc& frame) = 0;
};
using MakeFoliageRenderer = std::function<std::unique_ptr<FoliageRenderer>(const HostScene&, const Arguments&)>;

// Throws std::runtime_error naming the call and SSAM's message unless `status` is Ok.
void check(const ssam::gl::ScreenSpaceAlphaMaskGl& ssam, ssam::gl::Status status, const char* call);

// The host's own shader program from its vertex and fragment sources; throws
// std::runtime_error "<what>: <compile log>" when a stage does not compile.
GLuint linkProgram(const char* vertexSource, const char* fragmentSource, const std::string& what);

// The whole program: arguments, context (headless EGL on a device or surfaceless, else a GLFW
// window: Arguments::egl), the host
// scene, SSAM initialised with the platform's loader, frames, PNGs. Returns the exit status.
int runExample(const Tool& tool, int argc, char** argv, const MakeFoliageRenderer& makeRenderer);

}  // namespace gl_example
