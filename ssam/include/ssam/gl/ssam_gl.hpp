// SPDX-License-Identifier: MIT
#pragma once
// SSAM for engines that bring their own OpenGL ([Hathaway 2010] §3.5-3.7): the engine hands over the
// GL names of its opaque colour and depth textures and a callback that draws its foliage; SSAM
// runs the mask, colour and composite passes into its own framebuffers and composites onto the
// engine's colour texture, writing the foliage depth into the engine's depth texture.
//
//   ssam::gl::ScreenSpaceAlphaMaskGl ssam;                 // needs a current GL 3.3+ core context
//   ssam.render({colorTex, depthTex, width, height, viewProj}, [&](const ssam::gl::FoliageProgram& p) {
//       glBindVertexArray(leavesVao);                       // attributes at p's locations
//       p.setModel(leafModel);
//       p.bindBaseColorTexture(leafTexture);
//       glDrawElements(GL_TRIANGLES, leafIndexCount, GL_UNSIGNED_INT, nullptr);
//   });
//
// The callback runs twice per frame (mask pass, then colour pass) with SSAM's program bound,
// its framebuffer, blend, depth and cull state set; it should bind its VAO(s), set the per-draw
// uniforms through FoliageProgram and draw, and change no other state. Draw the same geometry
// in the same order both times (§3.8: only consistency of dispatch order is needed).
//
// Independent of our engine: no ECS, assets, windowing or render backend; only the GL-free
// ssam core (Config) and the engine render layer (BoundingBox, screenBounds) and the current GL context (through libepoxy).
#include <functional>
#include <memory>
#include <optional>
#include <span>

#include <glm/glm.hpp>

#include "engine/render/program.hpp"
#include "engine/render/raster_state.hpp"
#include "ssam/config.hpp"
#include "ssam/foliage.hpp"

namespace ssam::gl {

enum class FoliagePass { Mask, Color };
const char* foliagePassName(FoliagePass pass);

// Vertex attribute locations of SSAM's foliage programs. An attribute the engine's VAO does not
// enable reads SSAM's generic value: normal (0,0,1), uv (0,0), colour (1,1,1,1), instance model
// columns the identity, so a plain non-instanced mesh needs only position (+ uv for textures).
struct AttributeLocations {
    static constexpr unsigned int position = 0;       // vec3
    static constexpr unsigned int normal = 1;         // vec3, double-sided lighting (colour pass)
    static constexpr unsigned int uv = 2;             // vec2, base-colour texture coordinates
    static constexpr unsigned int color = 3;          // vec4, multiplies the base colour (straight alpha)
    static constexpr unsigned int instanceModel = 4;  // mat4 as 4 vec4 columns at 4..7 (divisor 1)
};

// What the callback gets: which pass, which program is bound, where its inputs are.
// clip position = viewProj (FrameDesc) * model (uniform) * instanceModel (attribute) * position.
struct FoliageProgram {
    FoliagePass pass = FoliagePass::Mask;
    unsigned int program = 0;           // bound with glUseProgram
    AttributeLocations attributes;
    int modelUniform = -1;              // mat4, identity until set
    int baseColorFactorUniform = -1;    // vec4, (1,1,1,1) until set; alpha scales the mask too
    int hasTextureUniform = -1;         // bool, false until bindBaseColorTexture(non-zero)
    int baseColorTextureUnit = 0;       // the sampler reads GL_TEXTURE0 + this unit
    // The colour pass discards fragments whose alpha is below this (Config::colorAlphaReference,
    // §3.5.3); the mask pass rejects nothing (the paper's alpha reference 0, §3.5.2). An engine
    // may bind its own program instead if it keeps these rules: mask pass writes vec4(alpha)
    // to every draw buffer, colour pass writes (lit rgb, alpha) and discards alpha < reference.
    float alphaReference = 0.0f;

    void setModel(const glm::mat4& model) const;
    void setBaseColorFactor(const glm::vec4& factor) const;
    // Binds a GL_TEXTURE_2D (straight alpha) to the base-colour unit; 0 = no texture. SSAM
    // restores the unit's previous binding after the pass.
    void bindBaseColorTexture(unsigned int texture) const;
};

using DrawFoliage = std::function<void(const FoliageProgram&)>;

struct FrameDesc {
    // The engine's opaque colour: GL_RGBA8, GL_SRGB8_ALPHA8 (blended in linear, as
    // GL_FRAMEBUFFER_SRGB does) or GL_RGBA16F / GL_RGBA32F; single-sample GL_TEXTURE_2D.
    unsigned int colorTexture = 0;
    // Its depth: GL_DEPTH_COMPONENT32F / 24 / 16 or GL_DEPTH24_STENCIL8 / GL_DEPTH32F_STENCIL8,
    // same size. Receives the foliage depth (for later transparent passes, §3.7).
    unsigned int depthTexture = 0;
    int width = 0;
    int height = 0;
    glm::mat4 viewProj{1.0f};  // in the engine's clip-space conventions (SSAM never changes glClipControl)
    engine::render::DirectionalLight light{{0.0f, 0.0f, 1.0f}, glm::vec3(0.0f), glm::vec3(1.0f)};  // default: unlit
    // World-space bounds of what the callback draws. Given: no pass runs (and the callback is
    // not called) when none is in view, and the composite is scissored to their screen region.
    // Not given: every pass runs and the composite covers the whole target.
    std::optional<std::span<const engine::render::BoundingBox>> foliageBounds;
};

struct FrameReport {
    int passesRun = 0;                       // 0 (nothing in view) or 3
    engine::render::Rect compositeRegion;    // GL window coordinates (y from the bottom row)
};

// GL names of SSAM's targets, e.g. to show the paper's Figures 3.6-3.8 (0 until first used).
struct GlIntermediates {
    unsigned int mask = 0;     // r = MAX mask, a = ADD mask (RGBA8 / RGBA16F)
    unsigned int maskAdd = 0;  // RG16F precision: the ADD mask in r (mask then holds MAX in r)
    unsigned int foliage = 0;  // rt_foliage, the colour format of the engine's colour texture
};

class ScreenSpaceAlphaMaskGl {
public:
    // Needs a current OpenGL 3.3+ core context (engine::Error otherwise); MaskPrecision::RG16F
    // needs per-buffer blend equations (GL 4.0 or ARB_draw_buffers_blend). GL objects are
    // created in, and must be destroyed with, that context current.
    explicit ScreenSpaceAlphaMaskGl(const Config& config = {});
    ~ScreenSpaceAlphaMaskGl();
    ScreenSpaceAlphaMaskGl(const ScreenSpaceAlphaMaskGl&) = delete;
    ScreenSpaceAlphaMaskGl& operator=(const ScreenSpaceAlphaMaskGl&) = delete;

    void setConfig(const Config& config);  // validates (engine::Error naming the knob)
    const Config& config() const { return config_; }

    // Runs the three passes. Every piece of GL state SSAM changes is restored before it returns
    // (README "Embedding with raw OpenGL" lists it), also when the callback throws.
    // engine::Error for bad textures, zero or mismatched sizes, incomplete framebuffers and no
    // current context.
    FrameReport render(const FrameDesc& frame, const DrawFoliage& drawFoliage);

    GlIntermediates intermediates() const;

    struct Impl;

private:
    Config config_;
    std::unique_ptr<Impl> impl_;
};

}  // namespace ssam::gl
