// SPDX-License-Identifier: MIT
#pragma once
// The OpenGL ES 3.0 driver under the render front end (device.hpp): WebGL2's API, run natively
// here on an EGL ES context (Mesa llvmpipe). It compiles the same GLSL as the GL 4.5 driver,
// translated to `#version 300 es`, and keeps the GL driver's conventions (upper-left origin,
// depth in [0, 1], scissor rows from the top) where ES 3.0 reaches them. What differs from GL
// 4.5, and why (README "Drivers"):
//   - ES 3.0 has no glClipControl: EXT_clip_control sets the origin and depth mode where the
//     context offers it (WebGL2 and Mesa do); without it every vertex stage the driver compiles
//     ends by negating y and remapping z to 2z - w, which gives the same picture and depth, up
//     to rounding, with depth passing through [-1, 1] (reverse-Z loses its float precision near
//     the far plane). describe() says which path the device took.
//   - No direct state access, no base-instance draws (the instance attributes are pointed at
//     the draw's first instance instead), no timer queries: a pass's time is the CPU wall time
//     of recording it (describe() says so), never the GPU's.
//   - Multisampled targets are renderbuffers, resolved by glBlitFramebuffer (the colour average
//     is the implementation's); a multisampled depth cannot be read per sample, so the
//     closest-sample depth resolve of [Hathaway 2010] §3.5.1 is refused with an engine::Error.
//   - Alpha-to-coverage is GL_SAMPLE_ALPHA_TO_COVERAGE (gl_SampleMask is ES 3.2): pipelines that
//     use it say so in PipelineInfo (exact = false). `precise` is ES 3.2 too: it is kept where
//     the context has EXT_gpu_shader5, and dropped (FMA contraction allowed) where not.
//   - Rendering to 16F/32F targets needs EXT_color_buffer_float and blending into 32F needs
//     EXT_float_blend; different blend states or write masks per target need
//     OES_draw_buffers_indexed. Each is refused by name when missing.
//   - Conditional rendering (ES 3.0 has none) waits for the query's result on the CPU.
#include <cstdint>
#include <memory>
#include <string>

#include "engine/render/device.hpp"
#include "engine/render/gl/gl_backend.hpp"
#include "engine/render/gl/gl_context.hpp"

namespace engine::render::gles {

struct GlesOptions {
    // The context: null makes and owns a headless EGL ES context of headless.major.minor.
    std::shared_ptr<gl::GlContext> context;
    gl::HeadlessEglOptions headless = {3, 0, true};
    gl::FailModeStrategy failModes = gl::FailModeStrategy::TwoPass;
};

std::unique_ptr<Device> createGlesBackend(const GlesOptions& options = {});
// Empty when an ES 3.0 context with what the driver needs can be made here, else why not.
std::string glesUnavailableReason(const GlesOptions& options = {});

}  // namespace engine::render::gles
