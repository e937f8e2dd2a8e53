// SPDX-License-Identifier: MIT
#pragma once
// The temporal pass (TAA) that `hashed+taa` and `alpha-test+taa` run after their
// technique: each frame is drawn with its projection moved by a sub-pixel jitter (Halton 2, 3),
// and a full-screen pass blends it with the history, the previous output, fetched where the
// pixel's surface was in the previous frame: reprojected through the pixel's depth and the
// previous camera, both without jitter, then clamped to the current frame's 3x3 neighbourhood
// so that what was disoccluded or changed does not leave a trail ([Karis 2014] "High Quality
// Temporal Supersampling", SIGGRAPH Advances in Real-Time Rendering; Yang et al. 2020, "A Survey
// of Temporal Antialiasing Techniques", EG STAR).
//
// Motion within the scene (wind, collision bend, the car) comes from motion vectors: a draw
// whose batch has MaskedBatch::motionVertices (each vertex's previous minus current position;
// foliage, or an opaque draw of FoliageFrame::movingOpaque) writes that
// motion, in world space, into a motion target (FoliageMotion, after the technique's frame,
// depth-tested against the depth it left and alpha-tested at the material's cutoff), and the
// pixels it covers fetch their history from where their surface was: the previous camera's
// projection of the pixel's world position plus that motion ([Karis 2014]'s velocity, taken as
// engines take it, from the previous frame's deformed position). Every other pixel
// follows the camera alone. TemporalOptions::motionVectors off keeps the camera alone for all.
#include <cstdint>

#include <glm/glm.hpp>

#include "engine/render/param_block.hpp"
#include "engine/render/program_desc.hpp"
#include "engine/render/texture.hpp"

namespace transparency {

struct TemporalOptions {
    // The weight of the current frame: history + (current - history) * blend, an exponential
    // average over about 1 / blend frames ([Karis 2014]'s exponential history; higher follows
    // motion sooner, lower averages more noise away). In (0, 1].
    float blend = 0.1f;
    int jitterPhases = 8;  // the Halton (2, 3) sequence repeats after this many frames; >= 1
    // Reproject by the draws' motion where they have one (above); false: by the camera alone,
    // as a TAA without motion vectors does (for comparing the two).
    bool motionVectors = true;
};

// The sub-pixel offset, in pixels within (-0.5, 0.5), of frame `frameIndex`: the Halton (2, 3)
// point of index 1 + frameIndex % phases, minus one half, rounded to 1/256 pixel.
glm::vec2 haltonJitter(std::uint64_t frameIndex, int phases);

// viewProj moved on screen by `jitterPixels` in a width x height target: clip x gains
// 2 jx / width * w, so every point moves by jx pixels right and jy pixels down (the engine's
// rows grow downwards: NDC y = 1 at row 0). A zero jitter returns viewProj itself.
glm::mat4 jitteredViewProj(const glm::mat4& viewProj, glm::vec2 jitterPixels, int width, int height);

// The matrix that takes (pixel x + 0.5, pixel y + 0.5, depth, 1) of the current frame to
// (previous pixel position * w, ..., w): the previous frame's pixel coordinates (centres at
// + 0.5) after division by the last component. Computed in double from the unjittered
// view-projections; nullopt-like false when `current` cannot be inverted.
bool reprojectionMatrix(const glm::mat4& current, const glm::mat4& previous, int width, int height, glm::mat4& out);

// What the resolve adds for a pixel whose surface moved by a world-space motion m since the
// previous frame (previous minus current position): with h = inverse(current) * NDC of the
// pixel, the homogeneous world position, and W = worldW . (x + 0.5, y + 0.5, depth, 1) its
// last component, the previous pixel position * w becomes
//   reprojection * (x + 0.5, y + 0.5, depth, 1) + W * previousToPixels * (m, 0)
// (the previous projection of h / W + m, times W). False where reprojectionMatrix is.
struct MotionReprojection {
    glm::mat4 previousToPixels{1.0f};  // previous view-projection, then clip to pixel coordinates * w
    glm::vec4 worldW{0.0f};            // the last row of inverse(current) after pixel-to-NDC
};
bool motionReprojection(const glm::mat4& current, const glm::mat4& previous, int width, int height,
                        MotionReprojection& out);

// TemporalResolve, one texel per pixel, into the frame and the next history (the same value):
//   p    = reprojection * (x + 0.5, y + 0.5, depth(x, y), 1); prev = p.xy / p.w
//   hist = history bilinear at prev (clamped to the edge), or none when prev is off screen,
//          not finite, or hasHistory is false
//   lo, hi = min, max of current over the 3x3 neighbourhood (clamped to the edge)
//          where motion is bound: moved by the rgb of the nearest (by depth) of the 3x3
//          pixels with motion alpha > 0 (MotionReprojection), taken as that pixel's screen
//          offset; the pixel's own when it is the one (it wins ties)
//   out  = hist ? h + (current - h) * blend with h = clamp(hist, lo, hi) : current
//          (exactly current where the clamped history equals it: a still pixel does not drift)
// Non-finite current components come out as 0.
// Its parameter block, declared once (engine/render/param_block.hpp; GLSL body in glsl/).
#define TRANSPARENCY_TEMPORAL_RESOLVE_PARAMS(UNIFORM, DIRECTION, TEXTURE)                                        \
    UNIFORM(glm::mat4, reprojection, glm::mat4(1.0f))                                                            \
    TEXTURE(current, Texel, FullSize, Required) /* the frame as the technique left it */                         \
    TEXTURE(depth, Texel, FullSize, Optional)   /* its depth (resolved, D32F) */                                 \
    TEXTURE(history, Texel, FullSize, Optional) /* the previous output */                                        \
    UNIFORM(float, blend, 0.1f)                                                                                  \
    UNIFORM(bool, hasHistory, false)                                                                             \
    UNIFORM(bool, copyOnly, false)             /* out = current at the pixel: the copy the resolve reads from */ \
    TEXTURE(motion, Texel, FullSize, Optional) /* RGBA16F: world motion, alpha > 0 where written */              \
    UNIFORM(glm::mat4, previousToPixels, glm::mat4(1.0f))                                                        \
    UNIFORM(glm::vec4, worldW, glm::vec4(0.0f))                                                                  \
    UNIFORM(bool, reverseDepth, false) /* the nearest surface has the largest depth */
ENGINE_PARAM_BLOCK(TemporalResolveParams, TRANSPARENCY_TEMPORAL_RESOLVE_PARAMS);

engine::render::ProgramDesc temporalResolveProgram();

// FoliageMotion, a mesh program drawn with a batch's motionVertices: out = (the interpolated
// normal, which is the world-space motion, AlphaOnly's saturated alpha) under AlphaOnlyParams.
engine::render::ProgramDesc foliageMotionProgram();

}  // namespace transparency
