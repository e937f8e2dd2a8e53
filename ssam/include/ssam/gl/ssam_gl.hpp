// SPDX-License-Identifier: MIT
#pragma once
// SSAM for engines that bring their own OpenGL ([Hathaway 2010] §3.5-3.7). The host hands over the
// GL names of its opaque colour and depth textures; SSAM runs the mask, colour and composite
// passes into its own framebuffers, composites onto the host's colour texture and writes the
// foliage depth into the host's depth texture (for later transparent passes, §3.7).
//
// Host-neutral: this header uses only standard C++17 and <ssam/version.hpp>. SSAM calls GL through
// entry points it resolves with the host's own loader (glfwGetProcAddress, SDL_GL_GetProcAddress,
// eglGetProcAddress, wglGetProcAddress wrapped, ...); nothing throws into host code: every call
// returns a Status, and the reason is passed to an optional message callback and kept for
// lastMessage().
//
// Two ways to draw the foliage:
//  (a) SSAM's built-in foliage programs: render(frame, draw) calls `draw` twice (mask pass, then
//      colour pass) with SSAM's program bound; the host binds its VAO (attribute locations:
//      attributeLocations()) and draws.
//  (b) The host's own shaders: beginFrame(), then beginMaskPass() / draw / endMaskPass(),
//      beginColorPass() / draw / endColorPass(), composite(). SSAM sets each pass's framebuffer,
//      viewport, blend, depth and cull state; the host binds its own program, which must output
//      what "The host-shader contract" below says.
//
// The host-shader contract (way b; SSAM's built-in programs are written to it):
//  Mask pass ([Hathaway 2010] §3.5.2, Table 3.1). Fragment output: the foliage's coverage alpha a,
//    saturated to [0, 1], in EVERY channel of `layout(location = 0) out vec4` -- vec4(a) -- and,
//    when PassInfo::drawBuffers is 2 (MaskPrecision::Rg16f), the same vec4(a) at location 1. No
//    lighting or colour fetch is needed. Do not alpha-test (the mask pass's reference is 0: a
//    fragment of alpha 0 adds nothing anyway). Do not write gl_FragDepth (the depth test
//    against the opaque depth must be early and exact). SSAM's blend state makes RGB the MAX and
//    A the SUM of the layers' alphas; depth is tested (Settings::depthTest), not written.
//  Colour pass (§3.5.3). Fragment output at location 0: (colour.rgb, a), straight (not
//    premultiplied) alpha, in the colour texture's space (linear for GL_SRGB8_ALPHA8: SSAM
//    enables GL_FRAMEBUFFER_SRGB); discard every fragment with !(a >= PassInfo::alphaReference)
//    (Settings::colorAlphaReference). Nothing is blended; depth is tested and written, so the
//    nearest surviving fragment's colour wins and its depth reaches the host's depth texture.
//  Both passes: draw the same geometry with the same vertex transform (wind, skinning, ...),
//    in the same order (§3.8 only needs consistency); both faces are drawn (culling is off: a
//    foliage card is seen from both sides) unless the host enables culling inside the pass.
//
// OpenGL 3.3+, core or compatibility profile (Api::Gl33), or OpenGL ES 3.0+ / WebGL2 (Api::Gles30,
// below). In a compatibility context SSAM also saves,
// disables and restores the fixed-function state that would act on its shaders' output
// (GL_ALPHA_TEST, GL_POLYGON_STIPPLE, glClampColor(GL_CLAMP_FRAGMENT_COLOR)): a host that leaves
// alpha testing on does not cut SSAM's leaf edges.
//
// A GL context must be current on the calling thread for every call but the constructor,
// setMessageCallback and lastMessage; the same context (or one sharing objects with it) for all.
// That includes release() and the destructor: SSAM's objects belong to the context, so without
// it current nothing can be deleted; release() then returns NoContext (and says so through the
// message callback), and the objects go when the host destroys its context.
//
// The host's GL state: every piece SSAM changes is saved when a call (or a begin...Pass) starts
// and restored when it returns (or at the matching end...Pass / composite), also on errors. That
// includes what the host binds between a begin...Pass and its end...Pass: its program, VAO,
// GL_ARRAY_BUFFER, active texture unit, GL_TEXTURE_2D bindings of units 0-3, generic vertex
// attributes, and the enables, blend, depth and mask state listed in ssam/README.md are back as
// they were before begin...Pass. Other state the host changes inside a pass (uniforms, sampler
// objects, textures of units 3 and up, buffer contents) stays as the host left it.
#include <cstddef>
#include <memory>
#include <type_traits>

#include "ssam/core/frame.hpp"
#include "ssam/core/host_passes.hpp"
#include "ssam/core/settings.hpp"
#include "ssam/core/status.hpp"
#include "ssam/version.hpp"

namespace ssam::gl {

// ---- Results (the core's: ssam/core/status.hpp) -------------------------------------------

using ssam::MessageCallback;
using ssam::Severity;
using ssam::severityName;
using ssam::Status;
using ssam::StatusCode;
using ssam::statusName;

// The host's GL loader. Both common shapes are taken: returning void* (SDL2's
// SDL_GL_GetProcAddress, glad's GLADloadproc) or a function pointer (glfwGetProcAddress,
// eglGetProcAddress, SDL3's SDL_GL_GetProcAddress).
using GetProcAddress = void* (*)(const char* name);
using GetProcAddressFunction = void (*(*)(const char* name))();

// ---- Plain data ----------------------------------------------------------------------------

// The core's (ssam/core/frame.hpp): Rect (GL window coordinates here: rows from the bottom unless
// GL_UPPER_LEFT), Box, Light (the built-in colour program's, way a).
using ssam::Box;
using ssam::Light;
using ssam::Rect;

// Vertex attribute locations of SSAM's built-in foliage programs (way a; initialize() and
// setAttributeLocations()):
// set them to the locations the host's own VAOs already use (e.g. uv at 8, normal at 2) so its
// vertex arrays are reused as they are (a host with something at 8 moves instanceTint too). Each
// below 16 (GL's minimum GL_MAX_VERTEX_ATTRIBS), no two overlapping (instanceModel takes four).
// An attribute the host's VAO does not enable reads SSAM's generic value: normal (0,0,1), uv
// (0,0), colour and instance tint (1,1,1,1), instance model columns the identity; a plain mesh
// needs only position (+ uv for a texture). SSAM restores the generic values it sets. The tint's alpha is how a host crossfades two levels of detail through
// the mask, sort-free: each level's instances carry its weight.
struct AttributeLocations {
    unsigned int position = 0;       // vec3
    unsigned int normal = 1;         // vec3, double-sided lighting (colour pass)
    unsigned int uv = 2;             // vec2, base-colour texture coordinates
    unsigned int color = 3;          // vec4, multiplies the base colour (straight alpha)
    unsigned int instanceModel = 4;  // mat4 as 4 vec4 columns at instanceModel .. + 3 (divisor 1)
    unsigned int instanceTint = 8;   // vec4 (divisor 1), multiplies the colour (straight alpha)
};

// The paper's knobs (ssam/core/settings.hpp), the same struct for every SSAM. Rg16f needs GL 4.0 or
// GL_ARB_draw_buffers_blend (two mask targets blended differently; on ES: Api below).
// depthMaskThreshold > 0: a copy of the host's depth and one full-screen pass (ssam/README.md,
// "Later transparent passes").
using ssam::DepthTest;
using ssam::MaskPrecision;
using ssam::Settings;

// ssam::Preset::Measured's knobs (ssam/docs/knobs.md "Presets": lower error than the paper's at its cost).
inline Settings measuredSettings() { return ssam::presetSettings(ssam::Preset::Measured); }

// The API of the host's context, named at initialize() (a context of the other API: InvalidArgument).
//  Gl33    OpenGL 3.3 or newer, core or compatibility: `#version 330 core` programs.
//  Gles30  OpenGL ES 3.0 or newer, and WebGL2 (ES 3.0 through Emscripten): the same programs as
//          `#version 300 es` (highp), only ES 3.0 entry points and state (no GL_FRAMEBUFFER_SRGB:
//          sRGB targets always encode; no compatibility state; colour masks and blending per draw
//          buffer only with ES 3.2 or OES/EXT_draw_buffers_indexed). MaskPrecision::Rgba16f, Rg16f
//          and a float colour texture need GL_EXT_color_buffer_float (RGBA32F also
//          GL_EXT_float_blend); Rg16f also per-buffer blending. ES 3.0 cannot ask a texture its size,
//          so FrameDesc::width x height is taken as the textures' (renderbuffers are checked).
//          What differs and why: ssam/docs/gles.md.
enum class Api : unsigned char { Gl33, Gles30 };

struct FrameDesc {
    // The host's opaque colour: GL_RGBA8, GL_SRGB8_ALPHA8 (blended in linear, as
    // GL_FRAMEBUFFER_SRGB does), GL_RGBA16F or GL_RGBA32F; a single-sample GL_TEXTURE_2D.
    unsigned int colorTexture = 0;
    // Its depth: GL_DEPTH_COMPONENT16 / 24 / 32F, GL_DEPTH24_STENCIL8 or GL_DEPTH32F_STENCIL8, the
    // same size. Receives the foliage depth. Either a single-sample GL_TEXTURE_2D (depthTexture)
    // or a single-sample renderbuffer (depthRenderbuffer), as the host keeps it; exactly one of
    // the two is non-zero. SSAM only attaches the depth, it never samples it.
    unsigned int depthTexture = 0;
    unsigned int depthRenderbuffer = 0;
    int width = 0;
    int height = 0;
    // Column-major (as GL and glm store it), in the host's clip conventions (SSAM reads
    // glClipControl's state and never changes it). Used for the bounds below, and by the
    // built-in programs.
    float viewProj[16] = {1.0f, 0.0f, 0.0f, 0.0f, 0.0f, 1.0f, 0.0f, 0.0f,
                          0.0f, 0.0f, 1.0f, 0.0f, 0.0f, 0.0f, 0.0f, 1.0f};
    Light light;  // the built-in colour program's (way a)
    // World-space boxes around everything the host will draw. Given (count > 0): when none is in
    // view no pass runs (SSAM costs nothing, the callback is not called) and the composite is
    // scissored to their screen region. Not given: every pass runs over the whole frame.
    const Box* foliageBounds = nullptr;
    std::size_t foliageBoundsCount = 0;
};

// The core's (ssam/core/frame.hpp): FrameReport::compositeRegion in GL window coordinates;
// FoliagePass and foliagePassName.
using ssam::FoliagePass;
using ssam::foliagePassName;
using ssam::FrameReport;

// What a pass of the host's own shaders must know (way b; see the contract above).
struct PassInfo {
    FoliagePass pass = FoliagePass::Mask;
    int drawBuffers = 1;          // mask pass: write vec4(alpha) to locations 0 .. drawBuffers - 1
    float alphaReference = 0.0f;  // colour pass: discard when !(alpha >= alphaReference); mask pass 0
};

namespace detail {
struct GlFunctions;
}

// What the built-in programs' draw callback gets (way a). Clip position = viewProj (FrameDesc) *
// model (setModel) * instanceModel (attribute) * position. Base = factor * colour * instanceTint *
// texel; the colour pass discards base.a < alphaReference and writes base.rgb * (ambient + light *
// lambert).
struct FoliageProgram {
    FoliagePass pass = FoliagePass::Mask;
    unsigned int program = 0;         // bound with glUseProgram
    int modelUniform = -1;            // mat4, identity until set
    int baseColorFactorUniform = -1;  // vec4, (1,1,1,1) until set; its alpha scales the mask too
    int hasTextureUniform = -1;       // bool, false until bindBaseColorTexture(non-zero)
    int baseColorTextureUnit = 0;     // the sampler reads GL_TEXTURE0 + this unit
    float alphaReference = 0.0f;      // colour pass: Settings::colorAlphaReference; mask pass: 0

    void setModel(const float columnMajor[16]) const noexcept;
    void setBaseColorFactor(float r, float g, float b, float a) const noexcept;
    // Binds a GL_TEXTURE_2D (straight alpha) to the base-colour unit; 0 = no texture. SSAM
    // restores the unit's previous binding after the pass.
    void bindBaseColorTexture(unsigned int texture) const noexcept;

    const detail::GlFunctions* gl = nullptr;  // SSAM's entry points (internal)
};

// GL names of SSAM's targets, e.g. to show the paper's Figures 3.6-3.8 (0 until first used).
struct Intermediates {
    unsigned int mask = 0;     // r = MAX, a = SUM (RGBA8 / RGBA16F); Rg16f: MAX in r
    unsigned int maskAdd = 0;  // Rg16f only: SUM in r
    unsigned int foliage = 0;  // rt_foliage, the format of the host's colour texture
};

// ---- SSAM ----------------------------------------------------------------------------------

// From HostPasses (ssam/core/host_passes.hpp): setMessageCallback, lastMessage, settings, render
// (way a), beginFrame ... composite (way b); what they mean for the host's GL state is said above.
class ScreenSpaceAlphaMaskGl : public HostPasses<ScreenSpaceAlphaMaskGl, FrameDesc, FoliageProgram, PassInfo> {
public:
    ScreenSpaceAlphaMaskGl() noexcept;  // no GL yet
    // Deletes SSAM's GL objects (release()); the context must be current then, or release()
    // must have been called while it was. Without one, the message callback is told (NoContext).
    ~ScreenSpaceAlphaMaskGl();
    ScreenSpaceAlphaMaskGl(ScreenSpaceAlphaMaskGl&&) noexcept;
    ScreenSpaceAlphaMaskGl& operator=(ScreenSpaceAlphaMaskGl&&) noexcept;

    // Resolves the GL entry points through the host's loader (MissingEntryPoint names the first
    // one it has no address for), checks the current context (`api`: OpenGL 3.3 or newer, core or
    // compatibility, or OpenGL ES 3.0 or newer), compiles SSAM's programs. May be called again
    // (e.g. after release()).
    // `attributes`: where the built-in programs read the host's vertex arrays (way a).
    Status initialize(GetProcAddress getProcAddress, const Settings& settings = {},
                      const AttributeLocations& attributes = {}, Api api = Api::Gl33) noexcept;
    Status initialize(GetProcAddressFunction getProcAddress, const Settings& settings = {},
                      const AttributeLocations& attributes = {}, Api api = Api::Gl33) noexcept;
    // Deletes SSAM's GL objects; initialize() again to use it. Needs the context current: without
    // one nothing is deleted and NoContext is returned (the objects then go with the context);
    // SSAM is released either way. Ok when there was nothing to delete.
    Status release() noexcept;

    // InvalidArgument naming the knob (the core's rules, ssam::settingsError).
    Status setSettings(const Settings& settings) noexcept;
    // New locations recompile the built-in programs (the context must be current then; before
    // initialize() they are only kept). InvalidArgument naming the attribute.
    Status setAttributeLocations(const AttributeLocations& attributes) noexcept;
    const AttributeLocations& attributeLocations() const noexcept;

    // Way (a), render(): `draw(user, program)` runs with SSAM's program, framebuffer and state
    // set: it binds its VAO(s) at attributeLocations(), sets per-draw values through `program` and
    // draws; it may instead bind its own program if that keeps the host-shader contract. Every
    // piece of GL state SSAM changes is restored before render() returns, also when `draw` throws.
    // Way (b): each begin...Pass saves the GL state it changes and sets the pass's; the matching
    // end...Pass restores it (between them, the host binds its program, VAOs and textures and
    // draws). composite() blends the foliage onto the host's colour, restores its state and ends
    // the frame. Out of order: InvalidCall; the open frame is abandoned and the host's state restored.

    Intermediates intermediates() const noexcept;

    struct Impl;

private:
    friend HostPasses;  // reaches impl_ and the two messages below
    static constexpr const char* kMovedFrom = "ssam::gl: this ScreenSpaceAlphaMaskGl was moved from (or out of memory)";
    static constexpr const char* kRenderWithoutCallback = "ssam::gl: render() without a draw callback";
    std::unique_ptr<Impl> impl_;
};

}  // namespace ssam::gl
