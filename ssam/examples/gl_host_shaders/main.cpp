// SPDX-License-Identifier: MIT
// ssam::gl with the host's own foliage shaders (way b): the same plain OpenGL program as
// gl_embedding (common/example_host.hpp), but its foliage is drawn by its own programs -- here
// with a wind bend in the vertex shader, as engines animate foliage -- inside the passes SSAM
// sets up: beginFrame, beginMaskPass / draw / endMaskPass, beginColorPass / draw / endColorPass,
// composite. SSAM sets each pass's framebuffer, blend, depth and cull state; the host's fragment
// shaders output what ssam/gl/ssam_gl.hpp's "host-shader contract" says:
//   mask pass    vec4(alpha) -- the coverage alpha in every channel ([Hathaway 2010] §3.5.2)
//   colour pass  (colour, alpha), discarding alpha < PassInfo::alphaReference (§3.5.3)
// With --wind 0 the shaders compute exactly what SSAM's built-in programs compute for this
// scene, so the image is gl_embedding's, bit for bit (a test checks it).
//
//   ssam_gl_host_shaders [--wind A]            a GLFW window when a display is available
//   ssam_gl_host_shaders --headless --out frame.png [--mask mask.png] [--wind A]
#include <stdexcept>
#include <string>

#include "example_host.hpp"

namespace {

using namespace gl_example;

// The host's foliage vertex shader: its own attribute layout and uniforms. The wind moves a
// vertex at height h (the card's texture v: 0 at its base, 1 at its top) by u_wind * h^2 in x
// (scene.hpp's windOffset: the check computes where the leaves went from the same formula).
constexpr const char* kFoliageVertex = R"(#version 330 core
layout(location = 0) in vec3 position;
layout(location = 2) in vec2 uv;
uniform mat4 u_viewProj;
uniform float u_wind;
out vec2 v_uv;
void main() {
    float h = uv.y;
    vec3 bent = position + vec3(u_wind * h * h, 0.0, 0.0);
    gl_Position = u_viewProj * vec4(bent, 1.0);
    v_uv = uv;
}
)";

// Mask pass: the coverage alpha (tint alpha * texel alpha), saturated, in every channel of every
// draw buffer SSAM has (PassInfo::drawBuffers: 2 with the Rg16f mask). No lighting, no discard.
constexpr const char* kMaskFragment = R"(#version 330 core
in vec2 v_uv;
uniform vec4 u_tint;
uniform sampler2D u_leaf;
layout(location = 0) out vec4 o_mask;
layout(location = 1) out vec4 o_maskAdd;
void main() {
    float a = clamp(u_tint.a * texture(u_leaf, v_uv).a, 0.0, 1.0);
    o_mask = vec4(a);
    o_maskAdd = vec4(a);
}
)";

// Colour pass: straight colour and alpha, alpha-tested at SSAM's reference; depth is written by
// the fixed function (SSAM's state), so the nearest surviving leaf's colour wins.
constexpr const char* kColorFragment = R"(#version 330 core
in vec2 v_uv;
uniform vec4 u_tint;
uniform sampler2D u_leaf;
uniform float u_alphaReference;
layout(location = 0) out vec4 o_color;
void main() {
    vec4 base = u_tint * texture(u_leaf, v_uv);
    if (!(base.a >= u_alphaReference)) discard;
    o_color = base;
}
)";

struct FoliageProgram {
    GLuint id = 0;
    GLint viewProj = -1, wind = -1, tint = -1, leaf = -1, alphaReference = -1;
    explicit FoliageProgram(const char* fragment) {
        id = linkProgram(kFoliageVertex, fragment, "foliage shader");
        viewProj = glGetUniformLocation(id, "u_viewProj");
        wind = glGetUniformLocation(id, "u_wind");
        tint = glGetUniformLocation(id, "u_tint");
        leaf = glGetUniformLocation(id, "u_leaf");
        alphaReference = glGetUniformLocation(id, "u_alphaReference");
    }
    ~FoliageProgram() { glDeleteProgram(id); }
    FoliageProgram(const FoliageProgram&) = delete;
    FoliageProgram& operator=(const FoliageProgram&) = delete;
};

class HostShaders final : public FoliageRenderer {
public:
    HostShaders(const HostScene& scene, float wind) : scene_(scene), wind_(wind) {}

    void render(ssam::gl::ScreenSpaceAlphaMaskGl& ssam, const ssam::gl::FrameDesc& frame) override {
        ssam::gl::FrameReport report;
        check(ssam, ssam.beginFrame(frame, &report), "ssam::gl beginFrame");
        if (!report.foliageInView) return;  // the frame is over: SSAM costs nothing
        ssam::gl::PassInfo pass;
        check(ssam, ssam.beginMaskPass(&pass), "ssam::gl beginMaskPass");
        drawCards(mask_, frame, pass);
        check(ssam, ssam.endMaskPass(), "ssam::gl endMaskPass");
        check(ssam, ssam.beginColorPass(&pass), "ssam::gl beginColorPass");
        drawCards(color_, frame, pass);
        check(ssam, ssam.endColorPass(), "ssam::gl endColorPass");
        check(ssam, ssam.composite(), "ssam::gl composite");
    }

private:
    // The same cards, the same bend, in the same order in both passes (§3.8).
    void drawCards(const FoliageProgram& program, const ssam::gl::FrameDesc& frame, const ssam::gl::PassInfo& pass) {
        glUseProgram(program.id);
        glUniformMatrix4fv(program.viewProj, 1, GL_FALSE, frame.viewProj);
        glUniform1f(program.wind, wind_);
        glUniform1f(program.alphaReference, pass.alphaReference);  // -1 in the mask program: ignored
        glActiveTexture(GL_TEXTURE0);
        glBindTexture(GL_TEXTURE_2D, scene_.leafTexture());
        glUniform1i(program.leaf, 0);
        scene_.drawCards([&](const float tint[4]) { glUniform4fv(program.tint, 1, tint); });
    }

    const HostScene& scene_;
    float wind_;
    FoliageProgram mask_{kMaskFragment};
    FoliageProgram color_{kColorFragment};
};

}  // namespace

int main(int argc, char** argv) {
    return runExample({"ssam_gl_host_shaders", true}, argc, argv, [](const HostScene& scene, const Arguments& args) {
        return std::make_unique<HostShaders>(scene, args.wind);
    });
}
