// SPDX-License-Identifier: MIT
// ssam::gl with SSAM's built-in foliage programs (way a): a plain OpenGL program
// (common/example_host.hpp: its own context, shaders, buffers and render targets) draws its
// opaque scene into its own colour + depth textures, then ssam::gl::ScreenSpaceAlphaMaskGl::render
// runs the mask, colour and composite passes ([Hathaway 2010] §3.5), calling back into the program
// to draw its foliage cards -- its VAO laid out at SSAM's default ssam::gl::AttributeLocations.
//
//   ssam_gl_embedding               a GLFW window when a display is available
//   ssam_gl_embedding --headless --out frame.png [--mask mask.png] [--egl device|surfaceless]
//                                   one frame on headless EGL: EGL_EXT_platform_device (NVIDIA's,
//                                   AMD's, Mesa's devices) or Mesa's surfaceless platform
// Exit codes (common/arguments.hpp): 0 ok, 1 error, 2 usage error, 77 no OpenGL 3.3 core
// context could be created (tests skip).
#include "example_host.hpp"

namespace {

using namespace gl_example;

class BuiltInPrograms final : public FoliageRenderer {
public:
    explicit BuiltInPrograms(const HostScene& scene) : scene_(scene) {}

    void render(ssam::gl::ScreenSpaceAlphaMaskGl& ssam, const ssam::gl::FrameDesc& frame) override {
        // Called twice: mask pass, then colour pass, with SSAM's program, framebuffer and state
        // set. The host binds its VAO, sets per-draw values through the program and draws the
        // same cards in the same order both times.
        const ssam::gl::Status status = ssam.render(frame, [&](const ssam::gl::FoliageProgram& program) {
            program.bindBaseColorTexture(scene_.leafTexture());
            scene_.drawCards(
                [&](const float tint[4]) { program.setBaseColorFactor(tint[0], tint[1], tint[2], tint[3]); });
        });
        check(ssam, status, "ssam::gl render");
    }

private:
    const HostScene& scene_;
};

}  // namespace

int main(int argc, char** argv) {
    return runExample({"ssam_gl_embedding", false}, argc, argv, [](const HostScene& scene, const Arguments&) {
        return std::make_unique<BuiltInPrograms>(scene);
    });
}
