// SPDX-License-Identifier: MIT
#pragma once
// The OpenGL 4.5 core backend: the same Backend semantics as the soft backend (which is
// the reference), mapped to GL state where GL has it and emulated where it does not.
//
// Conventions (so images match the soft backend without flips):
//   glClipControl(GL_UPPER_LEFT, GL_ZERO_TO_ONE): clip z in [0, w], NDC +y is window row 0,
//   which is the first stored row, i.e. the top of a Readback. Texture uv (0,0) is the first
//   stored row as in GL. Scissor rects are then given to GL as they are (y from the top).
//
// What is emulated, and how exactly (README "GL backend"):
//   - Alpha test in GLSL with `discard`; the PS2 GS fail modes FB_ONLY / ZB_ONLY / RGB_ONLY by
//     splitting a draw into steps that each write a subset of colour/alpha/depth for the
//     fragments that pass or fail ([PCSX2]; fail_mode_plan.hpp). Exact when depth cannot change
//     under the draw (no depth writes) or its test cannot depend on order (ALWAYS: the seed's
//     depth-always rewrite); otherwise the two-pass split is inexact where fragments of one draw
//     overlap, reported by PipelineInfo::exact = false + note and a warning, unless
//     GlOptions::failModes = PerTriangle, which is exact at two draws per triangle.
//   - Alpha-to-coverage with the soft backend's rule (the first round(alpha * samples) samples)
//     through gl_SampleMask; GL_SAMPLE_ALPHA_TO_COVERAGE's pattern is implementation-defined
//     (GlOptions::nativeAlphaToCoverage uses it anyway, and reports the pipelines inexact).
//   - Trilinear LOD in the shader from analytic UV derivatives, lerping two textureLod levels,
//     as the soft backend does (GL's own LOD precision is implementation-defined).
//   - Resolve by shaders: colour averaged in linear (sRGB decoded by the fetch, encoded by
//     GL_FRAMEBUFFER_SRGB), depth the closest sample under the given depth function.
//   - Clears and mip levels beyond those given are computed on the CPU with the soft backend's
//     rounding (glClearTexImage), so they are bit-identical.
// What GL leaves to the implementation and is not emulated: sample positions and counts
// (llvmpipe: 4x only, 2x becomes 4x, 8x is refused), the tie rule for samples exactly on an edge,
// float-to-half rounding, blending precision on 8-bit targets, sRGB conversion precision.
// llvmpipe (Mesa 22.x) defects worked around: a TIME_ELAPSED query begun before the first draw
// into a framebuffer, non-indexed draws of three triangles with a zero-area last one, and the
// scissor of multisampled targets (gl_shaders.cpp, gl_passes.cpp say where).
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>

#include "engine/render/backend.hpp"
#include "engine/render/gl/gl_context.hpp"

namespace engine::render::gl {

enum class FailModeStrategy : std::uint8_t {
    TwoPass,      // passing fragments, then failing ones (PCSX2's approach): fast, inexact on overlap
    PerTriangle,  // the same two steps per triangle: exact, two draws per triangle
};

struct GlOptions {
    // The context: null with useCurrentContext false creates and owns a HeadlessEglContext;
    // a given context (e.g. a GlfwWindowContext) is made current and shared; useCurrentContext
    // adopts whatever context is current on this thread (another engine's). The backend sets
    // every piece of GL state it relies on per pass and draw, so a host may change state between.
    std::shared_ptr<GlContext> context;
    bool useCurrentContext = false;
    HeadlessEglOptions headless;

    bool debugOutput = false;  // KHR_debug messages (errors, performance) to the log
    FailModeStrategy failModes = FailModeStrategy::TwoPass;
    bool nativeAlphaToCoverage = false;
    // readback() reads at most this many bytes per GL call (whole rows, at least one; never
    // over GLsizei's 2 GiB - 1, which a 16384x16384 float readback would wrap). Smaller bands
    // only cost calls; tests set it small to read in many bands.
    std::size_t readbackBandBytes = std::size_t(1) << 30;
};

struct GlInfo {
    std::string vendor, renderer, version, glslVersion;
    std::string context;  // GlContext::describe(), or "current context"
    int maxSamples = 0;   // GL_MAX_SAMPLES; 2x requests may get more samples (llvmpipe: 4)
};

class GlBackend : public Backend {
public:
    virtual const GlInfo& info() const = 0;
    virtual GlContext* context() const = 0;  // null when adopting the current context

    // Shows a single-sampled colour texture in the context's window: scaled to the window's
    // framebuffer, row 0 at the top, then swaps buffers. Returns false (and does nothing) when
    // the window is minimised / 0x0 or there is no window.
    virtual bool present(TextureHandle texture) = 0;

    // Wraps a 2D (or 2D multisample) texture created by the host in this context. Its size,
    // sample count and internal format are checked against `desc`; destroy() forgets it
    // without deleting it.
    virtual TextureHandle importTexture(unsigned int glTexture, const TextureDesc& desc) = 0;
    // The GL name behind a texture handle, for interop.
    virtual unsigned int glTexture(TextureHandle texture) const = 0;
};

// Throws engine::Error when no suitable context exists (no EGL, no 4.5 core, missing
// ARB_clip_control on a 4.3/4.4 window context).
std::unique_ptr<GlBackend> createGlBackend(const GlOptions& options = {});

}  // namespace engine::render::gl
