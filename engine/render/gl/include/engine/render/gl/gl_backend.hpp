// SPDX-License-Identifier: MIT
#pragma once
// The OpenGL 4.5 core driver under the render front end (device.hpp): the same semantics as
// the soft driver (which is the reference), mapped to GL state where GL has it and emulated
// where it does not.
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

#include "engine/render/device.hpp"
#include "engine/render/driver.hpp"
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

// What only the GL driver offers, reached as device.driverAs<GlDriver>().
class GlDriver : public Driver {
public:
    virtual const GlInfo& info() const = 0;
    virtual GlContext* context() const = 0;  // null when adopting the current context
    // The GL name behind a native texture, and a host's texture wrapped as one (importTexture).
    virtual unsigned int glTexture(NativeId texture) const = 0;
    virtual NativeId wrapTexture(unsigned int glTexture, const TextureDesc& desc, const std::string& what) = 0;
};

// A render device over the GL driver. Throws engine::Error when no suitable context exists
// (no EGL, no 4.5 core, missing ARB_clip_control on a 4.3/4.4 window context).
std::unique_ptr<Device> createGlBackend(const GlOptions& options = {});

// The GL driver under `device`; engine::Error when it runs another.
inline GlDriver& glDriver(const Device& device) { return device.driverAs<GlDriver>(); }

// Wraps a 2D (or 2D multisample) texture created by the host in the device's GL context. Its
// size, sample count and internal format are checked against `desc`; destroy() forgets it
// without deleting it. Device::present shows a texture in the context's window.
TextureHandle importTexture(Device& device, unsigned int glTexture, const TextureDesc& desc);
// The GL name behind a texture handle, for interop.
unsigned int glTexture(const Device& device, TextureHandle texture);

}  // namespace engine::render::gl
