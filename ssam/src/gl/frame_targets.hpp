// SPDX-License-Identifier: MIT
#pragma once
// SSAM's render targets for one host frame ([Hathaway 2010] §3.5): rt_mask (in the configured
// precision) and rt_foliage (in the format of the host's colour texture), each with the host's
// depth texture or renderbuffer attached, and the composite's framebuffer around the host's colour texture.
// Recreated only when the frame's size, the precision or the colour format change.
#include <optional>

#include "ssam/gl/ssam_gl.hpp"

namespace ssam::gl::detail {

struct GlFunctions;

class FrameTargets {
public:
    void createFramebuffers(const GlFunctions& gl);  // once, at initialisation
    void destroy(const GlFunctions& gl);             // every GL object

    // Checks the host's textures (2D, supported formats, the frame's size; Failure(InvalidTexture)
    // otherwise), (re)creates SSAM's targets and attaches the host's textures (Failure
    // (IncompleteFramebuffer) when the driver refuses them). Changes the draw framebuffer and the
    // active unit's GL_TEXTURE_2D binding: the caller restores them.
    void prepare(const GlFunctions& gl, const FrameDesc& frame, MaskPrecision precision);

    unsigned int maskFramebuffer() const { return maskFbo_; }
    unsigned int foliageFramebuffer() const { return foliageFbo_; }
    unsigned int compositeFramebuffer() const { return compositeFbo_; }
    unsigned int mask() const { return maskTex_; }
    unsigned int maskAdd() const { return maskAddTex_; }  // 0 unless Rg16f
    unsigned int foliage() const { return foliageTex_; }
    int depthFormat() const { return depthFormat_; }  // the host depth's internal format (last prepare)

private:
    void destroyTextures(const GlFunctions& gl);
    unsigned int maskFbo_ = 0, foliageFbo_ = 0, compositeFbo_ = 0;
    unsigned int maskTex_ = 0, maskAddTex_ = 0, foliageTex_ = 0;
    int width_ = 0, height_ = 0;
    int foliageFormat_ = 0, depthFormat_ = 0;
    std::optional<MaskPrecision> precision_;
    unsigned int attachedColor_ = 0, attachedDepth_ = 0;
    bool attachedDepthRenderbuffer_ = false, attachedDepthStencil_ = false;
};

// The composite's scissor in GL window coordinates: the screen region of the frame's
// foliageBounds (the whole frame when none are given), or nullopt when no box is in view.
// The host's clip conventions are read from glClipControl's state where it exists.
std::optional<Rect> compositeRegion(const GlFunctions& gl, const FrameDesc& frame);

}  // namespace ssam::gl::detail
