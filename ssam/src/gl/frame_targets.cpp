// SPDX-License-Identifier: MIT
#include "frame_targets.hpp"

#include <string>

#include <glm/gtc/type_ptr.hpp>

#include "engine/render/screen_bounds.hpp"
#include "failure.hpp"
#include "gl_functions.hpp"
#include "gl_objects.hpp"

namespace ssam::gl::detail {

namespace {

bool isColorFormat(GLint f) { return f == GL_RGBA8 || f == GL_SRGB8_ALPHA8 || f == GL_RGBA16F || f == GL_RGBA32F; }
bool isDepthFormat(GLint f) {
    return f == GL_DEPTH_COMPONENT16 || f == GL_DEPTH_COMPONENT24 || f == GL_DEPTH_COMPONENT32F ||
           f == GL_DEPTH24_STENCIL8 || f == GL_DEPTH32F_STENCIL8;
}
bool hasStencil(GLint f) { return f == GL_DEPTH24_STENCIL8 || f == GL_DEPTH32F_STENCIL8; }

GLuint createTarget(const GlFunctions& gl, GLint internalFormat, int width, int height) {
    GLuint t = 0;
    gl.GenTextures(1, &t);
    gl.BindTexture(GL_TEXTURE_2D, t);
    const bool isFloat = internalFormat == GL_RGBA16F || internalFormat == GL_RGBA32F || internalFormat == GL_R16F;
    const GLenum format = internalFormat == GL_R16F ? GL_RED : GL_RGBA;
    // Immutable storage where there is (GL 4.2): hosts can then make views of SSAM's targets.
    if (gl.textureStorage) gl.TexStorage2D(GL_TEXTURE_2D, 1, static_cast<GLenum>(internalFormat), width, height);
    else
        gl.TexImage2D(GL_TEXTURE_2D, 0, internalFormat, width, height, 0, format, isFloat ? GL_FLOAT : GL_UNSIGNED_BYTE,
                      nullptr);
    // Sampled with texelFetch only; a non-mipmap filter makes the texture complete.
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
    return t;
}

void attachDepth(const GlFunctions& gl, GLuint fbo, GLuint depth, bool renderbuffer, bool depthStencil) {
    gl.BindFramebuffer(GL_DRAW_FRAMEBUFFER, fbo);
    gl.FramebufferTexture2D(GL_DRAW_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_TEXTURE_2D, 0, 0);  // any kind
    const GLenum attachment = depthStencil ? GL_DEPTH_STENCIL_ATTACHMENT : GL_DEPTH_ATTACHMENT;
    if (renderbuffer) gl.FramebufferRenderbuffer(GL_DRAW_FRAMEBUFFER, attachment, GL_RENDERBUFFER, depth);
    else gl.FramebufferTexture2D(GL_DRAW_FRAMEBUFFER, attachment, GL_TEXTURE_2D, depth, 0);
}

// The host's depth as a texture or a renderbuffer (FrameDesc: exactly one), with a message that
// names a renderbuffer handed over as a texture (or the other way round) for what it is.
TextureInfo inspectDepth(const GlFunctions& gl, const FrameDesc& frame) {
    if ((frame.depthTexture != 0) == (frame.depthRenderbuffer != 0))
        throw Failure(Status::InvalidArgument, "ssam::gl: give the depth as exactly one of FrameDesc::depthTexture (" +
                                                   std::to_string(frame.depthTexture) +
                                                   ") and FrameDesc::depthRenderbuffer (" +
                                                   std::to_string(frame.depthRenderbuffer) + ")");
    if (frame.depthRenderbuffer) return inspectRenderbuffer(gl, frame.depthRenderbuffer, "depth renderbuffer");
    const GLuint name = frame.depthTexture;
    const bool alsoRenderbuffer = gl.IsRenderbuffer(name);
    if (!gl.IsTexture(name) && alsoRenderbuffer)
        throw Failure(Status::InvalidTexture, "ssam::gl: depth texture " + std::to_string(name) +
                                                  " is not a texture but a renderbuffer: pass it as "
                                                  "FrameDesc::depthRenderbuffer");
    const TextureInfo depth = inspectTexture2D(gl, name, "depth texture", TextureRole::Depth);
    if (!isDepthFormat(depth.internalFormat))
        throw Failure(Status::InvalidTexture,
                      "ssam::gl: depth texture " + std::to_string(name) + " has format " +
                          internalFormatName(depth.internalFormat) +
                          "; use a GL_DEPTH_COMPONENT* or depth-stencil format" +
                          (alsoRenderbuffer ? " (GL name " + std::to_string(name) +
                                                  " is also a renderbuffer: if that is your depth, pass it as "
                                                  "FrameDesc::depthRenderbuffer)"
                                            : std::string()));
    return depth;
}

// OpenGL ES 3.0 renders into float targets (rt_foliage takes the colour's format) only with
// GL_EXT_color_buffer_float, and blends into 32F ones (the composite) only with GL_EXT_float_blend.
void checkFloatColor(const GlFunctions& gl, GLint format, GLuint texture) {
    const char* missing = nullptr;
    if ((format == GL_RGBA16F || format == GL_RGBA32F) && !gl.colorBufferFloat) missing = "GL_EXT_color_buffer_float";
    else if (format == GL_RGBA32F && !gl.floatBlend) missing = "GL_EXT_float_blend";
    if (missing)
        throw Failure(Status::UnsupportedFeature, "ssam::gl: colour texture " + std::to_string(texture) + " is " +
                                                      internalFormatName(format) + ", which this OpenGL ES context " +
                                                      "cannot render and blend into without " + missing);
}

std::string sizeText(int width, int height) { return std::to_string(width) + "x" + std::to_string(height); }

}  // namespace

void FrameTargets::createFramebuffers(const GlFunctions& gl) {
    gl.GenFramebuffers(1, &maskFbo_);
    gl.GenFramebuffers(1, &foliageFbo_);
    gl.GenFramebuffers(1, &compositeFbo_);
}

void FrameTargets::destroyTextures(const GlFunctions& gl) {
    const GLuint textures[] = {maskTex_, maskAddTex_, foliageTex_};
    gl.DeleteTextures(3, textures);
    maskTex_ = maskAddTex_ = foliageTex_ = 0;
    width_ = height_ = 0;
    precision_.reset();
    foliageFormat_ = 0;
}

void FrameTargets::destroy(const GlFunctions& gl) {
    destroyTextures(gl);
    const GLuint fbos[] = {maskFbo_, foliageFbo_, compositeFbo_};
    gl.DeleteFramebuffers(3, fbos);
    *this = FrameTargets{};
}

void FrameTargets::prepare(const GlFunctions& gl, const FrameDesc& frame, MaskPrecision precision) {
    const TextureInfo color = inspectTexture2D(gl, frame.colorTexture, "colour texture");
    const TextureInfo depth = inspectDepth(gl, frame);
    if (!isColorFormat(color.internalFormat))
        throw Failure(Status::InvalidTexture, "ssam::gl: colour texture " + std::to_string(frame.colorTexture) +
                                                  " has format " + internalFormatName(color.internalFormat) +
                                                  "; use GL_RGBA8, GL_SRGB8_ALPHA8, GL_RGBA16F or GL_RGBA32F");
    checkFloatColor(gl, color.internalFormat, frame.colorTexture);
    if (!isDepthFormat(depth.internalFormat))
        throw Failure(Status::InvalidTexture, "ssam::gl: depth renderbuffer " +
                                                  std::to_string(frame.depthRenderbuffer) + " has format " +
                                                  internalFormatName(depth.internalFormat) +
                                                  "; use a GL_DEPTH_COMPONENT* or depth-stencil format");
    const char* depthKind = frame.depthRenderbuffer ? "depth renderbuffer" : "depth texture";
    for (const auto& [info, what] : {std::pair{color, "colour texture"}, std::pair{depth, depthKind}})
        if (info.width >= 0 && (info.width != frame.width || info.height != frame.height))
            throw Failure(Status::InvalidTexture, std::string("ssam::gl: the ") + what + " is " +
                                                      sizeText(info.width, info.height) + " but the frame is " +
                                                      sizeText(frame.width, frame.height));

    if (width_ != frame.width || height_ != frame.height || precision_ != precision ||
        foliageFormat_ != color.internalFormat) {
        destroyTextures(gl);
        switch (precision) {
            case MaskPrecision::Rgba8: maskTex_ = createTarget(gl, GL_RGBA8, frame.width, frame.height); break;
            case MaskPrecision::Rgba16f: maskTex_ = createTarget(gl, GL_RGBA16F, frame.width, frame.height); break;
            case MaskPrecision::Rg16f:
                maskTex_ = createTarget(gl, GL_R16F, frame.width, frame.height);
                maskAddTex_ = createTarget(gl, GL_R16F, frame.width, frame.height);
                break;
        }
        foliageTex_ = createTarget(gl, color.internalFormat, frame.width, frame.height);
        width_ = frame.width, height_ = frame.height;
        precision_ = precision;
        foliageFormat_ = color.internalFormat;
        gl.BindFramebuffer(GL_DRAW_FRAMEBUFFER, maskFbo_);
        gl.FramebufferTexture2D(GL_DRAW_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, maskTex_, 0);
        gl.FramebufferTexture2D(GL_DRAW_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, GL_TEXTURE_2D, maskAddTex_, 0);
        const GLenum maskBuffers[] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
        gl.DrawBuffers(maskAddTex_ ? 2 : 1, maskBuffers);
        gl.BindFramebuffer(GL_DRAW_FRAMEBUFFER, foliageFbo_);
        gl.FramebufferTexture2D(GL_DRAW_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, foliageTex_, 0);
        attachedDepth_ = 0;  // re-check completeness below
    }
    depthFormat_ = depth.internalFormat;
    const bool depthStencil = hasStencil(depth.internalFormat);
    const bool renderbuffer = frame.depthRenderbuffer != 0;
    const GLuint depthName = renderbuffer ? frame.depthRenderbuffer : frame.depthTexture;
    if (attachedDepth_ != depthName || attachedDepthRenderbuffer_ != renderbuffer ||
        attachedDepthStencil_ != depthStencil) {
        attachedDepth_ = 0;  // until both framebuffers are known complete
        attachDepth(gl, maskFbo_, depthName, renderbuffer, depthStencil);
        checkDrawFramebuffer(gl, "mask pass");
        attachDepth(gl, foliageFbo_, depthName, renderbuffer, depthStencil);
        checkDrawFramebuffer(gl, "colour pass");
        attachedDepth_ = depthName;
        attachedDepthRenderbuffer_ = renderbuffer;
        attachedDepthStencil_ = depthStencil;
    }
    if (attachedColor_ != frame.colorTexture) {
        attachedColor_ = 0;
        gl.BindFramebuffer(GL_DRAW_FRAMEBUFFER, compositeFbo_);
        gl.FramebufferTexture2D(GL_DRAW_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, frame.colorTexture, 0);
        checkDrawFramebuffer(gl, "composite");
        attachedColor_ = frame.colorTexture;
    }
}

// engine::render::screenBounds() expects our backend's clip conventions (z in [0, w], NDC +y = row 0): the
// host's are read from glClipControl's state and mapped to them.
std::optional<Rect> compositeRegion(const GlFunctions& gl, const FrameDesc& frame) {
    if (!frame.foliageBounds || frame.foliageBoundsCount == 0) return Rect{0, 0, frame.width, frame.height};
    GLint origin = GL_LOWER_LEFT, depthMode = GL_NEGATIVE_ONE_TO_ONE;
    if (gl.clipControl) {
        gl.GetIntegerv(GL_CLIP_ORIGIN, &origin);
        gl.GetIntegerv(GL_CLIP_DEPTH_MODE, &depthMode);
    }
    glm::mat4 viewProj = glm::make_mat4(frame.viewProj);
    if (depthMode == GL_NEGATIVE_ONE_TO_ONE) {
        glm::mat4 toZeroToOne(1.0f);  // z' = (z + w) / 2
        toZeroToOne[2][2] = 0.5f;
        toZeroToOne[3][2] = 0.5f;
        viewProj = toZeroToOne * viewProj;
    }
    engine::render::Rect region;
    bool any = false;
    for (std::size_t i = 0; i < frame.foliageBoundsCount; ++i) {
        const Box& box = frame.foliageBounds[i];
        const engine::render::BoundingBox bounds{glm::make_vec3(box.min), glm::make_vec3(box.max)};
        const std::optional<engine::render::Rect> r =
            engine::render::screenBounds(bounds, viewProj, frame.width, frame.height);
        if (!r) continue;
        region = engine::render::unite(region, *r);
        any = true;
    }
    if (!any) return std::nullopt;
    // screenBounds' rows count from NDC +1; with GL_LOWER_LEFT that is the top window row.
    if (origin == GL_LOWER_LEFT) region.y = frame.height - (region.y + region.height);
    return Rect{region.x, region.y, region.width, region.height};
}

}  // namespace ssam::gl::detail
